"""Clients and the middleware adaptor, offline (stand-in grounder and discoverer)."""

from __future__ import annotations

import numpy as np
import pytest
from test_clients_standins import StandInDiscoverer, StandInGrounder

from lucifer.clients.common import CONFIGS, RunResult, flags
from lucifer.clients.envs import SAREnv
from lucifer.clients.hierq import HierQ, rl_env_kwargs
from lucifer.clients.middleware import Advice, GridSignals, Middleware
from lucifer.clients.planner import HybridPlanner
from lucifer.kb import load_kb


@pytest.fixture(scope="module")
def kb():
    return load_kb("knowledge_base")


def _mw(kb, config="+D+G", **kw):
    g, d = flags(config)
    return Middleware(kb, grounding=g, discovery=d, grounder=StandInGrounder(kb), discoverer=StandInDiscoverer(), **kw)


# ---------------------------------------------------------------- middleware


async def test_signals_exclude_moves_into_reported_hazards(kb):
    env = SAREnv(kb)
    mw = _mw(kb)
    _, info = env.reset(seed=0, options={"layout": 0, "style": "standard"})
    sig = await mw.signals(info["reports"])
    lay = env.layout
    assert {c for c in range(env.n_cells) if sig.hazard[c]} == set(lay.hazard_cells)
    for cell in range(env.n_cells):
        for a in range(4):
            nxt = env.next_cell[cell][a]
            if nxt >= 0:
                assert sig.admissible[cell][a] == (nxt not in lay.hazard_cells)
            else:
                assert not sig.admissible[cell][a]
    assert all(sig.goal[c] for c in lay.info_cells)  # briefing names every information location
    # the potential is higher at the victim than at a hazard
    assert sig.phi[lay.info_cells[0]] > max(sig.phi[c] for c in lay.hazard_cells)
    assert sig.shaping(0, 1, gamma=1.0) == pytest.approx(sig.phi[1] - sig.phi[0])
    assert sig.contract.admissible  # the full SignalContract is there for display


async def test_identical_requests_are_cached(kb):
    env = SAREnv(kb)
    mw = _mw(kb)
    _, info = env.reset(seed=0, options={"layout": 0, "style": "messy"})
    a = await mw.signals(info["reports"])
    b = await mw.signals(list(info["reports"]))
    assert a is b
    assert mw.calls["ground"] == len(set(info["reports"]))
    assert mw.calls["contract"] == 1
    sig = env.signature_pool()[0][0]
    x = await mw.discover(sig)
    y = await mw.discover(sig, (), env.query_options)
    assert x is y and mw.calls["discover"] == 1 and isinstance(x, Advice)
    assert x.option == env.query_options[0] and x.ranked()[0] == x.option


async def test_concurrent_duplicates_share_one_grounding_call(kb):
    import asyncio

    mw = _mw(kb)
    await asyncio.gather(*(mw.ground("Fire reported at the bakery, stay out.") for _ in range(5)))
    assert mw.calls["ground"] == 1


async def test_flags_turn_signals_and_advice_off(kb):
    mw = _mw(kb, "baseline")
    sig = await mw.signals(["Fire reported at the bakery, stay out."])
    assert sig.neutral and all(len(a) == 4 for a in sig.allowed) and not any(sig.hazard)
    assert await mw.discover("strong smell of gas") is None
    assert mw.calls == {"ground": 0, "discover": 0, "contract": 0}


async def test_cache_export_import_avoids_backend_calls(kb):
    mw = _mw(kb)
    await mw.warm(["Fire reported at the bakery, stay out."], ["strong smell of gas"])
    other = Middleware(kb, grounder=_Boom(), discoverer=_Boom())
    other.import_cache(mw.export_cache())
    await other.signals(["Fire reported at the bakery, stay out."])
    assert (await other.discover("strong smell of gas")).option == "gas_sniffer"


class _Boom:
    async def ground(self, *a, **k):
        raise AssertionError("backend called despite the cache")

    async def discover(self, *a, **k):
        raise AssertionError("backend called despite the cache")


def test_neutral_signals_shape_nothing():
    n = GridSignals.neutral_for(4)
    assert n.shaping(0, 3) == 0.0 and n.prior[2] == [0.0] * 4


def test_flags():
    assert [flags(c) for c in CONFIGS] == [(False, False), (True, False), (False, True), (True, True)]
    with pytest.raises(ValueError):
        flags("+X")


# ---------------------------------------------------------------- hybrid planner


async def _planner_runs(kb, config, episodes=40, layout=None):
    env = SAREnv(kb, max_steps=100)
    p = HybridPlanner(env, _mw(kb, config), np.random.default_rng(0))
    eps = []
    for i in range(episodes):
        eps.append(await p.run_episode(seed=i, options=None if layout is None else {"layout": layout}))
    return eps


async def test_planner_grounding_masks_hazards_on_a_fixed_layout(kb):
    base = await _planner_runs(kb, "baseline", layout=0)
    guarded = await _planner_runs(kb, "+G", layout=0)
    assert sum(e.collisions for e in base) > 0  # A* without the contract walks into hidden hazards
    assert sum(e.collisions for e in guarded) == 0
    assert all(e.success for e in guarded)


async def test_planner_ablation_pattern(kb):
    res = {c: RunResult.from_episodes(await _planner_runs(kb, c)) for c in CONFIGS}
    assert res["+G"].sms == res["+G"].msr > res["baseline"].sms
    assert res["+D"].csr >= 99 and res["+D+G"].csr >= 99 > res["baseline"].csr
    assert res["+D+G"].msr == 100 and res["+D+G"].sms == 100


async def test_planner_records_a_path(kb):
    env = SAREnv(kb)
    p = HybridPlanner(env, _mw(kb), np.random.default_rng(0))
    ep = await p.run_episode(seed=0, record_path=True)
    assert ep.path[0] == env.layout.start and len(ep.path) >= 2
    assert all(c not in env.layout.hazard_cells for c in ep.path)


# ---------------------------------------------------------------- HierQ


async def _rl(kb, config, episodes=150, seed=0):
    env = SAREnv(kb, **rl_env_kwargs())
    c = HierQ(env, _mw(kb, config), np.random.default_rng(seed))
    return c, [await c.run_episode(seed=seed if i == 0 else None) for i in range(episodes)]


async def test_hierq_episodes_are_capped_and_learn(kb):
    c, eps = await _rl(kb, "+D+G", episodes=300)
    assert max(e.steps for e in eps) <= 30
    assert c.episodes == len(eps)
    early = RunResult.from_episodes(eps[:50]).msr
    late = RunResult.from_episodes(eps[-50:]).msr
    assert late > early + 30 and late >= 80


async def test_hierq_masking_never_collides(kb):
    _, eps = await _rl(kb, "+G", episodes=100)
    assert sum(e.collisions for e in eps) == 0
    _, base = await _rl(kb, "baseline", episodes=100)
    assert sum(e.collisions for e in base) > 0


async def test_hierq_follows_discovery(kb):
    _, eps = await _rl(kb, "+D", episodes=60)
    assert RunResult.from_episodes(eps).csr == 100.0
    _, base = await _rl(kb, "baseline", episodes=60)
    assert RunResult.from_episodes(base).csr < 60


async def test_hierq_same_seed_same_learning(kb):
    _, a = await _rl(kb, "+D+G", episodes=40, seed=3)
    _, b = await _rl(kb, "+D+G", episodes=40, seed=3)
    assert [(e.success, e.steps, e.collisions) for e in a] == [(e.success, e.steps, e.collisions) for e in b]


async def test_clients_report_query_outcomes(kb, tmp_path):
    from lucifer.telemetry.memory import TelemetryMemory

    mem = tmp_path / "t.sqlite"
    mw = _mw(kb, "+D+G", memory=str(mem), record_outcomes=True)
    env = SAREnv(kb)
    p = HybridPlanner(env, mw, np.random.default_rng(0))
    ep = await p.run_episode(seed=0)
    assert mw.flush() == ep.queries
    with TelemetryMemory(mem) as m:
        assert m.count() == ep.queries

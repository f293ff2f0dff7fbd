"""The third client: Farama MiniGrid's lava crossing through a generated knowledge base."""

from __future__ import annotations

import numpy as np
import pytest
from test_clients_standins import StandInDiscoverer, StandInGrounder

from lucifer.clients.common import CONFIGS, RunResult, flags
from lucifer.clients.middleware import Middleware
from lucifer.clients.minigrid_client import LavaSARWrapper, MiniGridPlanner, generate_kb, place_name
from lucifer.kb import load_kb


@pytest.fixture(scope="module")
def lava_kb(tmp_path_factory):
    return load_kb(generate_kb(9, 9, tmp_path_factory.mktemp("kb")))


def test_generated_kb_names_every_floor_cell(lava_kb):
    assert (lava_kb.rows, lava_kb.cols) == (9, 9)
    assert len(lava_kb.landmarks) == 49
    assert lava_kb.cell_owner[(1, 1)] == place_name(1, 1)
    assert any(t.term == "lava" for t in lava_kb.glossary)
    assert len(lava_kb.query_options) == 15


def test_lava_reaches_the_agent_only_as_reports(lava_kb):
    env = LavaSARWrapper(lava_kb)
    obs, info = env.reset(seed=0)
    lava = env.layout.hazard_cells
    assert len(info["reports"]) == len(lava)
    names = {lava_kb.cell_owner[divmod(c, 9)] for c in lava}
    assert all(any(n in r for n in names) for r in info["reports"])


def _run(kb, config, episodes=15):
    import asyncio

    g, d = flags(config)
    env = LavaSARWrapper(kb)
    mw = Middleware(kb, grounding=g, discovery=d, grounder=StandInGrounder(kb), discoverer=StandInDiscoverer())
    c = MiniGridPlanner(env, mw, np.random.default_rng(0))

    async def go():
        return [await c.run_episode(seed=i) for i in range(episodes)]

    return asyncio.run(go())


def test_minigrid_pattern(lava_kb):
    res = {c: RunResult.from_episodes(_run(lava_kb, c)) for c in CONFIGS}
    assert res["baseline"].msr < 100  # without the contract the planner walks into lava
    assert res["+G"].sms == res["+G"].msr > res["baseline"].sms
    assert res["+D"].csr >= 99
    assert res["+D+G"].msr == res["+D+G"].sms == 100


def test_same_seed_same_rollout(lava_kb):
    a = _run(lava_kb, "+D+G", episodes=3)
    b = _run(lava_kb, "+D+G", episodes=3)
    assert [(e.steps, e.layout) for e in a] == [(e.steps, e.layout) for e in b]

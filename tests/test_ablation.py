"""``lucifer eval ablation`` end to end on small budgets, with offline backends."""

from __future__ import annotations

import argparse
import json

import pytest
from test_clients_standins import StandInDiscoverer, StandInGrounder

from lucifer.clients.common import CONFIGS, mean_std
from lucifer.evals import ablation
from lucifer.kb import load_kb


@pytest.fixture(scope="module")
def kb():
    return load_kb("knowledge_base")


def _run(kb, client, **kw):
    return ablation.run_ablation(client, kb="knowledge_base", workers=1, grounder=StandInGrounder(kb),
                                 discoverer=StandInDiscoverer(), **kw)


def test_planner_result_has_the_spec_shape_and_pattern(kb):
    res = _run(kb, "planner", runs=2, episodes=30)
    assert set(res) >= {"client", "runs", "episodes", "wall_s", "configs"}
    assert (res["client"], res["runs"], res["episodes"]) == ("planner", 2, 30)
    assert list(res["configs"]) == list(CONFIGS)
    for m in res["configs"].values():
        assert set(m) == {"msr", "csr", "sms"}
        assert all(len(v) == 2 and 0 <= v[0] <= 100 for v in m.values())
    assert all(res["extra"]["pattern"].values()), res["extra"]["pattern"]
    json.dumps(res)  # plain JSON


def test_rl_runs_are_paired_and_reproducible(kb):
    a = _run(kb, "rl", runs=2, episodes=40, seed=5)
    b = _run(kb, "rl", runs=2, episodes=40, seed=5)
    assert a["configs"] == b["configs"]
    c = _run(kb, "rl", runs=2, episodes=40, seed=6)
    assert c["configs"] != a["configs"]


def test_run_seeds_are_the_same_for_every_config():
    s1, r1 = ablation.run_seeds(0, 3)
    s2, r2 = ablation.run_seeds(0, 3)
    assert s1 == s2 and r1.integers(1 << 30) == r2.integers(1 << 30)
    assert ablation.run_seeds(0, 4)[0] != s1


def test_middleware_is_called_once_per_distinct_request(kb):
    res = _run(kb, "planner", runs=1, episodes=20)
    warm = res["extra"]["middleware_calls_warm"]
    assert warm["ground"] > 0 and warm["discover"] > 0
    for cfg, calls in res["extra"]["middleware_calls_runs"].items():
        assert calls["ground"] == 0 and calls["discover"] == 0, cfg  # everything came from the warm cache


def test_prior_missions_end_with_the_right_option(kb):
    from lucifer.clients.envs import SAREnv

    env = SAREnv(kb)
    import numpy as np

    recs = ablation.prior_missions(env, np.random.default_rng(0))
    by_sig: dict[str, list[tuple[str, float]]] = {}
    for sig, opt, out in recs:
        by_sig.setdefault(sig, []).append((opt, out))
    for k, pool in enumerate(env.signature_pool()):
        for sig in pool:
            assert by_sig[sig][-1] == (env.query_options[k], 1.0)


def test_table_and_mean_std():
    res = {"client": "x", "configs": {c: {"msr": [1.0, 0.5], "csr": [2.0, 0.0], "sms": [3.0, 1.0]} for c in CONFIGS}}
    table = ablation.format_table(res)
    assert table.splitlines()[0] == "| x | MSR | CSR | SMS |" and "| +D+G | 1.0 ± 0.5 | 2.0 ± 0.0 | 3.0 ± 1.0 |" in table
    assert mean_std([]) == [0.0, 0.0]


def test_cli_writes_json_and_charts(tmp_path, monkeypatch, kb):
    real = ablation.run_ablation

    def offline(client, **kw):
        return real(client, workers=1, grounder=StandInGrounder(kb), discoverer=StandInDiscoverer(), **kw)

    monkeypatch.setattr(ablation, "run_ablation", offline)
    monkeypatch.setattr(ablation, "episode_picture", _fake_picture)
    out = tmp_path / "r.json"
    args = argparse.Namespace(kb="knowledge_base", client="planner", runs=1, episodes=10, seed=0,
                              json_out=str(out), charts=str(tmp_path / "charts"))
    assert ablation.cmd_eval_ablation(args) == 0
    data = json.loads(out.read_text())
    assert data["client"] == "planner"
    assert (tmp_path / "charts" / "ablation_planner.png").stat().st_size > 1000


async def _fake_picture(client, png, **kw):
    from pathlib import Path

    Path(png).write_bytes(b"png")
    return Path(png)


def test_unknown_client():
    with pytest.raises(ValueError):
        ablation.run_ablation("nope")

"""The SAR testbed environment: registration, gymnasium's checker, determinism, mission rules."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import lucifer.clients.envs as envs
from lucifer.clients.envs import ENV_IDS, SAREnv
from lucifer.clients.envs.core import INFO_TYPES, LAYOUTS, Actions, resolve_layouts
from lucifer.clients.planner import astar
from lucifer.kb import load_kb


@pytest.fixture(scope="module")
def kb():
    return load_kb("knowledge_base")


@pytest.fixture()
def env(kb):
    return SAREnv(kb, max_steps=100)


@pytest.mark.parametrize("env_id", sorted(ENV_IDS))
def test_check_env_every_registered_id(env_id):
    assert env_id in gym.registry
    env = gym.make(env_id)
    check_env(env.unwrapped, skip_render_check=True)
    env.close()


@pytest.mark.filterwarnings("ignore:.*different from the unwrapped version")
def test_lava_wrapper_registered_and_checked(tmp_path, monkeypatch):
    from lucifer.clients.minigrid_client import LavaSARWrapper

    monkeypatch.setenv("LUCIFER_HOME", str(tmp_path))
    assert envs.LAVA_ID in gym.registry
    env = gym.make(envs.LAVA_ID)
    inner = env
    while not isinstance(inner, LavaSARWrapper):
        inner = inner.env
    check_env(inner, skip_render_check=True)


def _rollout(env_id: str, seed: int, n: int = 60):
    env = gym.make(env_id)
    obs, info = env.reset(seed=seed)
    env.action_space.seed(seed)
    out = [(obs["agent"].tolist(), info["reports"], info["signature"])]
    for _ in range(n):
        obs, r, term, trunc, info = env.step(env.action_space.sample())
        out.append((obs["agent"].tolist(), obs["collected"].tolist(), float(r), term, trunc, info["signature"], info["reports"]))
        if term or trunc:
            obs, info = env.reset()
            out.append(("reset", obs["agent"].tolist(), info["layout"]))
    return out


@pytest.mark.parametrize("env_id", ["LuciferSAR-v0", "LuciferSAR-S30-v0"])
def test_same_seed_same_rollout(env_id):
    assert _rollout(env_id, 7) == _rollout(env_id, 7)
    assert _rollout(env_id, 7) != _rollout(env_id, 8)


def test_at_least_eight_valid_layouts(kb):
    resolved = resolve_layouts(kb, LAYOUTS)
    assert len(resolved) >= 8
    for lay in resolved:
        assert len(lay.info_cells) == 3 and len(set(lay.info_cells)) == 3
        assert lay.start not in lay.hazard_cells
        assert not set(lay.info_cells) & lay.hazard_cells
        assert len(lay.hazard_cells) >= 3  # non-sparse: hazards crowd the 5x5 town


def test_hazards_are_not_observed(env):
    obs, info = env.reset(seed=0, options={"layout": 0})
    assert set(obs) == {"agent", "collected", "targets", "at_info", "layout"}
    assert info["reports"], "the briefing reports reach the agent as text only"
    assert all(isinstance(r, str) for r in info["reports"])


def _cell_move(env, src: int, dst: int) -> int:
    return next(a for a in range(4) if env.next_cell[src][a] == dst)


def test_entering_a_hazard_is_a_collision(env):
    env.reset(seed=0, options={"layout": 0})
    lay = env.layout
    hazard = next(c for c in lay.hazard_cells if any(env.next_cell[lay.start][a] == c for a in range(4)))
    _, r, term, trunc, info = env.step(_cell_move(env, lay.start, hazard))
    assert info["collision"] and info["collisions"] == 1
    assert env.agent == hazard and r < -0.5
    assert not term and not trunc  # a collision does not end the mission


def _walk(env, goal: int) -> None:
    lay = env.layout
    allowed = [tuple(a for a in range(4) if env.next_cell[c][a] >= 0 and env.next_cell[c][a] not in lay.hazard_cells)
               for c in range(env.n_cells)]
    for a in astar(env.agent, goal, env.next_cell, env.cols, allowed):
        _, _, term, _, info = env.step(a)
        assert not info["collision"] and not term


def test_mission_terminates_only_after_all_three_types(env):
    obs, info = env.reset(seed=3, options={"layout": 2})
    _, _, term, _, _ = env.step(int(Actions.done))
    assert not term  # too early: a wasted step
    for k, _t in enumerate(INFO_TYPES):
        _walk(env, env.layout.info_cells[k])
        sig = env.signature_at(k)
        _, _, _, _, info = env.step(int(Actions.QUERY_0) + 0)  # probe the at-location signature first
        assert info["signature"] in (sig, None)
        q = env.query_options.index(env.correct_option(k))
        if not env.collected[k]:
            _, r, term, _, info = env.step(int(Actions.QUERY_0) + q)
            assert info["query"] == {"option": env.correct_option(k), "correct": True, "location": k}
            assert info["reports"] and r > 0 and not term
        assert env.collected[k]
    _, r, term, trunc, info = env.step(int(Actions.done))
    assert term and info["success"] and r == 1.0


def test_wrong_queries_exhaust_a_location(kb):
    env = SAREnv(kb, max_steps=200, max_queries=3)
    env.reset(seed=1, options={"layout": 1})
    _walk(env, env.layout.info_cells[0])
    wrong = [i for i, o in enumerate(env.query_options) if o != env.correct_option(0)]
    for n, q in enumerate(wrong[:3], 1):
        _, r, term, _, info = env.step(int(Actions.QUERY_0) + q)
        assert info["query"]["correct"] is False and r < 0
        assert term == (n == 3)
    assert not info["success"]


def test_query_away_from_information_location_is_a_no_op(env):
    env.reset(seed=0, options={"layout": 0})
    _, _, _, _, info = env.step(int(Actions.QUERY_0))
    assert info["query"] is None and info["signature"] is None


def test_right_query_depends_on_the_signature(env):
    from lucifer.telemetry.scenarios import QUERY_INFO_TYPE

    seen = set()
    for seed in range(30):
        env.reset(seed=seed)
        for k, t in enumerate(INFO_TYPES):
            opt = env.correct_option(k)
            assert QUERY_INFO_TYPE[opt] == t
            assert env.signature_at(k) in env.signature_pool()[env.query_options.index(opt)]
            seen.add(opt)
    assert len(seen) >= 10  # the right query varies between episodes


def test_render_modes(kb):
    env = SAREnv(kb, render_mode="ansi")
    env.reset(seed=0, options={"layout": 0})
    text = env.render()
    assert "A" in text and "X" in text
    env = SAREnv(kb, render_mode="rgb_array")
    env.reset(seed=0)
    img = env.render()
    assert img.shape == (5 * 32, 5 * 32, 3) and img.dtype == np.uint8


def test_registration_is_idempotent():
    envs.register_envs()
    envs.register_envs()
    assert "LuciferSAR-v0" in gym.registry

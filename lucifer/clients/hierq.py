"""HierQ: hierarchical tabular Q-learning with a strategic decision engine.

The strategic decision engine (SDE) sequences three workers:

* **navigation worker**: tabular Q over (target cell, cell) × 4 moves, shared across layouts
  (``share_nav``; per-layout tables otherwise), to reach the information location the SDE picked
  (it stops early at any other uncollected location it passes, ``opportunistic``);
* **information-collection worker**: picks queries at the location, tabular Q over
  (information type) × 15 options, never repeating a rejected option at one visit;
* **triage worker**: once all three information types are in, transmits the report.

The SDE itself is an SMDP Q-learner over (layout, collected set) × next location.
Episodes are capped at 30 steps (the env's ``max_steps``); a location takes at most 15 query
attempts (the env's ``max_queries``).

Contract hooks, all through :class:`~lucifer.clients.middleware.Middleware` signals:

* **+G** is policy shaping: constraint masking (moves outside U'(x) are never taken),
  priors Ψ_x(u) bias exploration (in proportion to 1 + Ψ) and break ties of the greedy choice,
  and potential-based reward shaping F = γΦ(x') − Φ(x) (scaled by ``shaping_scale``) is added to
  the navigation reward. The weights are small on purpose: Φ and Ψ come from language about
  victims, safe places and hazards, not from the worker's current target, so they guide early
  exploration and must not override what the worker learns.
* **+D** is following u*: the collection worker executes discovery's recommendation
  (then the next-ranked untried option) instead of its own choice.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from lucifer.clients.common import EpisodeResult
from lucifer.clients.envs.core.actions import N_MOVES, Actions
from lucifer.clients.envs.sar import SAREnv
from lucifer.clients.middleware import Middleware


@dataclass(frozen=True)
class HierQParams:
    """Learning rates, discount, exploration and reward scales of the workers."""

    alpha: float = 0.5
    gamma: float = 0.95
    epsilon: float = 0.2  # initial exploration
    epsilon_min: float = 0.01
    epsilon_decay: float = 0.99  # per episode
    prior_weight: float = 0.01  # +G: Ψ added to Q for the greedy choice (breaks ties)
    prior_visits: float = 0.0  # > 0: the prior's weight decays as w / (1 + visits(x) / prior_visits)
    prior_explore: bool = True  # +G: explore in proportion to 1 + Ψ
    shaping_scale: float = 0.1  # +G: weight of F = γΦ(x') − Φ(x)
    step_cost: float = -0.1
    collision_cost: float = -1.0
    reach_bonus: float = 1.0
    share_nav: bool = True  # one navigation table per target cell, shared across layouts
    opportunistic: bool = True  # the SDE collects at any uncollected location the worker passes
    max_steps: int = 30
    max_queries: int = 15


class HierQ:
    """The hierarchical RL client; learns across the episodes of one run."""

    name = "rl"

    def __init__(self, env: SAREnv, middleware: Middleware, rng: np.random.Generator, params: HierQParams | None = None) -> None:
        self.env = env
        self.mw = middleware
        self.rng = rng
        self.p = params or HierQParams()
        n_l, n_c = len(env.layouts), env.n_cells
        self.options = env.query_options
        self.n_q = len(self.options)
        self.q_nav: list[list[list[list[float]]]] = [[[[0.0] * N_MOVES for _ in range(n_c)] for _ in range(3)] for _ in range(n_l)]
        self.q_nav_shared: list[list[list[float]]] = [[[0.0] * N_MOVES for _ in range(n_c)] for _ in range(n_c)]
        self.n_nav: list[list[list[int]]] = [[[0] * n_c for _ in range(3)] for _ in range(n_l)]
        self.n_nav_shared: list[list[int]] = [[0] * n_c for _ in range(n_c)]
        self.q_sde: list[list[list[float]]] = [[[0.0] * 3 for _ in range(8)] for _ in range(n_l)]
        self.q_info: list[list[float]] = [[0.0] * self.n_q for _ in range(3)]
        # moves that stay on the grid: what the agent knows without any contract
        self.on_grid: list[tuple[int, ...]] = [tuple(a for a in range(N_MOVES) if env.next_cell[c][a] >= 0) for c in range(n_c)]
        self._info_at = [[lay.info_cells.index(c) if c in lay.info_cells else -1 for c in range(n_c)]
                         for lay in env.layouts]
        self.epsilon = self.p.epsilon
        self.episodes = 0

    # ------------------------------------------------------------------ choices
    def _choose_move(self, q: list[float], moves: tuple[int, ...], prior: list[float] | None, k: float = 0.0) -> int:
        rng = self.rng
        if rng.random() < self.epsilon:
            if prior is None or not self.p.prior_explore:
                return moves[int(rng.integers(len(moves)))]
            w = np.array([1.0 + prior[a] for a in moves]) + 1e-3
            return moves[int(rng.choice(len(moves), p=w / w.sum()))]
        if prior is None or k == 0.0:
            best = max(q[a] for a in moves)
            ties = [a for a in moves if q[a] == best]
        else:
            vals = [q[a] + k * prior[a] for a in moves]
            best = max(vals)
            ties = [a for a, v in zip(moves, vals, strict=True) if v == best]
        return ties[0] if len(ties) == 1 else ties[int(rng.integers(len(ties)))]

    def _choose_target(self, q: list[float], todo: list[int]) -> int:
        if self.rng.random() < self.epsilon:
            return todo[int(self.rng.integers(len(todo)))]
        best = max(q[k] for k in todo)
        ties = [k for k in todo if q[k] == best]
        return ties[0] if len(ties) == 1 else ties[int(self.rng.integers(len(ties)))]

    def _choose_query(self, k: int, tried: set[int]) -> int:
        q = self.q_info[k]
        free = [i for i in range(self.n_q) if i not in tried]
        if self.rng.random() < self.epsilon:
            return free[int(self.rng.integers(len(free)))]
        best = max(q[i] for i in free)
        ties = [i for i in free if q[i] == best]
        return ties[0] if len(ties) == 1 else ties[int(self.rng.integers(len(ties)))]

    # ------------------------------------------------------------------ episode
    async def run_episode(self, seed: int | None = None, record_path: bool = False,
                          options: dict[str, Any] | None = None) -> EpisodeResult:
        env, mw, p = self.env, self.mw, self.p
        _, info = env.reset(seed=seed, options=options)
        reports: list[str] = list(info["reports"])
        sig = await mw.signals(reports)
        use_g = not sig.neutral
        li = env.layout_index
        info_cells = env.layout.info_cells
        q_nav_l, q_sde_l = self.q_nav[li], self.q_sde[li]
        queries = correct = 0
        path = [env.agent] if record_path else []
        alpha, gamma = p.alpha, p.gamma
        over = False
        success = False

        while not over:
            collected = env.collected
            if all(collected):  # triage worker
                _, _, terminated, truncated, info = env.step(int(Actions.done))
                success = bool(info["success"])
                break
            mask = collected[0] + 2 * collected[1] + 4 * collected[2]
            todo = [k for k in range(3) if not collected[k]]
            k = self._choose_target(q_sde_l[mask], todo)
            t0 = env.step_count
            target = info_cells[k]
            q_nav = self.q_nav_shared[target] if p.share_nav else q_nav_l[k]
            visits = self.n_nav_shared[target] if p.share_nav else self.n_nav[li][k]

            # navigation worker
            while env.agent != target:
                pos = env.agent
                moves = sig.allowed[pos] if use_g else self.on_grid[pos]
                if not moves:
                    moves = self.on_grid[pos]
                if use_g:
                    visits[pos] += 1
                    w = p.prior_weight / (1.0 + visits[pos] / p.prior_visits) if p.prior_visits else p.prior_weight
                    a = self._choose_move(q_nav[pos], moves, sig.prior[pos], w)
                else:
                    a = self._choose_move(q_nav[pos], moves, None)
                _, _, terminated, truncated, info = env.step(a)
                nxt = env.agent
                if record_path:
                    path.append(nxt)
                r = p.step_cost + (p.collision_cost if info["collision"] else 0.0)
                reached = nxt == target
                if use_g and p.shaping_scale:
                    r += p.shaping_scale * sig.shaping(pos, nxt, gamma)
                if reached:
                    r += p.reach_bonus
                    tgt = r
                else:
                    nmoves = sig.allowed[nxt] if use_g and sig.allowed[nxt] else self.on_grid[nxt]
                    qn = q_nav[nxt]
                    tgt = r + gamma * max(qn[b] for b in nmoves)
                qa = q_nav[pos]
                qa[a] += alpha * (tgt - qa[a])
                if info["reports"]:
                    reports.extend(info["reports"])
                    sig = await mw.signals(reports)
                if terminated or truncated:
                    over = True
                    break
                if p.opportunistic and not reached:
                    other = self._info_at[li][nxt]
                    if other >= 0 and not env.collected[other]:
                        k = other  # interrupt: collect here, the SDE credits the option it got
                        break
            if over:
                break

            # information-collection worker
            tried: set[int] = set()
            tried_names: list[str] = []
            while not env.collected[k]:
                qi = -1
                signature = info["signature"]
                if signature is not None:
                    advice = await mw.discover(info["signature"], tried_names, self.options)
                    if advice is not None:
                        name = next((o for o in advice.ranked() if o not in tried_names), None)
                        if name is not None:
                            qi = self.options.index(name)
                if qi < 0:
                    qi = self._choose_query(k, tried)
                _, _, terminated, truncated, info = env.step(int(Actions.QUERY_0) + qi)
                qrec = info["query"]
                if qrec is not None:
                    mw.outcome(signature or "", qrec["option"], bool(qrec["correct"]))
                    queries += 1
                    ok = bool(qrec["correct"])
                    correct += ok
                    qv = self.q_info[k]
                    qv[qi] += 0.1 * ((1.0 if ok else 0.0) - qv[qi])
                    if not ok:
                        tried.add(qi)
                        tried_names.append(self.options[qi])
                if info["reports"]:
                    reports.extend(info["reports"])
                    sig = await mw.signals(reports)
                if terminated or truncated:
                    over = True
                    break

            # SDE: SMDP update for the option "go to k and collect it"
            dur = env.step_count - t0
            r_sde = p.step_cost * dur
            qs = q_sde_l[mask]
            if over:
                tgt = r_sde
            else:
                nmask = mask | (1 << k)
                rest = [j for j in range(3) if not (nmask >> j) & 1]
                tgt = r_sde + (gamma ** dur) * (max(q_sde_l[nmask][j] for j in rest) if rest else 1.0)
            qs[k] += alpha * (tgt - qs[k])

        self.episodes += 1
        self.epsilon = max(p.epsilon_min, self.epsilon * p.epsilon_decay)
        return EpisodeResult(success, env.collisions, queries, correct, env.step_count, info["layout"], path)


def rl_env_kwargs(env_kwargs: dict[str, Any] | None = None) -> dict[str, Any]:
    """Env settings of the RL protocol: 30-step episodes, 15 query attempts per location."""
    p = HierQParams()
    return {"max_steps": p.max_steps, "max_queries": p.max_queries, **(env_kwargs or {})}

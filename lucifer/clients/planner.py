"""Hybrid planner: A* navigation plus heuristics, no learning.

At each step the planner heads for the nearest uncollected information location along an A*
path, queries when it stands on one, and transmits the situation report once all three
information types are in. Its two contract hooks:

* **+G**: A* generates a cell's neighbours only through admissible moves U'(x); when the
  contract leaves no path it falls back to unconstrained A* (and says so in its counters).
* **+D**: at an information location it executes discovery's u* (then the next-ranked
  untried option) instead of a random untried query.

The planner never reads text: reports and signatures go to the middleware unread.
"""

from __future__ import annotations

import heapq
from itertools import permutations
from typing import Any

import numpy as np

from lucifer.clients.common import EpisodeResult
from lucifer.clients.envs.core.actions import N_MOVES, Actions
from lucifer.clients.envs.sar import SAREnv
from lucifer.clients.middleware import GridSignals, Middleware

#: Move orders A* may use to break ties; one is drawn per episode.
_ORDERS: tuple[tuple[int, ...], ...] = tuple(permutations(range(N_MOVES)))


def astar(
    start: int,
    goal: int,
    next_cell: list[list[int]],
    cols: int,
    allowed: list[tuple[int, ...]] | None = None,
    order: tuple[int, ...] = (0, 1, 2, 3),
) -> list[int] | None:
    """Moves of a shortest path from ``start`` to ``goal`` (Manhattan heuristic), or None.

    ``allowed[cell]`` restricts the moves generated at ``cell`` (U'(x)); ``order`` breaks ties.

    >>> nxt = [[-1, 2, -1, 1], [-1, 3, 0, -1], [0, -1, -1, 3], [1, -1, 2, -1]]  # 2x2 grid
    >>> astar(0, 3, nxt, 2)
    [1, 3]
    >>> astar(0, 3, nxt, 2, allowed=[(3,), (1,), (), ()])
    [3, 1]
    """
    if start == goal:
        return []
    gr, gc = divmod(goal, cols)

    def h(cell: int) -> int:
        r, c = divmod(cell, cols)
        return abs(r - gr) + abs(c - gc)

    rank = {a: i for i, a in enumerate(order)}
    frontier: list[tuple[int, int, int, int]] = [(h(start), 0, 0, start)]
    came: dict[int, tuple[int, int]] = {start: (-1, -1)}
    cost = {start: 0}
    tick = 0
    while frontier:
        _, g, _, cell = heapq.heappop(frontier)
        if cell == goal:
            moves: list[int] = []
            while cell != start:
                prev, a = came[cell]
                moves.append(a)
                cell = prev
            return moves[::-1]
        if g > cost[cell]:
            continue
        moves_here = order if allowed is None else sorted(allowed[cell], key=rank.__getitem__)
        for a in moves_here:
            nxt = next_cell[cell][a]
            if nxt < 0:
                continue
            ng = g + 1
            if ng < cost.get(nxt, 1 << 30):
                cost[nxt] = ng
                came[nxt] = (cell, a)
                tick += 1
                heapq.heappush(frontier, (ng + h(nxt), ng, tick, nxt))
    return None


class HybridPlanner:
    """A* + heuristics on :class:`SAREnv`; see the module docstring.

    ``rng`` drives the random parts (A* tie-break order per episode, random untried queries).
    """

    name = "planner"

    def __init__(self, env: SAREnv, middleware: Middleware, rng: np.random.Generator) -> None:
        self.env = env
        self.mw = middleware
        self.rng = rng
        self.options = env.query_options
        self._option_index = {o: i for i, o in enumerate(self.options)}
        self._paths: dict[tuple[int, int, int, int], list[int] | None] = {}
        self._moves: dict[tuple[int, int, int, int, int], int] = {}  # decision cache
        self.fallbacks = 0

    def _path(self, sig: GridSignals, pos: int, goal: int, order_i: int) -> list[int]:
        key = (id(sig.allowed), pos, goal, order_i)
        path = self._paths.get(key)
        if path is None and key not in self._paths:
            env = self.env
            allowed = None if sig.neutral else sig.allowed
            path = astar(pos, goal, env.next_cell, env.cols, allowed, _ORDERS[order_i])
            if path is None:  # the contract closes every route: fall back to plain A*
                self.fallbacks += 1
                path = astar(pos, goal, env.next_cell, env.cols, None, _ORDERS[order_i])
            self._paths[key] = path
        return path or []

    def _nearest(self, sig: GridSignals, pos: int, targets: list[int], order_i: int) -> int:
        return min(targets, key=lambda t: (len(self._path(sig, pos, t, order_i)), t))

    async def run_episode(self, seed: int | None = None, record_path: bool = False,
                          options: dict[str, Any] | None = None) -> EpisodeResult:
        env, mw = self.env, self.mw
        obs, info = env.reset(seed=seed, options=options)
        reports: list[str] = list(info["reports"])
        sig = await mw.signals(reports)  # ground the briefing
        order_i = int(self.rng.integers(len(_ORDERS)))
        tried: list[str] = []
        order: list[int] = []
        queries = correct = 0
        success = False
        signature = ""
        path = [env.agent] if record_path else []
        while True:
            pos = env.agent
            if all(env.collected):
                action = int(Actions.done)  # triage: transmit the situation report
            elif info["signature"] is not None:
                signature = info["signature"]
                advice = await mw.discover(info["signature"], tried, self.options)
                if advice is not None:
                    option = next((o for o in advice.ranked() if o not in tried), None)
                else:
                    option = None
                if option is None:
                    # a random untried option: walk one random permutation per location
                    if not tried:
                        order = self.rng.permutation(len(self.options)).tolist()
                    option = next(self.options[i] for i in order if self.options[i] not in tried)
                action = int(Actions.QUERY_0) + self._option_index[option]
            else:
                c = env.collected
                key = (id(sig.allowed), pos, c[0] + 2 * c[1] + 4 * c[2], order_i, env.layout_index)
                action = self._moves.get(key, -1)
                if action < 0:
                    targets = [cell for k, cell in enumerate(env.layout.info_cells) if not c[k]]
                    goal = self._nearest(sig, pos, targets, order_i)
                    action = self._moves[key] = self._path(sig, pos, goal, order_i)[0]
            obs, _, terminated, truncated, info = env.step(action)
            if record_path and action < N_MOVES:
                path.append(env.agent)
            q = info["query"]
            if q is not None:
                mw.outcome(signature, q["option"], q["correct"])
                queries += 1
                if q["correct"]:
                    correct += 1
                    tried = []
                else:
                    tried.append(q["option"])
            if info["reports"]:
                reports.extend(info["reports"])
                sig = await mw.signals(reports)  # the contract updates
            if terminated or truncated:
                success = bool(info["success"])
                break
        return EpisodeResult(success, env.collisions, queries, correct, env.step_count, info["layout"], path)


def planner_env_kwargs(env_kwargs: dict[str, Any] | None = None) -> dict[str, Any]:
    """Env settings of the planner protocol: 100-step cap."""
    return {"max_steps": 100, **(env_kwargs or {})}

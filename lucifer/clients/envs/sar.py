"""The SAR testbed: a search-and-rescue mission on the knowledge base's town grid."""

from __future__ import annotations

from typing import Any, SupportsFloat

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from lucifer.clients.envs.core.actions import MOVE_DELTAS, N_MOVES, Actions
from lucifer.clients.envs.core.constants import (
    INFO_TYPES,
    MAX_QUERIES_PER_LOCATION,
    REWARD_COLLECT,
    REWARD_COLLISION,
    REWARD_MOVE,
    REWARD_SUCCESS,
    REWARD_WRONG_QUERY,
)
from lucifer.clients.envs.core.layouts import LAYOUTS, Layout, resolve_layouts
from lucifer.clients.envs.core.reports import STYLES, briefing_reports, info_report
from lucifer.errors import LuciferError
from lucifer.kb import KnowledgeBase, load_kb

_COLOURS = {
    "floor": (236, 236, 236),
    "hazard": (214, 69, 65),
    "info": (66, 133, 244),
    "collected": (120, 190, 120),
    "agent": (30, 30, 30),
    "start": (250, 200, 60),
}


class SAREnv(gym.Env):
    """
    ## Description

    A search-and-rescue team moves on the town grid of a LUCIFER knowledge base (the shipped
    Market Square, 5×5; every cell is a named place, so the grid is dense with landmarks).
    Each episode draws one of the layouts (:data:`~lucifer.clients.envs.core.layouts.LAYOUTS`):
    a start place, hazard places the agent cannot see, and three *information locations*,
    one for each required information type (``victim``, ``hazard``, ``safe_route``).

    Hazards reach the agent only as spoken-style radio reports in ``info["reports"]``
    (dispatch's briefing at reset). At an uncollected information location ``info["signature"]``
    describes what the team observes there; exactly one of the 15 query options of the
    knowledge base is the right query for it (sampled per episode, consistent with the
    location's information type). The right query collects the information and returns a
    report; a wrong one costs a step. Entering a hazard cell is a collision: the agent gets
    there, is penalised, and the episode goes on.

    ## Action Space

    ``Discrete(5 + n_queries)``

    | Num | Name | Action |
    |-----|------|--------|
    | 0 | north | move one row up |
    | 1 | south | move one row down |
    | 2 | west | move one column left |
    | 3 | east | move one column right |
    | 4 | done | transmit the situation report (ends the mission once all three types are collected) |
    | 5+k | query k | run the k-th query option of ``query_options.yaml`` here |

    Moving off the grid, ``done`` too early, and queries away from an uncollected information
    location waste a step.

    ## Observation Space

    ``Dict``: ``agent`` (row, col); ``collected`` MultiBinary(3) in the order
    (victim, hazard, safe_route); ``targets`` the (row, col) of the three information
    locations, flattened; ``at_info`` 0 when not at an information location, else 1 + its
    index; ``layout`` the layout index. Hazards are not observed. Text (reports and the
    signature) comes in ``info`` and is meant for the middleware, not the client.

    ## Rewards

    -0.01 per move, -1 for a collision, -0.05 for a wrong query, +0.3 for collecting an
    information type, +1 for completing the mission.

    ## Termination

    The mission ends when the agent issues ``done`` with all three information types
    collected (success, ``info["success"]``), or fails when an information location has
    rejected ``max_queries`` query attempts (it goes silent). Truncation at ``max_steps``.

    ## Info

    ``reports`` (new reports), ``signature`` (or None), ``query`` ({option, correct} or None),
    ``collision``, ``collisions``, ``success``, ``layout`` (name), ``style``.

    ## Arguments

    ``kb`` knowledge base directory or loaded KB; ``max_steps`` (100); ``max_queries``
    per location (15); ``layouts``; ``novel_signatures`` draws signatures from discovery's
    held-out phrasing pool; ``signatures_per_option`` the size of the per-option signature pool.
    ``reset(options={"layout": i, "style": s})`` pins the layout / report style.
    """

    metadata = {"render_modes": ["ansi", "rgb_array"], "render_fps": 4}

    def __init__(
        self,
        kb: str | KnowledgeBase | None = None,
        max_steps: int = 100,
        max_queries: int = MAX_QUERIES_PER_LOCATION,
        layouts: tuple[Layout, ...] = LAYOUTS,
        novel_signatures: bool = False,
        signatures_per_option: int = 4,
        signature_seed: int = 0,
        render_mode: str | None = None,
    ) -> None:
        from lucifer.telemetry.scenarios import QUERY_INFO_TYPE, sample_signature

        self.kb = kb if isinstance(kb, KnowledgeBase) else load_kb(kb)
        self.rows, self.cols = self.kb.rows, self.kb.cols
        self.n_cells = self.rows * self.cols
        self.layouts = resolve_layouts(self.kb, layouts)
        self.max_steps = int(max_steps)
        self.max_queries = int(max_queries)
        self.render_mode = render_mode
        if not self.kb.query_options:
            raise LuciferError(f"{self.kb.root}: query_options.yaml is missing; the SAR testbed needs query options")
        self.query_options: tuple[str, ...] = tuple(o.name for o in self.kb.query_options)
        self.n_queries = len(self.query_options)

        # Which options answer which information type (from the KB, else discovery's table).
        by_type: dict[str, list[int]] = {t: [] for t in INFO_TYPES}
        for k, opt in enumerate(self.kb.query_options):
            t = getattr(opt, "info_type", None) or QUERY_INFO_TYPE.get(opt.name)
            if t in by_type:
                by_type[t].append(k)
        for t, ks in by_type.items():
            if not ks:
                raise LuciferError(f"{self.kb.root}: no query option reveals information type {t!r}")
        self._options_for_type = tuple(tuple(by_type[t]) for t in INFO_TYPES)

        # A finite pool of signatures per option, fixed by signature_seed: same env, same texts.
        sig_rng = np.random.default_rng(signature_seed)
        self._signatures = tuple(
            tuple(sample_signature(name, sig_rng, novel=novel_signatures) for _ in range(signatures_per_option))
            for name in self.query_options
        )

        # Precomputed tables: next cell per (cell, move); -1 marks the edge.
        nxt = np.full((self.n_cells, N_MOVES), -1, dtype=np.int64)
        for cell in range(self.n_cells):
            r, c = divmod(cell, self.cols)
            for a, (dr, dc) in enumerate(MOVE_DELTAS):
                if 0 <= r + dr < self.rows and 0 <= c + dc < self.cols:
                    nxt[cell, a] = (r + dr) * self.cols + c + dc
        self.next_cell: list[list[int]] = nxt.tolist()
        self._hazard = [[cell in lay.hazard_cells for cell in range(self.n_cells)] for lay in self.layouts]
        self._info_index = [
            [lay.info_cells.index(cell) if cell in lay.info_cells else -1 for cell in range(self.n_cells)]
            for lay in self.layouts
        ]
        self._layout_names = [lay.layout.name for lay in self.layouts]
        self._briefings = [[briefing_reports(self.kb, lay.layout, s) for s in STYLES] for lay in self.layouts]
        self._info_reports = [
            [[info_report(self.kb, lay.layout, t, s) for s in STYLES] for t in INFO_TYPES] for lay in self.layouts
        ]

        def frozen(values: Any, dtype: Any) -> np.ndarray:
            a = np.array(values, dtype=dtype)
            a.flags.writeable = False
            return a

        self._agent_obs = [frozen(divmod(cell, self.cols), np.int64) for cell in range(self.n_cells)]
        self._collected_obs = [frozen([(m >> i) & 1 for i in range(3)], np.int8) for m in range(8)]
        self._targets_obs = [frozen([v for cell in lay.info_cells for v in divmod(cell, self.cols)], np.int64)
                             for lay in self.layouts]

        self.action_space = spaces.Discrete(int(Actions.QUERY_0) + self.n_queries)
        self.observation_space = spaces.Dict(
            {
                "agent": spaces.MultiDiscrete([self.rows, self.cols]),
                "collected": spaces.MultiBinary(len(INFO_TYPES)),
                "targets": spaces.MultiDiscrete([self.rows, self.cols] * len(INFO_TYPES)),
                "at_info": spaces.Discrete(len(INFO_TYPES) + 1),
                "layout": spaces.Discrete(len(self.layouts)),
            }
        )
        # episode state
        self.layout_index = 0
        self.style = 0
        self.agent = 0
        self.collected = [False, False, False]
        self.correct: list[int] = [0, 0, 0]
        self.signature_index: list[int] = [0, 0, 0]
        self.attempts = [0, 0, 0]
        self.step_count = 0
        self.collisions = 0
        self._episode_reports: list[str] = []

    # ------------------------------------------------------------------ helpers
    @property
    def layout(self) -> Any:
        return self.layouts[self.layout_index]

    def cell_rc(self, cell: int) -> tuple[int, int]:
        return divmod(cell, self.cols)

    def signature_at(self, k: int) -> str:
        """The signature of information location ``k`` this episode."""
        return self._signatures[self.correct[k]][self.signature_index[k]]

    def correct_option(self, k: int) -> str:
        """The right query at information location ``k`` (for evaluation and pictures)."""
        return self.query_options[self.correct[k]]

    def signature_pool(self) -> tuple[tuple[str, ...], ...]:
        """The signatures each query option can show (indexed like ``query_options``)."""
        return self._signatures

    def episode_reports(self) -> list[str]:
        """Every report of this episode so far, in arrival order."""
        return list(self._episode_reports)

    def cell_labels(self) -> dict[int, str]:
        """Cell index -> the KB place standing on it."""
        return {r * self.cols + c: name for (r, c), name in self.kb.cell_owner.items()}

    def distinct_texts(self) -> tuple[list[str], list[str]]:
        """Every report and signature this env can emit (to warm a middleware cache)."""
        reports = sorted({t for per in self._briefings for s in per for t in s}
                         | {t for per in self._info_reports for typ in per for t in typ})
        sigs = sorted({s for per in self._signatures for s in per})
        return reports, sigs

    def _obs(self) -> dict[str, Any]:
        # Observation arrays are precomputed; each call returns fresh copies (gymnasium's rule).
        c = self.collected
        k = self._info_index[self.layout_index][self.agent]
        return {
            "agent": self._agent_obs[self.agent].copy(),
            "collected": self._collected_obs[c[0] + 2 * c[1] + 4 * c[2]].copy(),
            "targets": self._targets_obs[self.layout_index].copy(),
            "at_info": 0 if k < 0 else k + 1,
            "layout": self.layout_index,
        }

    def _signature_here(self) -> str | None:
        k = self._info_index[self.layout_index][self.agent]
        if k < 0 or self.collected[k]:
            return None
        return self.signature_at(k)

    # ------------------------------------------------------------------ gym API
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[dict[str, Any], dict[str, Any]]:
        super().reset(seed=seed)
        options = options or {}
        rng = self.np_random
        self.layout_index = int(options["layout"]) if "layout" in options else int(rng.integers(len(self.layouts)))
        style = options.get("style")
        if style is None:
            self.style = int(rng.integers(len(STYLES)))
        elif isinstance(style, str):
            self.style = STYLES.index(style)
        else:
            self.style = int(style)
        self.correct = [opts[int(rng.integers(len(opts)))] for opts in self._options_for_type]
        n_sig = len(self._signatures[0])
        self.signature_index = [int(rng.integers(n_sig)) for _ in INFO_TYPES]
        self.agent = self.layouts[self.layout_index].start
        self.collected = [False, False, False]
        self.attempts = [0, 0, 0]
        self.step_count = 0
        self.collisions = 0
        self._episode_reports = list(self._briefings[self.layout_index][self.style])
        info = {
            "reports": list(self._episode_reports),
            "signature": self._signature_here(),
            "query": None,
            "collision": False,
            "collisions": 0,
            "success": False,
            "layout": self.layouts[self.layout_index].layout.name,
            "style": STYLES[self.style],
        }
        return self._obs(), info

    def step(self, action: Any) -> tuple[dict[str, Any], SupportsFloat, bool, bool, dict[str, Any]]:
        a = int(action)
        self.step_count += 1
        reward = 0.0
        terminated = False
        collision = False
        reports: list[str] = []
        query: dict[str, Any] | None = None
        success = False
        li = self.layout_index
        if a < N_MOVES:
            reward = REWARD_MOVE
            nxt = self.next_cell[self.agent][a]
            if nxt >= 0:
                self.agent = nxt
                if self._hazard[li][nxt]:
                    collision = True
                    self.collisions += 1
                    reward += REWARD_COLLISION
        elif a == Actions.done:
            reward = REWARD_MOVE
            if all(self.collected):
                terminated = success = True
                reward = REWARD_SUCCESS
        else:
            q = a - int(Actions.QUERY_0)
            k = self._info_index[li][self.agent]
            reward = REWARD_MOVE
            if k >= 0 and not self.collected[k] and self.attempts[k] < self.max_queries:
                correct = q == self.correct[k]
                query = {"option": self.query_options[q], "correct": correct, "location": k}
                if correct:
                    self.collected[k] = True
                    reward = REWARD_COLLECT
                    reports.append(self._info_reports[li][k][self.style])
                    self._episode_reports.append(reports[-1])
                else:
                    self.attempts[k] += 1
                    reward = REWARD_WRONG_QUERY
                    if self.attempts[k] >= self.max_queries:
                        terminated = True  # the location went silent: the mission cannot complete
        truncated = not terminated and self.step_count >= self.max_steps
        info = {
            "reports": reports,
            "signature": self._signature_here(),
            "query": query,
            "collision": collision,
            "collisions": self.collisions,
            "success": success,
            "layout": self._layout_names[li],
            "style": STYLES[self.style],
        }
        return self._obs(), reward, terminated, truncated, info

    # ------------------------------------------------------------------ rendering
    def render(self) -> Any:
        if self.render_mode == "ansi":
            return self._render_ansi()
        if self.render_mode == "rgb_array":
            return self._render_rgb()
        return None

    def _render_ansi(self) -> str:
        lay = self.layouts[self.layout_index]
        rows = []
        for r in range(self.rows):
            line = []
            for c in range(self.cols):
                cell = r * self.cols + c
                k = self._info_index[self.layout_index][cell]
                ch = "."
                if cell in lay.hazard_cells:
                    ch = "X"
                if k >= 0:
                    ch = "vhs"[k] if not self.collected[k] else "*"
                if cell == self.agent:
                    ch = "A"
                line.append(ch)
            rows.append(" ".join(line))
        return "\n".join(rows)

    def _render_rgb(self, tile: int = 32) -> np.ndarray:
        lay = self.layouts[self.layout_index]
        img = np.zeros((self.rows * tile, self.cols * tile, 3), dtype=np.uint8)
        for cell in range(self.n_cells):
            r, c = divmod(cell, self.cols)
            k = self._info_index[self.layout_index][cell]
            colour = _COLOURS["floor"]
            if cell in lay.hazard_cells:
                colour = _COLOURS["hazard"]
            elif k >= 0:
                colour = _COLOURS["collected"] if self.collected[k] else _COLOURS["info"]
            elif cell == lay.start:
                colour = _COLOURS["start"]
            img[r * tile + 1:(r + 1) * tile - 1, c * tile + 1:(c + 1) * tile - 1] = colour
        r, c = divmod(self.agent, self.cols)
        q = tile // 4
        img[r * tile + q:(r + 1) * tile - q, c * tile + q:(c + 1) * tile - q] = _COLOURS["agent"]
        return img

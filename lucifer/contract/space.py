"""Client context spaces: contexts X, options U(x), a one-step outcome f(x, u), map cells.

A :class:`ContextSpace` is what a decision-maker brings to the contract. It says which
contexts exist, which options each has, where an option leads (one step), and which
knowledge-base grid cells a context stands on (that is how grounded objects, which live on
KB cells, reach contexts). A grid with compass moves (:class:`GridContextSpace`) is one
instance; :class:`ExplicitContextSpace` is any finite graph given as a table.

A space must not change after its first use: the transducer caches its :meth:`table`.

Context JSON (``lucifer ground --json --signals CONTEXT.json``), validated by
:func:`load_context_space`::

    {"type": "grid",                      # required
     "rows": 5, "cols": 5,                # default: the KB grid
     "moves": ["N", "S", "E", "W"],       # any of N S E W stay; default N S E W
     "edges": "exclude",                  # "exclude": moves off the grid / into a cell that is
                                          #   not a context are not options; "stay": they are
                                          #   options whose outcome is x itself
     "contexts": [[0, 0], [0, 1]],        # optional subset of cells (e.g. the free cells);
                                          #   default every cell
     "params": {"decay": 0.5}}            # optional ContractParams overrides

    {"type": "explicit",
     "contexts": [{"id": "depot", "cells": [[4, 0]], "options": {"drive_north": "hall"}},
                  {"id": "hall", "cells": [[0, 0]], "options": {}}],
     "params": {}}

In an explicit space every outcome must be a listed context id; ``cells`` may be empty
(a context off the map). Cells are KB cells ``[row, col]``.
"""

from __future__ import annotations

import json
from abc import ABC, abstractmethod
from collections.abc import Hashable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from lucifer.contract.types import ContractParams
from lucifer.errors import BadRequest

Cell = tuple[int, int]

MOVE_DELTAS: dict[str, Cell] = {"N": (-1, 0), "S": (1, 0), "E": (0, 1), "W": (0, -1), "stay": (0, 0)}
"""Grid moves; row 0 is the north edge (SPEC §1)."""


@dataclass(frozen=True, eq=False)
class SpaceTable:
    """A context space flattened into index arrays, built once per space.

    ``ext`` is X followed by any outcome the client's f(x, u) returns that is not in X
    (their cells still matter: an outcome outside X that holds a hazard is still excluded).
    """

    contexts: tuple[Hashable, ...]  # X, in client order (n)
    ext: tuple[Hashable, ...]  # X + outside outcomes (n_ext >= n)
    keys: tuple[str, ...]  # string key of each ext context
    options: tuple[Hashable, ...]  # union of all U(x), first-seen order (m)
    option_keys: tuple[str, ...]
    available: np.ndarray  # (n, m) bool: u_j ∈ U(x_i)
    next: np.ndarray  # (n, m) int: index into ext of f(x_i, u_j); -1 where unavailable
    cell_coords: np.ndarray  # (n_ext, k, 2) int: cells of each ext context, padded
    cell_valid: np.ndarray  # (n_ext, k) bool: which of those are real
    index: dict[Hashable, int]  # ext context -> row
    order: tuple[tuple[int, ...], ...] | None = None  # per row: option columns in U(x) order

    def columns(self, i: int) -> list[int]:
        """Option columns of U(x_i), in the order the client listed them."""
        if self.order is not None:
            return list(self.order[i])
        return np.flatnonzero(self.available[i]).tolist()

    @property
    def n(self) -> int:
        return len(self.contexts)


class ContextSpace(ABC):
    """A client's context space. Subclass and implement the four abstract methods.

    Contexts and options may be any hashable values; :meth:`key` / :meth:`option_key` give
    the strings the contract uses for them. :meth:`distance` is the metric for potentials,
    on KB cells (default Manhattan); override it for another metric.
    """

    _table_cache: SpaceTable | None = None

    @abstractmethod
    def contexts(self) -> Sequence[Hashable]:
        """The contexts X."""

    @abstractmethod
    def options(self, x: Hashable) -> Sequence[Hashable]:
        """U(x); may be empty (a terminal context)."""

    @abstractmethod
    def outcome(self, x: Hashable, u: Hashable) -> Hashable:
        """f(x, u): the context one step after taking u in x."""

    @abstractmethod
    def cells(self, x: Hashable) -> Sequence[Cell]:
        """KB grid cells (row, col) that context x stands on; empty if none."""

    def key(self, x: Hashable) -> str:
        return str(x)

    def option_key(self, u: Hashable) -> str:
        return str(u)

    def describe(self) -> str:
        return type(self).__name__

    def distance(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Distance between cells on the last axis (broadcasting). Default: Manhattan.

        >>> int(GridContextSpace(2, 2).distance(np.array([0, 0]), np.array([1, 1])))
        2
        """
        return np.abs(np.asarray(a) - np.asarray(b)).sum(axis=-1)

    def table(self) -> SpaceTable:
        """The flattened space (cached)."""
        if self._table_cache is None:
            self._table_cache = self._build_table()
        return self._table_cache

    def _build_table(self) -> SpaceTable:
        xs = tuple(self.contexts())
        index: dict[Hashable, int] = {}
        for i, x in enumerate(xs):
            if x in index:
                raise ValueError(f"context {x!r} is listed twice")
            index[x] = i
        ext = list(xs)
        opt_index: dict[Hashable, int] = {}
        rows: list[list[tuple[int, int]]] = []  # per context: (option col, ext index)
        for x in xs:
            row = []
            for u in self.options(x):
                j = opt_index.setdefault(u, len(opt_index))
                y = self.outcome(x, u)
                if y not in index:
                    index[y] = len(ext)
                    ext.append(y)
                row.append((j, index[y]))
            rows.append(row)
        n, m = len(xs), len(opt_index)
        available = np.zeros((n, m), dtype=bool)
        nxt = np.full((n, m), -1, dtype=np.int64)
        for i, row in enumerate(rows):
            for j, y in row:
                available[i, j] = True
                nxt[i, j] = y
        cells = [[tuple(int(v) for v in c) for c in self.cells(x)] for x in ext]
        k = max([1, *(len(c) for c in cells)])
        coords = np.zeros((len(ext), k, 2), dtype=np.int64)
        valid = np.zeros((len(ext), k), dtype=bool)
        for i, cs in enumerate(cells):
            if cs:
                coords[i, : len(cs)] = cs
                valid[i, : len(cs)] = True
        options = tuple(opt_index)
        return SpaceTable(
            contexts=xs,
            ext=tuple(ext),
            keys=tuple(self.key(x) for x in ext),
            options=options,
            option_keys=tuple(self.option_key(u) for u in options),
            available=available,
            next=nxt,
            cell_coords=coords,
            cell_valid=valid,
            index=index,
            order=tuple(tuple(j for j, _ in row) for row in rows),
        )


class GridContextSpace(ContextSpace):
    """Contexts are grid cells (row, col); options are compass moves (and ``stay``).

    ``edges="exclude"``: a move off the grid or into a cell that is not a context is not an
    option; ``edges="stay"``: it is an option whose outcome is the same cell (MiniGrid-style
    bump). Context keys are ``"row,col"``. The grid's cells are KB cells one to one.

    >>> g = GridContextSpace(2, 3)
    >>> g.options((0, 0)), g.outcome((0, 0), "E"), g.key((1, 2))
    (('S', 'E'), (0, 1), '1,2')
    """

    def __init__(
        self,
        rows: int,
        cols: int,
        moves: Sequence[str] = ("N", "S", "E", "W"),
        *,
        edges: Literal["exclude", "stay"] = "exclude",
        contexts: Sequence[Cell] | None = None,
    ):
        if rows <= 0 or cols <= 0:
            raise ValueError("a grid needs rows > 0 and cols > 0")
        unknown = [m for m in moves if m not in MOVE_DELTAS]
        if unknown or len(set(moves)) != len(moves):
            raise ValueError(f"moves must be distinct names from {list(MOVE_DELTAS)}, got {list(moves)}")
        if edges not in ("exclude", "stay"):
            raise ValueError(f"edges must be 'exclude' or 'stay', got {edges!r}")
        self.rows, self.cols, self.moves, self.edges = rows, cols, tuple(moves), edges
        if contexts is None:
            cells = [(r, c) for r in range(rows) for c in range(cols)]
        else:
            cells = [(int(r), int(c)) for r, c in contexts]
            bad = [c for c in cells if not (0 <= c[0] < rows and 0 <= c[1] < cols)]
            if bad:
                raise ValueError(f"context cells outside the {rows}x{cols} grid: {bad}")
            if len(set(cells)) != len(cells):
                raise ValueError("a context cell is listed twice")
        self._cells = tuple(cells)
        self._free = np.full((rows, cols), -1, dtype=np.int64)
        for i, (r, c) in enumerate(self._cells):
            self._free[r, c] = i

    def _target(self, x: Cell, u: str) -> Cell | None:
        dr, dc = MOVE_DELTAS[u]
        r, c = x[0] + dr, x[1] + dc
        if 0 <= r < self.rows and 0 <= c < self.cols and self._free[r, c] >= 0:
            return (r, c)
        return None

    def contexts(self) -> Sequence[Cell]:
        return self._cells

    def options(self, x: Hashable) -> Sequence[str]:
        cell = _as_cell(x)
        if self.edges == "stay":
            return self.moves
        return tuple(u for u in self.moves if self._target(cell, u) is not None)

    def outcome(self, x: Hashable, u: Hashable) -> Cell:
        cell = _as_cell(x)
        if u not in MOVE_DELTAS or u not in self.moves:
            raise KeyError(f"{u!r} is not an option of this grid")
        y = self._target(cell, str(u))
        if y is None:
            if self.edges == "exclude":
                raise KeyError(f"{u!r} is not an option at {cell}")
            return cell
        return y

    def cells(self, x: Hashable) -> Sequence[Cell]:
        return (_as_cell(x),)

    def key(self, x: Hashable) -> str:
        r, c = _as_cell(x)
        return f"{r},{c}"

    def index_of(self, x: Cell) -> int:
        """Row of context x in the contract tables (fast, for RL loops)."""
        i = int(self._free[x[0], x[1]])
        if i < 0:
            raise KeyError(f"{x} is not a context of this grid")
        return i

    def describe(self) -> str:
        return f"grid {self.rows}x{self.cols}, moves {','.join(self.moves)}, edges {self.edges}"

    def _build_table(self) -> SpaceTable:
        # Vectorised: targets of every (cell, move) at once.
        pos = np.array(self._cells, dtype=np.int64).reshape(-1, 2)
        deltas = np.array([MOVE_DELTAS[m] for m in self.moves], dtype=np.int64).reshape(-1, 2)
        tgt = pos[:, None, :] + deltas[None, :, :]
        inside = (tgt[..., 0] >= 0) & (tgt[..., 0] < self.rows) & (tgt[..., 1] >= 0) & (tgt[..., 1] < self.cols)
        r = np.clip(tgt[..., 0], 0, self.rows - 1)
        c = np.clip(tgt[..., 1], 0, self.cols - 1)
        idx = np.where(inside, self._free[r, c], -1)
        n = len(self._cells)
        if self.edges == "stay":
            own = np.broadcast_to(np.arange(n)[:, None], idx.shape)
            nxt = np.where(idx >= 0, idx, own)
            available = np.ones_like(idx, dtype=bool)
        else:
            available = idx >= 0
            nxt = idx
        ext = self._cells
        return SpaceTable(
            contexts=ext,
            ext=ext,
            keys=tuple(f"{r},{c}" for r, c in ext),
            options=self.moves,
            option_keys=self.moves,
            available=available,
            next=np.ascontiguousarray(nxt, dtype=np.int64),
            cell_coords=pos[:, None, :].copy(),
            cell_valid=np.ones((n, 1), dtype=bool),
            index={x: i for i, x in enumerate(ext)},
        )


def _as_cell(x: Any) -> Cell:
    try:
        r, c = x
        return (int(r), int(c))
    except (TypeError, ValueError):
        raise KeyError(f"{x!r} is not a grid cell (row, col)") from None


class ExplicitContextSpace(ContextSpace):
    """A finite context space given as a table: ``{id: (cells, {option: outcome id})}``.

    >>> s = ExplicitContextSpace({"a": ([(0, 0)], {"go": "b"}), "b": ([], {})})
    >>> s.options("a"), s.outcome("a", "go"), list(s.cells("b"))
    (('go',), 'b', [])
    """

    def __init__(self, table: Mapping[str, tuple[Sequence[Cell], Mapping[str, str]]]):
        self._table = {
            str(x): (tuple((int(r), int(c)) for r, c in cells), {str(u): str(y) for u, y in opts.items()})
            for x, (cells, opts) in table.items()
        }
        for x, (_, opts) in self._table.items():
            for u, y in opts.items():
                if y not in self._table:
                    raise ValueError(f"context {x!r}: option {u!r} leads to unknown context {y!r}")

    def contexts(self) -> Sequence[str]:
        return tuple(self._table)

    def options(self, x: Hashable) -> Sequence[str]:
        return tuple(self._table[str(x)][1])

    def outcome(self, x: Hashable, u: Hashable) -> str:
        return self._table[str(x)][1][str(u)]

    def cells(self, x: Hashable) -> Sequence[Cell]:
        return self._table[str(x)][0]

    def describe(self) -> str:
        return f"explicit, {len(self._table)} contexts"


# --- the context JSON -----------------------------------------------------------------


class _Spec(BaseModel):
    model_config = ConfigDict(extra="forbid")


class GridSpec(_Spec):
    type: Literal["grid"]
    rows: int | None = Field(default=None, gt=0, le=1000)
    cols: int | None = Field(default=None, gt=0, le=1000)
    moves: list[Literal["N", "S", "E", "W", "stay"]] = Field(default_factory=lambda: ["N", "S", "E", "W"], min_length=1)
    edges: Literal["exclude", "stay"] = "exclude"
    contexts: list[tuple[int, int]] | None = None
    params: ContractParams = Field(default_factory=ContractParams)

    @field_validator("moves")
    @classmethod
    def _distinct(cls, v: list[str]) -> list[str]:
        if len(set(v)) != len(v):
            raise ValueError("moves must be distinct")
        return v


class ExplicitContext(_Spec):
    id: str = Field(min_length=1)
    cells: list[tuple[int, int]] = Field(default_factory=list)
    options: dict[str, str] = Field(default_factory=dict)


class ExplicitSpec(_Spec):
    type: Literal["explicit"]
    contexts: list[ExplicitContext] = Field(min_length=1)
    params: ContractParams = Field(default_factory=ContractParams)


class ContextFile(BaseModel):
    spec: Annotated[GridSpec | ExplicitSpec, Field(discriminator="type")]


def load_context_space(
    source: str | Path | Mapping[str, Any], kb_rows: int | None = None, kb_cols: int | None = None
) -> tuple[ContextSpace, ContractParams]:
    """Validate a context JSON (path, JSON text or dict) into a space and its params.

    Raises :class:`lucifer.errors.BadRequest` naming the file and the field on bad input.
    ``kb_rows`` / ``kb_cols`` are the KB grid: the default grid size, and the bound that
    every cell must respect.

    >>> space, params = load_context_space({"type": "grid", "rows": 2, "cols": 2})
    >>> space.describe(), params.decay
    ('grid 2x2, moves N,S,E,W, edges exclude', 0.5)
    """
    where = "context JSON"
    if isinstance(source, Mapping):
        data: Any = dict(source)
    else:
        text = str(source)
        looks_json = text.lstrip()[:1] in ("{", "[")
        if not looks_json:
            path = Path(text)
            if not path.is_file():
                raise BadRequest(f"context file {text} does not exist")
            where = str(path)
            try:
                text = path.read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError) as exc:
                raise BadRequest(f"{where}: cannot read: {exc}") from None
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise BadRequest(f"{where}: malformed JSON at line {exc.lineno}, column {exc.colno}: {exc.msg}") from None
    if not isinstance(data, dict):
        raise BadRequest(f"{where}: must be a JSON object with a 'type' field")
    try:
        spec = ContextFile.model_validate({"spec": data}).spec
    except ValidationError as exc:
        msgs = []
        for err in exc.errors():
            loc = ".".join(str(p) for p in err["loc"][1:] if p not in ("grid", "explicit")) or "top level"
            msgs.append(f"{loc}: {err['msg']}")
        raise BadRequest(f"{where}: " + "; ".join(msgs)) from None
    try:
        if isinstance(spec, GridSpec):
            rows = spec.rows or kb_rows
            cols = spec.cols or kb_cols
            if rows is None or cols is None:
                raise ValueError("rows and cols are required when no KB grid is given")
            if kb_rows is not None and kb_cols is not None and (rows > kb_rows or cols > kb_cols):
                raise ValueError(f"a {rows}x{cols} grid does not fit the {kb_rows}x{kb_cols} KB grid")
            space: ContextSpace = GridContextSpace(
                rows, cols, spec.moves, edges=spec.edges, contexts=spec.contexts
            )
        else:
            ids = [c.id for c in spec.contexts]
            if len(set(ids)) != len(ids):
                raise ValueError("a context id is listed twice")
            if kb_rows is not None and kb_cols is not None:
                for c in spec.contexts:
                    for r, col in c.cells:
                        if not (0 <= r < kb_rows and 0 <= col < kb_cols):
                            raise ValueError(f"context {c.id!r}: cell [{r}, {col}] is outside the {kb_rows}x{kb_cols} KB grid")
            space = ExplicitContextSpace({c.id: (c.cells, c.options) for c in spec.contexts})
    except ValueError as exc:
        raise BadRequest(f"{where}: {exc}") from None
    return space, spec.params

"""The one place where clients meet LUCIFER: grounding, the Signal Contract and discovery.

Clients never read text. They hand reports and location signatures to a :class:`Middleware`
and get back only contract signals: per-context admissible options U'(x), priors Ψ_x(u),
potentials Φ(x) (as :class:`GridSignals`) and discovery advice u* (as :class:`Advice`).

The middleware is configured per ablation cell: ``grounding=False`` makes every signal
neutral (all options admissible, Φ = 0, Ψ = 0) without calling the grounder;
``discovery=False`` makes :meth:`Middleware.discover` answer ``None`` without calling the
discoverer. Identical requests are cached: the grounder is called once per distinct report
text, the discoverer once per distinct (signature, trace, options), the contract transducer
once per distinct sequence of reports. Everything that touches the other packages' APIs is
in this file, so API drift there is a one-file fix here.
"""

from __future__ import annotations

import asyncio
from collections.abc import Hashable, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

from lucifer.kb import KnowledgeBase, load_kb
from lucifer.types import GroundingResult

#: Grid moves in the order of the SAR env's movement actions (north, south, west, east).
GRID_MOVES: tuple[str, str, str, str] = ("N", "S", "W", "E")


class GrounderLike(Protocol):
    async def ground(self, text: str, report_id: str | None = None) -> GroundingResult: ...


class DiscovererLike(Protocol):
    async def discover(self, request: Any) -> Any: ...


@dataclass(frozen=True, eq=False)
class GridSignals:
    """The contract for a grid client as plain Python lists, indexed by cell ``row*cols+col``.

    ``allowed[cell]`` the admissible move indices U'(x) (indices into :data:`GRID_MOVES`);
    ``admissible[cell][a]`` the same as booleans; ``prior[cell][a]`` Ψ_x(u); ``phi[cell]`` Φ(x);
    ``hazard[cell]`` x ∈ X_u; ``goal[cell]`` x ∈ X_d ∪ X_o. ``contract`` is the full
    :class:`~lucifer.contract.types.SignalContract` for display (built lazily), ``version``
    the number of reports behind it.
    """

    allowed: list[tuple[int, ...]]
    admissible: list[list[bool]]
    prior: list[list[float]]
    phi: list[float]
    hazard: list[bool]
    goal: list[bool]
    version: int = 0
    neutral: bool = False
    _contract: Any = field(default=None, repr=False)

    def shaping(self, cell: int, next_cell: int, gamma: float = 0.99, terminal: bool = False) -> float:
        """Potential-based shaping F = γΦ(x') − Φ(x)."""
        return (0.0 if terminal else gamma * self.phi[next_cell]) - self.phi[cell]

    @property
    def contract(self) -> Any:
        return self._contract() if callable(self._contract) else self._contract

    @classmethod
    def neutral_for(cls, n_cells: int, n_moves: int = 4) -> GridSignals:
        """Signals that say nothing: every move admissible, Φ = Ψ = 0."""
        return cls(
            allowed=[tuple(range(n_moves))] * n_cells,
            admissible=[[True] * n_moves for _ in range(n_cells)],
            prior=[[0.0] * n_moves for _ in range(n_cells)],
            phi=[0.0] * n_cells,
            hazard=[False] * n_cells,
            goal=[False] * n_cells,
            neutral=True,
        )


@dataclass(frozen=True)
class Advice:
    """Discovery's answer at one decision point: u*, its confidence and the distribution."""

    option: str
    confidence: float
    distribution: dict[str, float]

    def ranked(self) -> list[str]:
        """Options from most to least likely (u* first)."""
        return sorted(self.distribution, key=lambda o: (-self.distribution[o], o))


class Middleware:
    """Grounding (+G) and discovery (+D) behind one narrow, cached, async interface.

    ``kb`` a KB directory or a loaded KB. ``grounder`` / ``discoverer`` default to the real
    ones (``lucifer.grounding.Grounder`` with ``model``, the discovery graph); tests pass
    stand-ins. ``rows`` / ``cols`` give the client's grid (default: the KB grid; a larger
    client grid, e.g. MiniGrid's, comes with its own generated KB).
    """

    def __init__(
        self,
        kb: str | KnowledgeBase | None = None,
        *,
        grounding: bool = True,
        discovery: bool = True,
        grounder: GrounderLike | None = None,
        discoverer: DiscovererLike | None = None,
        model: str = "builtin",
        contract_params: Any = None,
        memory: Any = None,
        trace_grounding: bool = False,
        record_outcomes: bool = False,
    ) -> None:
        self.kb = kb if isinstance(kb, KnowledgeBase) else load_kb(kb)
        self.grounding = grounding
        self.discovery = discovery
        self.model = model
        self._grounder = grounder
        self._discoverer = discoverer
        self._contract_params = contract_params
        self.memory = memory
        self.trace_grounding = trace_grounding
        self.record_outcomes = record_outcomes
        self._outcomes: list[tuple[str, str, float]] = []
        #: optional callback ``observer(event, payload)`` for displays ("discover": signature, advice)
        self.observer: Any = None
        self._space: Any = None
        self.n_cells = self.kb.rows * self.kb.cols
        self._neutral = GridSignals.neutral_for(self.n_cells)
        self._ground_cache: dict[str, GroundingResult] = {}
        self._ground_inflight: dict[str, asyncio.Future[GroundingResult]] = {}
        self._signal_cache: dict[tuple[str, ...], GridSignals] = {}
        self._advice_cache: dict[Hashable, Advice] = {}
        self._allowed_tables: dict[tuple[tuple[int, ...], ...], tuple[tuple[int, ...], ...]] = {}
        self.calls = {"ground": 0, "discover": 0, "contract": 0}

    # ------------------------------------------------------------------ backends
    def _get_grounder(self) -> GrounderLike:
        if self._grounder is None:
            from lucifer.grounding import Grounder

            self._grounder = Grounder(kb=self.kb.root, model=self.model, trace=self.trace_grounding)
        return self._grounder

    def _get_discoverer(self) -> DiscovererLike:
        if self._discoverer is None:
            from lucifer.graphs.discovery import Discoverer

            self._discoverer = Discoverer(kb=self.kb, memory=self.memory)
        return self._discoverer

    def _get_space(self) -> Any:
        if self._space is None:
            from lucifer.contract import ContractParams, GridContextSpace

            self._space = GridContextSpace(self.kb.rows, self.kb.cols, GRID_MOVES, edges="exclude")
            if self._contract_params is None:
                # Navigation clients need U'(x) to exclude hazards without forcing every step
                # into the nearest goal: the contract's exclusion-only case.
                self._contract_params = ContractParams(restrict_to_goals=False)
        return self._space

    # ------------------------------------------------------------------ grounding
    async def ground(self, report: str) -> GroundingResult:
        """Ground one report (cached per distinct text; concurrent duplicates share a call)."""
        hit = self._ground_cache.get(report)
        if hit is not None:
            return hit
        pending = self._ground_inflight.get(report)
        if pending is not None:
            return await pending
        fut: asyncio.Future[GroundingResult] = asyncio.get_running_loop().create_future()
        self._ground_inflight[report] = fut
        try:
            self.calls["ground"] += 1
            result = await self._get_grounder().ground(report)
        except BaseException as exc:
            fut.set_exception(exc)
            fut.exception()  # mark retrieved; the caller gets the exception below
            raise
        finally:
            self._ground_inflight.pop(report, None)
        self._ground_cache[report] = result
        fut.set_result(result)
        return result

    async def signals(self, reports: Sequence[str]) -> GridSignals:
        """The contract signals after ``reports`` (every report so far, in arrival order)."""
        if not self.grounding:
            return self._neutral
        key = tuple(reports)
        sig = self._signal_cache.get(key)
        if sig is None:
            results = await asyncio.gather(*(self.ground(r) for r in key))
            sig = self._build_signals(results)
            self._signal_cache[key] = sig
        if self.observer is not None:
            self.observer("signals", {"reports": key, "signals": sig})
        return sig

    def _build_signals(self, results: Sequence[GroundingResult]) -> GridSignals:
        from lucifer.contract import BeliefSession

        space = self._get_space()
        session = BeliefSession(self.kb, contract_params=self._contract_params)
        for i, res in enumerate(results):
            session.ingest(res.model_copy(update={"report_id": f"r{i + 1}"}))
        self.calls["contract"] += 1
        t = session.tables(space)
        n, cols = self.n_cells, self.kb.cols
        st = t.space
        # Space rows are cells in row-major order; map to our cell index defensively.
        row_of = [st.index[(c // cols, c % cols)] for c in range(n)]
        col_of = [st.options.index(m) for m in GRID_MOVES]
        adm = t.admissible.tolist()
        pri = t.prior.tolist()
        phi = t.phi.tolist()
        mu = t.member_u.tolist()
        goal = (t.member_d | t.member_o).tolist()
        admissible = [[bool(adm[row_of[c]][j]) for j in col_of] for c in range(n)]
        allowed = tuple(tuple(a for a, ok in enumerate(admissible[c]) if ok) for c in range(n))
        # identical U' tables are one object, so clients can key their plan caches on it
        allowed = self._allowed_tables.setdefault(allowed, allowed)
        return GridSignals(
            allowed=allowed,  # type: ignore[arg-type]
            admissible=admissible,
            prior=[[float(pri[row_of[c]][j]) for j in col_of] for c in range(n)],
            phi=[float(phi[row_of[c]]) for c in range(n)],
            hazard=[bool(mu[row_of[c]]) for c in range(n)],
            goal=[bool(goal[row_of[c]]) for c in range(n)],
            version=len(results),
            _contract=lambda: session.contract(space),
        )

    # ------------------------------------------------------------------ discovery
    async def discover(self, signature: str, trace: Sequence[str] = (), options: Sequence[str] = ()) -> Advice | None:
        """u* for an information location, or None when discovery is off.

        ``trace`` is a short summary of what the client already did here (options tried);
        ``options`` the candidate options U(x) (default: every option of the KB).
        """
        if not self.discovery:
            return None
        opts = tuple(options) or tuple(o.name for o in self.kb.query_options)
        key = (signature, tuple(trace), opts)
        advice = self._advice_cache.get(key)
        if advice is None:
            self.calls["discover"] += 1
            advice = await self._discover(signature, list(trace), list(opts))
            self._advice_cache[key] = advice
        if self.observer is not None:
            self.observer("discover", {"signature": signature, "trace": list(trace), "advice": advice})
        return advice

    async def _discover(self, signature: str, trace: list[str], options: list[str]) -> Advice:
        result = await self._get_discoverer().discover({"signature": signature, "trace": trace, "options": options})
        return _advice_from(result)

    def record(self, signature: str, option: str, outcome: float, trace: Sequence[str] = (), client: str | None = None) -> None:
        """Append one query outcome to telemetry memory (what discovery learns from)."""
        self._get_discoverer().record(signature, option, float(outcome), trace=list(trace), client=client)

    def outcome(self, signature: str, option: str, correct: bool) -> None:
        """A client reports how a query went; buffered into telemetry memory when recording is on."""
        if self.record_outcomes:
            self._outcomes.append((signature, option, 1.0 if correct else 0.0))
            if len(self._outcomes) >= 256:
                self.flush()

    def flush(self) -> int:
        """Write buffered query outcomes to telemetry memory; returns how many."""
        batch, self._outcomes = self._outcomes, []
        if batch:
            self.record_many(batch)
        return len(batch)

    def record_many(self, records: Sequence[tuple[str, str, float]], client: str | None = None) -> None:
        """Append many (signature, option, outcome) records in one transaction."""
        from lucifer.telemetry.memory import TelemetryMemory, TelemetryRecord

        mem = self.memory if isinstance(self.memory, TelemetryMemory) else TelemetryMemory(self.memory)
        try:
            mem.append([TelemetryRecord(signature=s, option=o, outcome=float(v), client=client) for s, o, v in records])
        finally:
            if mem is not self.memory:
                mem.close()

    async def aclose(self) -> None:
        """Flush telemetry and close the backends this middleware opened (trace store, memory)."""
        self.flush()
        g, self._grounder = self._grounder, None
        close = getattr(g, "aclose", None)
        if close is not None:
            await close()
        d, self._discoverer = self._discoverer, None
        if d is not None and hasattr(d, "close"):
            d.close()

    # ------------------------------------------------------------------ cache warming
    async def warm(self, reports: Sequence[str] = (), signatures: Sequence[str] = (), concurrency: int = 8) -> None:
        """Ground ``reports`` and discover ``signatures`` ahead of time, ``concurrency`` at a time."""
        sem = asyncio.Semaphore(concurrency)

        async def one(coro: Any) -> None:
            async with sem:
                await coro

        jobs: list[Any] = []
        if self.grounding:
            jobs += [one(self.ground(r)) for r in reports]
        if self.discovery:
            jobs += [one(self.discover(s)) for s in signatures]
        await asyncio.gather(*jobs)

    def export_cache(self) -> dict[str, Any]:
        """Grounding and discovery answers, picklable, to seed another process's middleware."""
        return {"ground": dict(self._ground_cache), "advice": dict(self._advice_cache)}

    def import_cache(self, cache: dict[str, Any]) -> None:
        self._ground_cache.update(cache.get("ground", {}))
        self._advice_cache.update(cache.get("advice", {}))


def _advice_from(result: Any) -> Advice:
    """Normalise whatever the discoverer returns into :class:`Advice`."""
    if isinstance(result, Advice):
        return result
    get = result.get if isinstance(result, dict) else lambda k, d=None: getattr(result, k, d)
    dist = get("distribution") or get("probs") or {}
    if isinstance(dist, list):  # [{"option": .., "p": ..}] or [(option, p)]
        dist = {(d["option"] if isinstance(d, dict) else d[0]): float(d.get("p", d.get("prob", 0.0)) if isinstance(d, dict) else d[1]) for d in dist}
    option = get("recommendation") or get("option") or get("u_star")
    if isinstance(option, dict):
        option = option.get("option") or option.get("name")
    if option is None and dist:
        option = max(dist, key=lambda o: dist[o])
    confidence = get("confidence")
    if confidence is None:
        confidence = float(dist.get(option, 0.0)) if dist else 0.0
    return Advice(option=str(option), confidence=float(confidence), distribution={str(k): float(v) for k, v in dict(dist).items()})

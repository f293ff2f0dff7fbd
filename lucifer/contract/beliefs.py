"""Belief maintenance over a stream of reports (beyond the paper).

A :class:`BeliefSession` ingests grounding results in report order and keeps one belief per
(location, category). Update rules (:class:`BeliefParams`, defaults in brackets):

* **Claim / confirmation** (noisy-OR): each report that claims (location, category) with
  grounding confidence c_o is independent evidence of reliability ``trust · c_o``
  [trust 0.7]. Confidence c ← 1 − (1 − c)(1 − trust · c_o), starting from c = 0. So one
  report gives 0.7, two give 0.91, three 0.973; always in [0, 1], never decreasing.
  Repeats inside one report count once (the highest c_o).
* **Conflict**: a claim whose role conflicts with an active belief on the same location
  (undesirable vs desirable: "the clinic is no longer safe" → hazard replaces safe_zone)
  supersedes it: the old belief leaves the active set (state ``superseded``,
  ``superseded_by``) and the new one starts fresh (``replaces``). Critical beliefs (victims)
  conflict with nothing: a victim in a burning building is both.
* **Denial** (``GroundingResult.denied``): an explicit denial (c_o ≥ retract_at [0.5]) of
  an active (location, category) retracts it (state ``retracted``). A hedged denial
  (c_o < retract_at) lowers it: c ← c · (1 − c_o), recorded as denial provenance. A denial
  that names a category with no active match falls back to an active belief of the same role
  on that location; with none it is recorded as ``denial_unmatched``.
* A report's denials are applied before its claims ("the fire at the bakery is out, the
  bakery is safe now" retracts the hazard and then claims the safe zone).
* Re-ingesting a report id already seen changes nothing (``duplicate_report``).

Every change is returned as a :class:`BeliefChange` in an :class:`IngestOutcome`, and every
belief keeps the :class:`~lucifer.contract.types.Provenance` (report id, character span,
trace id) of each report that claimed, confirmed or denied it. :meth:`BeliefSession.contract`
always reflects the current beliefs and is cached until they change.
"""

from __future__ import annotations

import asyncio
from typing import TYPE_CHECKING, Any, Literal, Protocol

from pydantic import BaseModel, ConfigDict, Field

from lucifer.contract.space import ContextSpace
from lucifer.contract.transducer import (
    ContractTables,
    build_tables,
    cells_of_object,
    contract_from_tables,
    provenance_of,
)
from lucifer.contract.types import Belief, BeliefState, ContractParams, SignalContract
from lucifer.kb.models import Role
from lucifer.types import GroundedObject, GroundingResult

if TYPE_CHECKING:
    from lucifer.kb.loader import KnowledgeBase

ROLE_CONFLICTS: dict[Role, frozenset[Role]] = {
    Role.UNDESIRABLE: frozenset({Role.DESIRABLE}),
    Role.DESIRABLE: frozenset({Role.UNDESIRABLE}),
    Role.CRITICAL: frozenset(),
}


class Grounder(Protocol):
    async def ground(self, text: str, report_id: str | None = ...) -> GroundingResult: ...


class BeliefParams(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    trust: float = Field(default=0.7, gt=0.0, le=1.0, description="Reliability of one report.")
    retract_at: float = Field(
        default=0.5, ge=0.0, le=1.0, description="Denials at least this confident retract; weaker ones lower."
    )


def confirm(c: float, c_obj: float, trust: float = 0.7) -> float:
    """Noisy-OR confidence update for one more report claiming the same thing.

    >>> round(confirm(0.0, 1.0), 3), round(confirm(0.7, 1.0), 3), round(confirm(0.91, 1.0), 3)
    (0.7, 0.91, 0.973)
    >>> confirm(0.5, 0.0)
    0.5
    """
    # max(): in floating point 1 - (1 - c) can fall a hair below c; a confirmation never lowers confidence
    return max(c, 1.0 - (1.0 - c) * (1.0 - trust * c_obj))


ChangeKind = Literal[
    "created", "confirmed", "superseded", "retracted", "weakened", "denial_unmatched", "duplicate_report"
]


class BeliefChange(BaseModel):
    model_config = ConfigDict(frozen=True)

    kind: ChangeKind
    belief_id: str | None
    location: str
    category: str
    confidence_before: float | None = None
    confidence_after: float | None = None
    by: str | None = Field(default=None, description="For superseded: the id of the replacing belief.")


class IngestOutcome(BaseModel):
    model_config = ConfigDict(frozen=True)

    report_id: str
    trace_id: str | None
    version: int = Field(description="Session version after this report.")
    changes: list[BeliefChange]


class BeliefSession:
    """Current beliefs from an ordered stream of reports; contracts always reflect them.

    >>> from lucifer.kb import load_kb
    >>> from lucifer.types import GroundedObject, GroundingResult
    >>> s = BeliefSession(load_kb("knowledge_base"))
    >>> fire = GroundedObject(entity="bakery", category="hazard", location="bakery", cells=[[1, 3]])
    >>> _ = s.ingest(GroundingResult(report="fire at the bakery", objects=[fire], trace_id="t1"))
    >>> [(b.location, b.category, round(b.confidence, 2)) for b in s.active_beliefs()]
    [('bakery', 'hazard', 0.7)]
    >>> _ = s.ingest(GroundingResult(report="the fire at the bakery is out", denied=[fire], trace_id="t2"))
    >>> s.active_beliefs()
    []
    """

    def __init__(
        self,
        kb: KnowledgeBase,
        *,
        grounder: Grounder | None = None,
        params: BeliefParams | None = None,
        contract_params: ContractParams | None = None,
    ):
        self.kb = kb
        self.grounder = grounder
        self.params = params or BeliefParams()
        self.contract_params = contract_params or ContractParams()
        self.version = 0
        self.history: list[IngestOutcome] = []
        self._beliefs: dict[str, Belief] = {}  # id -> belief, all states, creation order
        self._active: dict[tuple[str, str], str] = {}  # (location, category) -> id
        self._seen_reports: set[str] = set()
        self._next_id = 1
        self._seq_issued = 0
        self._seq_done = 0
        self._pending: dict[int, GroundingResult | None] = {}
        self._waiting: dict[int, asyncio.Future[IngestOutcome | None]] = {}
        self._cache: tuple[Any, ...] | None = None

    # --- queries --------------------------------------------------------------------

    def active_beliefs(self) -> list[Belief]:
        return [self._beliefs[i] for i in self._active.values()]

    def all_beliefs(self) -> list[Belief]:
        """Every belief ever held, retracted and superseded ones included."""
        return list(self._beliefs.values())

    def belief(self, belief_id: str) -> Belief:
        return self._beliefs[belief_id]

    def find(self, location: str, category: str) -> Belief | None:
        bid = self._active.get((location, category))
        return None if bid is None else self._beliefs[bid]

    def tables(self, space: ContextSpace, params: ContractParams | None = None) -> ContractTables:
        return self._build(space, params)[0]

    def contract(self, space: ContextSpace, params: ContractParams | None = None) -> SignalContract:
        """The Signal Contract of the current beliefs (rebuilt only when they changed)."""
        t, p, c = self._build(space, params)
        if c is None:
            c = contract_from_tables(t, space, p)
            assert self._cache is not None
            self._cache = (*self._cache[:4], c)
        return c

    def _build(self, space: ContextSpace, params: ContractParams | None) -> tuple[Any, ...]:
        p = params or self.contract_params
        cache = self._cache
        if cache is not None and cache[0] is space and cache[1] == p and cache[2] == self.version:
            return cache[3], p, cache[4]
        t = build_tables(self.active_beliefs(), space, self.kb, p)
        self._cache = (space, p, self.version, t, None)
        return t, p, None

    # --- ingestion ------------------------------------------------------------------

    async def ingest_report(self, text: str, report_id: str | None = None) -> IngestOutcome:
        """Ground ``text`` with the session's grounder, then ingest it.

        Groundings may run concurrently; results are applied in the order the calls were
        made, so a later report always revises an earlier one. A call whose grounding fails
        (or is cancelled) raises and is skipped; the reports after it still apply.
        (A plain :meth:`ingest` call applies at once, not queued behind pending ones.)
        """
        if self.grounder is None:
            raise RuntimeError("this BeliefSession has no grounder; pass grounder= or call ingest()")
        seq = self._seq_issued
        self._seq_issued += 1
        done: asyncio.Future[IngestOutcome | None] = asyncio.get_running_loop().create_future()
        self._waiting[seq] = done
        result: GroundingResult | None = None
        try:
            result = await self.grounder.ground(text, report_id=report_id)
            if result.report_id is None and report_id is not None:
                result = result.model_copy(update={"report_id": report_id})
        finally:
            self._pending[seq] = result  # None: failed, skip it
            self._drain()
        out = await done
        assert out is not None
        return out

    def _drain(self) -> None:
        """Apply every finished grounding whose predecessors are all applied (in order)."""
        while self._seq_done in self._pending:
            seq = self._seq_done
            result = self._pending.pop(seq)
            fut = self._waiting.pop(seq)
            self._seq_done += 1
            if result is None:
                fut.set_result(None)
                continue
            try:
                fut.set_result(self.ingest(result))
            except Exception as exc:  # surfaced to the caller that awaits this report
                fut.set_exception(exc)

    def ingest(self, result: GroundingResult) -> IngestOutcome:
        """Apply one grounding result: its denials, then its claims."""
        rid = result.report_id or f"r{len(self.history) + 1}"
        if rid in self._seen_reports:
            out = IngestOutcome(
                report_id=rid,
                trace_id=result.trace_id,
                version=self.version,
                changes=[BeliefChange(kind="duplicate_report", belief_id=None, location="", category="")],
            )
            self.history.append(out)
            return out
        self._seen_reports.add(rid)
        changes: list[BeliefChange] = []
        for obj in result.denied:
            changes.append(self._deny(obj, rid, result.trace_id))
        groups: dict[tuple[str, str], list[GroundedObject]] = {}
        for obj in result.objects:
            groups.setdefault((obj.location, obj.category), []).append(obj)
        for objs in groups.values():
            best = max(objs, key=lambda o: o.confidence)
            changes.extend(self._claim(best, [o for o in objs if o is not best], rid, result.trace_id))
        if any(c.kind != "denial_unmatched" for c in changes):
            self.version += 1
        out = IngestOutcome(report_id=rid, trace_id=result.trace_id, version=self.version, changes=changes)
        self.history.append(out)
        return out

    def _role(self, category: str) -> Role | None:
        cat = self.kb.category_by_name.get(category)
        return None if cat is None else cat.role

    def _new_id(self) -> str:
        bid = f"b{self._next_id}"
        self._next_id += 1
        return bid

    def _claim(
        self, obj: GroundedObject, others: list[GroundedObject], rid: str, trace_id: str | None
    ) -> list[BeliefChange]:
        key = (obj.location, obj.category)
        trust = self.params.trust
        old = self.find(*key)
        if old is not None:
            provs = [provenance_of(o, rid, trace_id, "confirmation") for o in [obj, *others]]
            c = confirm(old.confidence, obj.confidence, trust)
            self._beliefs[old.id] = old.model_copy(
                update={"confidence": c, "provenance": [*old.provenance, *provs]}
            )
            return [
                BeliefChange(
                    kind="confirmed", belief_id=old.id, location=key[0], category=key[1],
                    confidence_before=old.confidence, confidence_after=c,
                )
            ]
        changes: list[BeliefChange] = []
        new_id = self._new_id()
        role = self._role(obj.category)
        replaced: list[str] = []
        if role is not None:
            for (loc, cat), bid in list(self._active.items()):
                other = self._role(cat)
                if loc == obj.location and other is not None and other in ROLE_CONFLICTS[role]:
                    b = self._beliefs[bid]
                    self._beliefs[bid] = b.model_copy(
                        update={"state": BeliefState.SUPERSEDED, "superseded_by": new_id}
                    )
                    del self._active[(loc, cat)]
                    replaced.append(bid)
                    changes.append(
                        BeliefChange(
                            kind="superseded", belief_id=bid, location=loc, category=cat,
                            confidence_before=b.confidence, confidence_after=b.confidence, by=new_id,
                        )
                    )
        c = confirm(0.0, obj.confidence, trust)
        self._beliefs[new_id] = Belief(
            id=new_id,
            location=obj.location,
            category=obj.category,
            cells=cells_of_object(obj, self.kb),
            confidence=c,
            provenance=[provenance_of(o, rid, trace_id, "claim") for o in [obj, *others]],
            replaces=replaced,
        )
        self._active[key] = new_id
        changes.append(
            BeliefChange(kind="created", belief_id=new_id, location=key[0], category=key[1], confidence_after=c)
        )
        return changes

    def _deny(self, obj: GroundedObject, rid: str, trace_id: str | None) -> BeliefChange:
        target = self.find(obj.location, obj.category)
        if target is None:
            role = self._role(obj.category)
            for (loc, cat), bid in self._active.items():
                if loc == obj.location and role is not None and self._role(cat) == role:
                    target = self._beliefs[bid]
                    break
        if target is None:
            return BeliefChange(kind="denial_unmatched", belief_id=None, location=obj.location, category=obj.category)
        prov = provenance_of(obj, rid, trace_id, "denial")
        before = target.confidence
        if obj.confidence >= self.params.retract_at:
            self._beliefs[target.id] = target.model_copy(
                update={"state": BeliefState.RETRACTED, "provenance": [*target.provenance, prov]}
            )
            del self._active[(target.location, target.category)]
            return BeliefChange(
                kind="retracted", belief_id=target.id, location=target.location, category=target.category,
                confidence_before=before, confidence_after=before,
            )
        c = before * (1.0 - obj.confidence)
        self._beliefs[target.id] = target.model_copy(
            update={"confidence": c, "provenance": [*target.provenance, prov]}
        )
        return BeliefChange(
            kind="weakened", belief_id=target.id, location=target.location, category=target.category,
            confidence_before=before, confidence_after=c,
        )

"""Belief maintenance over a report stream: revision sequences, confidence, provenance."""

from __future__ import annotations

import asyncio
import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from lucifer.contract import (
    BeliefParams,
    BeliefSession,
    BeliefState,
    ContextStatus,
    GridContextSpace,
)
from lucifer.kb import Category, Role, load_kb
from lucifer.types import GroundedObject, GroundingResult, Span

KB = load_kb("knowledge_base")
GRID = GridContextSpace(KB.rows, KB.cols)


def g(location: str, category: str, report: str = "", entity: str | None = None, confidence: float = 1.0):
    """A grounded object whose span points at `entity` (default: the location) inside `report`."""
    entity = entity or location
    start = report.find(entity)
    span = Span(start=start, end=start + len(entity)) if start >= 0 else None
    return GroundedObject(
        entity=entity, category=category, location=location, cells=KB.cells_of(location),
        span=span, confidence=confidence,
    )


def report(text: str, rid: str, claims=(), denied=()) -> GroundingResult:
    return GroundingResult(
        report=text, report_id=rid, trace_id=f"trace-{rid}",
        objects=[g(loc, cat, text, ent) for loc, cat, ent in claims],
        denied=[g(loc, cat, text, ent) for loc, cat, ent in denied],
    )


def test_confirmations_raise_confidence_with_noisy_or():
    s = BeliefSession(KB)
    texts = ["Fire at the bakery.", "Bakery is burning.", "Smoke from the bread shop."]
    ents = ["bakery", "Bakery", "bread shop"]
    outs = [s.ingest(report(t, f"r{i}", [("bakery", "hazard", e)])) for i, (t, e) in enumerate(zip(texts, ents, strict=True))]
    assert [o.changes[0].kind for o in outs] == ["created", "confirmed", "confirmed"]
    (b,) = s.active_beliefs()
    assert b.confidence == pytest.approx(1 - 0.3**3)
    assert [o.changes[0].confidence_after for o in outs] == pytest.approx([0.7, 0.91, 0.973])
    assert [(p.report_id, p.kind, p.trace_id) for p in b.provenance] == [
        ("r0", "claim", "trace-r0"), ("r1", "confirmation", "trace-r1"), ("r2", "confirmation", "trace-r2"),
    ]
    for p, t in zip(b.provenance, texts, strict=True):
        assert t[p.span[0]:p.span[1]] == p.text
    c = s.contract(GRID)
    assert c.potentials["1,3"] == pytest.approx(-0.973)
    assert c.potentials["1,4"] == pytest.approx(-0.973 / 2)
    assert c.priors["1,4"]["W"] == -1.0  # -0.973 + 0.5 · (-0.973 + 0.4865), clipped


def test_repeats_inside_one_report_count_once():
    s = BeliefSession(KB)
    text = "Fire at the bakery, the bakery is on fire"
    r = GroundingResult(report=text, report_id="r1", trace_id="t", objects=[
        GroundedObject(entity="bakery", category="hazard", location="bakery", cells=[[1, 3]], span=Span(start=12, end=18)),
        GroundedObject(entity="bakery", category="hazard", location="bakery", cells=[[1, 3]], span=Span(start=24, end=30)),
    ])
    out = s.ingest(r)
    assert [c.kind for c in out.changes] == ["created"]
    (b,) = s.active_beliefs()
    assert b.confidence == pytest.approx(0.7)
    assert [p.span for p in b.provenance] == [(12, 18), (24, 30)]


def test_fire_is_out_retracts_and_contract_follows():
    s = BeliefSession(KB)
    s.ingest(report("Fire at the bakery.", "r1", [("bakery", "hazard", "bakery")]))
    before = s.contract(GRID)
    assert before.x_u == ["1,3"] and "W" not in before.admissible["1,4"]
    out = s.ingest(report("The fire at the bakery is out.", "r2", denied=[("bakery", "hazard", "bakery")]))
    assert [(c.kind, c.belief_id) for c in out.changes] == [("retracted", "b1")]
    assert s.active_beliefs() == []
    after = s.contract(GRID)
    assert after.x_u == [] and "W" in after.admissible["1,4"] and after.potentials["1,3"] == 0.0
    old = s.belief("b1")
    assert old.state == BeliefState.RETRACTED
    assert [(p.report_id, p.kind) for p in old.provenance] == [("r1", "claim"), ("r2", "denial")]
    assert old.provenance[1].span == (16, 22)  # "bakery" in "The fire at the bakery is out."


def test_hedged_denial_lowers_below_the_set_threshold():
    s = BeliefSession(KB)
    s.ingest(report("Fire at the bakery.", "r1", [("bakery", "hazard", "bakery")]))
    hedge = GroundingResult(report="maybe the bakery fire is out", report_id="r2", trace_id="t2",
                            denied=[g("bakery", "hazard", "maybe the bakery fire is out", confidence=0.3)])
    out = s.ingest(hedge)
    assert out.changes[0].kind == "weakened"
    assert s.find("bakery", "hazard").confidence == pytest.approx(0.7 * 0.7)
    c = s.contract(GRID)
    assert c.x_u == []  # 0.49 < min_confidence 0.5: no longer excluded…
    assert c.priors["1,4"]["W"] < 0  # …but still repulsive


def test_clinic_no_longer_safe_replaces_safe_zone_with_hazard():
    s = BeliefSession(KB)
    s.ingest(report("Clinic is safe, triage there.", "r1", [("clinic", "safe_zone", "Clinic")]))
    assert s.contract(GRID).x_d == ["2,4"]
    out = s.ingest(report("The clinic is no longer safe, gas leak.", "r2", [("clinic", "hazard", "clinic")]))
    assert [(c.kind, c.belief_id, c.by) for c in out.changes] == [("superseded", "b1", "b2"), ("created", "b2", None)]
    old, new = s.belief("b1"), s.belief("b2")
    assert old.state == BeliefState.SUPERSEDED and old.superseded_by == "b2" and new.replaces == ["b1"]
    c = s.contract(GRID)
    assert c.x_d == [] and c.x_u == ["2,4"]
    assert c.located["2,4"] == ["b2"]
    assert c.explain("2,4")[0].report_id == "r2"
    # and back: a later all-clear as a safe-zone claim replaces the hazard
    s.ingest(report("Clinic cleared, safe again.", "r3", [("clinic", "safe_zone", "Clinic")]))
    assert [(b.category, b.id) for b in s.active_beliefs()] == [("safe_zone", "b3")]


def test_victim_and_hazard_coexist_on_one_place():
    s = BeliefSession(KB)
    s.ingest(report("Fire at the school.", "r1", [("school", "hazard", "school")]))
    s.ingest(report("Kids trapped in the school.", "r2", [("school", "victim", "school")]))
    assert {b.category for b in s.active_beliefs()} == {"hazard", "victim"}
    c = s.contract(GRID)
    assert c.x_u == c.x_o == ["0,2"]
    assert "W" not in c.admissible["0,3"]  # safety first


def test_denials_before_claims_in_one_report():
    s = BeliefSession(KB)
    s.ingest(report("Fire at the bakery.", "r1", [("bakery", "hazard", "bakery")]))
    text = "Fire at the bakery is out, the bakery is a safe zone now."
    out = s.ingest(report(text, "r2", claims=[("bakery", "safe_zone", "bakery")], denied=[("bakery", "hazard", "bakery")]))
    assert [c.kind for c in out.changes] == ["retracted", "created"]
    assert s.belief("b1").state == BeliefState.RETRACTED  # retracted, not superseded
    assert [(b.category, b.replaces) for b in s.active_beliefs()] == [("safe_zone", [])]


def test_unmatched_denial_and_duplicate_report_change_nothing():
    s = BeliefSession(KB)
    s.ingest(report("Fire at the bakery.", "r1", [("bakery", "hazard", "bakery")]))
    v = s.version
    out = s.ingest(report("No fire at the bank.", "r2", denied=[("bank", "hazard", "bank")]))
    assert [c.kind for c in out.changes] == ["denial_unmatched"] and s.version == v
    dup = s.ingest(report("Fire at the bakery.", "r1", [("bakery", "hazard", "bakery")]))
    assert [c.kind for c in dup.changes] == ["duplicate_report"]
    assert s.find("bakery", "hazard").confidence == pytest.approx(0.7) and s.version == v
    assert [h.report_id for h in s.history] == ["r1", "r2", "r1"]


def test_denial_falls_back_to_same_role_category():
    kb = dataclasses.replace(KB, categories=(*KB.categories, Category(name="fire", role=Role.UNDESIRABLE)))
    s = BeliefSession(kb)
    s.ingest(report("The bakery is on fire.", "r1", [("bakery", "fire", "bakery")]))
    out = s.ingest(report("The bakery hazard is gone.", "r2", denied=[("bakery", "hazard", "bakery")]))
    assert [(c.kind, c.category) for c in out.changes] == [("retracted", "fire")]


def test_reclaim_after_retraction_is_a_new_belief():
    s = BeliefSession(KB)
    s.ingest(report("Fire at the bakery.", "r1", [("bakery", "hazard", "bakery")]))
    s.ingest(report("Bakery fire out.", "r2", denied=[("bakery", "hazard", "bakery")]))
    s.ingest(report("Bakery burning again.", "r3", [("bakery", "hazard", "Bakery")]))
    (b,) = s.active_beliefs()
    assert b.id == "b2" and b.confidence == pytest.approx(0.7)
    assert [p.report_id for p in b.provenance] == ["r3"]


def test_missing_report_ids_are_numbered():
    s = BeliefSession(KB)
    r = GroundingResult(report="Fire at the bank", trace_id="t", objects=[g("bank", "hazard", "Fire at the bank")])
    assert s.ingest(r).report_id == "r1"
    assert s.ingest(r.model_copy(update={"trace_id": "t2"})).report_id == "r2"
    assert s.find("bank", "hazard").confidence == pytest.approx(0.91)


def test_contract_is_cached_until_beliefs_change():
    s = BeliefSession(KB)
    c0 = s.contract(GRID)
    assert s.contract(GRID) is c0
    assert s.tables(GRID) is c0.tables
    s.ingest(report("Casualty at the park.", "r1", [("park", "victim", "park")]))
    c1 = s.contract(GRID)
    assert c1 is not c0 and c1.x_o == ["4,1"]
    assert c1.status["3,1"] == ContextStatus.OK and c1.admissible["3,1"] == ["S"]
    other = GridContextSpace(KB.rows, KB.cols, ("N", "S", "E", "W", "stay"))
    assert s.contract(other).options["3,1"][-1] == "stay"


def test_custom_trust():
    s = BeliefSession(KB, params=BeliefParams(trust=1.0))
    s.ingest(report("Fire at the bakery.", "r1", [("bakery", "hazard", "bakery")]))
    assert s.find("bakery", "hazard").confidence == 1.0


# --- async stream -------------------------------------------------------------------------


class FakeGrounder:
    """Grounds by a lookup table, after a per-report delay (later reports may finish first)."""

    def __init__(self, table, delays):
        self.table, self.delays = table, delays

    async def ground(self, text: str, report_id: str | None = None) -> GroundingResult:
        await asyncio.sleep(self.delays.get(report_id, 0.0))
        if text == "boom":
            raise RuntimeError("grounder failed")
        claims, denied = self.table[text]
        return report(text, None, claims, denied).model_copy(update={"report_id": None})


async def test_concurrent_ingest_applies_in_call_order():
    table = {
        "Clinic is safe.": ([("clinic", "safe_zone", "Clinic")], []),
        "The clinic is no longer safe.": ([("clinic", "hazard", "clinic")], []),
        "boom": ([], []),
        "Fire at the bakery.": ([("bakery", "hazard", "bakery")], []),
    }
    s = BeliefSession(KB, grounder=FakeGrounder(table, {"a": 0.05, "b": 0.0, "c": 0.01, "d": 0.0}))
    results = await asyncio.gather(
        s.ingest_report("Clinic is safe.", report_id="a"),
        s.ingest_report("The clinic is no longer safe.", report_id="b"),
        s.ingest_report("boom", report_id="c"),
        s.ingest_report("Fire at the bakery.", report_id="d"),
        return_exceptions=True,
    )
    assert isinstance(results[2], RuntimeError)
    assert [h.report_id for h in s.history] == ["a", "b", "d"]
    assert {(b.location, b.category) for b in s.active_beliefs()} == {("clinic", "hazard"), ("bakery", "hazard")}
    assert s.find("clinic", "hazard").provenance[0].report_id == "b"


async def test_ingest_report_needs_a_grounder():
    with pytest.raises(RuntimeError, match="grounder"):
        await BeliefSession(KB).ingest_report("x")


# --- properties -------------------------------------------------------------------------------

PLACES = ["bakery", "clinic", "school", "market square"]
CATS = ["hazard", "safe_zone", "victim"]
events = st.lists(
    st.tuples(st.booleans(), st.sampled_from(PLACES), st.sampled_from(CATS), st.floats(0.0, 1.0)),
    max_size=25,
)


@settings(max_examples=100, deadline=None)
@given(events=events)
def test_any_stream_keeps_beliefs_consistent(events):
    s = BeliefSession(KB)
    for k, (is_denial, loc, cat, conf) in enumerate(events):
        o = g(loc, cat, confidence=conf)
        before = s.find(loc, cat)
        r = GroundingResult(report="x", report_id=f"r{k}", trace_id=f"t{k}",
                            objects=[] if is_denial else [o], denied=[o] if is_denial else [])
        s.ingest(r)
        after = s.find(loc, cat)
        if not is_denial and before is not None:
            assert after is not None and after.id == before.id and after.confidence >= before.confidence
        if is_denial and before is not None and after is not None:
            assert after.confidence <= before.confidence
    active = s.active_beliefs()
    assert len({(b.location, b.category) for b in active}) == len(active)
    for b in active:
        assert 0.0 <= b.confidence <= 1.0 and b.state == BeliefState.ACTIVE and b.provenance
    roles = {(b.location, KB.category_by_name[b.category].role) for b in active}
    for loc in PLACES:
        assert not ((loc, Role.UNDESIRABLE) in roles and (loc, Role.DESIRABLE) in roles)
    c = s.contract(GRID)
    assert sorted(b.id for b in c.beliefs) == sorted(b.id for b in active)
    for x in c.contexts:
        assert set(c.admissible[x]) <= set(c.options[x]) and c.admissible[x]


async def test_cancelled_grounding_does_not_block_later_reports():
    table = {"Fire at the bakery.": ([("bakery", "hazard", "bakery")], []), "slow": ([], [])}
    s = BeliefSession(KB, grounder=FakeGrounder(table, {"a": 10.0, "b": 0.0}))
    slow = asyncio.create_task(s.ingest_report("slow", report_id="a"))
    fast = asyncio.create_task(s.ingest_report("Fire at the bakery.", report_id="b"))
    await asyncio.sleep(0.01)
    assert not fast.done()  # waits for report a, issued first
    slow.cancel()
    out = await asyncio.wait_for(fast, 1.0)
    assert out.report_id == "b" and s.find("bakery", "hazard") is not None

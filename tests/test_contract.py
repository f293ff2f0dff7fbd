"""Signal Contract transducer: the constraint equation, priors and potentials worked by hand."""

from __future__ import annotations

import json
from collections.abc import Hashable, Sequence

import numpy as np
import pytest

from lucifer.contract import (
    STATUS_ORDER,
    ContextSpace,
    ContextStatus,
    ContractParams,
    EquationCase,
    ExplicitContextSpace,
    GridContextSpace,
    build_contract,
    build_tables,
    load_context_space,
    shaping,
    signals_json,
)
from lucifer.errors import BadRequest
from lucifer.kb import load_kb
from lucifer.types import GroundedObject, GroundingResult, Span

KB = load_kb("knowledge_base")
PURE = ContractParams(softening=0.0)  # the paper's priors: role value of the outcome only


def obj(category: str, *cells: tuple[int, int], location: str = "somewhere", confidence: float = 1.0, **kw):
    return GroundedObject(
        entity=location, category=category, location=location, cells=[list(c) for c in cells],
        confidence=confidence, **kw,
    )


def hazard(*cells, **kw):
    return obj("hazard", *cells, location=kw.pop("location", f"h{cells[0]}"), **kw)


def victim(*cells, **kw):
    return obj("victim", *cells, location=kw.pop("location", f"v{cells[0]}"), **kw)


def safe(*cells, **kw):
    return obj("safe_zone", *cells, location=kw.pop("location", f"s{cells[0]}"), **kw)


G3 = GridContextSpace(3, 3)


# --- the constraint equation, case by case ----------------------------------------------


def test_no_beliefs_leaves_every_option_admissible():
    c = build_contract([], G3, KB, PURE)
    assert c.rule == EquationCase.NONE
    assert c.x_u == c.x_d == c.x_o == []
    for x in c.contexts:
        assert c.admissible[x] == c.options[x]
        assert c.status[x] == ContextStatus.OK
        assert set(c.priors[x].values()) == {0.0}
        assert c.potentials[x] == 0.0
    assert c.options["0,0"] == ["S", "E"]  # edges excluded by default
    assert c.options["1,1"] == ["N", "S", "E", "W"]


def test_only_undesirable_excludes_moves_into_it():
    c = build_contract([hazard((1, 1))], G3, KB, PURE)
    assert c.rule == EquationCase.EXCLUDE_UNDESIRABLE
    assert c.x_u == ["1,1"]
    assert c.options["0,1"] == ["S", "E", "W"]
    assert c.admissible["0,1"] == ["E", "W"]
    assert c.priors["0,1"] == {"S": -1.0, "E": 0.0, "W": 0.0}
    assert c.status["0,1"] == ContextStatus.OK
    # leaving the hazard is fine; corners never touch it
    assert c.admissible["1,1"] == ["N", "S", "E", "W"]
    assert c.admissible["0,0"] == ["S", "E"]


def test_only_goals_restrict_to_moves_into_them_with_fallback():
    c = build_contract([victim((1, 1))], G3, KB, PURE)
    assert c.rule == EquationCase.RESTRICT_TO_GOALS
    assert c.x_o == ["1,1"]
    assert c.admissible["0,1"] == ["S"]
    assert c.priors["0,1"] == {"S": 1.0, "E": 0.0, "W": 0.0}
    assert c.status["0,1"] == ContextStatus.OK
    # from a corner no option reaches X_o in one step: documented fallback, not ∅
    assert c.status["0,0"] == ContextStatus.FALLBACK_NO_GOAL_OPTION
    assert c.admissible["0,0"] == ["S", "E"]


def test_desirable_prior_is_half():
    c = build_contract([safe((1, 1))], G3, KB, PURE)
    assert c.x_d == ["1,1"]
    assert c.priors["1,0"]["E"] == 0.5
    assert c.admissible["1,0"] == ["E"]


def test_both_cases_intersect_and_safety_wins():
    c = build_contract([hazard((0, 1)), victim((1, 0))], G3, KB, PURE)
    assert c.rule == EquationCase.EXCLUDE_AND_RESTRICT
    assert c.admissible["0,0"] == ["S"]  # S → victim; E → hazard
    assert c.priors["0,0"] == {"S": 1.0, "E": -1.0}
    assert c.admissible["1,1"] == ["W"]  # N → hazard, W → victim
    # no safe goal move: fall back to the exclusion alone
    assert c.status["0,2"] == ContextStatus.FALLBACK_NO_GOAL_OPTION
    assert c.admissible["0,2"] == ["S"]  # W → hazard is still excluded


def test_all_options_into_hazard_falls_back_to_all_options():
    g = GridContextSpace(2, 2)
    c = build_contract([hazard((0, 1)), hazard((1, 0))], g, KB, PURE)
    assert c.status["0,0"] == ContextStatus.FALLBACK_NO_SAFE_OPTION
    assert c.admissible["0,0"] == c.options["0,0"] == ["S", "E"]
    assert c.priors["0,0"] == {"S": -1.0, "E": -1.0}
    assert c.admissible_sources["0,0"] == ["b1", "b2"]


def test_victim_inside_a_hazard_is_still_excluded():
    c = build_contract([hazard((1, 1)), victim((1, 1))], G3, KB, PURE)
    assert c.x_u == ["1,1"] and c.x_o == ["1,1"]
    assert "S" not in c.admissible["0,1"]
    assert c.priors["0,1"]["S"] == -1.0  # safety first: v(x) is the undesirable value
    assert c.status["0,1"] == ContextStatus.FALLBACK_NO_GOAL_OPTION


def test_terminal_context_reports_no_options():
    space = ExplicitContextSpace({"a": ([(0, 0)], {"go": "b"}), "b": ([(0, 1)], {})})
    c = build_contract([hazard((0, 1))], space, KB, PURE)
    assert c.status["b"] == ContextStatus.NO_OPTIONS
    assert c.admissible["b"] == [] == c.options["b"]
    assert c.status["a"] == ContextStatus.FALLBACK_NO_SAFE_OPTION
    assert c.admissible["a"] == ["go"]


def test_restriction_can_be_turned_off():
    c = build_contract([victim((1, 1))], G3, KB, ContractParams(softening=0.0, restrict_to_goals=False))
    assert c.rule == EquationCase.NONE
    assert c.admissible["0,1"] == ["S", "E", "W"]
    assert c.priors["0,1"]["S"] == 1.0


def test_weak_beliefs_shape_values_but_not_sets():
    c = build_contract([hazard((1, 1), confidence=0.4)], G3, KB, PURE)
    assert c.x_u == []
    assert c.admissible["0,1"] == ["S", "E", "W"]
    assert c.priors["0,1"]["S"] == pytest.approx(-0.4)
    assert c.potentials["1,1"] == pytest.approx(-0.4)


def test_multi_cell_landmark_covers_each_cell():
    sq = GroundedObject(entity="the square", category="safe_zone", location="market square", cells=[[1, 2], [2, 2]])
    c = build_contract([sq], GridContextSpace(KB.rows, KB.cols), KB, PURE)
    assert c.x_d == ["1,2", "2,2"]
    assert c.located["1,2"] == c.located["2,2"] == ["b1"]
    # one term per belief, at the nearest of its cells: Φ(0,2) = 0.5 · 0.5**1
    assert c.potentials["0,2"] == pytest.approx(0.25)


# --- potentials and priors, by hand --------------------------------------------------------


def test_potentials_sum_decaying_terms_and_clip():
    c = build_contract([hazard((0, 0)), victim((2, 2))], G3, KB)
    assert c.potentials["1,1"] == pytest.approx(-0.25 + 0.25)
    assert c.potentials["0,1"] == pytest.approx(-0.5 + 0.125)
    assert c.potentials["0,0"] == pytest.approx(-1 + 0.0625)
    assert c.potentials["2,2"] == pytest.approx(1 - 0.0625)
    two = build_contract([hazard((0, 0)), hazard((0, 1))], G3, KB)
    assert two.potentials["0,0"] == -1.0  # -1 - 0.5 clipped
    assert two.potentials["2,2"] == pytest.approx(-(0.5**4) - 0.5**3)


def test_radius_and_decay():
    c = build_contract([victim((0, 0))], G3, KB, ContractParams(radius=1, decay=0.25))
    assert c.potentials["0,1"] == pytest.approx(0.25)
    assert c.potentials["1,1"] == 0.0
    assert c.potential_sources["1,1"] == [] and c.potential_sources["0,1"] == ["b1"]


def test_softened_prior_points_toward_objectives():
    c = build_contract([victim((0, 0))], G3, KB)  # softening 0.5, decay 0.5
    # from (2,2): Φ = 0.5**4; N → (1,2): Φ = 0.5**3 → Ψ = 0.5 · (0.125 − 0.0625)
    assert c.priors["2,2"]["N"] == pytest.approx(0.5 * (0.125 - 0.0625))
    assert c.priors["1,1"]["N"] > 0 > c.priors["1,1"]["S"]
    # direct moves keep the role value, clipped to 1
    assert c.priors["0,1"]["W"] == 1.0
    assert c.priors["1,1"]["N"] == pytest.approx(0.5 * (0.5 - 0.25))


def test_kb_worked_example_on_market_square():
    objs = [
        GroundedObject(entity="bakery", category="hazard", location="bakery", cells=[[1, 3]], span=Span(start=12, end=18)),
        GroundedObject(entity="clinic", category="victim", location="clinic", cells=[[2, 4]]),
        GroundedObject(entity="square", category="safe_zone", location="market square", cells=[[1, 2], [2, 2]]),
    ]
    res = GroundingResult(report="x" * 40, objects=objs, trace_id="t1", report_id="r1")
    c = build_contract(res, GridContextSpace(5, 5), KB)
    # Φ(1,4) = -0.5 (bakery) + 0.5 (clinic) + 0.5·0.5**2 (square)
    assert c.potentials["1,4"] == pytest.approx(0.125)
    # Φ(0,4) = -0.25 + 0.25 + 0.5·0.5**3; Ψ_(1,4)(N) = 0.5·(Φ(0,4) − Φ(1,4))
    assert c.priors["1,4"]["N"] == pytest.approx(0.5 * (0.0625 - 0.125))
    assert c.priors["1,4"]["S"] == 1.0 and c.priors["1,4"]["W"] == -1.0
    assert c.admissible["1,4"] == ["S"]
    assert c.outcomes["1,4"] == {"N": "0,4", "S": "2,4", "W": "1,3"}


def test_unknown_category_and_missing_cells_are_warned_not_silent():
    odd = GroundedObject(entity="x", category="dragon", location="bakery", cells=[[1, 3]])
    nocells = GroundedObject(entity="clinic", category="hazard", location="clinic", cells=[])
    c = build_contract([odd, nocells], GridContextSpace(5, 5), KB)
    assert any("dragon" in w for w in c.warnings)
    assert c.x_u == ["2,4"]  # cells filled from the KB landmark


# --- provenance ------------------------------------------------------------------------


def test_every_element_traces_to_report_span_and_trace():
    text = "Fire at the bakery, casualty at the clinic."
    res = GroundingResult(
        report=text,
        trace_id="trace-9",
        report_id="rep-1",
        objects=[
            GroundedObject(entity="the bakery", category="hazard", location="bakery", cells=[[1, 3]],
                           span=Span(start=8, end=18), cue="Fire", cue_span=Span(start=0, end=4)),
            GroundedObject(entity="the clinic", category="victim", location="clinic", cells=[[2, 4]],
                           span=Span(start=32, end=42), cue="casualty", cue_span=Span(start=20, end=28)),
        ],
    )
    c = build_contract(res, GridContextSpace(5, 5), KB)
    assert c.located == {"1,3": ["b1"], "2,4": ["b2"]}
    (p,) = c.belief("b1").provenance
    assert (p.report_id, p.trace_id, p.span, p.cue_span) == ("rep-1", "trace-9", (8, 18), (0, 4))
    assert text[p.span[0]:p.span[1]] == p.text == "the bakery"
    assert c.admissible_sources["1,4"] == ["b1", "b2"]
    spans = {q.span for q in c.explain("1,4", "W")}
    assert spans == {(8, 18), (32, 42)}
    assert c.potential_sources["0,0"] == ["b1", "b2"]


# --- spaces ----------------------------------------------------------------------------


def test_grid_edges_stay_and_walls():
    g = GridContextSpace(2, 2, ("N", "S", "E", "W", "stay"), edges="stay")
    c = build_contract([victim((0, 0))], g, KB, PURE)
    assert c.options["0,0"] == ["N", "S", "E", "W", "stay"]
    assert c.outcomes["0,0"]["N"] == "0,0"
    assert c.admissible["0,0"] == ["N", "W", "stay"]  # bumps and stay keep it on the victim
    walls = GridContextSpace(1, 3, contexts=[(0, 0), (0, 2)])
    c2 = build_contract([], walls, KB)
    assert c2.contexts == ["0,0", "0,2"]
    assert c2.options["0,0"] == [] and c2.status["0,0"] == ContextStatus.NO_OPTIONS


class Ring(ContextSpace):
    """Contexts 0..n-1 on row 0; 'fwd' goes to x+1 — and from the last one to 'outside'."""

    def __init__(self, n: int):
        self.n = n

    def contexts(self) -> Sequence[Hashable]:
        return list(range(self.n))

    def options(self, x):
        return ["fwd", "back"] if x > 0 else ["fwd"]

    def outcome(self, x, u):
        if u == "back":
            return x - 1
        return x + 1 if x + 1 < self.n else "outside"

    def cells(self, x):
        return [(0, x if x != "outside" else self.n)]

    def distance(self, a, b):  # Chebyshev instead of Manhattan
        return np.abs(np.asarray(a) - np.asarray(b)).max(axis=-1)


def test_custom_space_outcome_outside_x_and_custom_distance():
    space = Ring(3)
    c = build_contract([hazard((0, 3))], space, KB, PURE)  # the hazard is on 'outside'
    assert c.contexts == ["0", "1", "2"]
    assert c.outcomes["2"]["fwd"] == "outside"
    assert c.admissible["2"] == ["back"]
    assert c.status["2"] == ContextStatus.OK
    d = build_contract([victim((1, 1))], space, KB)
    assert d.potentials["0"] == pytest.approx(0.5)  # Chebyshev distance 1


def test_tables_match_the_contract():
    c = build_contract([hazard((0, 1)), victim((2, 2), confidence=0.8)], G3, KB)
    t = c.tables
    for i, x in enumerate(t.space.keys[: t.space.n]):
        assert t.phi[i] == c.potentials[x]
        assert STATUS_ORDER[t.status[i]] == c.status[x]
        for j, u in enumerate(t.space.option_keys):
            assert bool(t.admissible[i, j]) == (u in c.admissible[x])
            assert t.prior[i, j] == c.priors[x].get(u, 0.0)
    i, j = G3.index_of((1, 1)), G3.index_of((1, 2))
    assert t.shaping(i, j, gamma=1.0) == pytest.approx(c.potentials["1,2"] - c.potentials["1,1"])
    fast = build_tables([hazard((0, 1)), victim((2, 2), confidence=0.8)], G3, KB)
    assert np.array_equal(fast.admissible, t.admissible) and np.allclose(fast.prior, t.prior)


def test_shaping_helper():
    assert shaping(0.5, 0.5, gamma=1.0) == 0.0
    assert shaping(-0.25, 0.5, gamma=0.5) == pytest.approx(0.5)
    assert shaping(0.3, 0.9, terminal=True) == pytest.approx(-0.3)
    assert np.allclose(shaping(np.zeros(3), np.ones(3), gamma=0.9), 0.9)


def test_params_validation():
    with pytest.raises(ValueError):
        ContractParams(role_values={"undesirable": 0.5})
    with pytest.raises(ValueError):
        ContractParams(decay=1.0)
    with pytest.raises(ValueError):
        ContractParams(bogus=1)
    p = ContractParams(role_values={"desirable": 1.0})
    assert p.role_values["critical"] == 1.0 and p.role_values["desirable"] == 1.0


# --- context JSON and signals_json ----------------------------------------------------------


def test_context_json_grid_defaults_to_kb_grid(tmp_path):
    f = tmp_path / "ctx.json"
    f.write_text(json.dumps({"type": "grid", "moves": ["N", "S", "E", "W", "stay"], "params": {"softening": 0}}))
    space, params = load_context_space(f, KB.rows, KB.cols)
    assert isinstance(space, GridContextSpace) and (space.rows, space.cols) == (5, 5)
    assert params.softening == 0.0
    res = GroundingResult(report="r", trace_id="t", objects=[
        GroundedObject(entity="bakery", category="hazard", location="bakery", cells=[[1, 3]])])
    out = signals_json(res, str(f), KB)
    json.dumps(out)  # plain JSON
    assert out["x_u"] == ["1,3"]
    assert out["priors"]["1,4"]["W"] == -1.0 and out["priors"]["1,4"]["stay"] == 0.0
    assert out["priors"]["1,3"]["stay"] == -1.0  # staying in the hazard
    assert out["status"]["1,4"] == "ok"
    assert out["beliefs"][0]["provenance"][0]["trace_id"] == "t"


def test_context_json_explicit():
    data = {"type": "explicit", "contexts": [
        {"id": "depot", "cells": [[4, 0]], "options": {"north": "hall", "wait": "depot"}},
        {"id": "hall", "cells": [[0, 0]]},
    ]}
    space, _ = load_context_space(json.dumps(data), KB.rows, KB.cols)
    out = signals_json([hazard((0, 0))], space, KB)
    assert out["admissible"] == {"depot": ["wait"], "hall": []}
    assert out["status"] == {"depot": "ok", "hall": "no_options"}


@pytest.mark.parametrize(
    ("data", "needle"),
    [
        ('{"type": "grid", ', "malformed JSON"),
        ("[1, 2]", "must be a JSON object"),
        ({"type": "hex"}, "type"),
        ({"type": "grid", "rows": 0}, "rows"),
        ({"type": "grid", "moves": ["NE"]}, "moves"),
        ({"type": "grid", "moves": ["N", "N"]}, "distinct"),
        ({"type": "grid", "extra": 1}, "extra"),
        ({"type": "grid", "rows": 9, "cols": 9}, "does not fit"),
        ({"type": "grid", "contexts": [[7, 7]]}, "outside"),
        ({"type": "grid", "params": {"decay": 2}}, "decay"),
        ({"type": "explicit", "contexts": [{"id": "a", "options": {"go": "nowhere"}}]}, "unknown context"),
        ({"type": "explicit", "contexts": [{"id": "a", "cells": [[9, 9]]}]}, "outside"),
        ({"type": "explicit", "contexts": [{"id": "a"}, {"id": "a"}]}, "twice"),
        ("/no/such/ctx.json", "does not exist"),
    ],
)
def test_context_json_rejects_bad_input(data, needle):
    with pytest.raises(BadRequest, match=needle):
        load_context_space(data if isinstance(data, str) else dict(data), KB.rows, KB.cols)

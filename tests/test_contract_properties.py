"""Property tests of the contract invariants, against a brute-force reference of the equations."""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lucifer.contract import (
    ContextStatus,
    ContractParams,
    ExplicitContextSpace,
    GridContextSpace,
    build_contract,
)
from lucifer.kb import load_kb
from lucifer.types import GroundedObject

KB = load_kb("knowledge_base")
ROLE = {"hazard": "undesirable", "safe_zone": "desirable", "victim": "critical"}
SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@st.composite
def grids(draw):
    rows, cols = draw(st.integers(1, 4)), draw(st.integers(1, 4))
    all_cells = [(r, c) for r in range(rows) for c in range(cols)]
    moves = draw(st.lists(st.sampled_from(["N", "S", "E", "W", "stay"]), min_size=1, max_size=5, unique=True))
    edges = draw(st.sampled_from(["exclude", "stay"]))
    subset = draw(st.none() | st.lists(st.sampled_from(all_cells), min_size=1, unique=True))
    return GridContextSpace(rows, cols, moves, edges=edges, contexts=subset)


@st.composite
def explicit_spaces(draw):
    n = draw(st.integers(1, 7))
    ids = [f"c{i}" for i in range(n)]
    table = {}
    for x in ids:
        cells = draw(st.lists(st.tuples(st.integers(0, 3), st.integers(0, 3)), max_size=2, unique=True))
        opts = draw(st.dictionaries(st.sampled_from(["a", "b", "c", "d"]), st.sampled_from(ids), min_size=1, max_size=4))
        if draw(st.integers(0, 5)) == 0:
            opts = {}  # a terminal context
        table[x] = (cells, opts)
    return ExplicitContextSpace(table)


@st.composite
def objects(draw):
    out = []
    for k in range(draw(st.integers(0, 10))):
        cells = draw(st.lists(st.tuples(st.integers(0, 3), st.integers(0, 3)), min_size=1, max_size=2, unique=True))
        out.append(
            GroundedObject(
                entity=f"o{k}",
                category=draw(st.sampled_from(list(ROLE))),
                location=f"loc{k}",
                cells=[list(c) for c in cells],
                confidence=draw(st.sampled_from([1.0, 0.7]) | st.floats(0.0, 1.0)),
            )
        )
    return out


params_st = st.builds(
    ContractParams,
    decay=st.floats(0.05, 0.95),
    radius=st.none() | st.floats(0, 6),
    softening=st.floats(0, 1),
    restrict_to_goals=st.booleans(),
    min_confidence=st.sampled_from([0.0, 0.5]) | st.floats(0, 1),
)

spaces = grids() | explicit_spaces()


def reference(space, objs, p: ContractParams):
    """The documented equations, written the slow and obvious way."""
    wv = p.role_values

    def on(x, o):
        return bool({tuple(c) for c in space.cells(x)} & {tuple(c) for c in o.cells})

    def members(x, role):
        return any(ROLE[o.category] == role and o.confidence >= p.min_confidence and on(x, o) for o in objs)

    def value(x):
        neg = [wv[ROLE[o.category]] * o.confidence for o in objs if on(x, o) and ROLE[o.category] == "undesirable"]
        if neg and min(neg) < 0:
            return min(neg)
        pos = [wv[ROLE[o.category]] * o.confidence for o in objs if on(x, o) and ROLE[o.category] != "undesirable"]
        return max(pos, default=0.0)

    def phi(x):
        total = 0.0
        for o in objs:
            ds = [abs(a[0] - b[0]) + abs(a[1] - b[1]) for a in space.cells(x) for b in o.cells]
            if not ds:
                continue
            d = min(ds)
            if p.radius is not None and d > p.radius:
                continue
            total += wv[ROLE[o.category]] * o.confidence * p.decay**d
        return max(-1.0, min(1.0, total))

    xs = list(space.contexts())
    every = set(xs) | {space.outcome(x, u) for x in xs for u in space.options(x)}
    xu = {x for x in every if members(x, "undesirable")}
    xg = {x for x in every if members(x, "desirable") or members(x, "critical")}
    adm, status, prior = {}, {}, {}
    for x in xs:
        opts = list(space.options(x))
        s = [u for u in opts if space.outcome(x, u) not in xu]
        g = [u for u in s if space.outcome(x, u) in xg] if (p.restrict_to_goals and xg) else s
        if not opts:
            adm[x], status[x] = [], ContextStatus.NO_OPTIONS
        elif not s:
            adm[x], status[x] = opts, ContextStatus.FALLBACK_NO_SAFE_OPTION
        elif not g:
            adm[x], status[x] = s, ContextStatus.FALLBACK_NO_GOAL_OPTION
        else:
            adm[x], status[x] = g, ContextStatus.OK
        prior[x] = {
            u: max(-1.0, min(1.0, value(space.outcome(x, u)) + p.softening * (phi(space.outcome(x, u)) - phi(x))))
            for u in opts
        }
    return adm, status, prior, {x: phi(x) for x in xs}, xu


@SETTINGS
@given(space=spaces, objs=objects(), p=params_st)
def test_invariants(space, objs, p):
    c = build_contract(objs, space, KB, p)
    assert len(c.contexts) == len(space.contexts())
    for x in c.contexts:
        opts, adm = c.options[x], c.admissible[x]
        assert set(adm) <= set(opts)  # U'(x) ⊆ U(x)
        assert len(set(adm)) == len(adm)
        if not adm:  # never silently empty
            assert opts == [] and c.status[x] == ContextStatus.NO_OPTIONS
        if c.status[x] == ContextStatus.FALLBACK_NO_SAFE_OPTION:
            assert adm == opts and all(c.outcomes[x][u] in c.x_u for u in opts)
        if c.status[x] in (ContextStatus.OK, ContextStatus.FALLBACK_NO_GOAL_OPTION):
            assert not any(c.outcomes[x][u] in c.x_u for u in adm)  # safety never traded
        assert -1.0 <= c.potentials[x] <= 1.0 and math.isfinite(c.potentials[x])
        assert set(c.priors[x]) == set(opts)
        assert all(-1.0 <= v <= 1.0 for v in c.priors[x].values())


@SETTINGS
@given(space=spaces, objs=objects(), p=params_st)
def test_matches_reference(space, objs, p):
    c = build_contract(objs, space, KB, p)
    adm, status, prior, phi, xu = reference(space, objs, p)
    for x in space.contexts():
        k = space.key(x)
        assert c.admissible[k] == [space.option_key(u) for u in adm[x]]
        assert c.status[k] == status[x]
        assert math.isclose(c.potentials[k], phi[x], abs_tol=1e-9)
        for u, v in prior[x].items():
            assert math.isclose(c.priors[k][space.option_key(u)], v, abs_tol=1e-9)
    assert set(c.x_u) == {space.key(x) for x in xu}


@SETTINGS
@given(space=grids(), objs=objects())
def test_pure_priors_take_role_values(space, objs):
    """With softening 0 a prior is exactly -c, 0 or +w·c of what stands on the outcome."""
    c = build_contract(objs, space, KB, ContractParams(softening=0.0))
    allowed = {0.0} | {round(-o.confidence if ROLE[o.category] == "undesirable" else
                             (0.5 if o.category == "safe_zone" else 1.0) * o.confidence, 12) for o in objs}
    for x in c.contexts:
        for v in c.priors[x].values():
            assert round(v, 12) in allowed

"""The contract transducer: beliefs × context space → priors, potentials, admissible options.

Definitions (all per :class:`~lucifer.contract.types.ContractParams`, defaults in brackets):

* A belief b (location, category, confidence c_b) has the role r_b of its category in the KB
  and the signed weight w_b = role_values[r_b] · c_b [critical +1, desirable +0.5,
  undesirable -1]. Beliefs whose category the KB lacks are ignored with a warning.
* Sets: x ∈ X_u (X_d, X_o) iff a belief of role undesirable (desirable, critical) with
  c_b ≥ min_confidence [0.5] stands on a cell of x.
* Value of a context, safety first: v(x) = min of w_b over undesirable beliefs on x if there is
  one, else the max of w_b over desirable/critical beliefs on x, else 0.
* Potential: Φ(x) = clip(Σ_b w_b · λ^d(x,b), -1, 1), d(x,b) the space's distance between
  the nearest cells of x and b [Manhattan], λ = decay [0.5]; terms with d > radius dropped.
  Attractive (positive) around desirable/critical beliefs, repulsive around undesirable ones.
* Prior: Ψ_x(u) = clip(v(f(x,u)) + s · (Φ(f(x,u)) − Φ(x)), -1, 1), s = softening [0.5].
  With s = 0 this is the paper's prior: w toward desirable/critical, -1 toward undesirable,
  0 toward neutral outcomes.
* Admissible options, the paper's equation with both cases combined:

      S(x) = {u ∈ U(x) | f(x,u) ∉ X_u}                      (S(x) = U(x) if X_u = ∅)
      G(x) = {u ∈ S(x) | f(x,u) ∈ X_d ∪ X_o}                (only if X_d ∪ X_o ≠ ∅)
      U'(x) = G(x)  if X_d ∪ X_o ≠ ∅ and G(x) ≠ ∅                    status ok
            = S(x)  if X_d ∪ X_o ≠ ∅, G(x) = ∅, S(x) ≠ ∅    status fallback_no_goal_option
            = S(x)  if X_d ∪ X_o = ∅ and S(x) ≠ ∅                    status ok
            = U(x)  if S(x) = ∅ ≠ U(x)                      status fallback_no_safe_option
            = ∅     if U(x) = ∅                              status no_options

  When only one of X_u, X_d ∪ X_o is non-empty this is exactly that case of the paper's
  equation; when both are, the restriction is applied inside the exclusion (safety is never
  traded for an objective), and an empty intersection falls back to the exclusion alone,
  which is the first case of the paper's equation read top to bottom.

Invariants (property-tested): U'(x) ⊆ U(x); U'(x) = ∅ only with status no_options;
Ψ, Φ ∈ [-1, 1].

For RL loops use :func:`build_tables` (numpy only, no pydantic) or cache the contract:
a :class:`~lucifer.contract.beliefs.BeliefSession` rebuilds only when beliefs change.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal, TypeVar

import numpy as np

from lucifer.contract.space import ContextSpace, SpaceTable
from lucifer.contract.types import (
    STATUS_ORDER,
    Belief,
    ContextStatus,
    ContractParams,
    EquationCase,
    Provenance,
    SignalContract,
)
from lucifer.kb.models import Role
from lucifer.types import GroundedObject, GroundingResult

if TYPE_CHECKING:
    from lucifer.kb.loader import KnowledgeBase

_OK, _NO_GOAL, _NO_SAFE, _NONE = (STATUS_ORDER.index(s) for s in (
    ContextStatus.OK,
    ContextStatus.FALLBACK_NO_GOAL_OPTION,
    ContextStatus.FALLBACK_NO_SAFE_OPTION,
    ContextStatus.NO_OPTIONS,
))

F = TypeVar("F", float, np.ndarray)


def shaping(phi_x: F, phi_next: F, gamma: float = 0.99, terminal: bool = False) -> F:
    """Potential-based shaping reward F = γ·Φ(x') − Φ(x) (Ng et al. 1999).

    Adding F to the client's reward leaves its optimal policies unchanged. At a terminal
    transition Φ(x') is taken as 0. Works on floats and numpy arrays alike.

    >>> shaping(0.25, 0.5, gamma=0.5)
    0.0
    >>> shaping(0.25, 0.5, gamma=1.0, terminal=True)
    -0.25
    >>> shaping(np.array([0.0, 0.5]), np.array([0.5, 0.0]), gamma=1.0)
    array([ 0.5, -0.5])
    """
    nxt = 0.0 * phi_next if terminal else phi_next
    return gamma * nxt - phi_x


@dataclass(frozen=True, eq=False)
class ContractTables:
    """The contract as numpy arrays indexed like ``space.table()`` (rows = X, cols = options).

    ``prior`` is 0 and ``admissible`` False where an option is not in U(x). ``status`` holds
    indexes into :data:`~lucifer.contract.types.STATUS_ORDER`.
    """

    space: SpaceTable
    phi: np.ndarray  # (n,)
    prior: np.ndarray  # (n, m)
    admissible: np.ndarray  # (n, m) bool
    status: np.ndarray  # (n,) int8
    value: np.ndarray  # (n_ext,) v(x)
    member_u: np.ndarray  # (n_ext,) bool
    member_d: np.ndarray
    member_o: np.ndarray
    rule: EquationCase
    beliefs: tuple[Belief, ...] = ()
    located: dict[int, list[int]] = field(default_factory=dict)  # ext row -> belief idx
    influence: np.ndarray | None = None  # (n_ext, B) potential terms
    warnings: tuple[str, ...] = ()

    def shaping(self, i: int, i_next: int, gamma: float = 0.99, terminal: bool = False) -> float:
        """F for a transition between context rows i → i_next."""
        return float(shaping(float(self.phi[i]), float(self.phi[i_next]), gamma, terminal))


# --- inputs -----------------------------------------------------------------------------


def _span(s: Any) -> tuple[int, int] | None:
    return None if s is None else (int(s.start), int(s.end))


def provenance_of(
    obj: GroundedObject,
    report_id: str | None,
    trace_id: str | None,
    kind: Literal["claim", "confirmation", "denial"] = "claim",
) -> Provenance:
    """The provenance record of one grounded object."""
    return Provenance(
        report_id=report_id,
        trace_id=trace_id,
        span=_span(obj.span),
        text=obj.entity,
        cue=obj.cue,
        cue_span=_span(obj.cue_span),
        confidence=obj.confidence,
        kind=kind,
    )


def cells_of_object(obj: GroundedObject, kb: KnowledgeBase | None) -> list[tuple[int, int]]:
    """The object's own cells, else its KB landmark's cells, else none."""
    if obj.cells:
        return [(int(c[0]), int(c[1])) for c in obj.cells]
    if kb is not None and obj.location in kb.landmark_by_name:
        return [tuple(c) for c in kb.cells_of(obj.location)]  # type: ignore[misc]
    return []


def beliefs_from_objects(
    objects: Iterable[GroundedObject],
    kb: KnowledgeBase | None = None,
    *,
    report_id: str | None = None,
    trace_id: str | None = None,
) -> list[Belief]:
    """One belief per (location, category), confidence = the highest object confidence.

    Used when a contract is built straight from one grounding result (no session): the
    objects are taken as they are, with no trust discount.
    """
    merged: dict[tuple[str, str], Belief] = {}
    for obj in objects:
        key = (obj.location, obj.category)
        prov = provenance_of(obj, report_id, trace_id)
        old = merged.get(key)
        if old is None:
            merged[key] = Belief(
                id=f"b{len(merged) + 1}",
                location=obj.location,
                category=obj.category,
                cells=cells_of_object(obj, kb),
                confidence=obj.confidence,
                provenance=[prov],
            )
        else:
            merged[key] = old.model_copy(
                update={"confidence": max(old.confidence, obj.confidence), "provenance": [*old.provenance, prov]}
            )
    return list(merged.values())


def as_beliefs(source: Any, kb: KnowledgeBase | None = None) -> list[Belief]:
    """Normalise a grounding result, a list of objects or beliefs, or a session."""
    if isinstance(source, GroundingResult):
        return beliefs_from_objects(source.objects, kb, report_id=source.report_id, trace_id=source.trace_id)
    if hasattr(source, "active_beliefs"):
        return list(source.active_beliefs())
    items = list(source)
    if all(isinstance(b, Belief) for b in items):
        return [b for b in items if b.state == "active"]
    if all(isinstance(o, GroundedObject) for o in items):
        return beliefs_from_objects(items, kb)
    raise TypeError("expected a GroundingResult, GroundedObjects, Beliefs or a BeliefSession")


# --- the transducer ---------------------------------------------------------------------


def build_tables(
    source: Any,
    space: ContextSpace,
    kb: KnowledgeBase,
    params: ContractParams | None = None,
) -> ContractTables:
    """Compute the contract as numpy tables (no pydantic; the fast path for RL loops)."""
    p = params or ContractParams()
    beliefs = as_beliefs(source, kb)
    st = space.table()
    warnings: list[str] = []

    roles: list[Role] = []
    used: list[Belief] = []
    for b in beliefs:
        cat = kb.category_by_name.get(b.category)
        if cat is None:
            warnings.append(f"belief {b.id} ({b.location}: {b.category}): category not in the KB; ignored")
            continue
        if not b.cells:
            warnings.append(f"belief {b.id} ({b.location}: {b.category}): no map cells; ignored")
            continue
        used.append(b)
        roles.append(cat.role)

    n, n_ext = st.n, len(st.ext)
    nb = len(used)
    w = np.array([p.role_values[r] * b.confidence for r, b in zip(roles, used, strict=True)], dtype=float)
    strong = np.array([b.confidence >= p.min_confidence for b in used], dtype=bool)
    is_u = np.array([r == Role.UNDESIRABLE for r in roles], dtype=bool)
    is_d = np.array([r == Role.DESIRABLE for r in roles], dtype=bool)
    is_o = np.array([r == Role.CRITICAL for r in roles], dtype=bool)

    # Which beliefs stand on which context: a cell overlap test, (n_ext, B).
    if nb:
        q = np.array([c for b in used for c in b.cells], dtype=np.int64).reshape(-1, 2)
        starts = np.concatenate([[0], np.cumsum([len(b.cells) for b in used])[:-1]])
        cc, cv = st.cell_coords, st.cell_valid  # (n_ext, k, 2), (n_ext, k)
        same = (cc[:, :, None, :] == q[None, None, :, :]).all(-1) & cv[:, :, None]  # (n_ext,k,L)
        on_cell = same.any(1)  # (n_ext, L)
        on = np.logical_or.reduceat(on_cell, starts, axis=1)  # (n_ext, B)
        d = np.asarray(space.distance(cc[:, :, None, :], q[None, None, :, :]), dtype=float)
        d = np.where(cv[:, :, None], d, np.inf).min(1)  # (n_ext, L)
        d = np.minimum.reduceat(d, starts, axis=1)  # (n_ext, B)
        infl = w[None, :] * np.power(p.decay, d)
        if p.radius is not None:
            infl = np.where(d <= p.radius, infl, 0.0)
        infl = np.where(np.isfinite(d), infl, 0.0)
        phi_ext = np.clip(infl.sum(1), -1.0, 1.0)
        neg = np.where(on & is_u[None, :], w[None, :], 0.0).min(1)
        pos = np.where(on & ~is_u[None, :], w[None, :], 0.0).max(1)
        value = np.where(neg < 0, neg, pos)
        member_u = (on & (is_u & strong)[None, :]).any(1)
        member_d = (on & (is_d & strong)[None, :]).any(1)
        member_o = (on & (is_o & strong)[None, :]).any(1)
    else:
        on = np.zeros((n_ext, 0), dtype=bool)
        infl = np.zeros((n_ext, 0))
        phi_ext = np.zeros(n_ext)
        value = np.zeros(n_ext)
        member_u = member_d = member_o = np.zeros(n_ext, dtype=bool)

    avail = st.available
    nxt = np.where(avail, st.next, 0)
    phi = phi_ext[:n]
    if n_ext:
        prior = value[nxt] + p.softening * (phi_ext[nxt] - phi[:, None])
        prior = np.where(avail, np.clip(prior, -1.0, 1.0), 0.0)
    else:
        prior = np.zeros(avail.shape)

    has_u = bool(member_u.any())
    member_g = member_d | member_o
    has_g = p.restrict_to_goals and bool(member_g.any())
    safe = avail & ~member_u[nxt] if has_u else avail
    goal = safe & member_g[nxt] if has_g else safe
    n_avail, n_safe, n_goal = avail.sum(1), safe.sum(1), goal.sum(1)
    status = np.full(n, _OK, dtype=np.int8)
    adm = np.where((n_goal > 0)[:, None], goal, safe)
    if has_g:
        status[(n_goal == 0) & (n_safe > 0)] = _NO_GOAL
    no_safe = (n_safe == 0) & (n_avail > 0)
    adm = np.where(no_safe[:, None], avail, adm)
    status[no_safe] = _NO_SAFE
    status[n_avail == 0] = _NONE

    rule = {
        (False, False): EquationCase.NONE,
        (True, False): EquationCase.EXCLUDE_UNDESIRABLE,
        (False, True): EquationCase.RESTRICT_TO_GOALS,
        (True, True): EquationCase.EXCLUDE_AND_RESTRICT,
    }[(has_u, has_g)]
    rows_, cols_ = np.nonzero(on)
    located: dict[int, list[int]] = {}
    for i, j in zip(rows_.tolist(), cols_.tolist(), strict=True):
        located.setdefault(i, []).append(j)
    return ContractTables(
        space=st,
        phi=phi,
        prior=prior,
        admissible=adm,
        status=status,
        value=value,
        member_u=member_u,
        member_d=member_d,
        member_o=member_o,
        rule=rule,
        beliefs=tuple(used),
        located=located,
        influence=infl,
        warnings=tuple(warnings),
    )


def contract_from_tables(t: ContractTables, space: ContextSpace, params: ContractParams) -> SignalContract:
    """Wrap tables into the pydantic :class:`SignalContract` with provenance."""
    st = t.space
    keys, okeys = st.keys, st.option_keys
    n = st.n
    ids = [b.id for b in t.beliefs]
    member = t.member_u | t.member_d | t.member_o
    options: dict[str, list[str]] = {}
    outcomes: dict[str, dict[str, str]] = {}
    admissible: dict[str, list[str]] = {}
    priors: dict[str, dict[str, float]] = {}
    adm_src: dict[str, list[str]] = {}
    # Plain lists once: per-row numpy calls dominate on large spaces.
    prior_l, adm_l, next_l = t.prior.tolist(), t.admissible.tolist(), st.next.tolist()
    if st.order is not None:
        cols = [list(o) for o in st.order]
    else:
        avail_l = st.available.tolist()
        cols = [[j for j, a in enumerate(row) if a] for row in avail_l]
    strong_at: dict[int, list[int]] = {}  # ext row -> strong belief idx standing there
    member_l = member.tolist()
    for y, bs in t.located.items():
        if member_l[y]:
            strong_at[y] = [bi for bi in bs if t.beliefs[bi].confidence >= params.min_confidence]
    for i in range(n):
        x = keys[i]
        js = cols[i]
        nx, pr, ad = next_l[i], prior_l[i], adm_l[i]
        options[x] = [okeys[j] for j in js]
        outcomes[x] = {okeys[j]: keys[nx[j]] for j in js}
        admissible[x] = [okeys[j] for j in js if ad[j]]
        priors[x] = {okeys[j]: pr[j] for j in js}
        src = {bi for j in js for bi in strong_at.get(nx[j], ())}
        adm_src[x] = [ids[bi] for bi in sorted(src)]
    located = {keys[i]: [ids[b] for b in bs] for i, bs in t.located.items()}
    pot_src: dict[str, list[str]] = {k: [] for k in keys[:n]}
    if t.influence is not None and t.influence.size:
        for i, b in zip(*np.nonzero(np.abs(t.influence[:n]) > 1e-12), strict=True):
            pot_src[keys[i]].append(ids[b])
    contract = SignalContract(
        space=space.describe(),
        rule=t.rule,
        contexts=list(keys[:n]),
        options=options,
        outcomes=outcomes,
        admissible=admissible,
        status={keys[i]: STATUS_ORDER[s] for i, s in enumerate(t.status.tolist())},
        priors=priors,
        potentials=dict(zip(keys[:n], t.phi.tolist(), strict=True)),
        x_u=[keys[i] for i in np.flatnonzero(t.member_u).tolist()],
        x_d=[keys[i] for i in np.flatnonzero(t.member_d).tolist()],
        x_o=[keys[i] for i in np.flatnonzero(t.member_o).tolist()],
        beliefs=list(t.beliefs),
        located=located,
        potential_sources=pot_src,
        admissible_sources=adm_src,
        warnings=list(t.warnings),
        params=params,
    )
    contract._tables = t
    return contract


def build_contract(
    source: Any,
    space: ContextSpace,
    kb: KnowledgeBase,
    params: ContractParams | None = None,
) -> SignalContract:
    """Build the Signal Contract.

    ``source``: a :class:`~lucifer.types.GroundingResult`, a list of
    :class:`~lucifer.types.GroundedObject` or of :class:`Belief`, or a
    :class:`~lucifer.contract.beliefs.BeliefSession` (its current beliefs).
    """
    p = params or ContractParams()
    return contract_from_tables(build_tables(source, space, kb, p), space, p)

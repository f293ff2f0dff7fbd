"""Pydantic types of the Signal Contract: beliefs with provenance, parameters, the contract.

Every value in a :class:`SignalContract` traces back to beliefs (``beliefs``), and every
belief carries :class:`Provenance` records: the report id, the character span of the words
that produced it, and the grounding trace id. Context and option identifiers are strings
(``ContextSpace.key`` / ``ContextSpace.option_key``) so a contract is plain JSON.
"""

from __future__ import annotations

from enum import StrEnum
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, field_validator

from lucifer.kb.models import Role

SpanT = tuple[int, int]


class ContextStatus(StrEnum):
    """How U'(x) was obtained for one context; never an empty set without saying so."""

    OK = "ok"
    """The constraint equation applied as written and left at least one option."""
    FALLBACK_NO_GOAL_OPTION = "fallback_no_goal_option"
    """X_d ∪ X_o is non-empty but no safe option of x leads into it in one step: U'(x) falls
    back to the X_u exclusion alone, {u ∈ U(x) | f(x,u) ∉ X_u} (U(x) when X_u is empty)."""
    FALLBACK_NO_SAFE_OPTION = "fallback_no_safe_option"
    """Every option of x leads into X_u: U'(x) falls back to U(x); the priors of those options
    are negative, so the client still sees the danger."""
    NO_OPTIONS = "no_options"
    """The client's U(x) is empty (a terminal context): U'(x) = ∅ because U(x) = ∅."""


STATUS_ORDER: tuple[ContextStatus, ...] = tuple(ContextStatus)
"""Integer code of each status in :attr:`ContractTables.status` (index in this tuple)."""


class EquationCase(StrEnum):
    """Which case of the paper's constraint equation the contract applied (global)."""

    NONE = "none"  # X_u = ∅ and X_d ∪ X_o = ∅: U'(x) = U(x)
    EXCLUDE_UNDESIRABLE = "exclude_undesirable"  # only X_u ≠ ∅ (or restriction disabled)
    RESTRICT_TO_GOALS = "restrict_to_goals"  # only X_d ∪ X_o ≠ ∅
    EXCLUDE_AND_RESTRICT = "exclude_and_restrict"  # both: intersection, with fallbacks


class BeliefState(StrEnum):
    ACTIVE = "active"
    RETRACTED = "retracted"  # an explicit denial removed it ("the fire is out")
    SUPERSEDED = "superseded"  # a conflicting claim on the same place replaced it


class Provenance(BaseModel):
    """Where one piece of evidence came from."""

    model_config = ConfigDict(frozen=True)

    report_id: str | None = Field(description="Id of the report that said it.")
    trace_id: str | None = Field(description="Grounding trace id (`lucifer trace show ID`).")
    span: SpanT | None = Field(description="[start, end) of the words naming the place.")
    text: str = Field(description="Those words.")
    cue: str | None = Field(default=None, description="The words that gave the category.")
    cue_span: SpanT | None = None
    confidence: float = Field(ge=0.0, le=1.0, description="Grounding confidence of the claim.")
    kind: Literal["claim", "confirmation", "denial"] = "claim"


class Belief(BaseModel):
    """A (location, category) claim held with a confidence, and the evidence behind it."""

    model_config = ConfigDict(frozen=True)

    id: str
    location: str
    category: str
    cells: list[SpanT] = Field(description="KB grid cells [row, col] of the location.")
    confidence: float = Field(ge=0.0, le=1.0)
    state: BeliefState = BeliefState.ACTIVE
    provenance: list[Provenance] = Field(default_factory=list)
    replaces: list[str] = Field(default_factory=list, description="Ids of beliefs it superseded.")
    superseded_by: str | None = None


def _default_role_values() -> dict[Role, float]:
    return {Role.CRITICAL: 1.0, Role.DESIRABLE: 0.5, Role.UNDESIRABLE: -1.0}


class ContractParams(BaseModel):
    """Knobs of the transducer; the defaults are the documented contract.

    * ``role_values`` w_r: signed weight of each role. Critical +1, desirable +0.5 (objectives
      outrank mere safety), undesirable -1. A belief contributes ``w_r · confidence``.
    * ``decay`` λ: potential term of a belief at distance d is ``w_r · c · λ**d``.
    * ``radius``: beliefs farther than this contribute nothing to Φ (None: no cut-off).
    * ``softening`` s: priors add ``s · (Φ(f(x,u)) − Φ(x))`` to the role value of the outcome,
      so options that move toward objectives (or away from hazards) lean positive even when
      their outcome holds nothing. ``0`` gives the paper's pure {-1, 0, +w} priors.
    * ``restrict_to_goals``: apply the X_d ∪ X_o restriction case of the equation (paper).
      False keeps only the X_u exclusion.
    * ``min_confidence``: a belief puts its contexts into X_u / X_d / X_o only when its
      confidence is at least this; weaker beliefs still shape Φ and Ψ.
    """

    model_config = ConfigDict(extra="forbid", frozen=True)

    role_values: dict[Role, float] = Field(default_factory=_default_role_values)
    decay: float = Field(default=0.5, gt=0.0, lt=1.0)
    radius: float | None = Field(default=None, ge=0.0)
    softening: float = Field(default=0.5, ge=0.0, le=1.0)
    restrict_to_goals: bool = True
    min_confidence: float = Field(default=0.5, ge=0.0, le=1.0)

    @field_validator("role_values")
    @classmethod
    def _roles(cls, v: dict[Role, float]) -> dict[Role, float]:
        full = {**_default_role_values(), **v}
        for role, w in full.items():
            if not -1.0 <= w <= 1.0:
                raise ValueError(f"role value of {role.value} must be in [-1, 1], got {w}")
            if role == Role.UNDESIRABLE and w > 0 or role != Role.UNDESIRABLE and w < 0:
                raise ValueError(f"role value of {role.value} has the wrong sign: {w}")
        return full


class SignalContract(BaseModel):
    """The Signal Contract for one context space and one set of beliefs.

    ``priors[x][u]`` Ψ_x(u) ∈ [-1, 1]; ``potentials[x]`` Φ(x) ∈ [-1, 1]; ``admissible[x]``
    U'(x) ⊆ ``options[x]`` = U(x), with ``status[x]`` saying how it was obtained;
    ``outcomes[x][u]`` = f(x, u). Provenance: ``located[x]`` lists the beliefs whose cells
    overlap x (why x is in X_u/X_d/X_o), ``potential_sources[x]`` the beliefs that shape Φ(x),
    ``admissible_sources[x]`` the set members at the outcomes of x that the rule looked at;
    each id resolves in ``beliefs`` to its :class:`Provenance` records. Use
    :meth:`explain` to get them directly.
    """

    model_config = ConfigDict(frozen=True)

    space: str = Field(description="Human description of the context space.")
    rule: EquationCase
    contexts: list[str]
    options: dict[str, list[str]]
    outcomes: dict[str, dict[str, str]]
    admissible: dict[str, list[str]]
    status: dict[str, ContextStatus]
    priors: dict[str, dict[str, float]]
    potentials: dict[str, float]
    x_u: list[str] = Field(description="Undesirable contexts X_u.")
    x_d: list[str] = Field(description="Desirable contexts X_d.")
    x_o: list[str] = Field(description="Critical contexts (objectives) X_o.")
    beliefs: list[Belief]
    located: dict[str, list[str]]
    potential_sources: dict[str, list[str]]
    admissible_sources: dict[str, list[str]]
    warnings: list[str] = Field(default_factory=list)
    params: ContractParams

    _tables: Any = PrivateAttr(default=None)

    @property
    def tables(self) -> Any:
        """The numpy tables the contract was built from (:class:`ContractTables`)."""
        return self._tables

    def belief(self, belief_id: str) -> Belief:
        for b in self.beliefs:
            if b.id == belief_id:
                return b
        raise KeyError(belief_id)

    def explain(self, x: str, u: str | None = None) -> list[Provenance]:
        """Provenance behind the signals of context ``x`` (and option ``u``, if given).

        For a context: beliefs located at x and those shaping Φ(x). For an option: also the
        beliefs located at its outcome f(x, u) (what its prior and admissibility rest on).
        """
        ids = [*self.located.get(x, []), *self.potential_sources.get(x, [])]
        if u is not None:
            nxt = self.outcomes[x][u]
            ids += [*self.located.get(nxt, []), *self.potential_sources.get(nxt, [])]
        seen: dict[str, None] = dict.fromkeys(ids)
        return [p for bid in seen for p in self.belief(bid).provenance]

    def to_json_dict(self) -> dict[str, Any]:
        """Plain-JSON form (what ``lucifer ground --json --signals`` prints)."""
        return self.model_dump(mode="json")


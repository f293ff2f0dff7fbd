"""Pydantic models of the knowledge-base files (SPEC §1).

A knowledge base is hand-edited YAML, i.e. untrusted input: every field is validated here and
every cross-file rule is checked in :mod:`lucifer.kb.loader`.
"""

from __future__ import annotations

from enum import StrEnum

from pydantic import BaseModel, ConfigDict, Field, field_validator


class Role(StrEnum):
    """Role of a category in the Information Space (X_u, X_d, X_o in the paper)."""

    UNDESIRABLE = "undesirable"
    DESIRABLE = "desirable"
    CRITICAL = "critical"


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


def _clean_name(value: str) -> str:
    value = " ".join(str(value).split())
    if not value:
        raise ValueError("must be a non-empty string")
    return value


class Category(_Strict):
    name: str = Field(description="Identifier used everywhere else, e.g. 'hazard'.")
    role: Role = Field(description="undesirable | desirable | critical")
    description: str = Field(default="", description="What the category means, in plain words.")

    _n = field_validator("name")(classmethod(lambda cls, v: _clean_name(v)))


class InformationSpace(_Strict):
    categories: list[Category] = Field(min_length=1)


class Grid(_Strict):
    rows: int = Field(gt=0, le=1000)
    cols: int = Field(gt=0, le=1000)


Cell = tuple[int, int]


class Landmark(_Strict):
    name: str = Field(description="Canonical name, unique in the KB.")
    aliases: list[str] = Field(default_factory=list)
    cells: list[Cell] = Field(min_length=1, description="Cells [row, col] the landmark covers.")
    description: str = ""

    _n = field_validator("name")(classmethod(lambda cls, v: _clean_name(v)))

    @field_validator("aliases")
    @classmethod
    def _aliases(cls, v: list[str]) -> list[str]:
        return [_clean_name(a) for a in v]

    @property
    def surface_forms(self) -> list[str]:
        """The canonical name followed by every alias."""
        return [self.name, *self.aliases]


class Relation(_Strict):
    subject: str
    relation: str
    object: str

    _n = field_validator("subject", "relation", "object")(
        classmethod(lambda cls, v: _clean_name(v))
    )

    @property
    def phrase(self) -> str:
        """The relation name as words: ``attached_to`` -> ``attached to``."""
        return " ".join(self.relation.replace("_", " ").replace("-", " ").split()).lower()


class MapFile(_Strict):
    grid: Grid
    landmarks: list[Landmark] = Field(min_length=1)
    relations: list[Relation] = Field(default_factory=list)


class GlossaryTerm(_Strict):
    term: str
    category: str

    _n = field_validator("term", "category")(classmethod(lambda cls, v: _clean_name(v)))


class Glossary(_Strict):
    terms: list[GlossaryTerm] = Field(default_factory=list)


class QueryOption(_Strict):
    """An information-gathering query a client can run at an information location."""

    name: str
    description: str = Field(default="", description="What the query finds and when it helps.")
    info_type: str | None = Field(
        default=None,
        description="Optional: the mission information the query reveals (victim | hazard | safe_route).",
    )
    cues: list[str] = Field(
        default_factory=list,
        description="Optional example observations that call for this query; matched like the description.",
    )

    _n = field_validator("name")(classmethod(lambda cls, v: _clean_name(v)))


class QueryOptions(_Strict):
    options: list[QueryOption] = Field(default_factory=list)

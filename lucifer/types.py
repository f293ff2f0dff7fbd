"""Contract-facing result types shared by grounding, the contract transducer and clients."""

from __future__ import annotations

from enum import StrEnum
from typing import Any

from pydantic import BaseModel, ConfigDict, Field


class Status(StrEnum):
    """Outcome of one grounding run, carried on every result."""

    OK = "ok"  # the configured backend produced valid output
    RETRIED = "retried"  # valid output after validation retries
    LLM_TIMEOUT = "llm_timeout"  # chat model timed out; builtin fallback objects returned
    LLM_UNAVAILABLE = "llm_unavailable"  # connection refused / model missing; builtin fallback
    LLM_INVALID = "llm_invalid"  # still invalid after the retry cap; builtin fallback
    LLM_ERROR = "llm_error"  # any other chat-model failure; builtin fallback
    EMPTY_REPORT = "empty_report"


class Span(BaseModel):
    """Character span [start, end) in the report text."""

    model_config = ConfigDict(frozen=True)
    start: int
    end: int


class GroundedObject(BaseModel):
    """One contract object: a KB landmark claimed to be in an Information Space category."""

    model_config = ConfigDict(frozen=True)

    entity: str = Field(description="The words of the report that refer to the place.")
    category: str = Field(description="A category name from the Information Space.")
    location: str = Field(description="Canonical landmark name from the knowledge base.")
    cells: list[list[int]] = Field(description="Grid cells [row, col] of the landmark.")
    span: Span | None = Field(default=None, description="Where `entity` is in the report.")
    cue: str | None = Field(default=None, description="The words that gave the category.")
    cue_span: Span | None = None
    confidence: float = Field(default=1.0, ge=0.0, le=1.0)
    via: str | None = Field(default=None, description="KB relation used to reach the place, if any.")

    def spec_dict(self) -> dict[str, Any]:
        """The SPEC §2 form of the object."""
        return {"entity": self.entity, "category": self.category, "location": self.location, "cells": self.cells}


class GroundingResult(BaseModel):
    report: str
    objects: list[GroundedObject] = Field(default_factory=list)
    trace_id: str
    status: Status = Status.OK
    backend: str = "builtin"
    report_id: str | None = None
    denied: list[GroundedObject] = Field(
        default_factory=list,
        description="Claims the report explicitly denies or revokes ('the fire at the bakery is out'). "
        "Not part of SPEC §2 objects; belief maintenance uses them to revise earlier reports.",
    )
    errors: list[str] = Field(default_factory=list, description="Why a fallback happened, if one did.")
    latency_s: float = 0.0

    def spec_dict(self) -> dict[str, Any]:
        return {
            "report": self.report,
            "objects": [o.spec_dict() for o in self.objects],
            "trace_id": self.trace_id,
            "status": self.status.value,
            "backend": self.backend,
        }

"""State of the grounding graph.

Input and output schemas are narrow (a report in, validated objects out); the working state in
between is internal. Values are plain JSON-able data so the SQLite checkpointer can store them.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass, field
from typing import Annotated, Any


@dataclass
class GroundingInput:
    report: str
    report_id: str | None = None


@dataclass
class GroundingOutput:
    objects: list[dict[str, Any]] = field(default_factory=list)
    denied: list[dict[str, Any]] = field(default_factory=list)
    status: str = "ok"
    errors: list[str] = field(default_factory=list)


@dataclass
class GroundingState:
    report: str
    report_id: str | None = None
    # retrieve
    retrieved: list[dict[str, Any]] = field(default_factory=list)
    # extract: place mentions with a status (active / retracted / negated / reference) and repair markers
    places: list[dict[str, Any]] = field(default_factory=list)
    markers: list[list[Any]] = field(default_factory=list)
    relation_tokens: list[int] = field(default_factory=list)  # words of a relation between two named places
    # classify: category cues and (entity, location, category) candidates
    cues: list[dict[str, Any]] = field(default_factory=list)
    candidates: list[dict[str, Any]] = field(default_factory=list)
    denied_candidates: list[dict[str, Any]] = field(default_factory=list)
    # ground
    grounded: list[dict[str, Any]] = field(default_factory=list)
    # validate
    objects: list[dict[str, Any]] = field(default_factory=list)
    denied: list[dict[str, Any]] = field(default_factory=list)
    rejected: list[dict[str, Any]] = field(default_factory=list)
    validation_errors: list[str] = field(default_factory=list)
    attempts: int = 0
    status: str = "ok"
    errors: Annotated[list[str], operator.add] = field(default_factory=list)
    # one entry per node run: what it read and what it wrote (shown by `lucifer trace show`)
    trace: Annotated[list[dict[str, Any]], operator.add] = field(default_factory=list)

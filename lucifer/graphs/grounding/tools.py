"""The tool a chat model calls to return its extraction (its schema is what the LLM sees)."""

from __future__ import annotations

from pydantic import BaseModel, Field


class ReportObject(BaseModel):
    entity: str = Field(description="The exact words of the report that name the place.")
    location: str = Field(description="Canonical landmark name from the knowledge base context.")
    category: str = Field(description="One category name from the Information Space.")


class ReportObjects(BaseModel):
    """Record every place the report makes a claim about, after applying the speaker's corrections."""

    objects: list[ReportObject] = Field(
        default_factory=list,
        description="One entry per (place, category) claim. Leave out places the speaker retracted, "
        "negated, or only used as a reference point. Empty if nothing is claimed.",
    )


TOOL_NAME = ReportObjects.__name__

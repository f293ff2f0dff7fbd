"""Per-run settings of the grounding graph, read by nodes through the LangGraph runtime."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from lucifer.graphs.grounding.resources import GroundingResources


@dataclass(kw_only=True)
class GroundingContext:
    model: str = field(
        default="builtin",
        metadata={"description": "Extraction backend: builtin, rule, ner, or a chat model as provider:model."},
    )
    top_k: int = field(default=8, metadata={"description": "KB documents retrieved per query."})
    max_retries: int = field(
        default=2, metadata={"description": "Validation failures sent back to extract before the fallback."}
    )
    timeout_s: float = field(default=60.0, metadata={"description": "Seconds before a chat-model call is abandoned."})
    resources: GroundingResources | Any = field(
        default=None, metadata={"description": "Loaded KB, analyzer, retriever and chat model (not serialised)."}
    )

"""Per-run settings of the discovery graph, read by nodes through the LangGraph runtime."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from lucifer.graphs.discovery.resources import DiscoveryResources

DEFAULT_TEMPERATURE = 1.0


@dataclass(kw_only=True)
class DiscoveryContext:
    model: str = field(
        default="builtin",
        metadata={"description": "Backend: builtin (deterministic policy) or a chat model as provider:model."},
    )
    max_retries: int = field(
        default=2, metadata={"description": "Invalid answers sent back to the chat model before the fallback."}
    )
    max_tool_rounds: int = field(
        default=6, metadata={"description": "Tool-calling rounds a chat model may take before it must answer."}
    )
    timeout_s: float = field(default=60.0, metadata={"description": "Seconds before a chat-model call is abandoned."})
    neighbors_k: int = field(default=5, metadata={"description": "Known signatures returned by similar_signatures."})
    clause_k: int = field(default=8, metadata={"description": "Nearest known clauses pooled per query clause."})
    clause_tau: float = field(
        default=0.05, metadata={"description": "Softmax temperature over clause similarities in the kNN pooling."}
    )
    prior_strength: float = field(
        default=1.0, metadata={"description": "Pseudo-records pulling outcome rates towards the option's prior."}
    )
    memory_weight: float = field(
        default=1.0,
        metadata={"description": "Weight of log(share of similar known clauses where the option worked best)."},
    )
    vote_smoothing: float = field(default=0.02, metadata={"description": "Added to the shares before the log."})
    prototype_weight: float = field(
        default=16.0, metadata={"description": "Weight of cosine(signature clause, option prototype from memory)."}
    )
    semantic_weight: float = field(
        default=4.0, metadata={"description": "Weight of cosine(signature clause, option description)."}
    )
    exact_weight: float = field(
        default=2.0,
        metadata={
            "description": "Log-odds per record at exactly this signature (+ per success, - per failure); "
            "about log(0.9 / 0.1): a right query succeeds about 9 times in 10."
        },
    )
    temperature: float = field(
        default=DEFAULT_TEMPERATURE,
        metadata={"description": "Confidence temperature, fitted on the calibration split (calibration.json)."},
    )
    temperature_cold: float = field(
        default=DEFAULT_TEMPERATURE,
        metadata={"description": "Confidence temperature when memory offers no evidence (empty memory)."},
    )
    resources: DiscoveryResources | Any = field(
        default=None, metadata={"description": "KB options, telemetry memory, index and chat model (not serialised)."}
    )

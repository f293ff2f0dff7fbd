"""Request, result and working state of the discovery graph.

The request is untrusted JSON from a client, so it is a strict pydantic model; the result is
what ``lucifer discover`` prints. The working state in between stays internal to the graph.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass, field
from typing import Annotated, Any

from langchain_core.messages import AnyMessage
from langgraph.graph import add_messages
from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from lucifer.types import Status


class TraceStep(BaseModel):
    """A structured step of the episodic trace: a query already run in this episode."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    option: str = Field(min_length=1, max_length=200, description="The query option that was run.")
    outcome: float = Field(ge=0.0, le=1.0, description="1 = it found the information.")
    signature: str | None = Field(
        default=None, max_length=1000, description="Where it ran; omitted = at the current location."
    )
    note: str = Field(default="", max_length=500)

    def text(self) -> str:
        where = f" at '{self.signature}'" if self.signature else " here"
        return f"ran {self.option}{where}: outcome {self.outcome:g}" + (f" ({self.note})" if self.note else "")


def trace_text(step: str | TraceStep) -> str:
    return step if isinstance(step, str) else step.text()


class DiscoveryRequest(BaseModel):
    """One decision point: where the client is, what just happened, what it could ask."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    signature: str = Field(
        min_length=1,
        max_length=1000,
        description="Location signature x_t: a short text of what is observed at the location.",
    )
    trace: list[str | TraceStep] = Field(
        default_factory=list,
        max_length=50,
        description="Episodic trace xi: the last few steps of the episode, as short texts or "
        "structured steps {option, outcome, signature?} for queries already run in this episode.",
    )
    options: list[str] = Field(
        min_length=1,
        max_length=100,
        description="Candidate query options U(x_t): names from the knowledge base.",
    )
    request_id: str | None = Field(default=None, max_length=200)

    @field_validator("signature")
    @classmethod
    def _signature(cls, v: str) -> str:
        v = " ".join(v.split())
        if not v:
            raise ValueError("the signature is empty")
        return v

    @field_validator("trace", mode="before")
    @classmethod
    def _trace(cls, v: Any) -> Any:
        return [v] if isinstance(v, str) else v

    @model_validator(mode="after")
    def _unique_options(self) -> DiscoveryRequest:
        cleaned = [" ".join(o.split()) for o in self.options]
        if any(not o for o in cleaned):
            raise ValueError("an option name is empty")
        if len(set(cleaned)) != len(cleaned):
            raise ValueError("options must be unique")
        object.__setattr__(self, "options", cleaned)
        return self

    def episodic_outcomes(self) -> dict[str, tuple[int, float]]:
        """``option -> (runs, summed outcome)`` of trace steps run at this signature."""
        from lucifer.telemetry.memory import signature_key

        here = signature_key(self.signature)
        out: dict[str, tuple[int, float]] = {}
        for step in self.trace:
            if isinstance(step, TraceStep) and (step.signature is None or signature_key(step.signature) == here):
                n, t = out.get(step.option, (0, 0.0))
                out[step.option] = (n + 1, t + step.outcome)
        return out


class DiscoveryResult(BaseModel):
    """P(u | x_t, xi, D) over U(x_t), the recommendation u* and its confidence."""

    signature: str
    options: list[str]
    distribution: dict[str, float] = Field(description="Probability of each candidate option; sums to 1.")
    recommendation: str = Field(description="u*: the option to query.")
    confidence: float = Field(ge=0.0, le=1.0, description="Calibrated probability that u* is right.")
    status: Status = Status.OK
    backend: str = "builtin"
    known_signature: bool = Field(default=False, description="The signature is in telemetry memory.")
    tools_called: list[str] = Field(default_factory=list)
    errors: list[str] = Field(default_factory=list, description="Why a fallback happened, if one did.")
    request_id: str | None = None
    latency_s: float = 0.0

    def spec_dict(self) -> dict[str, Any]:
        return self.model_dump(mode="json")


@dataclass
class DiscoveryInput:
    request: DiscoveryRequest


@dataclass
class DiscoveryOutput:
    result: DiscoveryResult | None = None


@dataclass
class DiscoveryState:
    request: DiscoveryRequest
    messages: Annotated[list[AnyMessage], add_messages] = field(default_factory=list)
    # a candidate answer from the agent: {"distribution", "recommendation", "confidence"}
    proposal: dict[str, Any] | None = None
    invalid: str | None = None  # why the last proposal was rejected
    attempts: int = 0  # validation failures and retried model errors so far
    model_failed: bool = False  # the last chat-model call raised and will be retried
    tool_rounds: int = 0
    status: Status = Status.OK
    errors: Annotated[list[str], operator.add] = field(default_factory=list)
    result: DiscoveryResult | None = None

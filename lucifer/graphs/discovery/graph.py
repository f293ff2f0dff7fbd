"""The discovery graph: an agent that calls memory tools, then a validated recommendation.

    START -> plan_queries
    plan_queries    --tool calls-->                      run_tools --> plan_queries
    plan_queries    --model error, retries left-->       plan_queries
    plan_queries    --timeout / unreachable / errors-->  fall_back --> END
    plan_queries    --answer-->                          validate_answer
    validate_answer --valid-->                           END
    validate_answer --invalid, retries left-->           plan_queries
    validate_answer --invalid, cap reached-->            fall_back --> END

``plan_queries`` is the agent. With the ``builtin`` backend it deterministically asks for all
four tools, then turns their evidence into a distribution (:mod:`.policy`); with a chat model
it lets the model call tools and answer in JSON. ``validate_answer`` checks that the
recommendation is in U(x_t) and the distribution is over U(x_t); an invalid answer is sent back
(up to ``max_retries``), then ``fall_back`` computes the builtin answer from the same tools and
records why (``status``). A chat-model error is retried the same way (``plan_queries`` loops
to itself), a timeout or an unreachable model falls back at once; either way the status says
what happened.
"""

from __future__ import annotations

import asyncio
import json
import re
from typing import Any, Literal

from langchain_core.messages import AIMessage, HumanMessage, SystemMessage, ToolMessage
from langchain_core.tools import BaseTool
from langgraph.graph import END, START, StateGraph
from langgraph.prebuilt import ToolNode
from langgraph.runtime import Runtime
from pydantic import BaseModel, Field, ValidationError

from lucifer.graphs.discovery import policy
from lucifer.graphs.discovery.context import DiscoveryContext
from lucifer.graphs.discovery.prompts import SYSTEM_PROMPT, request_prompt, retry_prompt
from lucifer.graphs.discovery.state import (
    DiscoveryInput,
    DiscoveryOutput,
    DiscoveryRequest,
    DiscoveryResult,
    DiscoveryState,
)
from lucifer.graphs.discovery.tools import (
    OPTION_FIT,
    OPTION_STATS,
    SIGNATURE_OUTCOMES,
    SIMILAR_SIGNATURES,
)
from lucifer.types import Status


class ModelAnswer(BaseModel):
    """The JSON a chat model must answer with."""

    recommendation: str = Field(description="One option of U(x_t), spelled exactly.")
    distribution: dict[str, float] | None = Field(default=None, description="Probability per option.")
    confidence: float | None = Field(default=None, ge=0.0, le=1.0)


def builtin_tool_calls(request: DiscoveryRequest, ctx: DiscoveryContext) -> list[dict[str, Any]]:
    """The tool calls the builtin agent makes for a request (same tools a chat model sees)."""
    sig, opts = request.signature, list(request.options)
    return [
        {"name": SIGNATURE_OUTCOMES, "args": {"signature": sig}, "id": "builtin-0", "type": "tool_call"},
        {"name": SIMILAR_SIGNATURES, "args": {"signature": sig, "options": opts, "k": ctx.neighbors_k},
         "id": "builtin-1", "type": "tool_call"},
        {"name": OPTION_STATS, "args": {"options": opts}, "id": "builtin-2", "type": "tool_call"},
        {"name": OPTION_FIT, "args": {"signature": sig, "options": opts}, "id": "builtin-3", "type": "tool_call"},
    ]


def builtin_proposal(evidence: dict[str, dict[str, Any]], request: DiscoveryRequest, ctx: DiscoveryContext) -> dict[str, Any]:
    opts = list(request.options)
    logits = policy.builtin_logits(evidence, opts, ctx, request.episodic_outcomes())
    warm = policy.has_memory_evidence(evidence) or bool(request.episodic_outcomes())
    dist = policy.distribution(logits, opts, ctx.temperature if warm else ctx.temperature_cold)
    best, conf = policy.recommend(dist)
    return {"distribution": dist, "recommendation": best, "confidence": conf}


def _evidence(messages: list[Any], signature: str) -> dict[str, dict[str, Any]]:
    """Artifacts of successful tool calls about ``signature`` (latest wins), by tool name."""
    calls = {
        tc["id"]: tc
        for m in messages
        if isinstance(m, AIMessage)
        for tc in m.tool_calls
    }
    out: dict[str, dict[str, Any]] = {}
    for m in messages:
        if isinstance(m, ToolMessage) and m.status != "error" and isinstance(m.artifact, dict):
            args = calls.get(m.tool_call_id, {}).get("args", {})
            if args.get("signature", signature) == signature:
                out[m.name or calls.get(m.tool_call_id, {}).get("name", "")] = m.artifact
    return out


def _failure_status(exc: BaseException) -> Status:
    name = type(exc).__name__.lower()
    if isinstance(exc, TimeoutError | asyncio.TimeoutError) or "timeout" in name:
        return Status.LLM_TIMEOUT
    if isinstance(exc, ConnectionError) or "connect" in name:
        return Status.LLM_UNAVAILABLE
    return Status.LLM_ERROR


def _text(content: Any) -> str:
    if isinstance(content, str):
        return content
    if isinstance(content, list):
        return "".join(b if isinstance(b, str) else str(b.get("text", "")) for b in content)
    return str(content)


def parse_answer(content: Any) -> ModelAnswer:
    """The JSON object in a model's final message (code fences and chatter around it allowed)."""
    text = _text(content)
    m = re.search(r"\{.*\}", text, flags=re.S)
    if m is None:
        raise ValueError("no JSON object in the answer")
    try:
        data = json.loads(m.group(0))
    except json.JSONDecodeError as exc:
        raise ValueError(f"the answer is not valid JSON ({exc.msg})") from None
    try:
        return ModelAnswer.model_validate(data)
    except ValidationError as exc:
        raise ValueError("the answer does not match the schema: " + "; ".join(e["msg"] for e in exc.errors())) from None


# -- nodes -------------------------------------------------------------------------------


async def plan_queries(state: DiscoveryState, runtime: Runtime[DiscoveryContext]) -> dict[str, Any]:
    """The agent: request tool calls, or turn tool results into a proposal."""
    ctx = runtime.context
    res = ctx.resources
    request = state.request
    if res.chat_model is None:
        if not any(isinstance(m, ToolMessage) for m in state.messages):
            return {"messages": [AIMessage(content="", tool_calls=builtin_tool_calls(request, ctx))],
                    "tool_rounds": state.tool_rounds + 1}
        proposal = builtin_proposal(_evidence(state.messages, request.signature), request, ctx)
        return {"proposal": proposal, "messages": [AIMessage(content=json.dumps(proposal))]}

    new: list[Any] = []
    if not state.messages:
        new = [SystemMessage(SYSTEM_PROMPT), HumanMessage(request_prompt(request, res.options))]
    if state.invalid is not None:
        new.append(HumanMessage(retry_prompt(state.invalid, request)))
    messages = [*state.messages, *new]
    force_answer = state.tool_rounds >= ctx.max_tool_rounds
    model = res.chat_model if force_answer else res.bound_model()
    try:
        reply = await asyncio.wait_for(model.ainvoke(messages), timeout=ctx.timeout_s)
    except Exception as exc:  # any model failure becomes an explicit status: retry or fall back
        status = _failure_status(exc)
        error = f"chat model failed: {type(exc).__name__}: {exc}"
        if status == Status.LLM_ERROR and state.attempts < ctx.max_retries:
            return {"messages": new, "errors": [error], "attempts": state.attempts + 1, "model_failed": True}
        return {"messages": new, "status": status, "invalid": None, "errors": [error], "proposal": None,
                "model_failed": False}
    update: dict[str, Any] = {"messages": [*new, reply], "invalid": None, "proposal": None, "model_failed": False}
    if isinstance(reply, AIMessage) and reply.tool_calls and not force_answer:
        update["tool_rounds"] = state.tool_rounds + 1
        return update
    try:
        answer = parse_answer(reply.content)
    except ValueError as exc:
        update["invalid"] = str(exc)
        return update
    update["proposal"] = answer.model_dump()
    return update


async def validate_answer(state: DiscoveryState, runtime: Runtime[DiscoveryContext]) -> dict[str, Any]:
    """Accept a proposal over U(x_t), or say why not (counted against ``max_retries``)."""
    request = state.request
    reason = state.invalid
    result: DiscoveryResult | None = None
    if reason is None:
        reason, result = _check(state.proposal, request)
    if result is not None:
        status = Status.RETRIED if state.attempts else state.status
        result = result.model_copy(update=_result_meta(state, runtime.context, status))
        return {"result": result, "status": status}
    return {"invalid": reason, "attempts": state.attempts + 1, "errors": [f"invalid answer: {reason}"]}


def _check(proposal: dict[str, Any] | None, request: DiscoveryRequest) -> tuple[str | None, DiscoveryResult | None]:
    if proposal is None:
        return "no answer", None
    opts = list(request.options)
    rec = proposal.get("recommendation")
    if rec not in opts:
        return f"recommendation {rec!r} is not a candidate option", None
    raw = proposal.get("distribution") or {}
    outside = [o for o in raw if o not in opts]
    if outside:
        return f"the distribution names options outside U(x_t): {', '.join(map(repr, outside))}", None
    conf = proposal.get("confidence")
    dist = {o: max(0.0, float(raw.get(o, 0.0))) for o in opts}
    total = sum(dist.values())
    if total <= 0:
        c = 1.0 if conf is None else float(conf)
        rest = (1.0 - c) / (len(opts) - 1) if len(opts) > 1 else 0.0
        dist = {o: (c if o == rec else rest) for o in opts}
        total = sum(dist.values())
    dist = {o: v / total for o, v in dist.items()}
    if conf is None:
        conf = dist[rec]
    return None, DiscoveryResult(
        signature=request.signature,
        options=opts,
        distribution=dist,
        recommendation=rec,
        confidence=min(1.0, max(0.0, float(conf))),
    )


def _result_meta(state: DiscoveryState, ctx: DiscoveryContext, status: Status) -> dict[str, Any]:
    res = ctx.resources
    return {
        "status": status,
        "backend": ctx.model,
        "known_signature": res.index.is_known(state.request.signature),
        "tools_called": [tc["name"] for m in state.messages if isinstance(m, AIMessage) for tc in m.tool_calls],
        "errors": list(state.errors),
        "request_id": state.request.request_id,
    }


async def fall_back(state: DiscoveryState, runtime: Runtime[DiscoveryContext]) -> dict[str, Any]:
    """The builtin answer from the same tools, with the status saying why it was needed."""
    ctx = runtime.context
    request = state.request
    tools = {t.name: t for t in ctx.resources.tools}
    evidence: dict[str, dict[str, Any]] = {}
    for call in builtin_tool_calls(request, ctx):
        msg = await tools[call["name"]].ainvoke(call)
        evidence[call["name"]] = msg.artifact
    proposal = builtin_proposal(evidence, request, ctx)
    status = state.status if state.status not in (Status.OK, Status.RETRIED) else Status.LLM_INVALID
    _, result = _check(proposal, request)
    assert result is not None
    meta = _result_meta(state, ctx, status)
    meta["backend"] = f"builtin (fallback from {ctx.model})"
    return {"result": result.model_copy(update=meta), "status": status}


# -- routers -----------------------------------------------------------------------------


def route_after_plan(
    state: DiscoveryState,
) -> Literal["plan_queries", "run_tools", "validate_answer", "fall_back"]:
    if state.model_failed:
        return "plan_queries"
    if state.status in (Status.LLM_TIMEOUT, Status.LLM_UNAVAILABLE, Status.LLM_ERROR):
        return "fall_back"
    last = state.messages[-1] if state.messages else None
    if isinstance(last, AIMessage) and last.tool_calls and state.proposal is None and state.invalid is None:
        return "run_tools"
    return "validate_answer"


def route_after_validate(
    state: DiscoveryState, runtime: Runtime[DiscoveryContext]
) -> Literal["plan_queries", "fall_back", "__end__"]:
    if state.result is not None:
        return "__end__"
    if state.invalid is None:
        raise ValueError("validate_answer produced neither a result nor a reason")
    if runtime.context.resources.chat_model is not None and state.attempts <= runtime.context.max_retries:
        return "plan_queries"
    return "fall_back"


# -- wiring ------------------------------------------------------------------------------


def build_graph(tools: list[BaseTool]) -> StateGraph:
    builder = StateGraph(
        DiscoveryState,
        context_schema=DiscoveryContext,
        input_schema=DiscoveryInput,
        output_schema=DiscoveryOutput,
    )
    builder.add_node(plan_queries)
    builder.add_node("run_tools", ToolNode(tools, handle_tool_errors=True))
    builder.add_node(validate_answer)
    builder.add_node(fall_back)

    builder.add_edge(START, "plan_queries")
    builder.add_conditional_edges(
        "plan_queries", route_after_plan, ["plan_queries", "run_tools", "validate_answer", "fall_back"]
    )
    builder.add_edge("run_tools", "plan_queries")
    builder.add_conditional_edges("validate_answer", route_after_validate, ["plan_queries", "fall_back", END])
    builder.add_edge("fall_back", END)
    return builder


def compile_graph(tools: list[BaseTool]) -> Any:
    """The compiled graph (no checkpointer: discovery runs are short and stateless)."""
    return build_graph(tools).compile(name="discovery")

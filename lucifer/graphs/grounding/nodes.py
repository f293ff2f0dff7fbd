"""Nodes of the grounding graph: async, verb_object named, each returning a partial update."""

from __future__ import annotations

import asyncio
import dataclasses
import difflib
import json
import time
from typing import Any, Literal

from langchain_core.messages import AIMessage, HumanMessage, SystemMessage
from langgraph.runtime import Runtime
from pydantic import ValidationError

from lucifer.graphs.grounding.context import GroundingContext
from lucifer.graphs.grounding.prompts import RETRY_PROMPT, SYSTEM_PROMPT, USER_PROMPT
from lucifer.graphs.grounding.resources import GroundingResources
from lucifer.graphs.grounding.state import GroundingState
from lucifer.graphs.grounding.tools import TOOL_NAME, ReportObjects
from lucifer.language.analyzer import CueMention, Extraction, PlaceMention, ReportAnalyzer
from lucifer.language.text import name_words
from lucifer.types import Status

LLM_CONTEXT_DOCS = 8  # retrieved KB documents shown to a chat model (small local models are slow readers)
GROUNDING_KINDS = ("landmark", "relation", "glossary", "category")
LLM_FAILURES = {Status.LLM_TIMEOUT.value, Status.LLM_UNAVAILABLE.value, Status.LLM_ERROR.value}


def _res(runtime: Runtime[GroundingContext]) -> GroundingResources:
    return runtime.context.resources


def _step(node: str, t0: float, inp: dict[str, Any], out: dict[str, Any]) -> list[dict[str, Any]]:
    return [{"node": node, "ms": round((time.perf_counter() - t0) * 1000, 2), "input": inp, "output": out}]


def _extraction(state: GroundingState, analyzer: ReportAnalyzer) -> Extraction:
    """Rebuild the analyzer's extraction from the (serialisable) state, over the tokens the analyzer read
    (slips respelled: "burnin'" is "burning" to the classifier too)."""
    places = [PlaceMention(**{k: tuple(v) if k == "also" else v for k, v in p.items() if k != "span"})
              for p in state.places]
    markers = [(int(a), int(b), bool(s)) for a, b, s in state.markers]
    return Extraction(analyzer.tokens(state.report), places, markers, set(state.relation_tokens))


# --------------------------------------------------------------------------- retrieve
async def retrieve_context(state: GroundingState, runtime: Runtime[GroundingContext]) -> dict[str, Any]:
    """Top-k KB documents for the report (and for each sentence of a long one)."""
    t0 = time.perf_counter()
    res = _res(runtime)
    if res.retriever is None:
        return {"retrieved": [], "trace": _step("retrieve_context", t0, {"report": state.report}, {"retrieved": []})}
    queries = [state.report[:2000]]
    hits = await asyncio.to_thread(res.retriever.retrieve, queries, runtime.context.top_k, GROUNDING_KINDS)
    retrieved = [h.as_dict() | {"text": h.text} for h in hits[: runtime.context.top_k * 2]]
    return {
        "retrieved": retrieved,
        "trace": _step("retrieve_context", t0, {"report": state.report},
                       {"retrieved": [f"{r['id']} ({r['score']:.2f})" for r in retrieved]}),
    }


# --------------------------------------------------------------------------- extract
async def extract_places(state: GroundingState, runtime: Runtime[GroundingContext]) -> dict[str, Any]:
    """Find place mentions: builtin analysis always; a chat model or baseline proposes claims too."""
    t0 = time.perf_counter()
    res = _res(runtime)
    ex = res.analyzer.extract(state.report)
    update: dict[str, Any] = {
        "places": [dataclasses.asdict(p) for p in ex.places],
        "markers": [list(m) for m in ex.markers],
        "relation_tokens": sorted(ex.relation_tokens),
        "attempts": state.attempts + 1,
    }
    if res.model in ("rule", "ner"):
        raw = await asyncio.to_thread(res.baseline().extract, state.report)
        update["candidates"] = [dict(o) | {"source": res.model} for o in raw]
    elif res.uses_llm:
        update.update(await _llm_extract(state, runtime))
    out = {k: v for k, v in update.items() if k in ("places", "candidates", "status")}
    out["places"] = [f"{p['text']!r}->{p['landmark']} [{p['status']}]" + (f" ({p['reason']})" if p.get("reason") else "")
                     for p in update["places"]]
    return update | {"trace": _step("extract_places", t0, {"report": state.report, "attempt": state.attempts + 1,
                                                          "validation_errors": state.validation_errors}, out)}


def _context_text(state: GroundingState, res: GroundingResources) -> str:
    lines = [f"- {r['text']}" for r in state.retrieved[:LLM_CONTEXT_DOCS]]
    mentioned = {p["landmark"] for p in state.places}
    for name in sorted(mentioned):
        lm = res.kb.landmark_by_name[name]
        lines.append(f"- {lm.name} (also: {', '.join(lm.aliases)})")
    return "\n".join(dict.fromkeys(lines)) or "(nothing retrieved)"


def _classify_failure(exc: BaseException) -> Status:
    if isinstance(exc, (asyncio.TimeoutError, TimeoutError)):
        return Status.LLM_TIMEOUT
    chain: list[BaseException] = []
    e: BaseException | None = exc
    while e is not None and len(chain) < 8:
        chain.append(e)
        e = e.__cause__ or e.__context__
    names = " ".join(type(x).__name__ for x in chain)
    if isinstance(exc, ConnectionError) or "Connect" in names or "Connection" in names:
        return Status.LLM_UNAVAILABLE
    if "Timeout" in names:
        return Status.LLM_TIMEOUT
    return Status.LLM_ERROR


async def _llm_extract(state: GroundingState, runtime: Runtime[GroundingContext]) -> dict[str, Any]:
    res = _res(runtime)
    ctx = runtime.context
    cats = "\n".join(f"- {c.name} ({c.role.value}): {c.description}" for c in res.kb.categories)
    messages: list[Any] = [
        SystemMessage(SYSTEM_PROMPT.format(categories=cats, context=_context_text(state, res), tool=TOOL_NAME)),
        HumanMessage(USER_PROMPT.format(report=state.report)),
    ]
    if state.validation_errors:
        # the previous answer goes back as plain text: small models' chat templates cannot render
        # an assistant turn that holds only a tool call
        prev = {"objects": [{k: c.get(k) for k in ("entity", "location", "category")} for c in state.candidates]}
        messages.append(AIMessage(json.dumps(prev)))
        messages.append(HumanMessage(RETRY_PROMPT.format(errors="\n".join(f"- {e}" for e in state.validation_errors),
                                                         tool=TOOL_NAME)))
    try:
        model = res.chat_model()
        # the OpenAI dict form forces the tool on llama.cpp (a grammar) and OpenAI-compatible servers
        bound = model.bind_tools([ReportObjects], tool_choice={"type": "function", "function": {"name": TOOL_NAME}})
        msg = await asyncio.wait_for(bound.ainvoke(messages), timeout=ctx.timeout_s)
    except Exception as exc:  # every failure becomes an explicit status, then the fallback
        status = _classify_failure(exc)
        return {"status": status.value, "candidates": [],
                "errors": [f"{res.model}: {status.value}: {type(exc).__name__}: {exc}"[:500]]}
    candidates, problems = _parse_tool_output(msg)
    return {"candidates": candidates, "validation_errors": problems, "status": Status.OK.value}


def _parse_tool_output(msg: Any) -> tuple[list[dict[str, Any]], list[str]]:
    calls = getattr(msg, "tool_calls", None) or []
    payload: Any = None
    for call in calls:
        if call.get("name") == TOOL_NAME:
            payload = call.get("args")
            break
    if payload is None:
        content = getattr(msg, "content", "") or ""
        text = content if isinstance(content, str) else json.dumps(content)
        start, end = text.find("{"), text.rfind("}")
        if start < 0 or end <= start:
            return [], [f"no `{TOOL_NAME}` tool call and no JSON in the answer"]
        try:
            payload = json.loads(text[start : end + 1])
        except json.JSONDecodeError as exc:
            return [], [f"answer is not valid JSON: {exc}"]
    try:
        parsed = ReportObjects.model_validate(payload)
    except ValidationError as exc:
        return [], [f"tool arguments do not match the schema: {e['loc']}: {e['msg']}" for e in exc.errors()][:5]
    return [o.model_dump() | {"source": "llm"} for o in parsed.objects], []


def route_after_extract(state: GroundingState) -> Literal["classify_claims", "fallback_builtin"]:
    if state.status in LLM_FAILURES:
        return "fallback_builtin"
    if state.status not in (Status.OK.value, Status.RETRIED.value):
        raise ValueError(f"unexpected status after extract: {state.status}")
    return "classify_claims"


# --------------------------------------------------------------------------- classify
async def classify_claims(state: GroundingState, runtime: Runtime[GroundingContext]) -> dict[str, Any]:
    """Builtin: cues, negation, category repairs, cue-to-place attachment. LLM: map category names."""
    t0 = time.perf_counter()
    res = _res(runtime)
    ex = _extraction(state, res.analyzer)
    cl = res.analyzer.classify(ex)
    update: dict[str, Any] = {"cues": [_cue_dict(c) for c in cl.cues]}
    update["denied_candidates"] = [_claim_dict(c.place, c.cue, "builtin") for c in cl.denied]
    if res.model == "builtin":
        update["candidates"] = [_claim_dict(c.place, c.cue, "builtin") for c in cl.claims]
    else:
        names = {c.name for c in res.kb.categories}
        fixed = []
        for cand in state.candidates:
            cat = str(cand.get("category", "")).strip()
            match = cat if cat in names else _closest(cat.replace(" ", "_").lower(), names)
            fixed.append(cand | {"category": match or cat})
        update["candidates"] = fixed
    out = {"cues": [f"{c.text!r}->{c.category} [{c.polarity}, {c.status}]" + (f" ({c.reason})" if c.reason else "")
                    for c in cl.cues],
           "candidates": [f"{c.get('entity')!r}: {c.get('location')}/{c.get('category')}" for c in update["candidates"]]}
    return update | {"trace": _step("classify_claims", t0, {"places": len(state.places)}, out)}


def _cue_dict(c: CueMention) -> dict[str, Any]:
    return dataclasses.asdict(c)


def _claim_dict(p: PlaceMention, c: CueMention, source: str) -> dict[str, Any]:
    return {"entity": p.text, "location": p.landmark, "category": c.category, "span": [p.start, p.end],
            "cue": c.text, "cue_span": [c.start, c.end], "via": p.via, "source": source}


def _closest(name: str, names: set[str]) -> str | None:
    hit = difflib.get_close_matches(name, sorted(names), n=1, cutoff=0.75)
    return hit[0] if hit else None


# --------------------------------------------------------------------------- ground
async def ground_cells(state: GroundingState, runtime: Runtime[GroundingContext]) -> dict[str, Any]:
    """Map each candidate's location (name or alias) to the KB landmark and its cells."""
    t0 = time.perf_counter()
    res = _res(runtime)
    kb, by_form = res.kb, res.landmark_by_form
    grounded = []
    for cand in state.candidates:
        loc = str(cand.get("location") or "")
        name = loc if loc in kb.landmark_by_name else by_form.get(name_words(loc))
        g = dict(cand) | {"location": name or loc, "cells": kb.cells_of(name) if name else []}
        grounded.append(g)
    out = {"grounded": [f"{g['location']} -> {g['cells']}" for g in grounded]}
    return {"grounded": grounded, "trace": _step("ground_cells", t0, {"candidates": len(state.candidates)}, out)}


# --------------------------------------------------------------------------- validate
async def validate_objects(state: GroundingState, runtime: Runtime[GroundingContext]) -> dict[str, Any]:
    """Enforce the contract guarantees; collect the reasons for every rejection."""
    t0 = time.perf_counter()
    res = _res(runtime)
    kb = res.kb
    report_l = state.report.lower()
    active = {p["landmark"] for p in state.places if p["status"] == "active"}
    dropped = {p["landmark"]: p for p in state.places if p["status"] in ("retracted", "negated", "reference")}
    objects: dict[tuple[str, str], dict[str, Any]] = {}
    rejected: list[dict[str, Any]] = []
    for g in state.grounded:
        loc, cat = g.get("location"), g.get("category")
        reason = None
        if loc not in kb.landmark_by_name:
            reason = f"location {loc!r} is not a landmark of the knowledge base"
        elif cat not in kb.category_by_name:
            reason = f"category {cat!r} is not in the Information Space ({', '.join(kb.category_by_name)})"
        elif g.get("cells") != kb.cells_of(loc):
            reason = f"cells of {loc!r} do not come from the knowledge base"
        elif g.get("source") != "builtin" and loc not in active:
            entity = str(g.get("entity") or "").lower()
            if loc in dropped:
                p = dropped[loc]
                reason = f"{loc!r} was {p['status']} in the report ({p.get('reason') or p['status']})"
            elif not entity or entity not in report_l:
                reason = f"{loc!r} is not mentioned in the report (entity {g.get('entity')!r} not found)"
        if reason:
            rejected.append({"location": loc, "category": cat, "entity": g.get("entity"), "reason": reason})
            continue
        key = (loc, cat)
        if key in objects:  # duplicates merge: keep the first mention, count the support
            objects[key]["support"] = objects[key].get("support", 1) + 1
            continue
        objects[key] = {k: g.get(k) for k in ("entity", "category", "location", "cells", "span", "cue", "cue_span", "via", "source")}
    denied = []
    for d in state.denied_candidates:
        if d["location"] in kb.landmark_by_name and d["category"] in kb.category_by_name and (d["location"], d["category"]) not in objects:
            denied.append(d | {"cells": kb.cells_of(d["location"])})
    errors = [r["reason"] for r in rejected]
    status = state.status
    if res.uses_llm and not errors and state.attempts > 1:
        status = Status.RETRIED.value
    out = {"objects": [f"{o['location']}/{o['category']}" for o in objects.values()],
           "denied": [f"{d['location']}/{d['category']}" for d in denied], "rejected": rejected}
    return {"objects": list(objects.values()), "denied": denied, "rejected": rejected,
            "validation_errors": errors if res.uses_llm else [], "status": status,
            "trace": _step("validate_objects", t0, {"grounded": len(state.grounded)}, out)}


def route_after_validate(state: GroundingState, runtime: Runtime[GroundingContext]) -> Literal["extract_places", "fallback_builtin", "__end__"]:
    if not state.validation_errors:
        return "__end__"
    if state.attempts <= runtime.context.max_retries:
        return "extract_places"
    return "fallback_builtin"


# --------------------------------------------------------------------------- fallback
async def fallback_builtin(state: GroundingState, runtime: Runtime[GroundingContext]) -> dict[str, Any]:
    """The chat model failed or stayed invalid: return the builtin analysis, with a status."""
    t0 = time.perf_counter()
    res = _res(runtime)
    cl = res.analyzer.classify(_extraction(state, res.analyzer))  # extract_places already ran the builtin analysis
    objects: dict[tuple[str, str], dict[str, Any]] = {}
    for c in cl.claims:
        objects.setdefault(c.key, _claim_dict(c.place, c.cue, "builtin-fallback") | {"cells": res.kb.cells_of(c.place.landmark)})
    denied = [_claim_dict(c.place, c.cue, "builtin-fallback") | {"cells": res.kb.cells_of(c.place.landmark)}
              for c in cl.denied if c.key not in objects]
    status = state.status if state.status in LLM_FAILURES else Status.LLM_INVALID.value
    errors = [] if state.status in LLM_FAILURES else [
        f"{res.model}: output still invalid after {state.attempts} attempt(s): " + "; ".join(state.validation_errors)[:400]]
    out = {"status": status, "objects": [f"{k[0]}/{k[1]}" for k in objects]}
    return {"objects": list(objects.values()), "denied": denied, "status": status, "errors": errors,
            "validation_errors": [], "trace": _step("fallback_builtin", t0, {"status": state.status}, out)}

"""Discovery graph: telemetry request -> P(u | x_t, xi, D), recommendation u* and confidence.

>>> from lucifer.graphs.discovery import Discoverer, DiscoveryRequest   # doctest: +SKIP
>>> d = Discoverer(kb="knowledge_base", memory="/tmp/telemetry.sqlite")  # doctest: +SKIP
>>> r = await d.discover(DiscoveryRequest(signature="knocking under rubble",
...                                       options=["acoustic_listen", "drone_overflight"]))  # doctest: +SKIP
>>> r.recommendation, r.confidence                                      # doctest: +SKIP
('acoustic_listen', 0.93)
"""

from __future__ import annotations

import asyncio
import json
import os
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from lucifer.errors import BackendError, BadRequest
from lucifer.graphs.discovery.context import DiscoveryContext
from lucifer.graphs.discovery.graph import build_graph, compile_graph
from lucifer.graphs.discovery.resources import DiscoveryResources
from lucifer.graphs.discovery.state import (
    DiscoveryRequest,
    DiscoveryResult,
    DiscoveryState,
    TraceStep,
    trace_text,
)
from lucifer.graphs.discovery.tools import TOOL_NAMES, make_tools
from lucifer.kb import KnowledgeBase, load_kb
from lucifer.telemetry.embedcache import EmbeddingCache
from lucifer.telemetry.memory import TelemetryMemory, TelemetryRecord

__all__ = [
    "TOOL_NAMES",
    "Discoverer",
    "DiscoveryContext",
    "DiscoveryRequest",
    "DiscoveryResult",
    "DiscoveryState",
    "TraceStep",
    "build_graph",
    "compile_graph",
    "parse_request",
]

BUILTIN = "builtin"


def parse_request(data: str | bytes | dict[str, Any] | DiscoveryRequest) -> DiscoveryRequest:
    """A validated request from JSON text, a dict or a request; :class:`BadRequest` if malformed."""
    if isinstance(data, DiscoveryRequest):
        return data
    try:
        if isinstance(data, str | bytes):
            return DiscoveryRequest.model_validate_json(data)
        return DiscoveryRequest.model_validate(data)
    except ValidationError as exc:
        problems = "; ".join(
            f"{'.'.join(str(p) for p in e['loc']) or 'request'}: {e['msg']}" for e in exc.errors()
        )
        raise BadRequest(f"invalid discovery request: {problems}") from None


class Discoverer:
    """Answers discovery requests through the compiled discovery graph.

    ``kb``: a loaded :class:`KnowledgeBase` or a KB directory (default ``$LUCIFER_KB`` /
    ``knowledge_base/``). ``memory``: a :class:`TelemetryMemory` or a SQLite path (default
    :func:`lucifer.paths.telemetry_db`). ``model``: ``builtin`` or ``provider:model``;
    ``chat_model`` passes a ready LangChain chat model instead (tests pass fakes here).
    Further keyword arguments override :class:`DiscoveryContext` fields.
    """

    def __init__(
        self,
        kb: KnowledgeBase | str | os.PathLike[str] | None = None,
        *,
        memory: TelemetryMemory | str | os.PathLike[str] | None = None,
        model: str | None = None,
        chat_model: Any = None,
        base_url: str | None = None,
        embedding_cache: EmbeddingCache | None = None,
        **settings: Any,
    ):
        from lucifer.embeddings import get_embedder
        from lucifer.graphs.discovery.calibration import load_calibration

        self.kb = kb if isinstance(kb, KnowledgeBase) else load_kb(kb)
        self._owns_memory = not isinstance(memory, TelemetryMemory)
        self.memory = memory if isinstance(memory, TelemetryMemory) else TelemetryMemory(memory)
        model = model or BUILTIN
        if chat_model is None and model != BUILTIN:
            if ":" not in model:
                raise BackendError(f"unknown discovery backend {model!r}: use builtin or provider:model")
            from lucifer.models import load_chat_model

            chat_model = load_chat_model(model, base_url, float(settings.get("timeout_s", 60.0)))
        elif chat_model is not None and model == BUILTIN:
            model = getattr(chat_model, "_llm_type", type(chat_model).__name__)
        for key, value in load_calibration().items():
            settings.setdefault(key, value)
        self.resources = DiscoveryResources(
            kb=self.kb,
            memory=self.memory,
            embedder=get_embedder(),
            chat_model=chat_model,
            cache=embedding_cache if embedding_cache is not None else EmbeddingCache(),
        )
        self.context = DiscoveryContext(model=model, resources=self.resources, **settings)
        self.resources.tools = make_tools(self.resources, self.context)
        self.graph = compile_graph(self.resources.tools)

    @property
    def backend(self) -> str:
        return self.context.model

    async def discover(self, request: DiscoveryRequest | dict[str, Any] | str) -> DiscoveryResult:
        """P(u | x_t, xi, D) over the request's options, u* and a calibrated confidence."""
        req = parse_request(request)
        self.resources.check_options(list(req.options))
        start = time.perf_counter()
        self.resources.index.refresh()
        out = await self.graph.ainvoke({"request": req}, context=self.context)
        result: DiscoveryResult = out["result"]
        return result.model_copy(update={"latency_s": time.perf_counter() - start})

    def discover_sync(self, request: DiscoveryRequest | dict[str, Any] | str) -> DiscoveryResult:
        """:meth:`discover` for synchronous callers (not from inside a running event loop)."""
        return asyncio.run(self.discover(request))

    def record(
        self,
        signature: str,
        option: str,
        outcome: float,
        *,
        trace: list[str | TraceStep] | str = "",
        episode: str | None = None,
        client: str | None = None,
    ) -> None:
        """Append one query outcome to telemetry memory (the index folds it in on next use)."""
        summary = trace if isinstance(trace, str) else "; ".join(trace_text(t) for t in trace)
        self.memory.append(
            TelemetryRecord(signature=signature, trace=summary[:4000], option=option, outcome=outcome,
                            episode=episode, client=client)
        )

    def with_settings(self, **settings: Any) -> Discoverer:
        """A shallow copy answering with other context settings (same memory and resources)."""
        other = object.__new__(Discoverer)
        other.__dict__.update(self.__dict__)
        other.context = replace(self.context, **settings)
        return other

    def close(self) -> None:
        """Close the telemetry memory if this discoverer opened it (a passed-in one stays open)."""
        if self._owns_memory:
            self.memory.close()


def load_request_arg(arg: str | None) -> str:
    """The request JSON from a CLI argument: JSON text, a file path, or ``-``/None for stdin."""
    import sys

    if arg is None or arg == "-":
        return sys.stdin.read()
    if arg.lstrip().startswith("{"):
        return arg
    path = Path(arg)
    if not path.is_file():
        raise BadRequest(f"the request is neither JSON nor a readable file: {arg!r}")
    return path.read_text(encoding="utf-8")


def dumps_result(result: DiscoveryResult) -> str:
    return json.dumps(result.spec_dict(), ensure_ascii=False)

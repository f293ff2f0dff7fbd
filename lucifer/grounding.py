"""The grounding service: ``await Grounder(...).ground(text)`` -> :class:`GroundingResult`.

One ``Grounder`` loads the KB, the vector index and the models once and is safe to share
between many asyncio tasks. Edits to the KB files are picked up on the next call.
"""

from __future__ import annotations

import asyncio
import os
import time
import uuid
from pathlib import Path
from typing import Any

from lucifer.embeddings import Embedder, get_embedder
from lucifer.errors import BadReport
from lucifer.graphs.grounding import GroundingContext, compile_graph
from lucifer.graphs.grounding.resources import GroundingResources
from lucifer.kb import KnowledgeBase, kb_fingerprint, load_kb, resolve_kb_dir
from lucifer.language.analyzer import ReportAnalyzer
from lucifer.models import resolve_model
from lucifer.retrieval import Retriever, SyncReport, make_client, open_collection, sync_index
from lucifer.traces import TraceStore
from lucifer.types import GroundedObject, GroundingResult, Span, Status

DEFAULT_MAX_CHARS = 20_000


def _span(v: Any) -> Span | None:
    return Span(start=int(v[0]), end=int(v[1])) if v else None


class Grounder:
    """Async grounding entry point shared by the CLI, the evaluators and the clients."""

    def __init__(
        self,
        kb: str | os.PathLike[str] | None = None,
        model: str | None = None,
        *,
        chroma_url: str | None = None,
        base_url: str | None = None,
        retries: int | None = None,
        timeout_s: float | None = None,
        top_k: int = 8,
        trace: bool = True,
        traces_path: str | os.PathLike[str] | None = None,
        embedder: Embedder | None = None,
        max_chars: int | None = None,
    ):
        self.kb_dir = resolve_kb_dir(kb)
        self.model = resolve_model(model)
        self.chroma_url = chroma_url
        self.base_url = base_url
        self.retries = 2 if retries is None else retries
        self.timeout_s = 60.0 if timeout_s is None else timeout_s
        self.top_k = top_k
        self.max_chars = max_chars or int(os.environ.get("LUCIFER_MAX_REPORT_CHARS", DEFAULT_MAX_CHARS))
        self.embedder = embedder or get_embedder()
        self._store = TraceStore(Path(traces_path) if traces_path else None) if trace else None
        self._graph = compile_graph()
        self._traced_graph: Any = None
        self._client: Any = None
        self._reload_lock = asyncio.Lock()
        self._in_flight = 0
        self.last_sync: SyncReport | None = None
        self._load()

    # ------------------------------------------------------------------ loading
    def _load(self) -> None:
        kb = load_kb(self.kb_dir)
        if self._client is None:
            self._client = make_client(kb.root, self.chroma_url)
        collection = open_collection(self._client, kb.root, self.embedder)
        self.last_sync = sync_index(kb, collection, self.embedder)
        self.resources = GroundingResources(
            kb=kb, embedder=self.embedder, analyzer=ReportAnalyzer(kb, self.embedder),
            retriever=Retriever(collection, self.embedder), model=self.model,
            base_url=self.base_url, timeout_s=self.timeout_s,
        )

    @property
    def kb(self) -> KnowledgeBase:
        return self.resources.kb

    async def _reload_if_changed(self) -> None:
        if kb_fingerprint(self.kb_dir) == self.resources.kb.fingerprint:
            return
        async with self._reload_lock:
            if kb_fingerprint(self.kb_dir) != self.resources.kb.fingerprint:
                chat = self.resources._chat_model  # the chat model does not depend on the KB; baselines do
                await asyncio.to_thread(self._load)  # a broken edit raises KBError; the old KB stays
                self.resources._chat_model = chat

    async def _graph_for_run(self) -> Any:
        if self._store is None:
            return self._graph
        if self._traced_graph is None:
            saver = await self._store.open()
            self._traced_graph = compile_graph(checkpointer=saver)
        return self._traced_graph

    # ------------------------------------------------------------------ grounding
    def check_report(self, text: Any) -> str:
        if not isinstance(text, str):
            raise BadReport(f"report must be text, got {type(text).__name__}")
        if not text.strip():
            raise BadReport("report is empty (nothing but whitespace)")
        if len(text) > self.max_chars:
            raise BadReport(f"report is {len(text)} characters; the limit is {self.max_chars} "
                            "(split it into several reports or set LUCIFER_MAX_REPORT_CHARS)")
        if "\x00" in text:
            raise BadReport("report contains a NUL character")
        return text

    async def ground(self, text: str, report_id: str | None = None) -> GroundingResult:
        """Ground one report. Raises :class:`BadReport` for empty, oversized or non-text input."""
        text = self.check_report(text)
        t0 = time.perf_counter()
        self._in_flight += 1
        try:
            if self._in_flight > 1:
                # reports run concurrently: encoding moves to a child process, so that it runs beside
                # the analysis instead of fighting it for the GIL ($LUCIFER_EMBED_WORKERS; once)
                self.embedder.start_processes()
            return await self._ground(text, report_id, t0)
        finally:
            self._in_flight -= 1

    async def _ground(self, text: str, report_id: str | None, t0: float) -> GroundingResult:
        await self._reload_if_changed()
        res = self.resources
        trace_id = uuid.uuid4().hex[:16]
        context = GroundingContext(model=self.model, top_k=self.top_k, max_retries=self.retries,
                                   timeout_s=self.timeout_s, resources=res)
        graph = await self._graph_for_run()
        config = {"configurable": {"thread_id": trace_id}, "recursion_limit": 10 + 4 * (self.retries + 1)}
        # durability="exit": the trace is checkpointed once, when the run ends (also when it fails),
        # instead of after every node; the final state holds every node's trace entry
        try:
            durability = {"durability": "exit"} if self._store is not None else {}  # (untraced: no checkpointer)
            out = await graph.ainvoke({"report": text, "report_id": report_id}, config=config, context=context,
                                      **durability)
        except Exception as exc:  # a node failed: its trace (up to that node) stays inspectable
            if self._store is not None:
                await self._store.record(trace_id, text, self.model, f"error: {type(exc).__name__}", 0,
                                         str(res.kb.root))
                exc.add_note(f"lucifer: the run's trace is kept; inspect it with `lucifer trace show {trace_id}`")
            raise
        result = GroundingResult(
            report=text,
            report_id=report_id,
            trace_id=trace_id,
            status=Status(out.get("status", "ok")),
            backend=self.model,
            errors=list(out.get("errors", [])),
            objects=[self._object(o) for o in out.get("objects", [])],
            denied=[self._object(o) for o in out.get("denied", [])],
            latency_s=time.perf_counter() - t0,
        )
        if self._store is not None:
            await self._store.record(trace_id, text, self.model, result.status.value, len(result.objects),
                                     str(res.kb.root))
        return result

    @staticmethod
    def _object(o: dict[str, Any]) -> GroundedObject:
        return GroundedObject(
            entity=o.get("entity") or o["location"], category=o["category"], location=o["location"],
            cells=o["cells"], span=_span(o.get("span")), cue=o.get("cue"), cue_span=_span(o.get("cue_span")),
            via=o.get("via"), confidence=1.0,
        )

    async def aclose(self) -> None:
        if self._store is not None:
            await self._store.close()
            self._traced_graph = None

    async def __aenter__(self) -> Grounder:
        return self

    async def __aexit__(self, *exc: object) -> None:
        await self.aclose()

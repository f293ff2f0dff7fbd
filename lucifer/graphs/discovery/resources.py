"""What the discovery graph reads: the KB's query options, telemetry memory and its index."""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from langchain_core.tools import BaseTool

from lucifer.embeddings import Embedder
from lucifer.errors import BadRequest
from lucifer.kb import KnowledgeBase, QueryOption
from lucifer.telemetry.embedcache import EmbeddingCache
from lucifer.telemetry.index import SignatureIndex
from lucifer.telemetry.memory import TelemetryMemory


@dataclass
class DiscoveryResources:
    kb: KnowledgeBase
    memory: TelemetryMemory
    embedder: Embedder
    chat_model: Any = None  # a LangChain chat model, or None for the builtin backend
    cache: EmbeddingCache | None = None  # persistent embeddings of memory clauses and options
    tools: list[BaseTool] = field(default_factory=list)  # set once the tools are made
    index: SignatureIndex = field(init=False)
    _bound: Any = field(init=False, default=None)
    _options: dict[str, QueryOption] = field(init=False, default_factory=dict)
    _option_vecs: dict[str, np.ndarray] = field(init=False, default_factory=dict)
    _lock: threading.Lock = field(init=False, default_factory=threading.Lock)

    def __post_init__(self) -> None:
        self.index = SignatureIndex(self.memory, self.embedder, self.cache)
        self._options = {o.name: o for o in self.kb.query_options}

    @property
    def options(self) -> dict[str, QueryOption]:
        """The KB's query options by name (the KB is immutable; reload it to see edits)."""
        return self._options

    def bound_model(self) -> Any:
        """The chat model with the discovery tools bound (built once)."""
        if self._bound is None:
            self._bound = self.chat_model.bind_tools(self.tools)
        return self._bound

    def check_options(self, names: list[str]) -> None:
        """Raise :class:`BadRequest` naming any option the knowledge base lacks."""
        known = self.options
        unknown = [n for n in names if n not in known]
        if unknown:
            have = ", ".join(sorted(known)) or "(none: add query_options.yaml to the KB)"
            raise BadRequest(
                f"unknown query option(s) {', '.join(repr(u) for u in unknown)}; "
                f"the knowledge base {self.kb.root} has: {have}"
            )

    def option_vectors(self, name: str) -> np.ndarray:
        """Unit vectors of an option's description and cues, shape (1 + len(cues), 384)."""
        vecs = self._option_vecs.get(name)
        if vecs is None:
            with self._lock:
                opt = self.options[name]
                texts = [opt.description or opt.name.replace("_", " "), *opt.cues]
                found = self.cache.get(texts, self.embedder.name) if self.cache is not None else {}
                fresh = [t for t in texts if t not in found]
                if fresh:
                    new = dict(zip(fresh, self.embedder.embed(fresh), strict=True))
                    found.update(new)
                    if self.cache is not None:
                        self.cache.put(new, self.embedder.name)
                vecs = self._option_vecs[name] = np.stack([found[t] for t in texts])
        return vecs

    def warm_up(self) -> None:
        """Index memory and embed every option once (the first request is then fast)."""
        self.index.refresh()
        for name in self.options:
            self.option_vectors(name)

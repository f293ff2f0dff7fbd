"""Offline stand-ins for the grounder and the discoverer, used by the client tests.

They are small, deterministic and good enough for the SAR testbed's reports; the real
backends are exercised by the integration tests and by ``lucifer eval ablation``.
"""

from __future__ import annotations

import itertools
import re

from lucifer.kb import KnowledgeBase
from lucifer.telemetry.scenarios import OPTIONS, POOLS, cue_phrases
from lucifer.types import GroundedObject, GroundingResult

_HAZARD = ("lava", "fire", "smoke", "gas", "collapse", "flood", "chemical", "wires", "unsafe", "no-go", "do not enter")
_VICTIM = ("trapped", "survivor", "casualty", "kids inside", "pinned", "people")
_SAFE = ("clear", "secure", "safe", "staging", "rally", "passable")
_REPAIR = re.compile(r"no wait|correction|i mean|sorry", re.I)


class StandInGrounder:
    """Keyword grounding with self-repair and one-hop KB relations."""

    def __init__(self, kb: KnowledgeBase) -> None:
        self.kb = kb
        self.calls = 0
        forms = [(f.lower(), lm.name) for lm in kb.landmarks for f in lm.surface_forms]
        self.forms = sorted(forms, key=lambda f: -len(f[0]))
        self._ids = itertools.count()

    def _places(self, text: str) -> list[str]:
        low = text.lower()
        for rel in self.kb.relations:
            low = low.replace(f"the building {rel.phrase} the {rel.object}", f" {rel.subject} ")
        found: list[tuple[int, str]] = []
        taken = [False] * len(low)
        for form, name in self.forms:
            for m in re.finditer(r"\b" + re.escape(form) + r"\b", low):
                if not any(taken[m.start():m.end()]):
                    found.append((m.start(), name))
                    for i in range(m.start(), m.end()):
                        taken[i] = True
        return [n for _, n in sorted(found)]

    async def ground(self, text: str, report_id: str | None = None) -> GroundingResult:
        self.calls += 1
        parts = _REPAIR.split(text)
        places = self._places(parts[-1]) or self._places(text)
        low = text.lower()
        for form, _ in self.forms:  # place names must not count as cues ("fire station")
            low = low.replace(form, " ")
        if any(c in low for c in _HAZARD):
            cat = "hazard"
        elif any(c in low for c in _VICTIM):
            cat = "victim"
        elif any(c in low for c in _SAFE):
            cat = "safe_zone"
        else:
            places = []
            cat = "hazard"
        objs = [
            GroundedObject(entity=p, category=cat, location=p, cells=[list(c) for c in self.kb.landmark_by_name[p].cells])
            for p in dict.fromkeys(places)
        ]
        return GroundingResult(report=text, objects=objs, trace_id=f"standin-{next(self._ids)}", report_id=report_id)


class StandInDiscoverer:
    """Exact cue lookup over discovery's phrase pools: always right on known signatures."""

    def __init__(self) -> None:
        self.calls = 0
        self.cues = sorted(((c, o) for o in OPTIONS for p in POOLS for c in cue_phrases(o, p)), key=lambda t: -len(t[0]))

    async def discover(self, request: dict) -> dict:
        self.calls += 1
        sig = request["signature"]
        options = request.get("options") or list(OPTIONS)
        best = next((o for c, o in self.cues if c in sig and o in options), options[0])
        dist = {o: (0.9 if o == best else 0.1 / max(1, len(options) - 1)) for o in options}
        return {"recommendation": best, "confidence": 0.9, "distribution": dist}

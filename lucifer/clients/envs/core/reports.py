"""Spoken-style radio reports of a layout, in three styles of increasing mess.

``standard`` reports are plain; ``messy`` ones stutter, use filler words and self-repair
("fire at the cafe, no wait, correction, at the bakery"); ``advanced_messy`` ones refer to places
through aliases and KB relations ("the shop attached to the bakery"). Reports are a pure
function of (layout, style), so a client sees a finite set of distinct reports and the
middleware can cache its answers.
"""

from __future__ import annotations

from lucifer.clients.envs.core.layouts import Layout
from lucifer.kb import KnowledgeBase

STYLES: tuple[str, str, str] = ("standard", "messy", "advanced_messy")


def _alias(kb: KnowledgeBase, place: str) -> str:
    lm = kb.landmark_by_name[place]
    return lm.aliases[0] if lm.aliases else place


def _the(name: str) -> str:
    """``the`` + name, unless the name already starts with it ('the inn')."""
    return name if name.lower().startswith("the ") else f"the {name}"


def _relational(kb: KnowledgeBase, place: str) -> str | None:
    """'the building attached to the bakery' when the KB relates ``place`` to another place."""
    for rel in kb.relations:
        if rel.subject == place:
            return f"the building {rel.phrase} the {rel.object}"
    return None


def _decoy(kb: KnowledgeBase, layout: Layout, place: str) -> str:
    """A place the speaker names by mistake before repairing: never part of the mission."""
    used = {layout.start, *layout.hazards, *layout.info.values()}
    free = [lm.name for lm in kb.landmarks if lm.name not in used]
    return free[(len(place) + len(layout.name)) % len(free)] if free else place


def briefing_reports(kb: KnowledgeBase, layout: Layout, style: str) -> list[str]:
    """Dispatch's briefing: every hazard, the victim lead, the staging area and the survey post."""
    out: list[str] = []
    for i, (place, kind) in enumerate(layout.hazards.items()):
        if style == "standard":
            out.append(f"{kind.capitalize()} reported at the {place}, keep clear.")
        elif style == "messy":
            if i % 2 == 0:
                out.append(f"uh, dispatch, we've got, we've got {kind} at the {_decoy(kb, layout, place)}, "
                           f"no wait, correction, at the {place}, over")
            else:
                out.append(f"um, {kind} at the, uh, {_the(_alias(kb, place))}, it's bad, stay out of there, over")
        else:
            ref = _relational(kb, place)
            if ref is not None:
                out.append(f"be advised, {kind} in {ref}, uh, nobody goes in there")
            else:
                out.append(f"okay so {_the(_alias(kb, place))}, yeah, {kind} there, it's a no-go, over")
    victim, safe, post = layout.info["victim"], layout.info["safe_route"], layout.info["hazard"]
    if style == "standard":
        out.append(f"A caller says people are trapped at the {victim}.")
        out.append(f"Staging area is set up at the {safe}, it is safe.")
        out.append(f"The {post} is secure, the survey team is waiting there.")
    elif style == "messy":
        out.append(f"uh, we got a call, someone trapped inside the, {_the(_alias(kb, victim))}, over")
        out.append(f"staging at the {_decoy(kb, layout, safe)}, sorry, I mean the {safe}, it's secure, over")
        out.append(f"survey crew is at, uh, {_the(_alias(kb, post))}, it's safe there, over")
    else:
        out.append(f"caller, um, says there's kids inside {_the(_alias(kb, victim))}, can't get out")
        out.append(f"{_the(_alias(kb, safe))} is all clear, we'll use it as the rally point")
        out.append(f"{_the(_alias(kb, post))} is checked and stable, the survey crew waits there")
    return out


def info_report(kb: KnowledgeBase, layout: Layout, info_type: str, style: str) -> str:
    """What the right query at an information location returns."""
    place = layout.info[info_type]
    if info_type == "victim":
        if style == "standard":
            return f"Confirmed two survivors trapped in the {place}, one injured."
        if style == "messy":
            return f"okay we, uh, we have a casualty at the, {_the(_alias(kb, place))}, unconscious, need medics, over"
        return f"found them, survivors pinned inside {_the(_alias(kb, place))}, breathing, over"
    if info_type == "hazard":
        first, kind = next(iter(layout.hazards.items()))
        if style == "standard":
            return f"Assessment done: the {first} has {kind}, it is unsafe."
        if style == "messy":
            return f"um, so, {_the(_alias(kb, first))}, yeah, {kind} confirmed, uh, do not enter, over"
        return f"hazard check complete, {kind} at {_the(_alias(kb, first))}, stay away"
    if style == "standard":
        return f"The route through the {place} is clear, use it as the evacuation route."
    if style == "messy":
        return f"uh, route via the, {_the(_alias(kb, place))}, it's clear, all clear, over"
    return f"scout says {_the(_alias(kb, place))} is passable, safe route, over"

"""Seeded generator for the grounding datasets (SPEC §3).

``python -m lucifer.evals.datagen`` rewrites the *generated* lines of every dataset listed in
:data:`TARGETS` and leaves the hand-written ones alone. A line's ``source`` field tells them
apart (``"hand"`` or ``"gen"``); hand-written lines keep their ids and their order, generated
lines follow them with the next free ids. Same code + same KB + same seed -> same file.

The generator is KB-driven: landmarks, aliases, glossary terms, relations and category names
are read from the knowledge base; only English phrasing lives here, in a :class:`Profile`
(how each relation NAME is said, which nouns fit which landmark) and in the role-keyed
phrase tables below (roles, not category names, so a KB that renames ``hazard`` to ``threat``
still gets correct labels). Every template produces its ``expected`` by construction.

Phrasings
---------
Places
    canonical name or any alias, with "the" added unless the form has it already
    (``the baker's``) or the profile lists it as article-less (``st mary's``).
Claims, by role (a ``{p}`` place slot; ``undesirable`` / ``desirable`` / ``critical``)
    undesirable: "{p} is on fire", "fire at {p}", "heavy smoke coming out of {p}",
    "strong smell of gas in {p}", "{p} has collapsed", "the roof of {p} has caved in",
    "{p} is flooded", "water rising fast in {p}", "live wires down outside {p}",
    "{p} is unsafe, do not enter", ...
    desirable: "{p} is all clear", "{p} has been secured", "{p} is safe to shelter in",
    "we've set up a shelter in {p}", "{p} checked and clear", ...
    critical: "people trapped in {p}", "someone's injured at {p}", "casualties at {p}",
    "man down at {p}", "a child is stuck in {p}", "someone calling for help in {p}", ...
    glossary: "{term} at {p}", "{term} reported at {p}", "{p}: {term}" for every KB term.
    lists: "people trapped in {p1} and {p2}", "{p1}, {p2} and {p3} are all clear", ...
    mixed: "{p} is on fire with people still inside" (hazard + victim on one place).
Standard
    1-4 claims joined by ", " / " and " / ". " / "; ", optional radio prefix ("Base, team
    two.", "Sitrep:") and suffix ("Over.", "Requesting backup.").
Messy (every clause gets one operator, the report gets fillers and a style)
    place repair "{wrong} -- no wait -- {right}" with markers (no / sorry / I mean /
    correction / scratch that / or rather / make that); double repair "{w1}, no, {w2} --
    sorry -- {right}"; category repair "{p} is safe -- correction -- it's flooded";
    negation "{claim}, not {wrong}" / "it's {right} that's {pred}, not {wrong}";
    false starts ("we've got -- there's"), stutters ("the ba-- the bakery"); fillers
    (uh, um, er, like, you know) before clauses and before place NPs; distractor
    mentions with no claim ("team two heading to {x}"); styles: clean, lowercase without
    punctuation, dashes and ellipses.
Advanced messy
    places reached through KB relations: "the {noun} {relation phrase} {anchor}" (one hop,
    forward or inverse), chained two hops where each hop is unique in the KB, claims on an
    anchor plus its neighbour ("fire at {a} and people trapped in the {noun} next to it"),
    repairs to a relational reference ("{a} -- no, the {noun} attached to it") and back
    ("the {noun} next to {a} -- sorry, {a} itself"), relational negation ("the {noun} next
    to {a} is on fire, not {a} itself"). Only references that resolve to exactly one
    landmark are emitted.
No-claim reports (about 10% of every regime, ``expected: []``)
    movement ("team two heading to {x}, over"), radio checks, passing mentions, and a few
    absence/revocation statements ("the fire at {x} is out", "no sign of fire at {x}").
"""

from __future__ import annotations

import json
import random
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from lucifer.kb import KnowledgeBase, load_kb

Role = str  # "undesirable" | "desirable" | "critical"
Claim = tuple[str, Role]  # (landmark, role)


# --------------------------------------------------------------------------- profiles


@dataclass(frozen=True)
class RelationPhrasing:
    """How one KB relation name is said. ``{a}`` is the anchor place.

    ``forward`` describes the relation's subject given its object ("attached to {a}");
    ``inverse`` describes the object given the subject ("that {a} is attached to").
    A symmetric relation uses ``forward`` both ways.
    """

    forward: tuple[str, ...]
    inverse: tuple[str, ...] = ()
    symmetric: bool = False


@dataclass(frozen=True)
class Profile:
    relations: dict[str, RelationPhrasing]
    kinds: dict[str, tuple[str, ...]] = field(default_factory=dict)
    no_article: frozenset[str] = frozenset()
    open_spaces: frozenset[str] = frozenset()  # no roofs, no "inside", nobody "trapped in" them
    teams: tuple[str, ...] = ("team two", "team 3", "unit four", "alpha team", "bravo", "squad six")

    def nouns(self, landmark: str) -> tuple[str, ...]:
        return self.kinds.get(landmark, ("building", "place", "one"))


MARKET_SQUARE = Profile(
    relations={
        "attached_to": RelationPhrasing(
            forward=("attached to {a}", "built onto {a}", "joined on to {a}", "connected to {a}"),
            inverse=("that {a} is attached to", "{a} is built onto"),
        ),
        "next_to": RelationPhrasing(
            forward=("next to {a}", "next door to {a}", "beside {a}", "right next to {a}"),
            symmetric=True,
        ),
        "across_from": RelationPhrasing(
            forward=("across from {a}", "opposite {a}", "across the street from {a}", "facing {a}"),
            symmetric=True,
        ),
        "behind": RelationPhrasing(
            forward=("behind {a}", "round the back of {a}", "at the back of {a}", "directly behind {a}"),
            inverse=("in front of {a}", "that {a} sits behind"),
        ),
    },
    kinds={
        "pharmacy": ("shop", "place", "one"),
        "bakery": ("shop", "building", "place"),
        "hardware store": ("shop", "building", "place"),
        "cafe": ("place", "shop", "one"),
        "supermarket": ("shop", "building", "one"),
        "park": ("place", "area", "green space"),
        "market square": ("place", "area", "open space"),
        "apartment block": ("building", "block", "one"),
    },
    no_article=frozenset({"st mary's"}),
    open_spaces=frozenset({"park", "market square"}),
)

RIVERBEND = Profile(
    relations={
        "adjoins": RelationPhrasing(
            forward=("adjoining {a}", "that adjoins {a}", "joined onto {a}", "sharing a wall with {a}"),
            symmetric=True,
        ),
        "opposite": RelationPhrasing(
            forward=("opposite {a}", "across from {a}", "over the road from {a}", "facing {a}"),
            symmetric=True,
        ),
        "upstream_of": RelationPhrasing(
            forward=("upstream of {a}", "upstream from {a}", "up the river from {a}"),
            inverse=("downstream of {a}", "downstream from {a}", "down the river from {a}"),
        ),
        "overlooks": RelationPhrasing(
            forward=("overlooking {a}", "that overlooks {a}", "looking down on {a}"),
            inverse=("that {a} overlooks", "down below {a}"),
        ),
    },
    kinds={
        "village green": ("place", "area", "open ground"),
        "caravan park": ("place", "site", "area"),
        "footbridge": ("crossing", "structure", "one"),
        "weir": ("structure", "place", "one"),
        "allotments": ("place", "area", "ground"),
        "quarry": ("place", "site", "one"),
        "ferry landing": ("place", "mooring", "one"),
        "tannery": ("works", "building", "place"),
    },
    no_article=frozenset({"st cuthbert's"}),
    open_spaces=frozenset({"village green", "caravan park", "footbridge", "weir", "allotments", "quarry",
                           "ferry landing"}),
)

# --------------------------------------------------------------------------- phrase tables

CLAIMS: dict[Role, tuple[str, ...]] = {
    "undesirable": (
        "{p} is on fire", "fire at {p}", "{p} is burning", "heavy smoke coming out of {p}",
        "smoke pouring from {p}", "strong smell of gas in {p}", "{p} has collapsed",
        "the roof of {p} has caved in", "part of {p} came down", "{p} is flooded",
        "water rising fast in {p}", "live wires down outside {p}", "{p} is unsafe, do not enter",
        "{p} looks structurally unsound", "flames showing at {p}", "there's a gas leak at {p}",
    ),
    "desirable": (
        "{p} is all clear", "{p} is clear", "{p} has been secured", "we've secured {p}",
        "{p} is safe to shelter in", "{p} is safe", "we've set up a shelter in {p}",
        "{p} checked and clear", "{p} is safe for evacuees", "triage tent set up at {p}",
        "{p} is secure, you can send people there",
    ),
    "critical": (
        "people trapped in {p}", "someone's injured at {p}", "there are casualties at {p}",
        "man down at {p}", "two survivors inside {p}", "a child is stuck in {p}",
        "we can hear someone calling for help in {p}", "an elderly woman is unconscious in {p}",
        "injured people at {p}, need medics", "a family is trapped inside {p}",
        "one person pinned under debris at {p}", "we've got wounded at {p}",
    ),
}

LIST_CLAIMS: dict[Role, tuple[str, ...]] = {
    "undesirable": ("fire at {p}", "flooding reported at {p}", "smoke coming from {p}", "{p} are both unsafe"),
    "desirable": ("{p} are all clear", "{p} have been secured", "{p} are safe to shelter in", "we've cleared {p}"),
    "critical": ("people trapped in {p}", "casualties at {p}", "injured people at {p}", "survivors reported in {p}"),
}

# "it's ..." continuations, used after a category repair or for a pronoun.
PRONOUN: dict[Role, tuple[str, ...]] = {
    "undesirable": ("it's on fire", "it's flooded", "there's a gas leak", "it's full of smoke", "it's collapsing"),
    "desirable": ("it's all clear", "it's safe", "it's secure", "it's clear, safe to shelter"),
    "critical": ("there are people trapped inside", "someone's hurt in there", "there's a casualty inside", "people need rescue in there",
                 "someone's hurt over there", "there's a man down there"),
}

# "it's {p} that's ...": predicates for cleft negations.
CLEFT: dict[Role, tuple[str, ...]] = {
    "undesirable": ("burning", "flooded", "on fire", "full of smoke"),
    "desirable": ("clear", "safe", "secured"),
    "critical": ("got people trapped", "got the casualties", "got someone injured"),
}

MIXED: tuple[tuple[str, tuple[Role, ...]], ...] = (
    ("{p} is on fire with people still inside", ("undesirable", "critical")),
    ("{p} has collapsed and there are people trapped under it", ("undesirable", "critical")),
    ("people trapped in {p} and it's flooding", ("critical", "undesirable")),
    ("smoke in {p}, someone's injured in there", ("undesirable", "critical")),
    ("{p} is flooded and someone's stranded on the roof", ("undesirable", "critical")),
)

GLOSSARY_TEMPLATES = ("{term} at {p}", "{term} reported at {p}", "{p}: {term}", "confirmed {term}, {p}")

PREFIXES = ("", "", "", "Base, {team}.", "{team} to base:", "Update:", "Sitrep:", "Be advised,",
            "Dispatch, this is {team}.", "Command, {team} here.")
SUFFIXES = ("", "", "", "Over.", "Over and out.", "Requesting backup.", "Please advise.", "Out.")
JOINERS = (", ", " and ", ". ", "; ", ", also ")
# No bare "and" between clauses that may start with a repaired place: "wounded at A, or rather B
# and C, no, D is clear" would leave it open whether C belongs to the first claim.
JOINERS_REPAIR = (". ", "; ", ", also ", "... ")

REPAIR_MARKERS = (", no, ", " -- no wait -- ", ", sorry, ", " -- I mean ", "... no, ", ", correction, ",
                  " -- scratch that -- ", ", no no, ", ", or rather ", ", uh, make that ")
CAT_REPAIR_MARKERS = (" -- correction -- ", ", no wait, ", ", sorry, I mean ", "... no, actually ",
                      ", correction: ", " -- scratch that, ")
FILLERS = ("uh", "um", "er", "like", "you know", "uhh", "erm")
FALSE_STARTS = ("we've got -- ", "there's -- ", "so the -- ", "I see, uh -- ", "okay so, ", "we have a -- ")
DISTRACTORS = ("{team} heading to {x}", "we're passing {x}", "just came from {x}",
               "on our way to {x}", "{team} is moving past {x}", "we parked the truck at {x}")

EMPTY = (
    "{team} heading to {x}, over.", "Radio check, base, do you copy?", "Passing {x} on the way to {y}.",
    "No change, continuing search.", "Arrived at {x}, starting the sweep now.", "Standing by near {x}, awaiting orders.",
    "Copy that, moving to {x}.", "The fire at {x} is out.", "No sign of fire at {x}.",
    "Base, repeat your last, over.", "{team} regrouping, ETA five minutes to {x}.",
    "Checking in, nothing to report.", "Sending the second truck round by {x}.",
)
EMPTY_MESSY = (
    "uh, base, we're, um, heading to {x} -- no, {y} -- over", "um can you, uh, repeat that, over",
    "er, {team} is -- we're moving past {x}, you know, nothing yet", "so the -- we're on our way to {x}, uh, stand by",
    "base, uh, radio check -- radio check -- do you copy", "like, we just passed {x}, er, continuing",
    "um, no fire at {x}, repeat, no fire, er, over",
)
EMPTY_ADV = (
    "{team} heading to the {noun} {rel}, over.", "uh, we're on our way to the {noun} {rel}.",
    "Passing the {noun} {rel}, continuing north.", "About to search the {noun} {rel}, stand by.",
    "we parked round by the {noun} {rel}, um, nothing yet", "Copy, moving to the {noun} {rel}.",
)


# --------------------------------------------------------------------------- generator


@dataclass
class Report:
    text: str
    expected: list[Claim]


_INDOOR = ("roof", "inside", "collaps", "structurally", "came down", "in there", "shelter in", "trapped",
           "stuck in", "coming out of", "pouring from", "caved", "under it", "flooding")


def _fits(template: str, open_space: bool) -> bool:
    return not open_space or not any(w in template for w in _INDOOR)


def _plural(np_text: str) -> bool:
    """Whether a place phrase takes a plural verb ("the flats are").

    >>> _plural("the flats"), _plural("st mary's"), _plural("the bus station")
    (True, False, False)
    """
    last = np_text.split()[-1].lower()
    return last.endswith("s") and not last.endswith(("'s", "ss", "us")) and last != "works"


def _agree(template: str, p: str) -> str:
    """Fill ``{p}`` and make a following "is/has/looks" agree with it."""
    if _plural(p):
        for sing, plur in (("{p} is ", "{p} are "), ("{p} has ", "{p} have "), ("{p} looks ", "{p} look ")):
            template = template.replace(sing, plur)
    return template.format(p=p)


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:] if s else s


class Generator:
    """Draws reports for one KB. All randomness goes through ``self.rng``."""

    def __init__(self, kb: KnowledgeBase, profile: Profile, seed: int):
        self.kb = kb
        self.profile = profile
        self.rng = random.Random(seed)
        self.names = [lm.name for lm in kb.landmarks]
        self.role_cat = {r: kb.categories_with_role(r)[0].name for r in ("undesirable", "desirable", "critical")}
        self.gloss: dict[Role, list[str]] = {r: [] for r in self.role_cat}
        for t in kb.glossary:
            self.gloss[kb.category_by_name[t.category].role.value].append(t.term)
        self.hops = self._hops()

    # -- places
    def np(self, name: str, canonical_bias: float = 0.5) -> str:
        lm = self.kb.landmark_by_name[name]
        form = lm.name if (not lm.aliases or self.rng.random() < canonical_bias) else self.rng.choice(lm.aliases)
        if form.lower().startswith("the ") or form.lower() in self.profile.no_article:
            return form
        return "the " + form

    def pick(self, k: int, exclude: Sequence[str] = ()) -> list[str]:
        pool = [n for n in self.names if n not in exclude]
        return self.rng.sample(pool, k)

    def role(self) -> Role:
        return self.rng.choice(("undesirable", "undesirable", "desirable", "critical", "critical"))

    def is_open(self, *names: str) -> bool:
        return any(n in self.profile.open_spaces for n in names)

    def choose(self, templates: Sequence[str], *names: str) -> str:
        return self.rng.choice([t for t in templates if _fits(t, self.is_open(*names))])

    def claim(self, role: Role, p: str, *names: str) -> str:
        """A claim of ``role`` about the place text ``p`` (landmark ``names``)."""
        return _agree(self.choose(CLAIMS[role], *names), p)

    # -- relations: (target, phrase-template) reachable in one unique hop from an anchor
    def _hops(self) -> dict[str, list[tuple[str, str]]]:
        """anchor -> [(target, phrase template with {a})] for hops unique in the KB."""
        by_key: dict[tuple[str, str, str], set[str]] = {}
        for rel in self.kb.relations:
            ph = self.profile.relations.get(rel.relation)
            if ph is None:
                continue
            by_key.setdefault((rel.object, rel.relation, "fwd"), set()).add(rel.subject)
            direction = "fwd" if ph.symmetric else "inv"
            by_key.setdefault((rel.subject, rel.relation, direction), set()).add(rel.object)
        hops: dict[str, list[tuple[str, str]]] = {}
        for (anchor, relname, direction), targets in by_key.items():
            if len(targets) != 1:
                continue
            ph = self.profile.relations[relname]
            phrases = ph.forward if direction == "fwd" else ph.inverse
            (target,) = targets
            for t in phrases:
                hops.setdefault(anchor, []).append((target, t))
        return hops

    def ref(self, anchor_np: str, phrase: str, target: str) -> str:
        noun = self.rng.choice(self.profile.nouns(target))
        return f"the {noun} {phrase.format(a=anchor_np)}"

    def one_hop(self, exclude: Sequence[str] = (), pronoun: bool = False) -> tuple[str, str, str, str]:
        """(target, reference text, anchor, phrase) for a random unique hop."""
        options = [(a, t, ph) for a, lst in self.hops.items() for t, ph in lst
                   if t not in exclude and a not in exclude and (not pronoun or ph.endswith("{a}"))]
        a, t, ph = self.rng.choice(options)
        return t, self.ref(self.np(a), ph, t), a, ph

    def two_hop(self, exclude: Sequence[str] = ()) -> tuple[str, str, str] | None:
        options = []
        for a, lst in self.hops.items():
            for b, ph1 in lst:
                for c, ph2 in self.hops.get(b, []):
                    if c != a and c not in exclude and a not in exclude and b not in exclude:
                        options.append((a, b, ph1, c, ph2))
        if not options:
            return None
        a, b, ph1, c, ph2 = self.rng.choice(options)
        inner = self.ref(self.np(a), ph1, b)
        return c, self.ref(inner, ph2, c), a

    # -- fillers
    def filler(self, p: float) -> str:
        return (self.rng.choice(FILLERS) + ", ") if self.rng.random() < p else ""

    def team(self) -> str:
        return self.rng.choice(self.profile.teams)

    def wrap(self, clauses: list[str], joiners: Sequence[str] = JOINERS) -> str:
        body = clauses[0]
        for c in clauses[1:]:
            j = self.rng.choice(joiners)
            body += j + (_cap(c) if j == ". " else c)
        pre = _cap(self.rng.choice(PREFIXES).format(team=self.team()))
        suf = self.rng.choice(SUFFIXES)
        if not pre or pre.endswith("."):
            body = _cap(body)
        body = body.rstrip(" ,")
        if body[-1] not in ".?!":
            body += "."
        return " ".join(x for x in (pre, body, suf) if x)

    # ----------------------------------------------------------------- standard
    def standard(self) -> Report:
        n = self.rng.choice((1, 2, 2, 3, 3, 4))
        used: list[str] = []
        clauses: list[str] = []
        exp: list[Claim] = []
        while len(exp) < n:
            kind = self.rng.choice(("single", "single", "single", "list", "gloss", "mixed"))
            if kind == "list" and n - len(exp) >= 2:
                k = min(self.rng.choice((2, 2, 3)), n - len(exp))
                places = self.pick(k, used)
                role = self.role()
                nps = [self.np(p) for p in places]
                joined = nps[0] if k == 1 else ", ".join(nps[:-1]) + " and " + nps[-1]
                t = self.choose(LIST_CLAIMS[role], *places)
                if "both" in t and k != 2:
                    t = "fire at {p}"
                    role = "undesirable"
                clauses.append(t.format(p=joined))
                exp += [(p, role) for p in places]
                used += places
            elif kind == "gloss":
                role = self.role()
                if not self.gloss[role]:
                    continue
                (p,) = self.pick(1, used)
                term = self.rng.choice(self.gloss[role])
                clauses.append(self.rng.choice(GLOSSARY_TEMPLATES).format(term=term, p=self.np(p)))
                exp.append((p, role))
                used.append(p)
            elif kind == "mixed" and n - len(exp) >= 2:
                (p,) = self.pick(1, used)
                if self.is_open(p):
                    continue
                t, roles = self.rng.choice(MIXED)
                clauses.append(t.format(p=self.np(p)))
                exp += [(p, r) for r in roles]
                used.append(p)
            else:
                (p,) = self.pick(1, used)
                role = self.role()
                clauses.append(self.claim(role, self.np(p), p))
                exp.append((p, role))
                used.append(p)
        return Report(self.wrap(clauses), exp)

    # ----------------------------------------------------------------- messy
    def _repaired_np(self, right: str, used: list[str], double: bool) -> str:
        wrongs = self.pick(2 if double else 1, used + [right])
        used += wrongs
        m1, m2 = self.rng.sample(REPAIR_MARKERS, 2)
        if double:
            return f"{self.np(wrongs[0])}{m1}{self.np(wrongs[1])}{m2}{self.np(right)}"
        return f"{self.np(wrongs[0])}{m1}{self.np(right)}"

    def _stutter(self, np_text: str) -> str:
        head = np_text[4:] if np_text.startswith("the ") else np_text
        if self.rng.random() < 0.5 or len(head) < 4:
            return f"the, the {head}" if np_text.startswith("the ") else f"{np_text}, {np_text}"
        return f"the {head[:2]}-- {np_text}"

    def messy_clause(self, used: list[str]) -> tuple[str, list[Claim]]:
        (p,) = self.pick(1, used)
        used.append(p)
        role = self.role()
        op = self.rng.choice(("repair", "repair", "double", "catrep", "catrep", "neg", "neg", "stutter", "plain", "plain"))
        fill = self.filler(0.35)
        if op in ("repair", "double"):
            return fill + self.claim(role, self._repaired_np(p, used, op == "double"), p), [(p, role)]
        if op == "catrep":
            wrong_role = self.rng.choice([r for r in CLAIMS if r != role])
            first = self.claim(wrong_role, self.np(p), p)
            return f"{fill}{first}{self.rng.choice(CAT_REPAIR_MARKERS)}{self.choose(PRONOUN[role], p)}", [(p, role)]
        if op == "neg":
            (w,) = self.pick(1, used)
            used.append(w)
            style = self.rng.randrange(3)
            if style == 0:
                return f"{fill}{self.claim(role, self.np(p), p)}, not {self.np(w)}", [(p, role)]
            if style == 1:
                return f"{fill}it's {self.np(p)} that's {self.choose(CLEFT[role], p)}, not {self.np(w)}", [(p, role)]
            return f"{fill}not {self.np(w)} -- {self.claim(role, self.np(p), p)}", [(p, role)]
        if op == "stutter":
            return fill + self.claim(role, self._stutter(self.np(p)), p), [(p, role)]
        return fill + self.claim(role, f"{self.filler(0.5)}{self.np(p)}", p), [(p, role)]

    def style(self, text: str) -> str:
        s = self.rng.random()
        if s < 0.3:  # lowercase, no punctuation
            text = re.sub(r"[.,;:!?]", "", text.lower())
            return re.sub(r"\s+", " ", text).strip()
        if s < 0.45:  # dashes and ellipses
            return text.replace(", ", "... ", 1).replace(" -- ", " - ")
        return text.replace(" -- ", " — ")

    def messy(self) -> Report:
        n = self.rng.choice((1, 1, 1, 2, 2, 3))
        used: list[str] = []
        clauses, exp = [], []
        if self.rng.random() < 0.25:
            (x,) = self.pick(1)
            used.append(x)
            clauses.append(self.rng.choice(DISTRACTORS).format(team=self.team(), x=self.np(x)))
        for _ in range(n):
            c, e = self.messy_clause(used)
            clauses.append(c)
            exp += e
        if self.rng.random() < 0.3:
            i = len(clauses) - n  # the first claim clause
            clauses[i] = self.rng.choice(FALSE_STARTS) + clauses[i]
        return Report(self.style(self.wrap(clauses, JOINERS_REPAIR)), exp)

    # ----------------------------------------------------------------- advanced
    def adv_clause(self, used: list[str]) -> tuple[str, list[Claim]]:
        role = self.role()
        op = self.rng.choice(("hop", "hop", "hop", "chain", "anchor_too", "repair_to", "repair_back",
                              "repair_between", "neg"))
        fill = self.filler(0.25)
        if op == "chain":
            r = self.two_hop(used)
            if r is not None:
                t, text, a = r
                used += [t, a]
                return fill + self.claim(role, text, t), [(t, role)]
            op = "hop"
        if op == "anchor_too":  # "fire at {a} and people trapped in the shop attached to it"
            t, _, a, ph = self.one_hop(used, pronoun=True)
            used += [t, a]
            r2 = self.rng.choice([r for r in CLAIMS if r != role] + [role])
            return (f"{fill}{self.claim(role, self.np(a), a)} and {self.claim(r2, self.ref('it', ph, t), t)}",
                    [(a, role), (t, r2)])
        if op == "repair_to":  # "{a} -- no, the shop attached to it"
            t, _, a, ph = self.one_hop(used, pronoun=True)
            used += [t, a]
            slot = f"{self.np(a)}{self.rng.choice(REPAIR_MARKERS)}{self.ref('it', ph, t)}"
            return fill + self.claim(role, slot, t, a), [(t, role)]
        if op == "repair_back":  # "the building next to {a} -- sorry, {a} itself"
            t, text, a, _ = self.one_hop(used)
            used += [t, a]
            slot = f"{text}{self.rng.choice(REPAIR_MARKERS)}{self.np(a)} itself"
            return fill + self.claim(role, slot, t, a), [(a, role)]
        if op == "repair_between":  # "the one next to {a1} -- sorry -- the one across from {a2}"
            t1, text1, a1, _ = self.one_hop(used)
            used += [t1, a1]
            t2, text2, a2, _ = self.one_hop(used)
            used += [t2, a2]
            slot = f"{text1}{self.rng.choice(REPAIR_MARKERS)}{text2}"
            return fill + self.claim(role, slot, t1, t2), [(t2, role)]
        t, text, a, _ = self.one_hop(used)
        used += [t, a]
        if op == "neg":
            if self.rng.random() < 0.5:
                pred = self.choose(CLEFT[role], t)
                return f"{fill}it's {text} that's {pred}, not {self.np(a)} itself", [(t, role)]
            return f"{fill}{self.claim(role, text, t)} -- repeat, not {self.np(a)} itself", [(t, role)]
        return fill + self.claim(role, text, t), [(t, role)]

    def advanced(self) -> Report:
        n = self.rng.choice((1, 1, 2, 2, 3))
        used: list[str] = []
        clauses, exp = [], []
        for i in range(n):
            if i > 0 and self.rng.random() < 0.3:  # a plain direct claim among relational ones
                (p,) = self.pick(1, used)
                used.append(p)
                role = self.role()
                clauses.append(self.claim(role, self.np(p), p))
                exp.append((p, role))
                continue
            c, e = self.adv_clause(used)
            clauses.append(c)
            exp += e
        text = self.wrap(clauses, JOINERS_REPAIR)
        if self.rng.random() < 0.3:
            text = self.style(text)
        else:
            text = text.replace(" -- ", " — ")
        return Report(text, exp)

    # ----------------------------------------------------------------- empty
    def empty(self, regime: str) -> Report:
        x, y = (self.np(n) for n in self.pick(2))
        if regime == "advanced_messy":
            a = self.rng.choice(sorted(self.hops))
            t, ph = self.rng.choice(self.hops[a])
            noun = self.rng.choice(self.profile.nouns(t))
            text = self.rng.choice(EMPTY_ADV).format(team=self.team(), noun=noun, rel=ph.format(a=self.np(a)))
            return Report(_cap(text), [])
        pool = EMPTY_MESSY if regime == "messy" else EMPTY
        return Report(_cap(self.rng.choice(pool).format(team=self.team(), x=x, y=y)), [])

    def report(self, regime: str) -> Report:
        make: dict[str, Callable[[], Report]] = {
            "standard": self.standard, "messy": self.messy, "advanced_messy": self.advanced}
        return make[regime]()


# --------------------------------------------------------------------------- files

REGIME_LETTER = {"standard": "s", "messy": "m", "advanced_messy": "a"}


@dataclass(frozen=True)
class Target:
    """One dataset file: which KB, which regimes, how many lines each, id prefix, seed."""

    path: str
    kb: str
    profile: Profile
    total_per_regime: int
    regimes: tuple[str, ...]
    id_prefix: str = ""
    seed: int = 0
    empty_share: float = 0.10


TARGETS: tuple[Target, ...] = (
    Target("datasets/grounding/standard.jsonl", "knowledge_base", MARKET_SQUARE, 150, ("standard",), seed=101),
    Target("datasets/grounding/messy.jsonl", "knowledge_base", MARKET_SQUARE, 150, ("messy",), seed=202),
    Target("datasets/grounding/advanced_messy.jsonl", "knowledge_base", MARKET_SQUARE, 150, ("advanced_messy",), seed=303),
    Target("datasets/grounding/riverbend.jsonl", "knowledge_bases/riverbend", RIVERBEND, 30,
           ("standard", "messy", "advanced_messy"), id_prefix="rb-", seed=404),
)


def _id_num(rid: str) -> int:
    m = re.search(r"(\d+)$", rid)
    return int(m.group(1)) if m else 0


def read_jsonl(path: Path) -> list[dict]:
    if not path.exists():
        return []
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


def build(target: Target, root: Path) -> list[dict]:
    """Hand-written lines of the file followed by freshly generated ones."""
    path = root / target.path
    kb = load_kb(root / target.kb)
    hand = [r for r in read_jsonl(path) if r.get("source", "hand") == "hand"]
    gen = Generator(kb, target.profile, target.seed)
    role_cat = gen.role_cat
    out: list[dict] = []
    seen = {r["report"].lower() for r in hand}
    for regime in target.regimes:
        mine = [r for r in hand if r["regime"] == regime]
        out += mine
        n_gen = max(0, target.total_per_regime - len(mine))
        want_empty = round(target.empty_share * target.total_per_regime)
        n_empty = min(n_gen, max(0, want_empty - sum(1 for r in mine if not r["expected"])))
        empty_slots = set(gen.rng.sample(range(n_gen), n_empty))
        prefix = f"{target.id_prefix}{REGIME_LETTER[regime]}-"
        next_id = max((_id_num(r["id"]) for r in mine), default=0) + 1
        for i in range(n_gen):
            for _ in range(100):
                rep = gen.empty(regime) if i in empty_slots else gen.report(regime)
                if rep.text.lower() not in seen:
                    break
            seen.add(rep.text.lower())
            exp = []
            for loc, role in rep.expected:
                item = {"location": loc, "category": role_cat[role]}
                if item not in exp:
                    exp.append(item)
            out.append({"id": f"{prefix}{next_id:03d}", "regime": regime, "report": rep.text,
                        "expected": exp, "source": "gen"})
            next_id += 1
    return out


def write_jsonl(path: Path, rows: list[dict]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("".join(json.dumps(r, ensure_ascii=False) + "\n" for r in rows), encoding="utf-8")


def main(argv: Sequence[str] | None = None) -> int:
    import argparse

    ap = argparse.ArgumentParser(prog="python -m lucifer.evals.datagen", description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=".", help="repository root (default: current directory)")
    ap.add_argument("--check", action="store_true", help="exit 1 if a file would change, write nothing")
    args = ap.parse_args(argv)
    root = Path(args.root)
    changed = 0
    for t in TARGETS:
        rows = build(t, root)
        path = root / t.path
        new = "".join(json.dumps(r, ensure_ascii=False) + "\n" for r in rows)
        old = path.read_text(encoding="utf-8") if path.exists() else ""
        if new != old:
            changed += 1
            if not args.check:
                write_jsonl(path, rows)
        n_hand = sum(1 for r in rows if r.get("source") == "hand")
        print(f"{t.path}: {len(rows)} reports ({n_hand} hand-written, {len(rows) - n_hand} generated)"
              + (" [would change]" if args.check and new != old else ""))
    return 1 if (args.check and changed) else 0


if __name__ == "__main__":
    raise SystemExit(main())

"""The builtin report analyzer: places, category cues, self-repairs, negation and KB relations.

It works in stages that the grounding graph exposes as separate nodes:

* :meth:`ReportAnalyzer.extract` finds place mentions (landmark names and aliases from the KB),
  resolves relational references through KB relations ("the shop attached to the bakery"),
  and applies self-repairs ("the bank — no wait — the bakery") and place negation ("not the
  school"), marking each mention ``active``, ``retracted``, ``negated`` or ``reference``.
* :meth:`ReportAnalyzer.classify` finds category cues (glossary terms, category names and
  descriptions, and a role vocabulary mapped onto the KB's categories), applies cue negation
  and category repairs, and attaches cues to places clause by clause.

Everything the analyzer knows about places and categories comes from the knowledge base; the
built-in vocabulary is about *roles* (undesirable / desirable / critical), so a KB with other
category names works unchanged. MiniLM embeddings break ties the vocabulary cannot (a role
shared by several categories, a relational head noun that fits several landmarks, an unknown
relation phrase).
"""

from __future__ import annotations

import difflib
import functools
import re
import threading
from collections.abc import Callable, Collection, Iterable, Iterator, Sequence
from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np

from lucifer.embeddings import Embedder
from lucifer.kb import Category, KnowledgeBase, Relation, Role
from lucifer.language import lexicon as lx
from lucifer.language.numbers import (
    SIBLING_UNITS,
    UNITS,
    is_number,
    is_ordinal,
    number_at,
    spoken_forms,
    text_ranges,
)
from lucifer.language.text import PhraseMatcher, Tokens, name_words, norm, norm_phrase, tokenize

MentionStatus = Literal["active", "retracted", "negated", "reference"]


@dataclass(frozen=True)
class PlaceMention:
    start_tok: int
    end_tok: int
    start: int
    end: int
    text: str
    landmark: str
    status: MentionStatus = "active"
    reason: str = ""
    via: str | None = None  # "pharmacy attached_to bakery" when reached through a relation
    replaces: int | None = None  # start token of the mention this one repairs
    anaphor: Literal["ordinal", "both", "neither"] | None = None  # "the first one", "both of them", "neither of them"
    also: tuple[str, ...] = ()  # the other places "both of them" / "neither of them" names
    counted_by: int | None = None  # a list member: start token of the first ordinal that names one of its list

    def as_dict(self) -> dict[str, object]:
        d: dict[str, object] = {"text": self.text, "span": [self.start, self.end], "landmark": self.landmark,
                                "status": self.status}
        if self.reason:
            d["reason"] = self.reason
        if self.via:
            d["via"] = self.via
        return d


@dataclass(frozen=True)
class CueMention:
    start_tok: int
    end_tok: int
    start: int
    end: int
    text: str
    category: str
    source: str  # glossary | category | lexicon | embedding
    polarity: Literal["affirmed", "denied"] = "affirmed"
    status: Literal["active", "retracted"] = "active"
    reason: str = ""
    replaces: int | None = None  # start token of the cue this one repairs

    def as_dict(self) -> dict[str, object]:
        d: dict[str, object] = {"text": self.text, "span": [self.start, self.end], "category": self.category,
                                "source": self.source, "polarity": self.polarity, "status": self.status}
        if self.reason:
            d["reason"] = self.reason
        return d


@dataclass(frozen=True)
class Claim:
    place: PlaceMention
    cue: CueMention

    @property
    def key(self) -> tuple[str, str]:
        return (self.place.landmark, self.cue.category)


@dataclass
class Extraction:
    """Output of the extract stage."""

    tokens: Tokens
    places: list[PlaceMention]
    markers: list[tuple[int, int, bool]] = field(default_factory=list)  # (start_tok, end_tok, strong)
    # words of a relation read between two named places ("the beck the day hole spills into"): no cues
    relation_tokens: set[int] = field(default_factory=set)

    @property
    def active(self) -> list[PlaceMention]:
        return [p for p in self.places if p.status == "active"]


@dataclass
class Classification:
    cues: list[CueMention]
    claims: list[Claim]
    denied: list[Claim]


# The reason of a denial made by "neither of them": it takes back only what it is said of, nothing earlier.
NEITHER = "said with 'neither'"

_REL_SPLIT = re.compile(r"[_\-\s]+")


def _one_edit(a: str, b: str) -> bool:
    """a and b differ by exactly one insertion, deletion, substitution or adjacent transposition."""
    if a == b:
        return False
    if len(a) == len(b):
        diff = [i for i in range(len(a)) if a[i] != b[i]]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1
                                   and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]])
    if abs(len(a) - len(b)) != 1:
        return False
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    i = next((k for k in range(len(short)) if short[k] != long_[k]), len(short))
    return short[i:] == long_[i + 1:]


_SOUND_SPELLINGS = (("ph", "f"), ("tion", "shun"), ("sion", "shun"), ("ck", "k"))
_SOUND_ENDINGS = (("ce", "s"),)
_HEARD_ENDINGS = (("ie", "y"), ("ey", "y"), ("ee", "y"))  # (a name's own "-ie" is the singular of "-ies": "gantries")


def _sound_of(word: str, heard: bool = False) -> str:
    """A word spelt as it sounds, so that transcribed spellings (``heard``) meet the written ones: "station" and
    "stayshun" -> "stashun"/"stayshun" (one edit apart), "police" and "polis" -> "polis", "bakery" and
    "bakerie" -> "bakery"."""
    for a, b in _SOUND_SPELLINGS:
        word = word.replace(a, b)
    for a, b in _SOUND_ENDINGS + (_HEARD_ENDINGS if heard else ()):
        if word.endswith(a) and len(word) > 3:
            word = word[:-len(a)] + b
    return word


def _weighty(word: str) -> bool:
    """A word long enough to say something when phrases and descriptions are matched word by word: four letters or
    more, or a short word of danger ("gas", "oil", "ice")."""
    return len(word) >= 4 or word in lx.SHORT_DANGER_WORDS


class ReportAnalyzer:
    """Builtin, LLM-free analysis of one report against one knowledge base."""

    def __init__(self, kb: KnowledgeBase, embedder: Embedder | None = None):
        self.kb = kb
        self.embedder = embedder
        # one call at a time: the stages keep per-call scratch state on the instance
        self._call_lock = threading.RLock()
        # (a hesitation inside a name is skipped: "the genny sh- shed", "the pumping, er, station")
        self._places: PhraseMatcher[str] = PhraseMatcher(lx.HESITATIONS)
        self._needs_article: set[tuple[str, ...]] = set()  # "the tower": an alias written with its article
        plain: set[tuple[str, ...]] = set()
        keys = {norm_phrase(f) for lm in kb.landmarks for f in lm.surface_forms}
        labelled = _letter_labelled(keys)
        for lm in kb.landmarks:
            for form in lm.surface_forms:
                key = norm_phrase(form)
                if key in labelled:
                    key = key[1:] if key[0] == "the" else key
                    self._places.add(key, lm.name)  # ("a wing" beside "b wing": "a" is its letter, not an article)
                    plain.add(key)
                    continue
                had_article = bool(key) and key[0] in ("the", "a", "an")
                while key and key[0] in ("the", "a", "an"):
                    key = key[1:]
                (self._needs_article if had_article else plain).add(key)
                self._places.add(key, lm.name)
        self._needs_article -= plain
        # "the halls" (of residence) beside "the main hall": the word said in the one number is the other's head
        heads_of: dict[str, set[str]] = {}  # last word as written -> the landmarks with a form ending on it
        for lm in kb.landmarks:
            for f in lm.surface_forms:
                if f.split():
                    heads_of.setdefault(f.split()[-1].lower(), set()).add(lm.name)
        self._plural_only: dict[tuple[str, ...], str] = {}
        for lm in kb.landmarks:
            for f in lm.surface_forms:
                raw = f.lower().split()
                if len(name_words(f)) == 1 and raw and raw[-1].endswith("s") and norm(raw[-1]) != raw[-1] \
                        and heads_of.get(norm(raw[-1]), set()) - {lm.name}:
                    self._plural_only[name_words(f)] = lm.name
        # "the medic's": a name that is someone's premises, said of the person alone ("waiting for the medic") is no
        # place (unless another form of it is the bare word)
        bare = {name_words(f) for lm in kb.landmarks for f in lm.surface_forms
                if not f.rstrip().lower().endswith(("'s", "’s", "s'"))}
        self._possessive_only = frozenset(
            name_words(f) for lm in kb.landmarks for f in lm.surface_forms
            if f.rstrip().lower().endswith(("'s", "’s")) and name_words(f) not in bare
            and name_words(f)[-1:] and (name_words(f)[-1] in lx.WORKER_PERSONS | lx.LAY_PERSONS
                                        or name_words(f)[-1] in _PERSON_WORDS))
        derived: set[tuple[str, ...]] = set()  # names the analyzer puts together, not the KB's own
        for key, name in self._compound_forms():
            self._places.add(key, name)
            derived.add(key)
        for key, name in _phonetic_forms(kb, keys, labelled):
            self._places.add(key, name)
        for key, name in _spoken_number_forms(kb, keys):
            self._places.add(key, name)  # ("runway two six" for "runway 26")
            derived.add(key)
        for key, name in _synonym_forms(kb):
            self._places.add(key, name)
            self._needs_article.add(key)  # ("the little stone church" for the one chapel; "church services" no name)
            derived.add(key)
        self._derived_keys = frozenset(derived - plain)
        self._role_category = self._map_roles()
        self._cues: PhraseMatcher[tuple[str, str]] = PhraseMatcher(lx.CUE_SKIPPABLE)
        self._build_cues()
        # the category a person placed at the scene claims (fixed per KB; an embedding when several are critical)
        self._person_category = self._category_for_role("critical", "person needs rescue")
        self._markers: PhraseMatcher[bool] = PhraseMatcher()
        for m in lx.WEAK_REPAIR:
            self._markers.add(norm_phrase(m), False)
        for m in lx.STRONG_REPAIR:
            self._markers.add(norm_phrase(m), True)
        self._negators: PhraseMatcher[str] = PhraseMatcher()
        for n in lx.NEGATOR_PHRASES:
            self._negators.add(norm_phrase(n), n)
        self._cancel: PhraseMatcher[str] = _CancelMatcher(lx.HESITATIONS)
        for c in lx.CANCEL_AFTER:
            self._cancel.add(norm_phrase(c), c)
        self._transit: PhraseMatcher[str] = PhraseMatcher(lx.HESITATIONS)  # "we're er at the car barn"
        for t in lx.TRANSIT:
            self._transit.add(norm_phrase(t), t)
        self._relations: PhraseMatcher[tuple[str, bool]] = PhraseMatcher()  # phrase -> (relation, inverse)
        self._build_relations()
        self._rel_keywords = self._relation_keywords()
        self._rel_keyword_items = sorted(self._rel_keywords.items())  # fixed order for compound matches
        # landmark pairs a KB relation links, either way round; glossary words that name a danger ("live steam");
        # landmarks that carry people in cars ("the funicular car")
        self._related_pairs = {(r.subject, r.object) for r in kb.relations} | {(r.object, r.subject) for r in kb.relations}
        self._danger_words = {w for t in kb.glossary for w in norm_phrase(t.term)
                              if kb.category_by_name[t.category].role == Role.UNDESIRABLE}
        self._conveyances = {lm.name for lm in kb.landmarks
                             if any(set(norm_phrase(f)) & lx.CONVEYANCE_WORDS for f in lm.surface_forms)}

    # ------------------------------------------------------------------ vocabulary
    def _role_cue_at(self, norms: tuple[str, ...], i: int, role: Role) -> bool:
        """Does a cue of a category with ``role`` start at token ``i``?"""
        h = self._cues.match_at(norms, i) if i < len(norms) else None
        return h is not None and h[1][0] in self.kb.category_by_name and self.kb.category_by_name[h[1][0]].role == role

    def _person_cue_at(self, norms: tuple[str, ...], i: int) -> bool:
        """Does a cue of the critical role start at token ``i`` ("the baker | trapped")?"""
        return self._role_cue_at(norms, i, Role.CRITICAL)

    def _bare_pair(self, norms: tuple[str, ...], a: int, b: int) -> bool:
        """"Starboard boats and port boats are both safe": two names of several words, each written with "the" in
        the KB, said side by side without it."""
        if norms[b:b + 1] in (("and",), ("or",)) and b + 1 < len(norms):
            h = self._places.match_at(norms, b + 1)
            return h is not None and h[0] - b - 1 >= 2 and norms[b + 1:h[0]] in self._needs_article
        if a >= 3 and norms[a - 1] in ("and", "or"):
            return any((h := self._places.match_at(norms, c)) is not None and h[0] == a - 1
                       and norms[c:a - 1] in self._needs_article and (c == 0 or norms[c - 1] not in lx.DETERMINERS)
                       for c in range(max(0, a - 5), a - 2))
        return False

    def _compound_forms(self) -> list[tuple[tuple[str, ...], str]]:
        """Names recombined from a landmark's own forms: "bus terminal" from "bus station" and "the terminal".

        The modifier of one multi-word form joins the head word of another form of the same
        landmark. A combination that another landmark could also produce, or that is already a
        form of some landmark, is left out.
        """
        existing = {name_words(f) for lm in self.kb.landmarks for f in lm.surface_forms}
        made: dict[tuple[str, ...], set[str]] = {}
        for lm in self.kb.landmarks:
            forms = [w for w in (name_words(f) for f in lm.surface_forms) if w]
            mods = {w[:-1] for w in forms if len(w) > 1}
            mods |= {w[:1] for w in forms if len(w) > 2 and w[0].isalpha()  # "victoria dock" for "victoria dry dock"
                     and self._name_word_owners.get(w[0], set()) <= {lm.name}}  # (a word only its names use)
            heads = {w[-1] for w in forms}
            for mod in mods:
                for head in heads:
                    key = (*mod, head)
                    if key not in existing and head not in mod and head not in _COMMON_PART_HEADS:
                        made.setdefault(key, set()).add(lm.name)  # (not "fire doors" from "fire station", "red doors")
            # ("J4" for "junction 4", "M6" for "motorway 6": a numbered name's initial and number written together)
            for form in forms:
                if len(form) == 2 and form[1].isdigit() and form[0].isalpha() and len(form[0]) >= 3:
                    if (form[0][0] + form[1],) not in existing:
                        made.setdefault((form[0][0] + form[1],), set()).add(lm.name)
            # ("A&E" alone for "a&e entrance": letters joined by an ampersand name the place on their own)
            for word in {w for form in forms for w in form if "&" in w}:
                if (word,) not in existing:
                    made.setdefault((word,), set()).add(lm.name)
        return [(key, next(iter(names))) for key, names in sorted(made.items()) if len(names) == 1]

    def _map_roles(self) -> dict[str, str | None]:
        out: dict[str, str | None] = {}
        for role in Role:
            cats = self.kb.categories_with_role(role)
            out[role.value] = cats[0].name if len(cats) == 1 else None
        return out

    def _category_for_role(self, role: str, phrase: str) -> str | None:
        cat = self._role_category.get(role)
        if cat is not None:
            return cat
        cats = self.kb.categories_with_role(role)
        if not cats:
            return None
        # words the descriptions themselves use decide first ("flooding" -> "... floodwater pouring over ...")
        # (not the words for parts and motion: "coming down" is no "water coming through floors")
        words = [w for w in norm_phrase(phrase) if _weighty(w) and w not in lx.DANGER_KIND_PARTS
                 and w not in ("come", "came", "comes", "filling", "filled", "fill", "full")]
        # (nor "filling": filled with smoke or with water, it is what fills that says the kind)
        # a phrase that says only what a category's name says first decides ("fire", "on fire" -> "fire_and_fumes",
        # though the other's description speaks of "a police or fire cordon"; not "water" for "fouled_water", a word
        # the name only qualifies, nor "fire showing", which says more)
        named = [c for c in cats if words and (name := norm_phrase(c.name.replace("_", " "))) and name[0] in words
                 and set(words) <= set(name) and name[0] not in lx.GENERIC_DANGER_WORDS]
        if len(named) == 1 and len(cats) > 1:
            return named[0].name
        described = [self._affirmed_words(c.description) for c in cats]
        overlap = [sum(any(_same_stem(w, d) for d in ds) for w in words) for ds in described]
        if overlap and max(overlap) == 1 and role == lx.UNDESIRABLE:
            # one word shared, against the whole kind of danger the phrase names: "water's coming up" where the
            # fire category speaks of escaping "hot water" and the storm one of flooded, waterlogged places
            key = norm_phrase(phrase)
            kind = self._danger_kind_by_words.get(key)
            votes = self._kind_votes(kind, cats) if kind in lx.DANGER_KINDS and not any(
                f" {' '.join(key)} " in self._description_text(c.description) for c in cats) else None
            # (not where a description says the very phrase: "tanks at risk of boiling over")
            if votes is not None and len(votes) > 1 and max(votes) >= sorted(votes)[-2] + 2:
                return cats[votes.index(max(votes))].name
        if overlap and max(overlap) > 0 and overlap.count(max(overlap)) == 1:
            return cats[overlap.index(max(overlap))].name
        if overlap and max(overlap) > 0 and not set(words) <= lx.GENERIC_DANGER_WORDS:
            # a tie of stems goes to the one that has the word itself ("blown in": "tents blown down", not "blowbacks";
            # but "dangerous" says no kind, whichever description has the very word)
            exact = [sum(w in ds for w in words) if n == max(overlap) else -1 for n, ds in zip(overlap, described, strict=True)]
            if max(exact) > 0 and exact.count(max(exact)) == 1:
                return cats[exact.index(max(exact))].name
        kind = self._danger_kind_of.get(phrase) if role == lx.UNDESIRABLE else None
        if kind is not None:
            cat = self._kind_category(kind, cats)
            if cat is not None:
                return cat
        if role == lx.CRITICAL and len(cats) > 1:
            # two critical categories, one of them for the lost: "a piper has fainted" is no lost person, whatever
            # MiniLM makes of it; "can't find my nan" is one
            lostish = [c for c in cats if _LOST_CATEGORY_WORDS & (described := set(norm_phrase(c.description)))
                       and not _HURT_CATEGORY_WORDS & described]
            said = set(norm_phrase(phrase))
            if lostish and len(lostish) < len(cats):
                if said & _SAID_LOST_WORDS:
                    if len(lostish) == 1:
                        return lostish[0].name
                elif said & _SAID_HURT_WORDS:
                    cats = [c for c in cats if c not in lostish]
                    if len(cats) == 1:
                        return cats[0].name
        if self.embedder is None:
            return cats[0].name
        vecs = self.embedder.embed([phrase] + [f"{c.name.replace('_', ' ')}: {c.description}" for c in cats])
        sims = vecs[1:] @ vecs[0]
        return cats[int(np.argmax(sims))].name

    _danger_kind_of = {p: kind for kinds in (lx.DANGER_KINDS, lx.DANGER_KIND_EXTRA)
                       for kind, phrases in kinds.items() for p in phrases}
    _danger_kind_by_words = {norm_phrase(p): kind for kinds in (lx.DANGER_KINDS, lx.DANGER_KIND_EXTRA)
                             for kind, phrases in kinds.items() for p in phrases}

    @staticmethod
    @functools.lru_cache(maxsize=256)
    def _description_text(description: str) -> str:
        """A category description as normalised words, space-padded, to find a phrase in it."""
        return f" {' '.join(norm_phrase(description))} "

    def _kind_votes(self, kind: str, cats: list[Category]) -> list[int]:
        """For each category, how many of its description's words the kind's words name (stems; no function
        word votes: "the fumes have drifted" shares "have" with "have fallen into"; nor "shedding", whose stem
        is any shed)."""
        cache = self.__dict__.setdefault("_kind_vote_cache", {})
        key = (kind, tuple(c.name for c in cats))
        if key not in cache:
            described = [self._affirmed_words(c.description) - lx.KIND_VOTE_STOPWORDS for c in cats]
            words = {w for p in lx.DANGER_KINDS[kind] for w in norm_phrase(p)
                     if (len(w) >= 4 or w in lx.SHORT_DANGER_WORDS and w == kind)
                     and w not in lx.DANGER_KIND_PARTS and w not in lx.KIND_VOTE_STOPWORDS}
            # (a kind's own short name votes: "gas" where a description says "fumes or gas")
            cache[key] = [sum(any(_same_stem(w, d) for w in words) for d in ds) for ds in described]
        return cache[key]

    def _kind_category(self, kind: str, cats: list[Category]) -> str | None:
        """The category a kind of danger (``lexicon.DANGER_KINDS``) reads as in this KB: the one whose
        description has the most words the kind's words name (stems, words for parts left out); else the
        closest in MiniLM space to the kind's words together."""
        cache = self.__dict__.setdefault("_kind_cache", {})
        if kind not in cache:
            votes = self._kind_votes(kind, cats)
            near = lx.KIND_FALLBACK.get(kind)
            if max(votes) > 0 and votes.count(max(votes)) == 1:
                cache[kind] = cats[votes.index(max(votes))].name
            elif max(votes) == 0 and near is not None and (cat := self._kind_category(near, cats)) is not None:
                cache[kind] = cat  # "smoke" where no description names it: where fire goes
            elif self.embedder is not None:
                text = ", ".join(lx.DANGER_KINDS[kind][:12])
                vecs = self.embedder.embed([text] + [f"{c.name.replace('_', ' ')}: {c.description}" for c in cats])
                cache[kind] = cats[int(np.argmax(vecs[1:] @ vecs[0]))].name
            else:
                cache[kind] = None
        return cache[kind]

    @staticmethod
    @functools.lru_cache(maxsize=256)
    def _affirmed_words(description: str) -> frozenset[str]:
        """Content words of a category description, leaving out its negated clauses ("Nothing is burning")."""
        out: set[str] = set()
        for clause in re.split(r"[.;:()\u2014\u2013]|\s-\s", description):
            if re.search(r"[a-z]_[a-z]", clause):
                continue  # "(smoke is flare_and_rubble)": a note sending a word to another category, not this one's
            # ("wind-blown embers": one word, not "blown")
            for part in clause.split(","):
                ws = norm_phrase(re.sub(r"(?<=[a-z])-(?=[a-z])", "", part))
                # ("dangerous to enter for a reason other than flames at it": what the category leaves to another)
                cut = next((i for i in range(len(ws)) if ws[i:i + 2] in (("other", "than"), ("rather", "than"),
                                                                         ("apart", "from")) or ws[i] in ("except", "excluding")), None)
                if cut is not None:
                    out.update(w for w in ws[:cut] if _weighty(w))
                    continue
                neg = next((i for i, w in enumerate(ws) if w in lx.NEGATORS), None)
                if neg is None:
                    out.update(w for w in ws if _weighty(w))
                    continue
                rel = next((i for i, w in enumerate(ws[:neg]) if w in ("where", "which", "when", "that")), None)
                if rel is None:
                    break  # "Nothing is burning, smoke or fire": the negation runs on through the clause's list
                # "water where it should not be, such as ...": only the relative clause is negated
                out.update(w for w in ws[:rel] if _weighty(w))
        return frozenset(out)

    def _build_cues(self) -> None:
        entries: dict[tuple[str, ...], tuple[str, str]] = {}
        # 1. role vocabulary (weakest), mapped onto the KB's categories
        for phrase, role in lx.ROLE_CUES.items():
            cat = self._category_for_role(role, phrase)
            if cat:
                entries[norm_phrase(phrase)] = (cat, "lexicon")
        violent = [c for c in self.kb.categories if c.role == Role.UNDESIRABLE
                   and set(norm_phrase(c.description)) & {norm(w) for w in lx.VIOLENCE_WORDS}]
        if len(violent) == 1:
            # 1a. a fight, where the KB's own words count violence a danger
            for phrase in lx.VIOLENCE_CUES:
                entries.setdefault(norm_phrase(phrase), (violent[0].name, "lexicon"))
        if self._animal_category is not None:
            # 1b. animals in trouble, where the KB has a category for them ("a bullock loose", "ewes swimming")
            for animal in lx.ANIMAL_WORDS:
                for state in lx.ANIMAL_TROUBLE:
                    entries.setdefault(norm_phrase(f"{animal} {state}"), (self._animal_category, "lexicon"))
        # 2. words listed in category descriptions, e.g. "(fire, gas, collapse, flooding)"
        for cat in self.kb.categories:
            for inner in re.findall(r"\(([^)]*)\)", cat.description):
                shared = None  # "(burning bins, cars, tyres, a gas leak)": "burning" goes with the bare nouns after it
                for n, part in enumerate(re.split(r",|;|\bor\b|\band\b", inner)):
                    key = norm_phrase(part)
                    if n == 0 and len(key) == 2 and key[0].endswith("ing"):
                        shared = key[0]
                    elif shared is not None and len(key) == 1 and not key[0].endswith("ing"):
                        key = (shared, key[0])
                    if len(key) == 1 and key[0] in lx.VEHICLE_WORDS:
                        continue  # ("burning buildings or cars": a car is no danger said alone)
                    if 0 < len(key) <= 3 and not (set(key) & {"e", "g", "eg", "etc"}):
                        entries[key] = (cat.name, "category")
        # 2b. a list after a colon or a dash: "Structural damage - collapsed or loose masonry, fallen trees"; the
        # KB's own words for its category, where the vocabulary has no word yet
        for cat in self.kb.categories:
            for key in _description_list_items(cat.description):
                entries.setdefault(key, (cat.name, "category"))
        # 2c. dangers only some KBs count, said in words their descriptions use ("failed building services ...
        # live or arcing electrics": "the lights are out" is one there, no danger in a town square)
        undesirable = self.kb.categories_with_role(Role.UNDESIRABLE)
        for triggers, phrases in lx.DESCRIBED_KINDS.values():
            named = [c for c in undesirable
                     if any(re.search(rf"\b{re.escape(t)}", c.description.lower()) for t in triggers)]
            if len(named) == 1:
                for phrase in phrases:
                    entries.setdefault(norm_phrase(phrase), (named[0].name, "category"))
        # 2d. comforts a KB's one safe-place category names ("out of the heat ..., with shade, water, clean air or
        # generator power": "the generator's running" there)
        desirable = self.kb.categories_with_role(Role.DESIRABLE)
        if len(desirable) == 1:
            said = " ".join(norm_phrase(desirable[0].description))
            for comfort, (triggers, phrases) in lx.DESCRIBED_COMFORTS.items():
                if any(re.search(rf"\b{re.escape(' '.join(norm_phrase(t)))}\b", said) for t in triggers):
                    for phrase in phrases:
                        entries.setdefault(norm_phrase(phrase), (desirable[0].name, "category"))
                    if comfort == "water":  # a tank or pool "full to the brim" is a water supply there, no flood
                        for phrase in lx.WATER_SUPPLY_FULL:
                            entries[norm_phrase(phrase)] = (desirable[0].name, "category")
        # 3. category names themselves ("hazard", "safe zone")
        for cat in self.kb.categories:
            entries[norm_phrase(cat.name.replace("_", " "))] = (cat.name, "category")
        # 4. the glossary (strongest: the KB says so explicitly)
        place_keys = {k[1:] if k[:1] == ("the",) else k for lm in self.kb.landmarks
                      for k in (norm_phrase(f) for f in lm.surface_forms)}
        for term in self.kb.glossary:
            key = norm_phrase(term.term)
            entries[key] = (term.category, "glossary")
            # "range is hot" where "the range" is a place: what the term says of it, said after the place
            rest = next((key[n:] for n in range(len(key) - 1, 0, -1) if key[:n] in place_keys), ())
            if len(rest) >= 2:
                entries.setdefault(rest, (term.category, "glossary"))
        for term in self.kb.glossary:
            for form in _verb_forms(term.term) + _determined_forms(term.term) + _event_forms(term.term) \
                    + _particle_verb_forms(term.term):
                # "undercut": "the spate is undercutting its back wall"; "dropped plug": "she's dropped her plug"
                entries.setdefault(norm_phrase(form), (term.category, "glossary"))
        for phrase in lx.NEUTRAL_PHRASES:
            entries[norm_phrase(phrase)] = ("", "neutral")
        for key, val in list(entries.items()):
            # "ammonia leek": a leak misspelt as it sounds, inside a phrase of more words (not "the leek beds")
            if len(key) >= 2 and val[1] != "neutral" and any(w in _SOUND_ALIKE_WORDS for w in key):
                entries.setdefault(tuple(_SOUND_ALIKE_WORDS.get(w, w) for w in key), val)
        for key, val in entries.items():
            self._cues.add(key, val)

    def _build_relations(self) -> None:
        """Surface forms of every relation: synonym groups plus forms derived from the KB's own names.

        The matcher maps a phrase to ``(relation phrase, inverse)``; ``inverse`` means the report
        reads the relation backwards ("downstream of" for ``upstream_of``, "overlooked by" for
        ``overlooks``).
        """
        forms: dict[tuple[str, ...], tuple[str, bool]] = {}
        for canon, syns in lx.RELATION_SYNONYMS.items():
            for syn in syns:
                forms[norm_phrase(syn)] = (canon, False)
        # a synonym group that a KB relation is named by ("directly_above" for "above") stays that
        # relation's, even where another relation reads it backwards ("at_the_foot_of", a "below" word)
        owned = {core: rel.phrase for rel in self.kb.relations
                 if (core := _relation_core(rel.phrase)) in lx.RELATION_SYNONYMS}
        for canon, phrase in list(owned.items()):  # ... and its opposite group, which reads it backwards
            opposite = lx.INVERSE_PHRASES.get(canon)
            if opposite:
                owned.setdefault(opposite, phrase)
        own_names = {norm_phrase(rel.phrase): rel.phrase for rel in self.kb.relations}
        kb_phrases = set(own_names.values())
        # synonym groups a KB relation is said by ("underneath" is a "below" word): read forwards first
        kb_groups = {canon for canon, syns in lx.RELATION_SYNONYMS.items() for rel in self.kb.relations
                     if len(rel.phrase.split()) == 1 and rel.phrase in syns}
        for rel in self.kb.relations:
            name = set(norm_phrase(rel.phrase))
            for form, inverse in _relation_forms(rel.phrase):
                key = norm_phrase(form)
                if own_names.get(key, rel.phrase) != rel.phrase:
                    continue  # the KB's own name, "downhill_from", is that relation's, whatever group has its words
                held = forms.get(key)
                if held is not None and owned.get(held[0], rel.phrase) != rel.phrase and not name <= set(key):
                    continue
                if inverse and held is not None and not held[1] and (held[0] in kb_phrases or held[0] in kb_groups) \
                        and held[0] != rel.phrase:
                    continue  # "at the foot of": ``sits_at_the_foot_of`` says it, ``looks_out_over`` only reads it backwards
                forms[key] = (rel.phrase, inverse)
        for rel in self.kb.relations:
            # "the building at the top of the path" for ``zigzag path leads_up_to mountain hut``: where a way leads up
            # (or down) to is at its top (or its bottom); only where no relation of the KB is named so
            words = rel.phrase.replace("_", " ").split()
            if len(words) >= 3 and words[0] in _WAY_VERBS and words[-2] in ("up", "down") and words[-1] in ("to", "into", "onto"):
                for end in (("top", "top end", "head") if words[-2] == "up" else ("bottom", "bottom end", "foot")):
                    forms.setdefault(norm_phrase(f"at the {end} of"), (rel.phrase, True))
        kb_named = {val[0] for val in forms.values()} & {rel.phrase for rel in self.kb.relations}
        kb_exact = {norm_phrase(rel.phrase.replace("_", " ")): rel.phrase for rel in self.kb.relations}
        for key, val in list(forms.items()):
            if len(key) >= 3 and key[0] in ("that", "which") and (val[0] not in kb_named or kb_exact.get(key[1:]) not in (
                    None, val[0])) and forms.get(key[1:], val)[0] in kb_named:
                forms[key] = forms[key[1:]]  # "the houses that back onto it": the KB's own ``back onto``, not "behind"
                # (also where the KB has a ``behind`` of its own: the words are those of ``back onto``)
        for key, val in list(forms.items()):
            if len(key) >= 2 and key[-1] == "from" and val[0] in kb_phrases and key[-2].endswith("ed"):
                forms.setdefault((*key[:-1], "off"), val)  # "the station that's fed off it" for ``is fed from``
        for key, val in list(forms.items()):
            for adverb in lx.RELATION_ADVERBS:
                forms.setdefault((adverb, *key), val)
            bare = tuple(w for w in key if w != "the")
            if len(bare) >= 2 and bare != key:
                forms.setdefault(bare, val)  # a log drops articles: "bldg over rd from community hall"
            for n, w in enumerate(key[1:-3], start=1):  # (an article with a noun and a word after it: not "at its top")
                if w in ("a", "an", "the", "its", "their"):
                    for other in ("a", "an", "the", "its", "their"):
                        # "shares the oven wall with" for `shares an oven wall with`
                        forms.setdefault((*key[:n], other, *key[n + 1:]), val)
        for key, val in forms.items():
            self._relations.add(key, val)

    def _unique_stems(self, usable: Callable[[str], bool]) -> dict[str, str]:
        """Stems of the usable words of the KB's relation names -> the one relation name that has them.

        A stem that two relation names share is left out: it would not tell them apart."""
        own: dict[str, set[str]] = {}  # the word's own stem
        synonym: dict[str, set[str]] = {}  # stems of its link synonyms
        for rel in self.kb.relations:
            for w in rel.phrase.split():
                if len(w) >= 3 and usable(w):
                    stems = _link_stems(w)
                    mine = _link_stems(w, synonyms=False)
                    for stem in stems:
                        (own if stem in mine else synonym).setdefault(stem, set()).add(rel.phrase)
        out = {stem: next(iter(rels)) for stem, rels in synonym.items() if len(rels) == 1}
        # a relation whose name has the word itself wins over one that has only a synonym of it
        # ("feeds_fuel_to" owns "feed" next to "serves")
        out.update({stem: next(iter(rels)) for stem, rels in own.items() if len(rels) == 1})
        for stem, rels in own.items():
            if len(rels) > 1:
                out.pop(stem, None)
        return out

    def _relation_keywords(self) -> dict[str, tuple[str, str]]:
        """Stems of the distinctive words of the KB's relation names -> (relation phrase, voice).

        ``voice`` is "passive" for names such as ``supplied_by`` (said backwards as "the plant
        that supplies X"), "active" for verbs such as ``tunnels_into``, else "other".
        """
        voice: dict[str, str] = {}
        for rel in self.kb.relations:
            words = rel.phrase.split()
            if _passive_name(rel.phrase):
                voice[rel.phrase] = "passive"
            elif words and words[0].endswith("s") and not words[0].endswith("ss") and not _direction_word(words[0]):
                voice[rel.phrase] = "active"
            else:
                voice.setdefault(rel.phrase, "other")
        # (not a word of the KB's own names: "car park" of "is the customer car park for" where "upper car park"
        # and "lower car park" are landmarks)
        tails = {words[-n:] for lm in self.kb.landmarks for f in lm.surface_forms
                 for words in [name_words(f)] for n in range(2, len(words) + 1)}
        named = {w for rel in self.kb.relations for words in [tuple(norm_phrase(rel.phrase))]
                 for i in range(len(words)) for n in (2, 3) if words[i:i + n] in tails for w in words[i:i + n]}
        stems = self._unique_stems(lambda w: w not in lx.RELATION_NAME_STOPWORDS and not _direction_word(w)
                                   and w not in lx.DIRECTION_FAMILIES and w not in named)
        return {stem: (phrase, voice[phrase]) for stem, phrase in stems.items()}

    def _keyword_relation(self, word: str) -> tuple[str, str] | None:
        if word in lx.RELATION_NAME_STOPWORDS or len(word) < 3:
            return None
        own = _link_stems(word, synonyms=False)
        # the word's own stem before its synonyms, an exact stem before a compound; fixed order
        stems = sorted(own) + sorted(_link_stems(word) - own)
        for stem in stems:
            if stem in self._rel_keywords:
                return self._rel_keywords[stem]
        for stem in stems:
            for key, hit in self._rel_keyword_items:
                if min(len(stem), len(key)) >= 5 and (stem.endswith(key) or key.endswith(stem)):
                    return hit
        return None

    def _remap_absent_group(self, norms: tuple[str, ...],
                            hit: tuple[int, int, tuple[str, bool]]) -> tuple[int, int, tuple[str, bool]]:
        """A listed phrase whose relation group the KB lacks ("backing onto" is ``behind``) is read as
        the KB relation that shares one of its words ("back_to_back_with"), or else the one the head
        noun names ("the annexe tacked onto X": ``annexe_of``)."""
        a, b, (phrase, flipped) = hit
        if any(self._relation_matches(rel, phrase) for rel in self.kb.relations) or phrase in lx.INVERSE_PHRASES \
                and any(self._relation_matches(rel, lx.INVERSE_PHRASES[phrase]) for rel in self.kb.relations):
            return hit
        weak = self._weak_keywords()
        for w in norms[a:b]:
            for stem in _link_stems(w):
                if stem in weak:
                    return a, b, (weak[stem], False)
        if a > 0:
            head = self._keyword_relation(norms[a - 1])
            if head is not None:
                return a, b, (head[0], False)
        return hit

    def _weak_keywords(self) -> dict[str, str]:
        """Stems of every word of the KB's relation names but function words, each naming one relation."""
        if getattr(self, "_weak_cache", None) is None:
            function_words = lx.RELATION_ENDINGS | {"the", "a", "an", "is", "and", "into", "at", "in"}
            self._weak_cache = self._unique_stems(lambda w: w not in function_words)
        return self._weak_cache

    def _keyword_hits(self, toks: Tokens, norms: tuple[str, ...], covered: set[int],
                      cue_tokens: set[int], known: set[int]) -> list[tuple[int, int, tuple[str, bool]]]:
        """Relation phrases the tables do not list, found by a distinctive word of a KB relation name:
        "the block at the other end of the service tunnel from X" (``connected_by_tunnel_to``),
        "the tower bridged to it" (``linked_by_skybridge_to``), "the tunnel that feeds X" (``fed_by``)."""
        out: list[tuple[int, int, tuple[str, bool]]] = []
        if not self._rel_keywords:
            return out
        taken = set(covered)
        for t in range(len(norms)):
            k = t + 1  # past the verb's particles: "leaning on the shed", "spreading out below the old mill"
            while t in cue_tokens and k < min(t + 3, len(norms)) \
                    and norms[k] in lx.RELATION_ENDINGS | {"out", "up", "down", "into", "in"} and not toks.clause_start[k]:
                k += 1
            if t in cue_tokens and t not in known and t > 0 and (norms[t - 1] in ("that", "which")
                                              or norms[t - 1] not in lx.COPULAS | lx.DETERMINERS | {"re", "ve"}) \
                    and norms[k:k + 1] and norms[k] in lx.ARTICLES \
                    and (k + 1 in covered or k > t + 1 and k + 1 < len(norms) and self._place_head_word(norms[k + 1])) \
                    and not toks.clause_start[t] and self._keyword_relation(toks.tokens[t].text.lower()) is not None \
                    and toks.tokens[t].text.lower().endswith(("ing", "ed", "s")):
                pass  # "the wall sheltering the towpath": a cue word ("shelter") used as the relation's verb (not a noun:
                # "fence down on the deer fence")
            elif t in taken or t in cue_tokens or t in known or t + 1 in known:
                continue  # (a word right before a listed phrase heads it: "the annexe tacked onto X")
            word = toks.tokens[t].text
            opening = toks.clause_start[t] or t > 0 and norms[t - 1] in lx.ARTICLES and toks.clause_start[t - 1] \
                or t > 0 and norms[t - 1] == "and" and t + 1 < len(norms) and norms[t + 1] in ("are", "were")
            # ("The chapel and vestry are under a foot of water": a subject, not ``shares_a_vestry_wall_with``)
            if opening and (word.lower().endswith(("'s", "’s")) or t + 1 < len(norms)
                            and (norms[t + 1] in ("is", "are", "was", "were", "has", "s")
                                 or toks.tokens[t + 1].text.lower().endswith("ing")
                                 and not word.lower().endswith(("ing", "ed")))):
                continue  # "Water's pouring through ...", "Water is up over ...": a subject, not "lifts_water_out_of"
                # ("Waves coming straight over the wall": not ``keeps_the_waves_off``)
            if opening and norms[t + 1:t + 2] == ("of",) \
                    and norms[t] in ("bank", "banks", "edge", "side", "shore", "foot", "top", "end"):
                continue  # "bank of the acid creek has slumped": the creek's own bank, not ``stands_on_the_bank_of``
            if t > 0 and word[:1].isupper() and not word.isupper() and toks.tokens[t - 1].text[:1].isupper() \
                    and not toks.sentence_start[t]:
                continue  # "Red Watch to TCC": a word of a name, not a relation's verb
            hit = self._keyword_relation(word.lower())
            if hit is None:
                continue
            if t > 0 and toks.tokens[t - 1].text.lower().replace("’", "'") in ("that's", "it's") \
                    and not word.lower().endswith(("ed", "ing", "s")):
                continue  # "no, that's steam off the refinery stack": what it is, not ``sends steam and power to``
            if t > 0 and (is_number(norms[t - 1]) or norms[t - 1] in lx.NUMBER_WORDS) and not word.lower().endswith(("ed", "ing")):
                continue  # "two wagons on their sides": things counted, not ``loads_wagons_at``
            verb = hit[0].replace("_", " ").split()[0]
            if t > 0 and norms[t - 1] == "the" and verb.endswith("s") and not verb.endswith("ss") \
                    and toks.tokens[t].text.lower() == verb[:-1] and t + 1 < len(norms) and norms[t + 1] in lx.ARTICLES:
                continue  # "the tarmac over the pipe the beck drains through": a noun heading a clause, not ``pipes ...``
            rel_words = hit[0].replace("_", " ").split()
            if t > 0 and norms[t - 1] in ("the", "a", "an") and t + 1 < len(norms) and norms[t + 1] in ("the", "a", "an") \
                    and not toks.clause_start[t + 1] and not word.lower().endswith(("ed", "ing", "s")) \
                    and norm(rel_words[0]) != norms[t] \
                    and (end := next((m for m in range(t + 2, min(len(norms), t + 10)) if toks.clause_start[m]),
                                     min(len(norms), t + 10))) > t + 2 \
                    and norms[end - 1] in _STRANDED_ENDS and rel_words[-1] in _STRANDED_ENDS \
                    and norms[end - 1] != rel_words[-1]:
                continue  # "the water the pump house draws from": a noun heading a clause that ends the other way
                # from the relation (``pumps water up to``)
            if t > 0 and ("a" in norms[max(0, t - 2):t] or "an" in norms[max(0, t - 2):t]) \
                    and not _same_stem(norms[t], hit[0].split()[0]) and not word.lower().endswith(("ed", "ing")):
                continue  # "there's a derailed wagon on it": a thing, not the noun inside ``loads_wagons_at``
            if t + 1 < len(norms) and ":" in toks.gaps[t + 1]:
                continue  # "From the medical lead: the saucer ...": a speaker's label, not "leads_off"
            if t > 0 and norms[t - 1].endswith("ing") and norms[t] in _PEOPLE_WORDS | {"camper", "visitor", "guest"}:
                continue  # "we're walking campers out through the gate": the people moved, not ``lets_the_campers_into``
            if t >= 2 and word.lower().endswith("ing") and toks.tokens[t - 1].text.lower().replace("’", "'").endswith("'s") \
                    and (t - 1) not in covered and norms[t - 1] not in lx.GENERIC_HEADS | lx.DESCRIPTION_HEADS \
                    and norms[t - 2] in lx.ARTICLES:
                continue  # "the wind's keeping the smoke off us": that clause's own verb, not ``keeps_watch_over``
            if norms[t] in lx.PART_NOUNS | lx.PREMISES_PARTS and t + 1 < len(norms) and norms[t + 1] == "of":
                continue  # "the back wall of the Stella" is part of it, not "shares_a_wall_with"
            if norms[t] in ("back", "front", "side") and norms[t + 1:t + 2] and norms[t + 1] in lx.PREMISES_PARTS \
                    and norms[t + 2:t + 3] == ("of",):
                continue  # "the back yard of the pink": its own yard, not ``shares_a_back_yard_with``
            if norms[t] in ("top", "bottom", "back", "front") and t > 0 and norms[t - 1] in ("up", "on", "at", "down", "out") \
                    and norms[t + 1:t + 2] != ("of",):
                continue  # "the big one up top", "out back": where, not ``tops_up`` or ``backs_onto``
            if t > 0 and (norms[t - 1] in lx.COPULAS or toks.tokens[t - 1].text.lower().endswith(("'s", "’s"))) \
                    and hit[0].split()[0].startswith(norms[t]) and norms[t] != hit[0].split()[0]:
                continue  # "apron's open": a state, not "opens_onto"
            if t >= 2 and norms[t - 1] in lx.COPULAS and norms[t - 2] in lx.PART_NOUNS | lx.DANGER_KIND_PARTS \
                    and word.lower().endswith("ed"):
                continue  # "the book barn's roof is rolled back": a state of a part, not "rolls_down_to"
            if toks.clause_start[t] and t + 1 < len(norms) and norms[t + 1] in lx.MOVED_PEOPLE | {
                    "them", "it", "clear", "away", "out", "back", "off", "everybody"}:
                continue  # "..., keep everyone clear of them": an order, not "keeps_watch_over"
            said = [w for w in norms[max(0, t - 4):t] if w not in lx.FILLERS | lx.SENTENCE_ADVERBS]
            if said and said[-1] in ("is", "are", "was", "were", "s", "re") \
                    and any(f"{art} {word.lower()}" in hit[0].replace("_", " ") for art in ("the", "a")):
                continue  # "the top plots are just er glass everywhere": a noun of the relation's name said as a state
            back = [w for w in norms[max(0, t - 4):t] if w not in ("ve", "have", "had", "just", "now", "already", "d")]
            if back and back[-1] in ("i", "we", "they", "he", "she", "you", "ive", "weve", "theyve", "youve", "wed", "theyd") \
                    and norms[t + 1:t + 2] \
                    and (norms[t + 1] in lx.DETERMINERS or t + 1 in covered) and norms[t].endswith("ed"):
                continue  # "we've opened the parish church as a rest centre": the speaker's deed, not "opens_onto"
            if back and back[-1] in ("im", "were", "am", "m") and norms[t].endswith("ed"):
                continue  # "I'm parked up on the headland car park": where the speaker is, not "car park for"
            if t > 0 and norms[t - 1] in ("who", "whos"):
                continue  # "the stoker -- the bloke who stokes it": what a person does, not ``is_stoked_from``
            if t > 0 and (t - 1) in cue_tokens and word.lower().endswith("ing"):
                continue  # "smoke pouring out of the place ...": the danger's own verb, not ``pours_for_the_boaters_on``
            if norms[t] in lx.HEARSAY_VERBS and norms[t + 1:t + 2] not in (("its",), ("their",)):
                continue  # "lads from tin town say the cottage ...": who tells it, not ``says_its_prayers_at``
            obj = [w for w in norms[max(0, t - 4):t] if w not in lx.FILLERS | lx.ARTICLES | {"all", "both", "our"}]
            if norms[t] in lx.MOVED_PEOPLE and obj and obj[-1] in lx.MOVING_VERBS:
                continue  # "I've walked all the guests up to the Fellside": whom we moved, not "built_for_the_guests_of"
            if norms[t + 1:t + 2] in (("it",), ("them",)) and t > 0 and norms[t - 1] in (
                    "cant", "cannot", "couldnt", "wont", "can", "could", "to", "dont", "didnt"):
                continue  # "they can't open it from their side": a deed done to it, not ``opens off``
            noun = not _same_stem(norms[t], hit[0].replace("_", " ").split()[0]) \
                and not word.lower().endswith(("ed", "ing"))
            anchor_hit = self._places.match_at(norms, t + 2) if noun and t + 2 < len(norms) else None
            if noun and t > 0 and norms[t - 1] in lx.DETERMINERS and norms[t + 1:t + 2] in (("the",), ("a",), ("an",)) \
                    and anchor_hit is not None and not any(
                        r.phrase == hit[0] and anchor_hit[1] in (r.subject, r.object) for r in self.kb.relations) and any(
                    t + 1 < k <= t + 6 and not any(toks.clause_start[m] for m in range(t + 1, k + 1)) for k in known):
                continue  # "the water the dam holds back": a noun of a relation's name heading a description whose
                # own words the tables list further on
            phrase, voice = hit
            if voice == "active" and t > 0 and norms[t - 1] in lx.ARTICLES - {"that"} and phrase.split()[0] in (
                    norms[t], toks.tokens[t].text.lower()):
                continue  # "the vents on the forecourt": the verb of ``vents_into`` said as a noun
            if t > 0 and norms[t - 1] in lx.ARTICLES - {"that"} and self._place_head_word(norms[t]) \
                    and _link_stems(phrase.split()[0], synonyms=False) & _link_stems(norms[t], synonyms=False):
                continue  # "the stand the fan zone is set up behind": a word names end in, not "stands_on_..."
            particles = set(phrase.split()[1:]) & _PARTICLES
            if len(particles) >= 2 and t + 1 < len(norms) and norms[t + 1] in ("on", "onto", "in", "into", "at") \
                    and not {norms[t + 1], *_SAME_PARTICLE.get(norms[t + 1], ())} & particles \
                    and _same_stem(norms[t], phrase.split()[0]) \
                    and not toks.clause_start[t + 1]:
                continue  # "dropping on the larch plantation" is no ``drops down from``: another particle
            b = t + 1
            for j in range(t + 1, min(t + 4, len(norms))):
                if j in taken or toks.clause_start[j] or norms[j] in lx.COPULAS:
                    break  # ("the river it crosses is way over its banks": the verb ends there, a clause goes on)
                if j == t + 1 and norms[j] in ("up", "down", "off", "back") and j + 1 < len(norms) \
                        and norms[j + 1] in lx.RELATION_ENDINGS | {"at", "into", "by"} and j + 1 not in taken \
                        and not toks.clause_start[j + 1] and not set(phrase.replace("_", " ").split()[1:-1]) & _OWN_PARTICLES \
                        and not (back and back[-1] in ("im", "were", "am", "m", "we", "i")):
                    # (not where the relation has a particle of its own, "looking up at" for ``looks out over``, nor
                    # where the speaker is: "we're parked up at")
                    b = j + 2  # "the boat tied up at the jetty": a particle, then the preposition
                    break
                if norms[j] in lx.RELATION_ENDINGS | {"into", "by"}:
                    b = j + 1
                    if b < len(norms) and norms[j] in ("on", "up", "down", "out", "off", "over") \
                            and norms[b] in ("from", "to", "of", "onto", "with") and not toks.clause_start[b]:
                        b += 1  # "carries on from", "looks out over", "climbs up to": the particle and its preposition
                    break
            a = t
            while a > 0 and t - a < 8 and not toks.clause_start[a] and (a - 1) not in taken | known | cue_tokens:
                w = norms[a - 1]
                if w in lx.GENERIC_HEADS and a - 1 > 0 and norms[a - 2] in lx.DETERMINERS:
                    break
                if w in lx.COORDINATORS or w in lx.PRONOUNS - {"that"}:
                    break
                if a - 1 > 0 and norms[a - 2] in lx.ARTICLES and w.isalpha() and len(w) >= 3 and w not in lx.PREPOSITIONS \
                        and w not in lx.COPULAS and w not in lx.FILLERS and w not in lx.DETERMINERS:
                    break  # "the compound that supplies it": any noun after an article heads the description
                a -= 1
            word = toks.tokens[t].text.lower()
            passive_here = "by" in norms[t + 1 : b] or word.endswith(("ed", "en")) or word in lx.IRREGULAR_PARTICIPLES
            flipped = (voice == "passive" and not passive_here) or (voice == "active" and "by" in norms[t + 1 : b])
            first = phrase.split()[0]
            if voice == "other" and first.endswith("ed") and not passive_here \
                    and word.endswith(("ing", "s")) and _same_stem(word.rstrip("s"), first):
                flipped = not flipped  # "the wall sheltering the towpath" for ``towpath sheltered_behind flood wall``
            if any(lx.ANTONYMS.get(w) in phrase.split() for w in norms[a:b]):
                flipped = not flipped
            out.append((a, b, (phrase, flipped)))
            taken.update(range(a, b))
        return out

    # ------------------------------------------------------------------ extract
    def tokens(self, text: str) -> Tokens:
        """The report's tokens as the analyzer reads them: slips of the words it knows respelled."""
        with self._call_lock:
            return self._respell(tokenize(text))

    def extract(self, text: str) -> Extraction:
        """Place mentions with their status, and the repair markers (thread-safe)."""
        with self._call_lock:
            return self._extract(text)

    def _extract(self, text: str) -> Extraction:
        toks = self._respell(tokenize(text))
        norms = toks.norms(0, len(toks))
        places: list[PlaceMention] = []
        all_cues = self._cues.find_all(norms)
        all_relations = self._relations.find_all(norms)
        cue_spans = [(a, b) for a, b, _ in all_cues if b - a > 1]
        cue_hits = cue_spans + [(a, b) for a, b, _ in all_relations if b - a > 2]
        log = _is_log(toks)
        glossary_ends = {cb for ca, cb, (_, src) in all_cues if src == "glossary" and cb - ca > 1
                         and norms[cb - 1] not in lx.GENERIC_HEADS | lx.UNNAMING_HEADS | lx.DESCRIPTION_HEADS}
        # a cue that is only a preposition before a place's name ("casualty in the river" where "the river" is
        # one): the place, not the cue
        place_cues = set(cue_spans)
        place_hits = list(self._places.find_all(norms))
        # "people from café they go to laundry next door to lobby": a speaker who leaves out the articles the KB writes
        # its names with, said so of two names or more
        bare = {a for a, b, _ in place_hits if b - a == 1 and norms[a:b] in self._needs_article and a > 0
                and norms[a - 1] in ("to", "from", "in", "at", "into", "inside") and not toks.clause_start[a]}
        learner_bare = bare if len({norms[a] for a in bare}) >= 2 else set()
        for a, b, landmark in place_hits:
            if any(ca <= a and b <= cb and cb - ca > b - a and not (
                    (ca, cb) in place_cues and cb == b and a - ca <= 2
                    and all(norms[i] in lx.PREPOSITIONS or norms[i] in lx.ARTICLES for i in range(ca, a)))
                   for ca, cb in cue_hits) and not (
                    b in glossary_ends and not any(ca <= a and b <= cb and cb - ca > b - a and cb not in glossary_ends
                                                   for ca, cb in cue_hits)
                    and not self._bare_in_glossary(norms, a, b, all_cues)):
                # ("a backed-up goit", "water over the hatches": a glossary term that ends in a place's name names it)
                continue  # "first aid post" is a cue, "across the square from" a relation
            if b - a == 1 and self._plural_only.get(norms[a:b]) == landmark \
                    and toks.tokens[a].text.lower().replace("’", "'").removesuffix("'s") == norms[a]:
                continue  # "the hall's unsafe" is not "the halls" (of residence) where "the main hall" is a name
            if self._possessive_only and tuple(w for w in norms[a:b] if w != "the") in self._possessive_only \
                    and not toks.tokens[b - 1].text.lower().replace("’", "'").endswith(("'s", "s")) \
                    and norms[max(0, a - 2):a] in (("for", "the"), ("call", "the"), ("get", "the"), ("fetch", "the")):
                continue  # "sitting on the ROM pad waiting for the medic": the person, not "the medic's" (nor
                # "the mechanics", typed without its apostrophe)
            if b - a == 1 and norms[a] in lx.BODY_PARTS and a >= 2 and norms[a - 1] == "the" \
                    and norms[a - 2] in ("to", "on", "from") and any(norms[m] in lx.INJURY_WORDS | {"bleeding"}
                                                                    for m in range(max(0, a - 5), a - 2)):
                continue  # "a casualty with burns to the face": a body part, not "the face" of a quarry
            if b - a == 1 and norms[a] in lx.PHONETIC_LETTERS and (
                    b < len(norms) and is_number(norms[b]) and not toks.clause_start[b]
                    or a > 0 and norms[a - 1] == "to" and not toks.clause_start[a]
                    and any(toks.sentence_start[j] for j in range(max(0, a - 3), a))):
                continue  # "Control to Alpha one", "Oscar Two here": a call sign, not the spoken letter of a place
            if norms[b:b + 1] == ("control",) and (b + 1 == len(norms) or toks.clause_start[b + 1]) \
                    and (a == 0 or toks.sentence_start[a] or norms[a - 1] in ("to", "from")
                         or norms[max(0, a - 2):a] == ("this", "is")):
                continue  # "Carran control, this is Fire One", "Lifeboat to Carran control.": the radio station
                # named after the place is called, nothing is said of the place
            if a == 0 and norms[a:b] in lx.CALL_RECEIVERS and norms[b:b + 1] in (("relaying",), ("here",), ("to",)):
                continue  # "Dispatch relaying from the co-op manager: ...": the control room, not a place called so
            prev = norms[a - 1] if a > 0 else ""
            k = a - 1
            while k > 0 and a - k <= 2 and (norms[k] in lx.NAME_ADJECTIVES or norms[k] in lx.HESITATIONS
                                             or norms[k] in _SUBSTANCE_MODIFIERS and k == a - 1 and b - a >= 2
                                             or norms[k] in _SITE_MODIFIERS and k == a - 1 and b - a >= 2
                                             and self._places.match_at(norms, k) is None) \
                    and not toks.clause_start[k + 1]:
                k -= 1  # "the big rusty dredger", "the sch school": the article before the adjectives or a word begun
                # ("the factory car park": the site the KB covers, said before a name of two words)
            if k < a - 1 and norms[k] in lx.ARTICLES:
                prev = norms[k]
            acronym = b == a + 1 and a > 0 and len(toks.tokens[a].text) >= 2 and toks.tokens[a].text.isupper()
            # (not the first word: "ECR to bridge" is who calls)
            heading = (a == 0 or toks.sentence_start[a]) and b < len(norms) and (
                toks.gaps[b].strip().startswith(":") or b + 1 < len(norms) and toks.gaps[b + 1].strip().startswith(":")
                and norms[b] in lx.PART_NOUNS | lx.LOCATIVE_PARTS | {"steps", "step"})  # ("Cenotaph steps: ...")
            heading = heading or (a == 0 or toks.sentence_start[a]) and toks.tokens[a].text[:1].isupper() \
                and norms[b:b + 1] == ("to",) and b + 1 < len(norms) and toks.tokens[b + 1].text[:1].isupper()
            # ("Wetsuit Shack to Lake Rescue.": a place calling by its name, the article left off as call signs do)
            heading = heading or (a == 0 or toks.sentence_start[a]) and b + 1 < len(norms) \
                and norms[b] in lx.ROLE_LABELS | lx.SPEAKER_ROLES \
                and (norms[b + 1] == "here" or norms[b + 1:b + 4] == ("on", "the", "phone")) \
                or (a == 0 or toks.sentence_start[a]) and norms[b:b + 1] == ("here",) \
                and (b + 1 == len(norms) or toks.sentence_start[b + 1] or ":" in toks.gaps[b + 1])
            # ("TV compound here. Our generator took a lightning strike": who calls, from where)
            # ("Little railway driver here: my train's stalled": who calls, by the place they work)
            if norms[a:b] in self._derived_keys and norms[b - 1] in lx.STOREY_WORDS and "of" in norms[b:b + 2]:
                continue  # "smoke from the top floor windows of the barracks": a storey of that place, no "upper gun floor"
            if norms[a:b] in self._derived_keys and prev in ("a", "an", "another"):
                continue  # "he fell off the back of a hire boat": any boat, not the hire base's "kingfisher boats"
            if norms[a:b] in self._needs_article and b - a == 1 and norms[b:b + 1] == ("of",) and b + 2 < len(norms) \
                    and (h := self._places.match_at(norms, b + 2 if norms[b + 1] in lx.ARTICLES else b + 1)) is not None \
                    and h[1] != landmark:
                continue  # "sitting on the step of the dining hall": a part of another place, not "the steps"
            if norms[a:b] in self._needs_article and prev in ("a", "an", "another") and b - a == 1 \
                    and (toks.tokens[a - 1].text.islower() or norms[b:b + 1] == ("of",)):
                # (not a letter that labels it: "the A cabins"; but "A stack of casing rolled")
                continue  # "a horse down in a box": the KB's "the box" is one place, "a box" any
            if norms[a:b] in self._needs_article and prev in ("that", "which") and b - a == 1 and b < len(norms) \
                    and norms[b] in lx.ARTICLES and norms[a] in self._relation_verbs:
                continue  # "the pontoon that pumps the diesel for the fish quay": the verb of `pumps_diesel_for`
            if norms[a:b] in self._needs_article and prev == "both" and a >= 2 and norms[a - 2] == "across":
                continue  # "a lorry jackknifed right across both lanes": the two lanes of the road, not "the lanes"
            if norms[a:b] in self._needs_article and prev not in lx.DETERMINERS | {"our", "your", "my", "his", "her", "both"} \
                    and a not in learner_bare and b not in glossary_ends and not acronym and not heading and not self._telegraphic_subject(toks, norms, a, b) \
                    and not (log and (b - a >= 2 or prev in lx.PREPOSITIONS and len(norms[a]) >= 5)) \
                    and not (b - a >= 2 and prev in ("in", "at", "from") and a >= 2 and norms[a - 2] in ("live", "living", "lives", "stay", "staying")) \
                    and not (b - a >= 2 and prev in ("in", "at", "inside") and a >= 2 and not toks.clause_start[a - 1] and any(
                        (h := self._cues.match_at(norms[:a - 1], k)) is not None and h[0] == a - 1 and h[1][1] != "neutral"
                        for k in range(max(0, a - 5), a - 1))) \
                    and not ((b - a >= 2 or len(norms[a]) >= 6) and (a == 0 or toks.sentence_start[a])
                             and toks.tokens[b - 1].text.lower().replace("’", "'").endswith("'s")) \
                    and not (b - a >= 2 and self._bare_pair(norms, a, b)) \
                    and not ((a == 0 or toks.sentence_start[a]) and norms[b:b + 1] == ("itself",)) \
                    and not (prev == "of" and a >= 2 and norms[a - 2] in ("stretch", "section", "length", "part")) \
                    and not (toks.clause_start[a] and toks.tokens[b - 1].text.lower().replace("’", "'").endswith("'s")
                             and any(norms[i - 1] == "the" and norms[i:i + b - a] == norms[a:b] for i in range(1, a))):
                # ("we're at the kirk, ..., kirk's our rest centre now": said again, without its article; "the
                # stretch of trail" is the trail's)
                # ("Jam tent's gone up": a name that opens its sentence as the subject, "the" left off; "both kilns" is
                # "both the kilns")
                # ("I live in toast rack, number 14": the article a learner of the language leaves out; "Stock breakout
                # in pig lines": a name of several words, right after a cue and "in")
                # the KB wrote "the tower": "bell tower" is not it (a log drops articles: "fire LPG plant",
                # "leak at bldg at mouth of galleria")
                continue
            if b - a == 1 and prev in lx.COMPOUND_MODIFIERS and not (a > 0 and toks.clause_start[a]) \
                    and not any(p.end_tok == a for p in places):
                continue  # "car park", "bell tower"
            if b - a == 1 and a > 0 and not toks.clause_start[a] and (prev in ("is", "was", "looks", "seems") or
                                                                 toks.tokens[a - 1].text.lower().endswith(("'s", "’s"))) \
                    and (b == len(norms) or toks.clause_start[b] or norms[b] in lx.COORDINATORS) \
                    and toks.tokens[a].text.lower() != toks.tokens[a].text.lower().rstrip("s") + "s" \
                    and any(norm_phrase(f)[-1:] == norms[a:b] and f.lower().endswith("s") for f in
                            self.kb.landmark_by_name[landmark].surface_forms):
                continue  # "it's flat and it's clear": a predicate, not the landmark the KB calls "flats"
            raw = toks.tokens[a].text.lower()
            if b - a == 1 and (prev in ("a", "an") or prev == "the" and self._person_cue_at(norms, b)) \
                    and not raw.endswith(("'s", "’s", "s")) and all(
                    norm_phrase(f)[-1:] != norms[a:b] or f.lower().endswith(("'s", "’s")) for f in
                    self.kb.landmark_by_name[landmark].surface_forms):
                continue  # "there's a baker trapped", "has the baker trapped": a person, not "the baker's"
            if b - a == 1 and not raw.endswith("s") and (a == 0 or toks.clause_start[a] or prev not in
                                                         lx.DETERMINERS | lx.PREPOSITIONS | {"my", "our", "your", "his", "her", "their"}) \
                    and not (b < len(norms) and (norms[b].isdigit() or norms[b] in lx.NUMBER_WORDS | {"one"})) \
                    and all(norm_phrase(f)[-1:] != norms[a:b] or f.lower().endswith("s") for f in
                            self.kb.landmark_by_name[landmark].surface_forms):
                continue  # "a customer's fainted in there, flat on the floor": the singular of "flats", no name
            if b - a == 1 and prev in ("our", "my", "your", "his", "her") and raw.endswith(("'s", "’s")) \
                    and b < len(norms) and norms[b] in ("gone", "come", "been", "just", "said", "says", "coming", "going"):
                continue  # "our doctor's gone out to him": a person, not "the doctors'"
            if prev == "after" and b < len(norms) and norms[b] in ("club", "clubs", "care", "activities", "session"):
                continue  # "he's at the library for after school club": when, not where
            if b - a == 1 and not raw.endswith("s") and (
                    b < len(norms) and norms[b] in ("upstair", "downstair", "upstairs", "downstairs", "above", "below", "overhead")
                    or prev in ("whole", "his", "her", "their")) \
                    and all(norm_phrase(f)[-1:] != norms[a:b] or f.lower().endswith("s") for f in
                            self.kb.landmark_by_name[landmark].surface_forms):
                continue  # "the whole flat upstairs has come down through it": one home, not the "flats"
            if b - a == 1 and raw.endswith("s") and not raw.endswith(("'s", "’s", "ss")) and raw != norms[a] \
                    and toks.tokens[a].text[:1].isupper() and all(
                        not norm_phrase(f)[-1:] == norms[a:b] or not f.lower().rstrip("'’").endswith("s")
                        for f in self.kb.landmark_by_name[landmark].surface_forms):
                continue  # "we've shunted the Fords and Fergies up the top end": tractors, not the ford
            if b - a == 1 and prev in ("a", "an", "one") and not raw.endswith("s") and all(
                    f.lower().endswith("s") for f in self.kb.landmark_by_name[landmark].surface_forms
                    if norm_phrase(f)[-1:] == norms[a:b]):
                continue  # "we've a van nose-down in the drain": one van, not the caravan park's "the vans"
            if b - a == 1 and prev in lx.MODAL_BEFORE_VERB and not (a > 0 and toks.clause_start[a]):
                continue  # "don't park anything round there": the word as a verb
            if b - a == 1 and norms[a] in ("front", "back", "side", "top", "bottom", "end") and norms[b:b + 1] == ("of",):
                continue  # "the glasshouse is burning, the whole front of it": a part of a place, not "the front"
            if b - a == 1 and norms[a] in ("front", "back", "side", "bottom") and b < len(norms) \
                    and not toks.clause_start[b] and norms[b].isalpha() and norms[b] not in lx.FUNCTION_WORDS \
                    and toks.tokens[a].text.lower() == norms[a] and self._cues.match_at(norms, b) is None:
                continue  # "the back legs have shifted": a word that says which legs, not "the backs" (a lane)
            if b - a == 1 and norms[a] in lx.EVENT_NOUNS and b + 1 < len(norms) and norms[b] in ("at", "on", "near") \
                    and norms[b + 1] in lx.ARTICLES and not toks.clause_start[b]:
                continue  # "re the slip at the cliff path": the landslip there, not the slipway called "the slip"
            if b - a == 1 and prev == "the" and raw.endswith("s") and not raw.endswith(("'s", "’s", "ss", "s'")) \
                    and raw != norms[a] and norms[a] + "s" == raw and all(
                        not f.lower().rstrip("'’").endswith("s") for f in self.kb.landmark_by_name[landmark].surface_forms
                        if norm_phrase(f)[-1:] == norms[a:b]) \
                    and (b >= len(norms) or norms[b] not in ("is", "has", "was", "got", "been", "gone", "just")):
                # (but "the unions got its windows blown in": the "'s" left out)
                continue  # "that's the lanterns on the water": many lanterns, not the minster called "the lantern"
            if b - a == 1 and prev == "the" and not raw.endswith("s") and b < len(norms) \
                    and norms[b] in ("it", "they", "we", "you", "that", "which") and not toks.clause_start[b] and all(
                        f.lower().endswith("s") for f in self.kb.landmark_by_name[landmark].surface_forms
                        if norm_phrase(f)[-1:] == norms[a:b]):
                continue  # "the ride it powers": one ride, described, not the fairground called "the rides"
            if b - a == 1 and a > 0 and toks.tokens[a - 1].text.lower() in ("their", "his", "her", "my", "your", "both") \
                    and norms[a] in lx.BODY_PARTS:
                continue  # "a lad with burns on his arms", "burns to both arms": his arms, not "the arms" (a pub)
            if b < len(norms) and norms[b] in lx.SPEAKER_ROLES | lx.ROLE_LABELS and not toks.clause_start[b] and a >= 3 \
                    and (norms[a - 1] == "the" and (norms[a - 3:a - 1] == ("this", "is") or norms[a - 2] in ("its", "im")
                                                    or norms[a - 2] in lx.FILLERS and norms[a - 4:a - 2] == ("this", "is"))
                         or norms[a - 2:a] == ("of", "the") and toks.tokens[b].text.lower().endswith("s")):
                # "This is the lock keeper", "one of the start marshals went through": who, no place said (kept as
                # a reference, so that no later reading takes the words for the place: "the tipping hall marshal")
                places.append(self._mention(toks, a, b, landmark, status="reference", reason="names who calls"))
                continue
            station = self._station_named(toks, norms, a, b, landmark)
            if station is not None:
                places.append(self._mention(toks, a, b, landmark, status="reference", reason=station))
                continue
            if b - a == 1 and a > 0 and toks.tokens[a - 1].text.lower() in ("its", "their", "his", "her") \
                    and toks.tokens[a].text.lower().endswith("s") and not any(
                        f.lower().endswith("s") for f in self.kb.landmark_by_name[landmark].surface_forms):
                continue  # "the pond's over its banks": a thing of its own, not the landmark
            if b - a == 1 and raw.endswith("s") and any(p.end_tok == a for p in places) \
                    and self._relations.match_at(norms, a) is not None and not any(
                        f.lower().endswith("s") for f in self.kb.landmark_by_name[landmark].surface_forms):
                continue  # "the school that big blue towers over": a verb after a name, not "the tower"
            places.append(self._mention(toks, a, b, landmark))
        places.extend(self._partial_names(toks, norms, {i for p in places for i in range(p.start_tok, p.end_tok)}))
        places.extend(self._head_names(toks, norms, {i for p in places for i in range(p.start_tok, p.end_tok)},
                                       {b for _, b, _ in all_relations}))
        rel_ends = {b for a, b, _ in all_relations if b - a >= 2}
        rel_ends |= {e for _, b, _ in all_relations if (e := _past_approach(norms, b)) > b}
        places.extend(self._modifier_names(toks, norms, {i for p in places for i in range(p.start_tok, p.end_tok)},
                                           rel_ends))
        places.extend(self._headless_names(toks, norms, {i for p in places for i in range(p.start_tok, p.end_tok)}))
        places.extend(self._things_of_a_ground(toks, norms, {i for p in places for i in range(p.start_tok, p.end_tok)}))
        places.extend(self._modifier_ones(toks, norms, places))  # (before a slip: "the larch ones" is no "larches")
        places.extend(self._misheard_names(toks, norms, {i for p in places for i in range(p.start_tok, p.end_tok)},
                                           {i for a, b, _ in all_cues for i in range(a, b)}))
        places.extend(self._definite_heads(toks, norms, places))
        places.extend(self._numbered_places(toks, norms, {i for p in places for i in range(p.start_tok, p.end_tok)}))
        places = [p for p in places if not _names_what_came(norms, p)]
        # ("passengers are being walked up onto ...": people, not the "passenger car park" the word is part of)
        places = [p for p in places if not ((p.end_tok - p.start_tok == 1 and norms[p.start_tok] in _PEOPLE_OR_GROUPS
                                             or p.end_tok - p.start_tok >= 2 and norms[p.end_tok - 1] in ("crew", "crews")
                                             and toks.tokens[p.end_tok - 1].text.lower() in ("crew", "crews"))
                                            and p.via is None and norms[p.start_tok:p.end_tok] not in {
                                                name_words(f) for f in self.kb.landmark_by_name[p.landmark].surface_forms})]
        # (nor "the staging area for the fire crews": a crew, not the "crash crew's" fire station)
        for idx, p in enumerate(places):
            if p.end_tok < len(norms) and norms[p.end_tok] in lx.MODIFIED_BY and not toks.clause_start[p.end_tok] \
                    and not (toks.tokens[p.end_tok].text.lower() == "lots" and norms[p.end_tok + 1:p.end_tok + 2] == ("of",)) \
                    and norms[p.end_tok : p.end_tok + 2] not in lx.PART_OF_PLACE \
                    and norms[p.end_tok : p.end_tok + 2] not in (("guy", "rope"), ("guy", "ropes")) \
                    and not (norms[p.end_tok] in lx.CARRIAGE_WORDS and p.landmark in self._conveyances) \
                    and not self._people_of_place_hurt(toks, norms, p.end_tok) \
                    and not self._people_of_place_tell(toks, norms, p.end_tok) \
                    and not self._people_there_with(norms, p):
                # ("the funicular car has come off its rails": the car is part of the railway)
                places[idx] = replace(p, status="reference", reason=f"modifier of '{toks.tokens[p.end_tok].text}'")
            elif p.end_tok < len(norms) and norms[p.end_tok] in lx.PEOPLE_OF_PLACE and p.start_tok >= 2 \
                    and norms[p.start_tok - 2:p.start_tok] == ("for", "the"):
                # "they're using the bank as the shelter for the hotel guests": whom it is for, not where
                places[idx] = replace(p, status="reference", reason=f"modifier of '{toks.tokens[p.end_tok].text}'")
            elif p.end_tok < len(norms) and norms[p.end_tok] in ("end", "ends") and p.start_tok >= 1 \
                    and norms[p.start_tok - 1] == "the" and not toks.clause_start[p.end_tok] \
                    and (p.end_tok + 1 >= len(norms) or norms[p.end_tok + 1] != "of") \
                    and any(q.end_tok <= p.start_tok and q.landmark != p.landmark
                            and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok] for q in places):
                # "LAKESHORE CAR PARK - water over the bonnets at the lake end": the end of the place before it
                places[idx] = replace(p, status="reference", reason="names an end of the place before it")
            elif p.end_tok - p.start_tok == 1 and p.end_tok + 2 < len(norms) and norms[p.end_tok].isalpha() \
                    and norms[p.end_tok + 1] == "of" and p.start_tok >= 1 and norms[p.start_tok - 1] == "the" \
                    and not toks.clause_start[p.end_tok] and norms[p.end_tok] not in lx.FUNCTION_WORDS | lx.COPULAS \
                    and self._cues.match_at(norms, p.end_tok) is None \
                    and any(q.start_tok in (p.end_tok + 2, p.end_tok + 3) and q.landmark != p.landmark for q in places):
                # "the river pier of the long legs": a part of the place after it, the river only says which
                places[idx] = replace(p, status="reference", reason=f"modifier of '{toks.tokens[p.end_tok].text}'")
            elif p.start_tok >= 3 and norms[p.start_tok - 1] in lx.ARTICLES and norms[p.start_tok - 2] == "from" \
                    and (norms[p.start_tok - 3] in lx.NUMBER_WORDS | {"hundred", "dozen"} or norms[p.start_tok - 3].isdigit()) \
                    and norms[p.start_tok - 3] not in ("999", "911", "112", "000", "111") \
                    and not toks.clause_start[p.start_tok - 2]:
                # "about two hundred from the bottling line mustered there": whom, by where they came from (not a
                # call: "a walker has rung 999 from the trig")
                places[idx] = replace(p, status="reference", reason="where the people counted came from")
            elif self._fallen_into(toks, norms, p, places):
                # "the bridge ... it's collapsed into the drain", "bricks falling into the river": where it fell
                places[idx] = replace(p, status="reference", reason="where something fell, no claim of its own")
            elif p.start_tok >= 2 and norms[p.start_tok - 1] == "from" and p.end_tok < len(norms) \
                    and norms[p.start_tok - 2] in _PEOPLE_WORDS | {"lads", "guys", "lot", "neighbours", "neighbors"} \
                    and norms[p.end_tok] in lx.HEARSAY_VERBS and not toks.clause_start[p.end_tok]:
                # "lads from tin town say the cottage ... its roof's been ripped off": who tells, not where
                places[idx] = replace(p, status="reference", reason="where the people who tell of it are from")
        for idx, p in enumerate(places):
            # "the supermarket across the square": where the place is, seen from here, not a place of its own
            if p.start_tok >= 3 and norms[p.start_tok - 1] in lx.ARTICLES and norms[p.start_tok - 2] in ("across", "over") \
                    and any(q.end_tok == p.start_tok - 2 for q in places) \
                    and (p.end_tok >= len(norms) or toks.clause_start[p.end_tok]) \
                    and self._relations.match_at(norms, p.start_tok - 2) is None:
                places[idx] = replace(p, status="reference", reason="where the place before it is")
            elif p.start_tok >= 3 and norms[p.start_tok - 1] == "the" and norms[p.start_tok - 2] in ("on", "in") \
                    and norms[p.end_tok - 1] in lx.AREA_HEADS and p.end_tok - p.start_tok == 1 \
                    and any(q.end_tok == p.start_tok - 2 and q.landmark != p.landmark for q in places) \
                    and (p.end_tok >= len(norms) or toks.clause_start[p.end_tok]):
                # "Fire in the coffee shop on the square.": where the shop is, not a place of its own
                places[idx] = replace(p, status="reference", reason="where the place before it is")
        starts = self._false_starts(toks, {i for p in places for i in range(p.start_tok, p.end_tok)})
        for fs in starts:
            nxt = min((p for p in places if p.start_tok >= fs.end_tok and (
                p.start_tok - fs.end_tok <= 3
                # ("the candy floss st— no hang on, it's the burger vans": repair words only, between)
                or p.start_tok - fs.end_tok <= 7 and all(w in _REPAIR_GAP_WORDS or w in lx.FILLERS
                                                         for w in norms[fs.end_tok:p.start_tok]))),
                      key=lambda p: p.start_tok, default=None)
            if nxt is not None and nxt.replaces is None:
                places[places.index(nxt)] = replace(nxt, replaces=fs.start_tok)
        places.extend(starts)
        markers = self._find_markers(toks, {i for p in places for i in range(p.start_tok, p.end_tok)})
        ex = Extraction(toks, places, markers)
        self._resolve_descriptions(ex)
        self._resolve_possessives(ex)
        self._resolve_relations(ex)
        again = self._description_heads_again(ex, norms)
        ex.places.extend(again)
        if again:  # ("the old church looking down on that grass": a description anchored on the one said again)
            self._resolve_relations(ex)
        self._resolve_itself(ex)
        self._resolve_between(ex, norms)
        self._apposed_part(ex, norms)
        self._relative_clause_anchors(ex, norms)
        self._way_ends(ex, norms)
        self._apposed_anchor(ex, norms)
        self._locating_place(ex, norms)
        for idx, p in enumerate(ex.places):
            if p.status == "active" and p.via is None and norms[p.end_tok:p.end_tok + 2] in (
                    ("same", "thing"), ("same", "place"), ("same", "difference")) \
                    and any(q.landmark == p.landmark and q.end_tok <= p.start_tok and q.status == "reference"
                            for q in ex.places):
                # "round pit two -- er, sorry, the ski pit, same thing --": another name for a description's anchor
                ex.places[idx] = replace(p, status="reference", reason="another name for a place said before")
            elif p.status == "active" and p.start_tok >= 3 and any(
                    norms[k:k + 3] in (("no", "problem", "with"), ("nothing", "wrong", "with"))
                    and all(w in lx.DETERMINERS for w in norms[k + 3:p.start_tok]) for k in range(max(0, p.start_tok - 5), p.start_tok - 2)):
                # "No problems with the big wheel itself, but the ground it's the centrepiece of is getting swamped"
                ex.places[idx] = replace(p, status="reference", reason="said to be fine: no claim")
        self._resolve_containers(ex, norms)
        heads = self._definite_heads(toks, norms, ex.places)  # again, after descriptions ("the portal with ...")
        ex.places.extend(heads)
        self._singular_of_plurals(ex, toks, norms)
        # (once descriptions are resolved: "the bridge over the sixteen foot ... it's collapsed into the drain")
        ex.places[:] = [replace(h, status="reference", reason="where something fell, no claim of its own")
                        if h.status == "active" and h.via is None and self._fallen_into(toks, norms, h, ex.places)
                        else h for h in ex.places]
        if any(norms[h.start_tok] in ("that", "this") and (
                h.end_tok < len(norms) and self._relations.match_at(norms, h.end_tok) is not None
                or h.start_tok - 1 in self._rel_tokens) for h in heads):
            self._resolve_relations(ex)  # "the yard that shed takes its plate from": the shed anchors a relation
            # (or ends one: "the trees next to the workers' row, and the building standing above that grove")
        self._speakers_premises(ex, norms)
        self._ordinal_anaphora(toks, norms, ex)
        self._apply_place_negation(ex)
        self._apply_pronoun_negation(ex, norms)
        self._apply_restarts(ex)
        self._apply_dropped(ex)
        self._apply_other_times(ex, norms)
        self._apply_place_repairs(ex)
        self._apply_trailing_repairs(ex)
        self._apply_hesitation_chains(ex, norms)
        self._apply_first_was_right(ex, norms)
        self._apply_written_corrections(ex)
        self._apply_mistaken_first(ex, norms)
        self._apply_confirmations(ex, norms)
        self._apply_no_claim_frames(ex, norms)
        self._apply_transit(ex)
        self._apply_cut_off(ex, norms)
        self._apply_not_ours(ex, norms)
        ex.places.sort(key=lambda p: p.start_tok)
        return ex

    @staticmethod
    def _apply_not_ours(ex: Extraction, norms: tuple[str, ...]) -> None:
        """"hi its jodie at smithy row theres mud all over the school ... the school not our houses": the caller's
        own place, said at the start, is what the news is not about."""
        k = next((i for i in range(len(norms) - 2) if norms[i] == "not" and norms[i + 1] in ("our", "my")
                  and norms[i + 2] in ("house", "home", "place", "street", "cottage", "row", "flat", "end")), None)
        if k is None:
            return
        for idx, p in enumerate(ex.places):
            j = p.start_tok
            while j > 0 and norms[j - 1] in lx.DETERMINERS:
                j -= 1
            if p.status == "active" and p.via is None and p.end_tok <= k and j >= 1 and norms[j - 1] in ("at", "from") \
                    and ex.tokens.sentence_of[p.start_tok] == 0 and j <= 6:
                ex.places[idx] = replace(p, status="reference", reason="the caller's own place, said not to be it")

    def _speakers_premises(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"Night watchman at the leather works. ... a stink right through the yard": a report that opens by
        saying whose premises the speaker is on (a short first sentence naming one place and no claim) reads a
        later bare "the yard" as that place's yard, not as the landmark whose name ends in "yard"."""
        toks = ex.tokens
        first = [p for p in ex.places if toks.sentence_of[p.start_tok] == 0 and p.status == "active"]
        if len({p.landmark for p in first}) != 1 or not first[0].start_tok <= 6:
            return
        opener = first[0]
        end = next((i for i in range(1, len(norms)) if toks.sentence_of[i] > 0), len(norms))
        if end == len(norms) or end > 10:
            return
        # ("Vats at the leather works have split. Brown slick spreading across the yard": a claim said of it first
        # reads the yard of the next sentence so too)
        claimed = any(self._cues.match_at(norms, i) is not None for i in range(end))
        for idx, p in enumerate(ex.places):
            w = norms[p.start_tok]
            if claimed and toks.sentence_of[p.start_tok] != 1:
                continue
            if p.status != "active" or p.via is not None or p.end_tok - p.start_tok != 1 or p.start_tok < end \
                    or w not in lx.PREMISES_PARTS or norms[p.start_tok - 1] != "the" or p.landmark == opener.landmark \
                    or any(name_words(f) == (w,) for f in self.kb.landmark_by_name[p.landmark].surface_forms):
                continue
            ex.places[idx] = replace(self._mention(toks, p.start_tok, p.end_tok, opener.landmark),
                                     reason=f"the {w} of '{opener.text}', where the speaker is")

    @staticmethod
    def _apply_no_claim_frames(ex: Extraction, norms: tuple[str, ...]) -> None:
        """Frames that name a place and claim nothing of it:

        * what a place used to be ("across from the church there used to be a bank");
        * a place the speaker never said ("I never said the bank was burning, I said the grocer's");
        * a place a danger has not reached ("fire on the embankment, it hasn't reached the allotments yet");
        * a place the speaker cannot see or does not know about ("the granary next to it -- actually I can't see the
          granary from here", "I don't actually know about the front car park");
          named just before and taken back by a repair, that mention goes too."""
        toks = ex.tokens
        marker_starts = {a for a, _, _ in ex.markers}
        for idx, p in enumerate(ex.places):
            j = p.start_tok
            while j > 0 and norms[j - 1] in lx.DETERMINERS:
                j -= 1
            if p.status == "active" and j >= 3 and norms[j - 3:j] == ("used", "to", "be") \
                    and not (j >= 4 and norms[j - 4] in ("that", "which") and p.via is not None):
                # (not "the place that used to be low fold's stables": the place it is now, so described)
                ex.places[idx] = replace(p, status="reference", reason="what a place used to be: no claim")
                continue  # "across from the church there used to be a bank ...; it's the coffee place now"
            if p.status == "active" and j >= 2 and norms[j - 1] == "said" and norms[j - 2] in ("never", "didnt", "not"):
                ex.places[idx] = replace(p, status="negated", reason="the speaker never said it")
                continue  # "I never said the bank was burning, I said the grocer's"
            if p.status == "active" and j >= 2 and norms[j - 1] in ("reached", "got", "hit", "touched") and any(
                    norms[m] in ("hasnt", "havent", "hadnt", "not", "nt", "never") for m in range(max(0, j - 4), j - 1)):
                # "fire on the embankment, it hasn't reached the allotments yet": nothing there yet
                ex.places[idx] = replace(p, status="reference", reason="not reached yet: no claim")
                continue
            if p.status == "active" and j >= 4 and norms[j - 3:j] in (("come", "back", "to"), ("got", "back", "to"),
                                                                      ("it", "back", "to")) \
                    and any(norms[m] in ("hasnt", "havent", "hadnt", "not", "nt", "never", "didnt")
                            for m in range(max(0, j - 5), j - 3)):
                # "went out to the white dumps and hasn't come back to the van park": not there, where they are awaited
                ex.places[idx] = replace(p, status="reference", reason="not come back to it: no claim")
                continue
            if p.status != "active" or j < 2 or p.via is not None:
                continue
            if norms[j - 1] == "see" and norms[j - 2] in ("cant", "cannot", "couldnt", "not"):
                k, why = j - 2, "the speaker cannot see it"
            elif j >= 3 and norms[j - 1] == "about" and norms[j - 2] in ("know", "sure") and (k := next(
                    (m for m in range(j - 3, max(-1, j - 6), -1) if norms[m] in ("dont", "didnt", "not", "cant")), -1)) >= 0:
                why = "the speaker does not know"  # "the front car park -- no wait, I don't actually know about the
                # front car park, forget that"
            else:
                continue
            ex.places[idx] = replace(p, status="reference", reason=f"{why}: no claim")
            while k > 0 and norms[k - 1] in {"i", "we", "you"} | lx.FILLERS:
                k -= 1
            if not any(k - 3 <= m <= k for m in marker_starts):
                continue
            for idx2, q in enumerate(ex.places):
                if q.status == "active" and q.landmark == p.landmark and q.end_tok <= k and k - q.end_tok <= 8 \
                        and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok]:
                    ex.places[idx2] = replace(q, status="retracted", reason=f"taken back: {why}")

    @staticmethod
    def _apply_other_times(ex: Extraction, norms: tuple[str, ...]) -> None:
        """"I'm at the almshouses actually, sorry, the surgery was this morning": a place said of another time is
        no claim, and no repair."""
        toks = ex.tokens
        for idx, p in enumerate(ex.places):
            if p.status != "active" or p.via is not None:
                continue
            k = p.end_tok
            if norms[k:k + 1] not in (("was",), ("s",)) or any(
                    q.landmark == p.landmark and q.status == "active" and q.end_tok <= p.start_tok for q in ex.places):
                continue  # ("the hot zone is the hotel, no sorry, the hotel was this morning, now it's the garage")
            for when in lx.OTHER_TIMES:
                e = k + 1 + len(when)
                if norms[k + 1:e] == when and (e >= len(norms) or toks.clause_start[e]):
                    ex.places[idx] = replace(p, status="reference", reason="said of another time: no claim")
                    break

    @staticmethod
    def _apply_first_was_right(ex: Extraction, norms: tuple[str, ...]) -> None:
        """"fire on the kitchens -- no, the chapel -- no, I had it right the first time": the speaker goes back
        to the first place of the repairs; the ones put in its stead are taken back."""
        toks = ex.tokens
        for m in range(len(norms)):
            if not _first_was_right_at(norms, m):
                continue
            n = toks.sentence_of[m]
            said = sorted((p for p in ex.places if p.end_tok <= m and p.status in ("active", "retracted")
                           and p.via is None and toks.sentence_of[p.start_tok] >= n - 1), key=lambda p: p.start_tok)
            if len(said) < 2 or not any(p.status == "retracted" for p in said) \
                    or len({p.landmark for p in said}) < 2:
                continue
            first, first_text = said[0].landmark, said[0].text
            named = next((q for q in sorted(ex.places, key=lambda q: q.start_tok) if m < q.start_tok <= m + 12
                          and q.status == "active" and q.via is None), None)
            if named is not None and named.landmark in {p.landmark for p in said} and named.landmark != first:
                # "the bridge - the footbridge - no, the pontoon one - wait, I was right first time, it's the
                # footbridge": the place named after it says which "first" the speaker means
                first, first_text = named.landmark, named.text
            for p in said:
                i = ex.places.index(p)
                if p.landmark == first:
                    ex.places[i] = replace(p, status="active", reason="the speaker went back to it")
                else:
                    ex.places[i] = replace(p, status="retracted", reason=f"the speaker went back to '{first_text}'")

    @staticmethod
    def _apply_hesitation_chains(ex: Extraction, norms: tuple[str, ...]) -> None:
        """"smoke off the granary, er, the mill, no hang on, it's the timber yard": a place the speaker
        hesitates away from to another, with no "and" between them, goes with the next one when a repair
        takes that back; the speaker was searching for the place, not listing two."""
        toks = ex.tokens
        for _ in range(3):  # (a chain of three: "the granary, er, the mill, um, the barn, no, the yard")
            changed = False
            for y in [q for q in ex.places if q.status == "retracted" and q.reason.startswith("self-repair")]:
                x = max((q for q in ex.places if q.status == "active" and q.via is None and q.end_tok <= y.start_tok
                         and q.landmark != y.landmark), key=lambda q: q.end_tok, default=None)
                if x is None or y.start_tok - x.end_tok > 5 or toks.sentence_of[x.start_tok] != toks.sentence_of[y.start_tok]:
                    continue
                between = norms[x.end_tok:y.start_tok]
                if not any(w in lx.FILLERS for w in between) \
                        or not all(w in lx.FILLERS or w in lx.ARTICLES for w in between) \
                        or not toks.gaps[x.end_tok].strip().startswith((",", "\u2014", "-", "...")):
                    continue
                ReportAnalyzer._take_back(ex, x, y, f"self-repair: hesitated on to '{y.text}', itself taken back")
                changed = True
            if not changed:
                break

    @staticmethod
    def _apply_cut_off(ex: Extraction, norms: tuple[str, ...]) -> None:
        """"... and, uh, the bakery's-- [garbled]": what was being said of the place was lost; it has no claim."""
        toks = ex.tokens
        for i, p in enumerate(ex.places):
            if p.status != "active":
                continue
            j = p.start_tok
            while j > 0 and not toks.clause_start[j] and norms[j - 1] in lx.DETERMINERS | lx.FILLERS | {"and", "then", "also"}:
                j -= 1
            if j > 0 and not toks.clause_start[j] and norms[j] not in ("and", "then", "also"):
                continue  # ("people trapped in the bakery's--": the place ends a claim, it does not open one)
            end = p.end_tok
            raw = toks.tokens[end - 1].text.lower().replace("’", "'")
            if not raw.endswith("'s"):
                if end < len(norms) and norms[end] in ("is", "has", "was") and not toks.clause_start[end]:
                    end += 1
                else:
                    continue
            gap = toks.gaps[end] if end < len(norms) else toks.text[toks.tokens[-1].end:]
            if not any(d in gap for d in ("--", "—", "–", "...", "…")):
                continue
            rest = [w for w in norms[end:] if w not in lx.FILLERS]
            if all(w in lx.LOST_WORDS for w in rest):
                ex.places[i] = replace(p, status="retracted", reason="cut off before anything was said of it")

    def _relative_clause_anchors(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"the spring the bottling works takes its water from has gone rusty": a place named, then a related
        place that only leads to it through a relative clause ending in a stranded preposition."""
        toks = ex.tokens
        related = self._related_pairs
        active = sorted((p for p in ex.places if p.status == "active" and p.via is None), key=lambda p: p.start_tok)

        def only_describes(p1: PlaceMention, p2: PlaceMention) -> None:
            ex.places[ex.places.index(p2)] = replace(p2, status="reference",
                                                     reason=f"reference point of a relative clause describing '{p1.text}'")
        described = [p for p in ex.places if p.status == "active" and p.via is not None]
        for p1 in active:
            p2 = min((p for p in ex.places if p.start_tok >= p1.end_tok and p.status != "reference"),
                     key=lambda p: p.start_tok, default=None)
            if p2 is None or p2 not in described or (p1.landmark, p2.landmark) not in related:
                continue
            gap = norms[p1.end_tok:p2.start_tok]
            participle = toks.tokens[p1.end_tok].text.lower().endswith("ed") if gap else False
            if 2 <= len(gap) <= 4 and participle and all(w in lx.PREPOSITIONS | lx.RELATION_ENDINGS | {"out", "up", "off", "down"}
                                                          for w in gap[1:]) \
                    and not any(toks.clause_start[i] for i in range(p1.end_tok, p2.start_tok + 1)):
                only_describes(p1, p2)  # "the heaps tipped out of the level the magazine kept the powder for"
                continue
            if 2 <= len(gap) <= 4 and gap[0] in ("that", "which") and norms[p1.end_tok + 1].isalpha() \
                    and len(norms[p1.end_tok + 1]) >= 4 and norms[p1.end_tok + 1] not in lx.COPULAS | lx.FUNCTION_WORDS \
                    and (toks.tokens[p1.end_tok + 1].text.lower().endswith(("s", "ed")) or p1.text.lower().endswith("s")) \
                    and not any(toks.clause_start[i] for i in range(p1.end_tok, p2.start_tok + 1)) \
                    and not any(self._cues.match_at(norms, i) is not None for i in range(p1.end_tok + 1, p2.start_tok)):
                # "the scales that weigh for the yard that queues into our customs": the yard, described, only says
                # which scales
                only_describes(p1, p2)
        for p1, p2 in zip(active, active[1:], strict=False):
            gap = norms[p1.end_tok:p2.start_tok]
            if (p1.landmark, p2.landmark) in related and 3 <= len(gap) <= 5 and gap[0] in ("that", "which") \
                    and gap[-1] in lx.ARTICLES and toks.tokens[p1.end_tok + 1].text.lower().endswith(("s", "ed")) \
                    and norms[p1.end_tok + 1] not in lx.COPULAS | {"has", "had"} and not toks.gaps[p1.end_tok].strip() \
                    and not any(toks.clause_start[i] for i in range(p1.end_tok + 1, p2.end_tok)) \
                    and (norms[p1.end_tok + 1] == "use" or not any(
                        self._cues.match_at(norms, i) is not None for i in range(p1.end_tok + 1, p2.start_tok))):
                # "the school that uses the hall as its gym": the hall only says which school
                only_describes(p1, p2)
                continue
            if (p1.landmark, p2.landmark) in related and 4 <= len(gap) <= 6 and toks.clause_start[p1.end_tok] \
                    and not toks.sentence_start[p1.end_tok] and gap[0] in lx.ARTICLES and gap[-1] in lx.ARTICLES \
                    and gap[-2] in lx.PREPOSITIONS | lx.RELATION_ENDINGS and gap[-3].isalpha() \
                    and not any(w in lx.COPULAS | {"s"} or w in _PEOPLE_WORDS for w in gap[1:-2]) \
                    and not any(toks.clause_start[i] for i in range(p1.end_tok + 1, p2.end_tok)) \
                    and not any(self._cues.match_at(norms, i) is not None for i in range(p1.end_tok, p2.start_tok)):
                # "she's on the plank, the little footbridge over the leat": an aside that says which place,
                # by one the KB relates to it
                only_describes(p1, p2)
                continue
            if (p1.landmark, p2.landmark) not in related or len(gap) > 2 \
                    or not all(w in lx.ARTICLES or w in ("that", "which") for w in gap) \
                    or any(toks.clause_start[i] for i in range(p1.end_tok, p2.start_tok + 1)):
                continue
            v = p2.end_tok
            # (a particle may follow the verb: "the pond the goit tops up, its wall's bulging")
            w = v + 1 if v + 2 < len(norms) and norms[v + 1] in ("up", "out", "off", "down", "over") \
                and not toks.clause_start[v + 1] else v
            if w + 1 < len(norms) and norms[v].isalpha() and len(toks.tokens[v].text) >= 4 \
                    and toks.tokens[v].text.lower().endswith(("s", "ed")) \
                    and norms[v] not in lx.COPULAS and (norms[w + 1] in lx.COPULAS | {"has", "have", "had"}
                                                       or toks.clause_start[w + 1]) \
                    and not toks.clause_start[v] and self._cues.match_at(norms, v) is None:
                # "the mill the lade drives is on fire": a transitive verb closes the relative clause
                only_describes(p1, p2)
                continue
            end = p2.end_tok
            while end < len(norms) and end - p2.end_tok < 7 and not toks.clause_start[end] \
                    and norms[end] not in lx.RELATION_ENDINGS:
                end += 1
            if end >= len(norms) or norms[end] not in lx.RELATION_ENDINGS or end == p2.end_tok:
                continue
            if end + 1 < len(norms) and norms[end + 1] in lx.RELATION_ENDINGS | {"from"} and not toks.clause_start[end + 1]:
                end += 1  # "the ramp the sailing club puts its boats in from has cracked"
            verb = norms[p2.end_tok]
            nxt = end + 1
            closed = nxt >= len(norms) or toks.clause_start[nxt] or norms[nxt] in lx.COPULAS | {"has", "have", "had"}
            raw_verb = toks.tokens[p2.end_tok].text.lower()  # (the key drops a verb's "s": "puts" is "put")
            if closed and (verb.endswith(("s", "ed")) or verb in ("look", "take", "draw", "feed", "face")
                           or raw_verb.endswith("s") and raw_verb.isalpha() and len(raw_verb) >= 4) \
                    and verb not in lx.COPULAS:
                only_describes(p1, p2)
                continue
            last = next((k for k in range(end, min(len(norms), p2.end_tok + 8)) if k + 1 >= len(norms)
                         or toks.clause_start[k + 1]), None)
            if verb in ("is", "s") and last is not None and norms[last] in ("of", "to", "from") and last - p2.end_tok >= 3 \
                    and not any(self._cues.match_at(norms, k) is not None for k in range(end, last)):
                # "the arches Del's gym is on the end of --": where the gym is, said only to say which arches
                only_describes(p1, p2)

    def _never_a_building(self, name: str) -> bool:
        """A landmark every name of which ends in a word for a boat, an open ground, a way or water ("the fuel
        float", "the fish barge", "the wharf"): no "building" describes it."""
        return all(name_words(f)[-1:] and name_words(f)[-1] in _OPEN_OR_AFLOAT
                   for f in self.kb.landmark_by_name[name].surface_forms)

    def _bare_in_glossary(self, norms: tuple[str, ...], a: int, b: int, all_cues: list) -> bool:
        """"soft mud has swallowed the slipway": a glossary term ending in a word the KB names a place by only with
        its article ("the mud"), said with no article before the term or the word, is the danger, not the place."""
        if norms[a:b] not in self._needs_article or a == 0 or norms[a - 1] in lx.DETERMINERS:
            return False
        return any(src == "glossary" and cb == b and ca < a and (ca == 0 or norms[ca - 1] not in lx.DETERMINERS)
                   for ca, cb, (_, src) in all_cues)

    def _locating_place(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"The crane on B dock is swinging loose": a named place said "on" or "at" another that the KB relates to it
        (the hoist stands at the end of the south dock); the second only says which one or where, a reference point."""
        toks = ex.tokens
        for idx, q in enumerate(ex.places):
            if q.status != "active" or q.via is not None or q.start_tok < 2:
                continue
            k = q.start_tok - 1
            if norms[k] in lx.ARTICLES:
                k -= 1
            if k < 1 or norms[k] not in ("on", "at") or any(toks.clause_start[t] for t in range(k, q.start_tok + 1)):
                continue
            p = next((p for p in ex.places if p.end_tok == k and p.status == "active" and p.via is None), None)
            if p is None or p.landmark == q.landmark or (p.landmark, q.landmark) not in self._related_pairs \
                    or any(o is not q and o.landmark == q.landmark and o.status == "active" for o in ex.places):
                continue
            ex.places[idx] = replace(q, status="reference", reason=f"reference point for '{p.text}'")

    def _apposed_anchor(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"a woman down on the line the lift drops its fish onto, the lift that unloads the scow": a description
        after a comma whose head noun repeats a noun the clause before used as no place, only says which that noun
        was; it claims nothing of its own."""
        toks = ex.tokens
        taken = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        for idx, p in enumerate(ex.places):
            s0 = p.start_tok
            if p.status != "active" or p.via is None or s0 < 4 or norms[s0] != "the" or p.end_tok - s0 < 4 \
                    or not toks.clause_start[s0] or toks.sentence_start[s0] or norms[s0 + 2] not in ("that", "which"):
                continue
            head = norms[s0 + 1]
            earlier = [i for i in range(max(1, s0 - 10), s0 - 1) if norms[i] == head and norms[i - 1] == "the"
                       and i not in taken and toks.sentence_of[i] == toks.sentence_of[s0]
                       and any(q.start_tok < i and q.end_tok <= s0 for q in ex.places if q.status == "active")]
            if earlier:
                ex.places[idx] = replace(p, status="reference", reason=f"says which '{head}' the clause before meant")

    def _way_ends(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"the walkway, the catwalk down to the stinker, it's gone": a way named, then where it leads, with no verb
        between; the place it leads to only says which way is meant."""
        toks = ex.tokens
        active = sorted((p for p in ex.places if p.status == "active" and p.via is None), key=lambda p: p.start_tok)
        for p1, p2 in zip(active, active[1:], strict=False):
            last = norms[p1.end_tok - 1]
            gap = norms[p1.end_tok:p2.start_tok]
            if last not in lx.ROUTE_HEADS | _WAY_NOUNS or p1.landmark == p2.landmark or not 2 <= len(gap) <= 4 \
                    or gap[0] not in lx.ROUTE_LINKS or "to" not in gap[:2] or not set(gap) <= lx.ROUTE_LINKS | lx.ARTICLES \
                    or any(toks.clause_start[i] for i in range(p1.end_tok, p2.end_tok)) \
                    or p1.start_tok >= 1 and norms[p1.start_tok - 1] in ("from", "between") \
                    or p1.start_tok >= 2 and norms[p1.start_tok - 2] in ("from", "between"):
                continue  # (not "from the mill down to the weir": the stretch between the two)
            i = ex.places.index(p2)
            ex.places[i] = replace(p2, status="reference", reason=f"where '{p1.text}' leads")

    def _ordinal_anaphora(self, toks: Tokens, norms: tuple[str, ...], ex: Extraction) -> None:
        """"the chemist's and the coffee shop. The first one -- a woman on the floor": an ordinal, "the
        former" / "the latter" or "the other one" names a place of the last list of places said before it.

        The list is the most recent sentence (up to the anaphor) that names two or more landmarks; "the
        other one" needs a list of two and names the one not named last. Anything that does not resolve
        to exactly one list member ("the first car", "the second of three fires") is left alone. The
        members of a list so named are ``counted_by`` the first such ordinal: they borrow no claim said
        after it. "both of them" / "neither of them" name every member (``also``): what is said of the
        mention is said of each, and after "neither" it is denied.
        """
        places = ex.places
        out: list[PlaceMention] = []
        taken = {i for p in places for i in range(p.start_tok, p.end_tok)}
        for i in range(len(norms)):
            word = norms[i]
            # "...; both are marked safe": "both" opening its clause before its verb
            bare = word == "both" and i not in taken and toks.clause_start[i] and i > 0 \
                and (norms[i + 1:i + 2] in (("are",), ("were",), ("have",), ("had",), ("need",), ("look",), ("re",))
                     or i + 1 < len(norms) and (self._cues.match_at(norms, i + 1) is not None
                                                or norms[i + 1] in lx.PREDICATIVE_CUES)
                     and any(d in toks.gaps[i] for d in (":", "—", "–", " - ", "--")))  # ("the library and the school: both sound")
            of_them = word in ("both", "neither") and norms[i + 1:i + 3] in (("of", "them"), ("of", "those"),
                                                                              ("of", "these"))
            every = bare or of_them
            start = i
            if of_them:
                i += 1  # (the mention starts at "both", as an ordinal's starts at its "the")
            elif bare:
                pass  # (the mention is the word itself)
            elif i in taken or not (word in lx.ORDINAL_PLACES or word == "other"):
                continue
            elif i > 0 and (norms[i - 1] == "the" or norms[i - 1] == "that" and norms[i + 1:i + 2] == ("one",)):
                start = i - 1  # ("that second one I gave you")
            elif not (toks.clause_start[i] and norms[i + 1:i + 2] == ("one",)):
                continue  # (a bare "First one, empty" opens its clause)
            end = i + 1
            nxt = norms[end] if end < len(norms) else ""
            if of_them:
                end += 1
            elif bare:
                pass
            elif nxt == "of" and norms[end + 1:end + 2] in (("them",), ("those",), ("these",), ("the",)):
                after = end + 2
                if norms[end + 1] == "the" or after < len(norms) and not toks.clause_start[after] \
                        and norms[after] not in lx.COPULAS | lx.ANAPHOR_VERBS:
                    continue  # "the second of those fires", "the first of the crews": counted things
                end = after  # "the second of those is where we're mustering"
            elif nxt in ("one", "ones") or nxt in lx.GENERIC_HEADS and end not in taken and word != "other":
                end += 1
            elif nxt and not toks.clause_start[end] and nxt not in lx.COPULAS | lx.ANAPHOR_VERBS \
                    and not toks.tokens[i].text.lower().endswith(("'s", "’s")) \
                    and not (word in ("former", "latter") and nxt in lx.COORDINATORS):
                continue  # "the first crew", "the other bore": a noun the ordinal counts, not a place
            earlier = [p for p in places + out if p.start_tok < start and p.status == "active"]
            spans = [(q.start_tok, q.end_tok) for q in places if q.via is not None]
            listed: list[str] = []
            members: list[int] = []
            for n in sorted({toks.sentence_of[p.start_tok] for p in earlier}, reverse=True):
                said = [p for p in sorted(places, key=lambda p: p.start_tok)
                        if (p.status == "active" or p.status == "reference" and not any(  # "the town hall and the
                            sa <= p.start_tok < se for sa, se in spans))  # building next to it": both are listed
                        and toks.sentence_of[p.start_tok] == n and p.start_tok < start]
                names = list(dict.fromkeys(p.landmark for p in said))
                if len(names) >= 2:
                    listed, members = names, [p.start_tok for p in said]
                    break
            if not listed and word in lx.ORDINAL_PLACES and word not in ("former", "latter"):
                # "One, flooding at the bus depot. Two, flooding at the sports hall. ... The second one, I got that
                # wrong": items said one to a sentence count as a list too
                names = list(dict.fromkeys(p.landmark for p in sorted(earlier, key=lambda p: p.start_tok)
                                           if p.via is None))
                if len(names) >= 2:
                    listed, members = names, [p.start_tok for p in earlier]
            if not listed and word == "other" and earlier:
                # "the west one is clear, and the other one's got a burning car": of two landmarks that share
                # a head ("west portal", "east portal"), the one not just named
                last = max(earlier, key=lambda p: p.start_tok)
                pair = next((names for names in self._head_groups().values()
                             if last.landmark in names and len(names) == 2), None)
                if pair is not None:
                    listed = [last.landmark, next(n for n in pair if n != last.landmark)]
            if not listed or bare and len(listed) != 2:
                continue
            if word == "both" and len(listed) > 2:
                listed = listed[-2:]  # ("the pumphouse, er, no — the row ..., and the one ..., both of them": two)
            if every:
                landmark = listed[-1]
            elif word == "other":
                if len(listed) != 2 or {"from", "one"} <= set(norms[max(0, start - 6):start]):
                    continue  # (not "glass from one end to the other": one thing and another, no place)
                if any(norms[k] == "one" and norms[k - 1] not in lx.DETERMINERS and not norms[k - 1].endswith(("th", "st", "rn"))
                       and toks.sentence_of[k] == toks.sentence_of[start] for k in range(max(1, start - 8), start)):
                    continue  # "a dog walker has pulled one out, the other's still out there": the other lad
                if any(norms[k] == "one" and norms[k + 1] in ("at", "in", "on", "by", "near")
                       and norms[k - 1] not in lx.DETERMINERS and toks.sentence_of[k] == toks.sentence_of[start]
                       for k in range(1, start - 1)):
                    continue  # "two hurt, one at the bouncy castle, ..., and the other one at the food stalls": people
                if any(end < p.start_tok <= end + 8 and toks.sentence_of[p.start_tok] == toks.sentence_of[start]
                       for p in places):
                    continue  # "no the other one, the one next to it, the school": the speaker goes on to name it
                last = max((p for p in earlier if p.landmark in listed), key=lambda p: p.start_tok)
                landmark = listed[1 - listed.index(last.landmark)]
            else:
                k = lx.ORDINAL_PLACES[word]
                if k >= len(listed):
                    continue
                landmark = listed[k]
            out.append(replace(self._mention(toks, start, end, landmark), anaphor=word if every else "ordinal",
                               also=tuple(listed[:-1]) if every else (),
                               reason=f"'{toks.text[toks.tokens[start].start:toks.tokens[end - 1].end]}' of the list "
                                      f"{', '.join(listed)}"))
            taken.update(range(start, end))
            for idx, p in enumerate(places):
                if p.start_tok in members and p.counted_by is None:
                    places[idx] = replace(p, counted_by=start)
        places.extend(out)

    def _telegraphic_subject(self, toks: Tokens, norms: tuple[str, ...], a: int, b: int) -> bool:
        """"Precinct secure, holding evacuees there": radio speech drops the article of a sentence's subject
        ("Clean air lab reports smoke inside": the subject that reports what it has)."""
        contracted = toks.tokens[b - 1].text.lower().endswith(("'s", "’s"))  # "tower's clear"
        opens = toks.sentence_start[a] or a > 1 and toks.sentence_start[a - 2] and norms[a - 2].isdigit() \
            and norms[a - 1].isdigit() and ":" in toks.gaps[a - 1]  # ("23:09 fosse overtopping": a log's time first)
        if not opens and a > 0 and ":" in toks.gaps[a]:
            opens = True  # "Fire crew Alpha: chapel searched, swept and clear": the message after who calls
        if not opens and a > 0:
            s0 = max((t for t in range(a) if toks.sentence_start[t]), default=0)
            # ("okay so um top car park's ...": fillers first)
            opens = a - s0 <= 4 and all(norms[t] in lx.FILLERS | {"and", "but", "then"} for t in range(s0, a))
        listed = False
        if not opens and a > 0 and toks.clause_start[a] and "," in toks.gaps[a]:
            # ("Control: mill yard flooded, wool store flooded, big mill ground floor flooded": a log's list, each
            # item a subject without its article, after one said so)
            s0 = max((t for t in range(a + 1) if toks.sentence_start[t]), default=0)
            starts = [t for t in range(s0, a) if toks.clause_start[t]] + [a]
            listed = opens = any(
                2 <= e - c <= 4 and norms[c].isalpha() and norms[c] not in lx.DETERMINERS | lx.PRONOUNS
                and self._places.match_at(norms, c) is not None and self._cues.match_at(norms, e - 1) is not None
                for c, e in zip(starts, starts[1:], strict=False))
        if not opens or b >= len(norms) or (norms[a] in lx.DESCRIPTIVE_WORDS and not contracted and not listed):
            return False
        if not contracted and b + 2 < len(norms) and norms[b] in ("ground", "top", "first", "upper", "lower", "second") \
                and norms[b + 1] in lx.STOREY_WORDS and not toks.clause_start[b + 1]:
            b += 1  # "big mill ground floor flooded"
        if not contracted and b + 1 < len(norms) and norms[b] in lx.STOREY_WORDS | lx.PART_NOUNS | lx.ROOMS_OF_A_BUILDING \
                | {"kitchen", "kitchens"} and not toks.clause_start[b] \
                and not toks.clause_start[b + 1]:
            b += 1  # "Gym roof's come down": the part of the place is the subject's head, the place said before it
        if not contracted and norms[b] in _PLACING_PREPOSITIONS and any(
                self._places.match_at(norms, t) is not None for t in range(b + 1, min(len(norms), b + 4))):
            return True  # "Graveyard behind Bethel is flooded": placed by another
        if not contracted and norms[b] in ("and", "or") and b + 2 < len(norms) and (
                self._places.match_at(norms, b + 1) is not None
                or norms[b + 1] in lx.ARTICLES and self._places.match_at(norms, b + 2) is not None):
            return True  # "Doo line and the runway are both safe": the first of two subjects
        return toks.clause_start[b] or norms[b] in lx.COPULAS | lx.CREW_ACTION_VERBS \
            or self._cues.match_at(norms, b) is not None \
            or norms[b] in ("report", "reports", "reporting", "reported") and b + 1 < len(norms) \
            and self._cues.match_at(norms, b + 1) is not None \
            or (norms[b] in lx.TELEGRAPHIC_LINKS and (self._cues.match_at(norms, b + 1) is not None
                                                        or norms[b + 1:b + 2] == ("and",)  # "Sidings checked and clear"
                                                        and self._cues.match_at(norms, b + 2) is not None))

    def _people_of_place_hurt(self, toks: Tokens, norms: tuple[str, ...], w: int) -> bool:
        """"the pharmacy's owner is trapped", "the bakery staff are injured": the people the place's name
        modifies (token ``w``) are said at once to need help; where they are is the place."""
        if norms[w] not in lx.PEOPLE_OF_PLACE_WORDS or self._person_category is None:
            return False
        j = w + 1
        while j < len(norms) and j - w <= 3 and not toks.clause_start[j] and norms[j] in lx.COPULAS | lx.FILLERS | {
                "been", "all", "still", "both", "badly", "just"} and self._cues.match_at(norms, j) is None:
            j += 1  # (not past a cue that starts with a copula: "the kid got bit by a dog")
        hit = self._cues.match_at(norms, j) if j < len(norms) and not toks.clause_start[j] else None
        return hit is not None and hit[1][0] == self._person_category

    @staticmethod
    def _fallen_into(toks: Tokens, norms: tuple[str, ...], p: PlaceMention, places: list[PlaceMention]) -> bool:
        """"the bridge over the sixteen foot ... it's collapsed into the drain": a thing (no person) fallen into
        water (a river, a drain), after another place said in its sentence; the water only says where it went."""
        k = p.start_tok - 1
        while k >= 0 and norms[k] in lx.ARTICLES:
            k -= 1
        if k < 1 or norms[k] not in ("into", "onto") or toks.clause_start[k]:
            return False
        v = k - 1
        if norms[v] not in lx.FALLEN_VERBS:
            return False
        subj = [w for w in norms[max(0, v - 3):v] if w not in ("has", "have", "had", "s", "is", "are", "been", "just",
                                                                    "now", "all", "half", "partly")]
        if not subj or subj[-1] in _PERSON_WORDS | lx.LAY_PERSONS | lx.WORKER_PERSONS | lx.PERSON_SUBJECTS \
                | {"someone", "somebody", "man", "woman", "kid", "child", "he", "she", "they", "i", "we"}:
            return False
        water = WATERCOURSE_WORDS & (set(name_words(p.landmark)) | set(norms[p.start_tok:p.end_tok]))
        if not water:
            return False  # ("the steeple has collapsed into the minster": the minster is hit too)
        n = toks.sentence_of[p.start_tok]
        return any(q.end_tok <= k and q.landmark != p.landmark and toks.sentence_of[q.start_tok] == n
                   and q.status == "active" for q in places)

    def _station_named(self, toks: Tokens, norms: tuple[str, ...], a: int, b: int, landmark: str) -> str | None:
        """The name at ``a:b`` names a station the report speaks to or of, not a place of its news: why, or None."""
        opens = a == 0 or toks.sentence_start[a]
        if opens and norms[b:b + 1] == ("copy",) \
                and b + 1 < len(norms) and norms[b + 1] in ("we", "weve", "i", "ive", "this", "over", "control"):
            return "names who is called"  # "fire station copy we have a pool fire in the sump"
        if norms[b:b + 3] in (("on", "the", "radio"), ("on", "the", "phone")) and a >= 2 and "get" in norms[max(0, a - 3):a]:
            return "names who is called"  # "somebody get the fire tower on the radio"
        if opens and norms[b:b + 3] in (("has", "a", "visual"), ("has", "eyes", "on"), ("have", "a", "visual"),
                                        ("have", "eyes", "on")):
            return "names who sees it"  # "Lookout has a visual on two figures ...": from where, no claim of its own
        if opens and norms[b:b + 2] == ("to", "the") and b + 2 < len(norms) \
                and (h := self._places.match_at(norms, b + 2)) is not None and h[1] != landmark \
                and "please" in norms[h[0]:h[0] + 3]:
            return "names who is sent"  # "First aid to the dog ring please, a lady's been bitten": not where it happened
        return None

    @staticmethod
    def _people_there_with(norms: tuple[str, ...], p: PlaceMention) -> bool:
        """"man down in the truck park lads are with him now" (said without a stop): where the casualty is, then
        the people with them, no "truck park lads" the place's name modifies."""
        w = p.end_tok
        return p.start_tok >= 2 and norms[p.start_tok - 1] in lx.ARTICLES \
            and norms[p.start_tok - 2] in ("in", "at", "on", "inside", "by") \
            and norms[w + 1:w + 2] in (("are",), ("re",), ("is",), ("s",)) \
            and norms[w + 2:w + 3] == ("with",) \
            and norms[w + 3:w + 4] in (("him",), ("her",), ("them",), ("the",), ("it",))

    def _people_of_place_tell(self, toks: Tokens, norms: tuple[str, ...], w: int) -> bool:
        """"Brewery staff tell me their cellars are flooding": the people the place's name modifies (token ``w``)
        tell of their own place ("their" and a thing that is no person), and a cue says what it is."""
        if norms[w] not in lx.PEOPLE_OF_PLACE_WORDS:
            return False
        j = w + 1
        while j < len(norms) and j - w <= 2 and norms[j] in lx.FILLERS | {"have", "are", "just", "now"}:
            j += 1
        if j >= len(norms) or norms[j] not in lx.HEARSAY_VERBS - {"think", "thinks", "thought", "reckon", "reckons",
                                                                  "reckoned", "heard", "hear", "rumour", "rumor"}:
            return False
        k = next((i for i in range(j + 1, min(len(norms), j + 5)) if norms[i] == "their"), None)
        if k is None or k + 1 >= len(norms) or norms[k + 1] in _PERSON_WORDS or norms[k + 1] in lx.PERSON_NOUNS \
                or any(toks.sentence_start[i] for i in range(w, k + 2)):
            return False
        return any(self._cues.match_at(norms, i) is not None for i in range(k + 2, min(len(norms), k + 6))
                   if not any(toks.sentence_start[m] for m in range(k + 2, i + 1)))

    @functools.cached_property
    def _grounds_of_things(self) -> dict[str, str]:
        """What stands on a ground named after it, by landmark: "caravan" of "seabank caravan site" (the only
        name that holds the word, and it ends in a word for ground)."""
        owners: dict[str, set[str]] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                words = name_words(form)
                if len(words) >= 2 and words[-1] in lx.GROUND_HEADS:
                    for w in words[:-1]:
                        if w.isalpha() and len(w) >= 4:
                            owners.setdefault(w, set()).add(lm.name)
        used = self._name_word_owners
        return {w: next(iter(v)) for w, v in owners.items() if len(v) == 1 and used.get(w, v) == v}

    def _things_of_a_ground(self, toks: Tokens, norms: tuple[str, ...], taken: set[int]) -> list[PlaceMention]:
        """"the bank the caravans huddle under": the things a ground is named after, said in the plural, are the
        ground ("seabank caravan site")."""
        out = []
        for i in range(1, len(norms)):
            w, raw = norms[i], toks.tokens[i].text.lower()
            if i in taken or norms[i - 1] != "the" or w not in self._grounds_of_things or not raw.endswith("s") \
                    or raw.endswith("'s") or raw == w:
                continue
            anchors = i + 1 < len(norms) and not toks.clause_start[i + 1] and (
                self._relations.match_at(norms, i + 1) is not None or norms[i + 1] in self._relation_verbs)
            if not anchors:
                continue  # (only as a relation's anchor: "the giraffes are all right" are the animals)
            out.append(self._mention(toks, i - 1, i + 1, self._grounds_of_things[w]))
        return out

    def _partial_names(self, toks: Tokens, norms: tuple[str, ...], taken: set[int]) -> list[PlaceMention]:
        """"the hardware —": the first words of a multi-word name, cut off by a pause."""
        if not hasattr(self, "_prefixes"):
            cue_words = {w for key in self._cue_keys() for w in key}
            self._prefixes = {k: next(iter(v)) for k, v in self._name_prefix_owners.items()
                              if len(v) == 1 and not set(k) & cue_words and not set(k) & lx.GENERIC_HEADS}
        out = []
        for i in range(1, len(norms)):
            if norms[i - 1] != "the" or i in taken:
                continue
            for n in (2, 1):
                key = norms[i : i + n]
                end = i + n
                owners = self._name_prefix_owners.get(key, ()) if n == 2 else ()
                if len(key) == 2 and len(owners) == 1 and end < len(norms) and norms[end] in lx.MODIFIED_BY \
                        and not toks.clause_start[end] and not any(j in taken for j in range(i, end)):
                    # "the drainage board lads": the name's first words before the people of the place
                    out.append(self._mention(toks, i, end, next(iter(owners))))
                    taken.update(range(i, end))
                    break
                if len(key) == 2 and len(owners) == 1 and (end == len(norms) or toks.clause_start[end]) \
                        and not toks.tokens[end - 1].text.lower().replace("’", "'").endswith("'s") \
                        and not any(j in taken for j in range(i, end)) and self._cues.match_at(norms, i) is None \
                        and any(len(ws := name_words(f)) == 3 and ws[:2] == key and ws[2] in lx.GENERIC_HEADS
                                and f.lower().split()[-3:-1] == [t.text.lower() for t in toks.tokens[i:end]]
                                for f in self.kb.landmark_by_name[next(iter(owners))].surface_forms):
                    # "the other one at the street food, er, burns": "street food row" without its plain last word
                    out.append(self._mention(toks, i, end, next(iter(owners))))
                    taken.update(range(i, end))
                    break
                if len(key) < n or key not in self._prefixes or any(j in taken for j in range(i, end)):
                    continue
                gap = toks.gaps[end] if end < len(norms) else toks.text[toks.tokens[end - 1].end :]
                if end < len(norms) and not re.search(r"[—–\-]|\.\.\.|…", gap):
                    continue
                if not gap[:1].isspace() or len(" ".join(key)) < 4:
                    continue  # "st--" is a word cut off (a false start), not a short name
                if i >= 2 and end < len(norms) and norms[end] == norms[i - 2] and norms[end] in lx.PREPOSITIONS:
                    continue  # "fire at the mash -- at the still house": the frame said again, the name given up
                out.append(self._mention(toks, i, end, self._prefixes[key]))
                taken.update(range(i, end))
                break
        return out

    def _head_names(self, toks: Tokens, norms: tuple[str, ...], taken: set[int],
                    rel_ends: set[int]) -> list[PlaceMention]:
        """"the lodge" for "security lodge", "the chandler's" for "ship chandler's": after "the", the head
        word of a multi-word name that no other landmark's name shares (generic heads such as "shop" left out).
        ``rel_ends``: where the report's relation phrases end."""
        if not hasattr(self, "_heads"):
            owners: dict[str, set[str]] = {}
            for lm in self.kb.landmarks:
                for form in lm.surface_forms:
                    words = name_words(form)
                    if len(words) >= 2:
                        owners.setdefault(words[-1], set()).add(lm.name)
            words_elsewhere = self._name_word_owners
            # (a word of a longer cue still heads a name: "the well" is the town well, "well alight" aside)
            cue_words = self._single_cue_words
            rel_words = self._relation_name_words
            # (nor a word the KB's descriptions use of other landmarks too: "ride" of "splash ride", where the
            # coaster and the ghost house are rides as well)
            described: dict[str, set[str]] = {}
            name_keys = sorted({name_words(f) for other in self.kb.landmarks for f in other.surface_forms}, key=len,
                               reverse=True)
            for lm in self.kb.landmarks:
                words = list(norm_phrase(lm.description or ""))
                for key in name_keys:  # (a landmark named in a description is not the word used of it: "by the main gate")
                    n = len(key)
                    for i in range(len(words) - n + 1):
                        if n and tuple(words[i:i + n]) == key:
                            words[i:i + n] = [""] * n
                for i in range(1, len(words)):  # (nor "below the lodge": the one lodge, named by its head word)
                    if words[i - 1] == "the" and owners.get(words[i], set()) - {lm.name} \
                            and len(owners.get(words[i], set())) == 1:
                        words[i] = ""
                for w in words:
                    described.setdefault(w, set()).add(lm.name)
            # (a word another landmark's alias holds only before its own head still heads this one: "the church"
            # where "the church hall" is the hall's other name; the longer name is matched first when it is said.
            # Not a word of another canonical name: "the windmill" where "windmill green" is one)
            modifying: dict[str, set[str]] = {}
            for lm in self.kb.landmarks:
                canonical = set(name_words(lm.name))
                for form in lm.surface_forms:
                    for w in name_words(form)[:-1]:
                        if w not in canonical:
                            modifying.setdefault(w, set()).add(lm.name)
            self._heads = {w: next(iter(names)) for w, names in owners.items()
                           if len(names) == 1 and (words_elsewhere.get(w, set()) == names
                                                   or words_elsewhere.get(w, set()) - modifying.get(w, set()) == names)
                           and (len(w) >= 4 or w in lx.SHORT_PLACE_NOUNS) and w.isalpha()
                           and len(described.get(w, set()) - names) < 3
                           and w not in cue_words and w not in rel_words and w not in lx.DESCRIPTIVE_WORDS
                           and w not in lx.STOREY_WORDS and w not in lx.PART_NOUNS  # ("the roof" of anything)
                           and w not in lx.LOCATIVE_PARTS  # ("at tower five, full burial at the base": its base)
                           and w not in ("step", "steps", "door", "doors", "window", "windows")
                           and not (w in lx.WATER_BODIES and all(name_words(n)[-1:] != (w,) for n in names))}
            # heads that are words of a safe place as well ("the refuge" where "gas refuge" is the one refuge): the
            # landmark where the sentence puts it in a place's own position (below)
            desirable_words = {key[0] for bucket in self._cues._by_first.values() for key, (c, _src) in bucket
                               if len(key) == 1 and c in self.kb.category_by_name
                               and self.kb.category_by_name[c].role == Role.DESIRABLE}
            self._cue_heads = {w: next(iter(names)) for w, names in owners.items()
                               if len(names) == 1 and w in cue_words and w in desirable_words and w.isalpha()
                               and len(w) >= 5 and words_elsewhere.get(w, set()) == names
                               and not described.get(w, set()) - names and w not in rel_words}
            # ("the river is coming in under the doors": the water itself, where only "the back river" is a name)
            # ("can't get up the step": any doorstep; "the fire doors": any building's, not "the red doors")
            # heads no other landmark's description uses either: "the chapel is safe" where the castle chapel is
            # the one chapel the KB speaks of
            self._sole_heads = {w for w, name in self._heads.items() if not described.get(w, set()) - {name}}
            # ("the shop" where every name of the one shop ends in "shop": the gift shop, the souvenir shop) a head too
            # generic to name on its own names the one landmark all of whose names it heads
            self._own_heads = {w for w in self._sole_heads if w in lx.OWN_NAMING_HEADS and all(
                name_words(f)[-1:] == (w,) for f in self.kb.landmark_by_name[self._heads[w]].surface_forms)}
            # heads another landmark's names use only before their own head ("dunes" of "sand dunes", where
            # "dunes halt" is the halt): the head only as a relation's anchor ("the chalets that back onto the dunes")
            last_words = {w for lm in self.kb.landmarks for f in lm.surface_forms if (ws := name_words(f)) for w in ws[-1:]}
            self._anchor_heads = {w: next(iter(names)) for w, names in owners.items()
                                  if len(names) == 1 and w not in self._heads and len(w) >= 4 and w.isalpha()
                                  and all(w not in name_words(f)[-1:] for other in words_elsewhere.get(w, set()) - names
                                          for f in self.kb.landmark_by_name[other].surface_forms)
                                  and w in last_words and w not in cue_words and w not in rel_words
                                  and w not in lx.UNNAMING_HEADS | lx.DESCRIPTION_HEADS
                                  and (w not in lx.GENERIC_HEADS or words_elsewhere.get(w, set()) == names
                                       and name_words(next(iter(names)))[-1:] == (w,))}
            # ("the hut next to the place across from the shop": a generic head, the last word of the one name that
            # holds it, anchors a relation)
        out = []
        for i in range(0, len(norms)):
            w = norms[i]
            if w in self._first_words and i >= 2 and i not in taken and norms[i - 1] == "the" \
                    and ((i - 1) in rel_ends or norms[i - 2] in lx.RELATION_ENDINGS - {"of", "in", "at", "on", "by"}) \
                    and toks.tokens[i].text.lower().endswith("s") and toks.tokens[i].text.lower() != w \
                    and (i + 1 >= len(norms) or toks.clause_start[i + 1]):
                # "the hut that watches over the elephants": the animals said for the one place named after them
                # (``_first_words``, as ``_modifier_names`` reads them), as a relation's anchor only
                out.append(self._mention(toks, i, i + 1, self._first_words[w]))
                continue
            if w in self._anchor_heads and i >= 2 and i not in taken and norms[i - 1] == "the" and (i - 1) in rel_ends \
                    and (i + 1 >= len(norms) or toks.clause_start[i + 1] or norms[i + 1] in lx.COPULAS):
                out.append(self._mention(toks, i, i + 1, self._anchor_heads[w]))
                continue
            if w in self._cue_heads and i >= 1 and i not in taken and norms[i - 1] == "the" and (
                    (toks.clause_start[i - 1] or i == 1) and (
                        toks.tokens[i].text.lower().endswith(("'s", "’s"))
                        or i + 1 < len(norms) and norms[i + 1] in ("is", "has", "was"))
                    or i >= 2 and norms[i - 2] in ("at", "in", "inside", "into", "from")):
                # "the refuge is, uh, it's safe, no wait, the gas is getting in", "team two at the refuge now"
                out.append(self._mention(toks, i, i + 1, self._cue_heads[w]))
                continue
            opens = (i == 0 or toks.sentence_start[i] or toks.clause_start[i] and ":" in toks.gaps[i]
                     and w in self._sole_heads) \
                and w in self._heads and i not in taken \
                and (w not in lx.UNNAMING_HEADS | lx.GENERIC_HEADS | lx.DESCRIPTION_HEADS
                     or w in self._sole_heads and (w not in lx.UNNAMING_HEADS or w in self._own_heads)) and (
                toks.tokens[i].text.lower().endswith(("'s", "’s")) or i + 1 < len(norms) and norms[i + 1] in ("is", "has")
                or ":" in toks.gaps[i] and i + 1 < len(norms) and self._cues.match_at(norms, i + 1) is not None
                or i + 2 < len(norms) and norms[i + 1] in lx.STOREY_WORDS | {"wall", "walls", "door", "doors", "windows"}
                and not toks.clause_start[i + 1])
            # ("crane's leaning badly", "Chapel roof open to the sky": a report that opens on the bare head, said of it)
            if opens:
                out.append(self._mention(toks, i, i + 1, self._heads[w]))
                continue
            single = self._one_word_aliases().get(w) if w not in self._heads else None
            if single is not None and i not in taken and self._described_modifier(toks, norms, i, taken, single):
                out.append(self._mention(toks, i, i + 1, single))  # "the roof condensers": "the condensers"
                continue
            if i == 0 or w not in self._heads or i in taken or (i - 1) in taken or not (
                    norms[i - 1] == "the" or norms[i - 1] in ("my", "our") and (i - 1) in rel_ends
                    or self._described_modifier(toks, norms, i, taken)
                    or _after_same(norms, i)
                    # ("the place over the road from that church")
                    or norms[i - 1] in ("that", "this") and i >= 2 and (norms[i - 2] in lx.PREPOSITIONS or (i - 1) in rel_ends)):
                # ("the hall right below my cottage": the speaker's own, as a relation's anchor; not "my kitchen";
                # "the road that same gully empties onto": the one said before)
                continue
            if i >= 2 and norms[i - 1] == "the" and norms[i - 2] in ("up", "down") \
                    and w in ("hill", "road", "lane", "street", "slope", "valley", "track"):
                continue  # "ironmasters is way up the hill": which way, not "nob hill"
            contracted = toks.tokens[i].text.lower().endswith(("'s", "’s"))
            raw = toks.tokens[i].text.lower()
            if i + 2 < len(norms) and norms[i + 1] in ("at", "of") and not contracted \
                    and any(t in taken for t in range(i + 2, min(len(norms), i + 5))):
                continue  # "the playground at the primary school": that place's own, not the adventure playground
            if i + 2 < len(norms) and norms[i + 1] in ("in", "inside") and not contracted and (after := next(
                    (h for t in range(i + 2, min(len(norms), i + 5)) if t in taken
                     and (h := self._places.match_at(norms, t)) is not None), None)) is not None \
                    and after[1] != self._heads[w] and (after[1], self._heads[w]) not in self._related_pairs:
                continue  # "fell off the stage in the cinema": the cinema's own stage, not the landing stage (but "the
                # gate in the sea wall", where the KB sets the sluice gate in it, is that gate)
            if i + 2 < len(norms) and norms[i + 1] == "of" and norms[i + 2] in lx.ARTICLES and w in lx.EARTHWORKS \
                    and not contracted:
                continue  # "over the bank of the pond": the pond's own bank, not "the bring bank"
            if raw.endswith("s") and not contracted and not raw.endswith("ss") and raw != w and not any(
                    name_words(f)[-1:] == (w,) and f.lower().rstrip().endswith("s")
                    for f in self.kb.landmark_by_name[self._heads[w]].surface_forms):
                continue  # "walking wounded off the trails": many trails, not the one "skyline trail"
            # "the baths themselves are being used as a warm centre" (not "it's not the hotel itself burning")
            selfsame = i + 1 < len(norms) and norms[i + 1] in ("itself", "themselves", "themselve") \
                and norms[i - 2:i - 1] != ("not",)
            said_of = contracted or i + 1 >= len(norms) or toks.clause_start[i + 1] or norms[i + 1] in lx.COPULAS \
                or selfsame \
                or norms[i + 1] in ("and", "but") and norms[i + 2:i + 3] in (
                    ("theres",), ("there",), ("its",), ("it",), ("i",), ("we",), ("hes",), ("shes",), ("theyre",))
            # ("collapsed across the yard and there's a lad pinned under it": a clause of its own follows)
            verb_next = i + 2 < len(norms) and i >= 2 and norms[i - 2] in lx.GENERIC_HEADS | lx.DESCRIPTION_HEADS \
                and toks.tokens[i + 1].text.lower().endswith(("s", "ed")) \
                and norms[i + 2] in lx.RELATION_ENDINGS | {"into", "in", "at"} and not toks.clause_start[i + 2]  # ("the maltings empties into")
            # ("The stream the spillway feeds has burst its banks": a relative clause's verb, then the main clause's)
            d = 1 if i >= 4 and norms[i - 2] == norms[i - 1] == "the" else 0  # ("the row the, the footbridge carries")
            verb_next = verb_next or i >= 3 + d and i + 1 < len(norms) and norms[i - 3 - d] in lx.ARTICLES | {"whose"} \
                and norms[i - 2 - d].isalpha() and norms[i - 2 - d] not in _NOT_HEADS and (i - 2 - d) not in taken \
                and toks.tokens[i + 1].text.lower().endswith(("s", "ed")) and not toks.clause_start[i + 1] \
                and (i + 2 >= len(norms) or toks.clause_start[i + 2]
                     or norms[i + 2] in lx.COPULAS | {"has", "have", "had", "that", "thats", "which"}
                     or self._relations.match_at(norms, i + 1) is not None)  # ("the field the school plays its games on")
            if w in ("gate", "gates", "fence", "wall", "walls") and i >= 2 and toks.clause_start[i - 1] and (i - 2) in taken \
                    and (contracted or said_of):
                continue  # "the old dock, the gate's gone": the place just named, its gate (not the town gate)
            if w in ("path", "track", "trail") and name_words(self._heads[w])[-1:] != (w,) and (i - 1) not in rel_ends \
                    and not _after_same(norms, i):
                continue  # "stone has come away onto the path": any path, where only other names of the mule track end so
            if w in lx.UNNAMING_HEADS and w not in self._own_heads and not (
                        (i - 1) in rel_ends and w in self._sole_heads and name_words(self._heads[w])[-1:] == (w,)
                        and (i + 1 >= len(norms) or toks.clause_start[i + 1] or norms[i + 1] in lx.COPULAS)) \
                    or (w in lx.GENERIC_HEADS or w in lx.DESCRIPTION_HEADS) and (i - 1) not in rel_ends \
                    and not ((said_of or verb_next) and (w in lx.GENERIC_HEADS and (contracted or w not in lx.DESCRIPTION_HEADS)
                                          or w in self._sole_heads and (w not in lx.UNNAMING_HEADS or w in self._own_heads)
                                          and norms[i - 2:i - 1] != ("from",))):
                # "the terrace" names the one terrace only as a relation's anchor ("back to back with the terrace"),
                # or as what a predicate is said of ("the barn's out now")
                continue
            if i + 1 < len(norms) and norms[i + 1] in ("that", "which", "where", "who") and not toks.clause_start[i + 1] \
                    and not (i >= 2 and norms[i - 1] == "the" and (norms[i - 2] == "its" or norms[i - 3:i - 1] == ("it", "is"))
                             and norms[i + 1] == "that") \
                    and not (norms[i + 1] == "where" and (i + 2 >= len(norms) or norms[i + 2] in lx.ARTICLES)
                             and not self._names_anchor(toks, norms, i + 2, taken)):
                # ("the cage where the spare gas bottles are kept": what is kept there, no place the relation needs)
                continue  # "the compound that supplies it": a description for the relation passes (but "it's the
                # slipway that's under": a cleft, the place named)
            if i + 1 < len(norms) and not toks.clause_start[i + 1] and norms[i + 1].isalpha() \
                    and not selfsame and norms[i + 1] not in lx.FUNCTION_WORDS \
                    and self._relations.match_at(norms, i + 1) is None \
                    and not toks.tokens[i].text.lower().endswith(("'s", "’s")) and not verb_next \
                    and not (norms[i + 1] in lx.STOREY_WORDS | {"kitchen"} and (
                        i + 2 >= len(norms) or toks.clause_start[i + 2] or norms[i + 2] in lx.COPULAS | {"that", "thats"})):
                # (but "the museum cellar that's flooded": a part of the one museum, in it)
                continue  # "the lodge gate": a longer noun phrase ("the barn's out now" is the barn)
            if i + 1 < len(norms) and toks.gaps[i + 1] == "-":
                continue  # "the walk-outs": a word of its own, hyphenated
            if w in lx.BODY_PARTS and i >= 2 and norms[i - 2] in ("to", "on", "from") \
                    and any(norms[m] in lx.INJURY_WORDS | {"bleeding", "hurt", "hit", "injured"}
                            for m in range(max(0, i - 6), i - 2)):
                continue  # "bleeding heavily from the head": the casualty's, no "pier head"
            out.append(self._mention(toks, i, i + 1, self._heads[w]))
        # "the car park" for "valley car park" / "the big car park": a two-word tail only one landmark's names end in
        if not hasattr(self, "_pair_heads"):
            # (and no other landmark's name holds the pair anywhere: "the car park" is none of "car park level 1",
            # "car park level 2" and "ground level car park"; a two-word name is its own tail)
            pairs: dict[tuple[str, ...], set[str]] = {}
            held: dict[tuple[str, ...], set[str]] = {}
            for lm in self.kb.landmarks:
                for form in lm.surface_forms:
                    words = name_words(form)
                    if len(words) >= 2:
                        pairs.setdefault(words[-2:], set()).add(lm.name)
                    for n in range(len(words) - 1):
                        held.setdefault(words[n:n + 2], set()).add(lm.name)
            self._pair_heads = {k: next(iter(v)) for k, v in pairs.items() if len(v) == 1 and held.get(k, v) == v}
        taken_now = taken | {i for p in out for i in range(p.start_tok, p.end_tok)}
        for i in range(0, len(norms) - 1):
            key = norms[i:i + 2]
            # (or opening a clause of its own, as sitreps do: "Sitrep: pumping house flooded to the motor floor")
            opens = (i == 0 or toks.clause_start[i]) and (
                i + 2 >= len(norms) or toks.clause_start[i + 2] or norms[i + 2] in lx.COPULAS | {"has", "have", "had"}
                or self._cues.match_at(norms, i + 2) is not None)
            if key in self._pair_heads and (i > 0 and norms[i - 1] == "the" or opens) \
                    and not {i, i + 1} & taken_now and not toks.clause_start[i + 1] \
                    and not (i + 2 < len(norms) and norms[i + 2] in lx.SPEAKER_ROLES | lx.ROLE_LABELS
                             and not toks.clause_start[i + 2] and norms[max(0, i - 4):i].count("this")):
                # (not "this is um the tipping hall marshal": who calls, the name only says which marshal)
                out.append(self._mention(toks, i, i + 2, self._pair_heads[key]))
                taken_now.update((i, i + 1))
        return out

    @functools.cached_property
    def _name_word_owners(self) -> dict[str, set[str]]:
        """Every word of every landmark's names, with the landmarks whose names hold it."""
        owners: dict[str, set[str]] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                for w in name_words(form):
                    owners.setdefault(w, set()).add(lm.name)
        return owners

    @functools.cached_property
    def _relation_verbs(self) -> frozenset[str]:
        """The first words of the KB's relation names ("pumps" of ``pumps_diesel_for``)."""
        return frozenset(norm_phrase(r.phrase)[0] for r in self.kb.relations if norm_phrase(r.phrase))

    @functools.cached_property
    def _kb_nouns(self) -> frozenset[str]:
        """Words the KB's landmark descriptions use as nouns of their own, after "the", twice or more ("beside
        the burn", "over the burn"), which its category descriptions do not use: said so, they are no cue."""
        counts: dict[str, int] = {}
        for lm in self.kb.landmarks:
            words = norm_phrase(lm.description or "")
            for i in range(1, len(words)):
                if words[i - 1] == "the":
                    counts[words[i]] = counts.get(words[i], 0) + 1
        used = {w for c in self.kb.categories for w in norm_phrase(c.description or "")}
        return frozenset(w for w, n in counts.items() if n >= 2 and w not in used and w.isalpha())

    @functools.cached_property
    def _single_cue_words(self) -> set[str]:
        """Cues of one word ("flooded"): no word of a name that could be one of them names the place."""
        return {key[0] for key in self._cue_keys() if len(key) == 1}

    @functools.cached_property
    def _relation_name_words(self) -> set[str]:
        """The words of the KB's relation names."""
        return {w for rel in self.kb.relations for w in rel.phrase.split()}

    def _described_as_thing(self, name: str, word: str) -> bool:
        """The landmark's description has ``word`` as a noun of its own ("with the big wood-fired evaporator, its
        stack"), not only before another ("coastguard lookout hut"), and the name does not say whose ("doctor's room")."""
        lm = self.kb.landmark_by_name[name]
        if "'" in lm.name or "’" in lm.name:
            return False
        words = re.findall(r"[a-z0-9]+|[,.;:()\-]", (lm.description or "").lower())
        return any(t in (word, word + "s") and (k + 1 == len(words) or not words[k + 1].isalnum()
                                                 or words[k + 1] in lx.FUNCTION_WORDS)
                   for k, t in enumerate(words))

    @functools.cached_property
    def _first_words(self) -> dict[str, str]:
        """First words of multi-word names that only one landmark's names hold (for ``_modifier_names``)."""
        owners = self._name_word_owners
        cue_words = self._single_cue_words
        rel_words = self._relation_name_words
        firsts: dict[str, str] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                words = [w for w in name_words(form) if w not in lx.ARTICLES]
                w = words[0] if len(words) >= 2 else ""
                if len(w) >= 5 and w.isalpha() and owners.get(w) == {lm.name} and w not in cue_words \
                        and w not in rel_words and w not in lx.FUNCTION_WORDS | lx.DESCRIPTIVE_WORDS \
                        | lx.GENERIC_HEADS | lx.STOREY_WORDS | lx.PART_NOUNS and not _direction_word(w):
                    firsts[w] = lm.name
        return firsts

    @functools.cached_property
    def _nickname_firsts(self) -> frozenset[str]:
        """First words (of ``_first_words``) that begin two or more names of their landmark ("genny house", "the genny
        shed"): the place's own nickname, said bare as well ("the tank that feeds the genny")."""
        count: dict[str, set[tuple[str, ...]]] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                words = tuple(w for w in name_words(form) if w not in lx.ARTICLES)
                if len(words) >= 2 and self._first_words.get(words[0]) == lm.name:
                    count.setdefault(words[0], set()).add(words)
        return frozenset(w for w, forms in count.items() if len(forms) >= 2)

    @functools.cached_property
    def _side_words(self) -> dict[str, str]:
        """First words that tell a pair of landmarks apart by side or direction ("southbound lay-by" beside
        "northbound lay-by", "upper car park" beside "lower car park"), with the landmark each names."""
        names = [(lm.name, tuple(w for w in name_words(f) if w not in lx.ARTICLES))
                 for lm in self.kb.landmarks for f in lm.surface_forms]
        owners: dict[str, set[str]] = {}
        for name, words in names:
            if len(words) >= 2 and (_direction_word(words[0]) or words[0] in lx.SIDE_WORDS) and any(
                    other != name and len(ws) == len(words) and ws[1:] == words[1:] and ws[0] != words[0]
                    for other, ws in names):
                owners.setdefault(words[0], set()).add(name)
        return {w: next(iter(v)) for w, v in owners.items() if len(v) == 1 and self._name_word_owners.get(w) == v}

    @functools.cached_property
    def _name_prefix_owners(self) -> dict[tuple[str, ...], set[str]]:
        """The first words of every multi-word name (all but its last), with the landmarks whose names begin so."""
        return self._name_part_owners(lambda words, n: words[:n])

    @functools.cached_property
    def _tail_owners(self) -> dict[tuple[str, ...], set[str]]:
        """The last words of every multi-word name (all but its first), with the landmarks whose names end so."""
        return self._name_part_owners(lambda words, n: words[-n:])

    def _name_part_owners(self, part: Callable[[tuple[str, ...], int], tuple[str, ...]]) -> dict[tuple[str, ...], set[str]]:
        """``part(words, n)`` of every name's words for n = 1 .. len - 1, with the landmarks whose names have it."""
        owners: dict[tuple[str, ...], set[str]] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                words = name_words(form)
                for n in range(1, len(words)):
                    owners.setdefault(part(words, n), set()).add(lm.name)
        return owners

    def _shared_tail_itself(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"the mast towering over the top car park and two spectators hurt in the car park itself": the last words
        of several names, said with "itself", are the one of those places said last."""
        taken = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        for k in range(2, len(norms)):
            if norms[k] != "itself":
                continue
            for n in (3, 2, 1):
                a = k - n
                if a < 1 or norms[a - 1] != "the" or any(i in taken for i in range(a - 1, k)):
                    continue
                owners = self._tail_owners.get(norms[a:k], set())
                if len(owners) < 2:
                    continue
                prev = max((p for p in ex.places if p.end_tok <= a - 1 and p.landmark in owners and p.status != "retracted"),
                           key=lambda p: p.end_tok, default=None)
                if prev is not None:
                    ex.places.append(self._mention(toks, a - 1, k, prev.landmark))
                    taken.update(range(a - 1, k))
                break

    @functools.cached_property
    def _headless_forms(self) -> dict[tuple[str, ...], str]:
        """Multi-word names without their last word ("cavendish" for "cavendish stand", "valley primary"
        for "valley primary school"), where only one landmark's names begin so and no name is just that."""
        owners = self._name_prefix_owners
        whole = {name_words(form) for lm in self.kb.landmarks for form in lm.surface_forms}
        banned = self._single_cue_words | self._relation_name_words | lx.FUNCTION_WORDS | lx.DESCRIPTIVE_WORDS \
            | lx.GENERIC_HEADS | lx.STOREY_WORDS | lx.PART_NOUNS
        described = {lm.name: " " + " ".join(norm_phrase(lm.description)) + " " for lm in self.kb.landmarks}
        out: dict[tuple[str, ...], str] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                key = name_words(form)[:-1]
                last = key[-1] if key else ""
                own = [" " + " ".join(name_words(f)) + " " for f in lm.surface_forms] if len(key) == 1 else []
                if any(f" {' '.join(key)} " in functools.reduce(lambda t, o: t.replace(o, " "), own, d)
                       for name, d in described.items() if name != lm.name):
                    continue  # "at High Garth farm" in other places' descriptions: the name of something larger
                    # (not this landmark's own name there: "the laundrette at the foot of Kestrel Tower")
                if len(owners.get(key, ())) == 1 and key not in whole and len(last) >= 4 and last.isalpha() \
                        and last not in banned and not _direction_word(last) \
                        and not (len(key) == 1 and self._name_word_owners.get(last, set()) != {lm.name}):
                    out[key] = lm.name
        return out

    @functools.cached_property
    def _possessive_headless(self) -> frozenset[tuple[str, ...]]:
        """Headless forms whose last word is a possessive in the alias ("greencaps" of "the greencaps' house"):
        the people of the place, a name said in lowercase as well."""
        known = self.embedder.vocabulary() if self.embedder is not None else frozenset()
        # (a word of its own, no common noun: "the driver" of "the drivers' room" is any driver)
        return frozenset(key for lm in self.kb.landmarks for form in lm.surface_forms
                         if len(form.split()) >= 2 and form.split()[-2].endswith(("'", "'s", "’", "’s"))
                         and (key := name_words(form)[:-1]) in self._headless_forms
                         and len(key) == 1 and key[0] not in _PEOPLE_WORDS and key[0] not in known
                         and form.split()[-2].lower().rstrip("'’s") not in known)

    def _headless_names(self, toks: Tokens, norms: tuple[str, ...], taken: set[int]) -> list[PlaceMention]:
        """"fire in the Cavendish" (cavendish stand), "Headteacher of Valley Primary" (valley primary school),
        "St Barbara's is open" (st barbara's church): a name said without its last word, as a proper noun
        (capitalised; one word only after "the"), ending its noun phrase."""
        out: list[PlaceMention] = []
        for i in range(len(norms)):
            if i in taken:
                continue
            for n in (3, 2, 1):
                key = norms[i:i + n]
                end = i + n
                if len(key) < n or key not in self._headless_forms or any(j in taken for j in range(i, end)):
                    continue
                if n == 1 and (toks.sentence_start[i] or norms[i - 1] not in ("the", "at", "in", "inside", "from", "not")) \
                        and norms[end:end + 2] != ("i", "mean") \
                        and not (toks.sentence_start[i] and toks.tokens[i].text.lower().endswith(("'s", "’s"))
                                 and norms[i + 1:i + 2] in (("where",), ("now",), ("being",), ("our",), ("the",))):
                    continue  # (one capitalised word where a sentence starts, or "Mr Rowley", names no place; but
                    # "Kohima's where we're sending everyone": what is said of it names it)
                if not all(toks.tokens[j].text[:1].isupper() for j in range(i, end)) \
                        and not (key in self._possessive_headless and i > 0 and norms[i - 1] == "the"
                                 and end < len(norms) and not toks.clause_start[end]
                                 and norms[end] not in lx.FUNCTION_WORDS):
                    continue  # ("the valley primary concern": a plain phrase, not a name; but "the greencaps" of
                    # "the greencaps' house": whose it is, named lowercase too)
                if end < len(norms) and not toks.clause_start[end] and norms[end] not in lx.FUNCTION_WORDS \
                        and norms[end] not in lx.COPULAS and not re.search(r"[,.;:!?—–\-(]", toks.gaps[end]) \
                        and not (key in self._possessive_headless and toks.tokens[end - 1].text.lower().endswith("s")) \
                        and norms[end:end + 2] != ("i", "mean"):
                    continue  # "the Cavendish family": the word modifies a noun of its own ("the greencaps keep
                    # an eye on it": the people, plural, doing it)
                out.append(self._mention(toks, i, end, self._headless_forms[key]))
                taken = taken | set(range(i, end))
                break
        return out

    @functools.cached_property
    def _clipped_forms(self) -> dict[tuple[str, str], str]:
        """(clipped first word, last word) of two-word names, for one landmark each ("bio", "block")."""
        known = self.embedder.vocabulary() if self.embedder is not None else frozenset()
        # "the bio block" for "biosciences block": a clipped first word, then the name's own last word
        clipped: dict[tuple[str, str], set[str]] = {}
        for lm in self.kb.landmarks:
            for form in lm.surface_forms:
                words = [x for x in name_words(form) if x not in lx.ARTICLES]
                if len(words) == 2 and len(words[0]) >= 6:
                    for n in range(3, len(words[0]) - 2):
                        # (a clipping, not a word of its own: "the car park" is no "caravan park")
                        if words[0][:n] in lx.CLIPPINGS or words[0][:n] not in known:
                            clipped.setdefault((words[0][:n], words[1]), set()).add(lm.name)
        return {k: next(iter(v)) for k, v in clipped.items() if len(v) == 1}

    def _modifier_names(self, toks: Tokens, norms: tuple[str, ...], taken: set[int],
                        rel_ends: set[int]) -> list[PlaceMention]:
        """"the generator place" for "generator compound", "guarding the approach to reception" for "reception
        pavilion", "the bio block" for "biosciences block": the first word of a multi-word name that no other
        landmark's name holds, with a vague head after it ("place", "site", "spot") or said bare as the
        anchor of a relation phrase (``rel_ends``: where the report's relation phrases end); or that word
        clipped, with the name's own last word. (Said bare anywhere else it is too often a plain word: "the
        overflow" of a chapel, "the giraffes" of a giraffe paddock.)"""
        out = []
        for i in range(1, len(norms) - 1):
            key = (norms[i], norms[i + 1])
            if key in self._clipped_forms and norms[i - 1] in lx.ARTICLES - {"a", "an"} and not {i, i + 1} & taken \
                    and not toks.clause_start[i + 1]:
                out.append(self._mention(toks, i, i + 2, self._clipped_forms[key]))
                taken = taken | {i, i + 1}
        for i, w in enumerate(norms):
            if w in self._side_words and i not in taken and (i == 0 or toks.clause_start[i] or norms[i - 1] in lx.ARTICLES) \
                    and (i + 1 >= len(norms) or toks.clause_start[i + 1]) \
                    and any(norms[j] in self._side_words and norms[j] != w and self._side_words[norms[j]] != self._side_words[w]
                            and toks.sentence_of[j] == toks.sentence_of[i] for j in range(len(norms))) and (
                        any(norms[j] in _REPAIR_WORDS for j in range(max(0, i - 3), min(len(norms), i + 4)) if j != i)
                        or any(_first_was_right_at(norms, j) for j in range(max(0, i - 8), i))):
                # "on the southbound, no, northbound lay-by": the word that tells the pair apart, said alone in a
                # repair
                out.append(self._mention(toks, i, i + 1, self._side_words[w]))
                continue
            if w not in self._first_words or i in taken or i == 0:
                continue
            nxt = i + 1
            after = nxt + 1
            # (or the head its own description uses: "the caravan field" for a "caravan and camping field")
            if nxt < len(norms) and (norms[nxt] in lx.VAGUE_PLACE_HEADS or norms[nxt] in self._place_nouns()
                                     and norms[nxt] in self._description_words()[self._first_words[w]]) \
                    and not toks.clause_start[nxt] \
                    and norms[i - 1] in lx.ARTICLES - {"a", "an"} and nxt not in taken \
                    and (w, norms[nxt]) not in self._glossary_keys \
                    and (after >= len(norms) or toks.clause_start[after] or norms[after] in lx.COPULAS
                         or norms[after] in lx.PERSON_SUBJECTS | lx.COORDINATORS | {"theres", "there"}) \
                    and not (after < len(norms) and self._relations.match_at(norms, after) is not None):
                # (only a noun phrase that ends there: "the ferry building upstream of the weir" is a description
                # for the relation passes, headed by "building"; not "it's a rally point", any one, a glossary term)
                out.append(self._mention(toks, i - 1, nxt + 1, self._first_words[w]))
                continue
            name = self._first_words[w]
            if norms[i - 1] == "the" and len(name_words(name)) == 2 and name_words(name)[0] == w \
                    and name_words(name)[1] in _HOUSING_HEADS and w not in lx.WATER_WORDS | lx.VEHICLE_WORDS \
                    and self._described_as_thing(name, w) \
                    and not toks.tokens[i].text.lower().endswith("s") \
                    and (nxt >= len(norms) or toks.clause_start[nxt] or norms[nxt] in lx.COPULAS | {"has", "have", "from", "s"}):
                # "the shed they fire the evaporator from": the machine the evaporator house is named for, said for it
                out.append(self._mention(toks, i, nxt, name))
                continue
            j = i - 1 if norms[i - 1] == "the" else i
            if j in rel_ends and (nxt >= len(norms) or toks.clause_start[nxt] or norms[nxt] in lx.COPULAS | {"has", "have"}) \
                    and not toks.tokens[i].text.lower().endswith(("'s", "’s")) and w not in lx.WATER_WORDS:
                # (not "where it dips through the water": the water itself, not the "water bowser")
                out.append(self._mention(toks, i, nxt, self._first_words[w]))
            elif w in self._nickname_firsts and norms[i - 1] == "the" \
                    and (nxt >= len(norms) or toks.clause_start[nxt] or norms[nxt] in lx.COPULAS | {"has", "have"}) \
                    and not (nxt < len(norms) and re.search(r"[—–-]|\.\.\.|…", toks.gaps[nxt])) \
                    and (self.embedder is None or w not in self.embedder.vocabulary()) \
                    and toks.tokens[i].text.lower() == w and w not in lx.WATER_WORDS:
                # (said as the names say it: not "the giraffes are all right", the animals)
                out.append(self._mention(toks, i, nxt, self._first_words[w]))  # "the tank that feeds the genny"
        return out

    def _resolve_containers(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"the fuel station shop at the motorway services", "the HGV park at the services": a place said with
        a landmark whose cells hold all of its own ("at", "in", "inside", "on", "within" it) is located by
        it; the larger one is a reference point, not a claim."""
        cells = {lm.name: {tuple(c) for c in lm.cells} for lm in self.kb.landmarks}
        for idx, q in enumerate(ex.places):
            if q.status != "active" or q.via is not None:
                continue
            k = q.start_tok - 1
            if k >= 1 and norms[k - 1] in lx.DETERMINERS and norms[k].isalpha():
                k -= 1  # "at the motorway services": a modifier the name did not take in
            while k >= 0 and norms[k] in lx.DETERMINERS:
                k -= 1
            if k < 1 or norms[k] not in ("at", "in", "inside", "on", "within") or ex.tokens.clause_start[k]:
                continue
            p = next((p for p in ex.places if p.end_tok == k and p.status == "active"), None)
            if p is not None and p.landmark != q.landmark and cells[p.landmark] < cells[q.landmark]:
                ex.places[idx] = replace(q, status="reference", reason=f"holds '{p.text}'")

    @functools.cached_property
    def _number_ranges(self) -> dict[str, list[tuple[int, int, str]]]:
        """unit -> (low, high, landmark) of every numbered range the KB gives a landmark: in its name or an
        alias ("tower floors 9-12", "car park level 1"); else a range in its description ("Pier with gates 1 to
        4"). A single number a description mentions in passing ("on the roof, above floor 12") is none."""
        out: dict[str, list[tuple[int, int, str]]] = {}
        for lm in self.kb.landmarks:
            named = {r for form in lm.surface_forms for r in text_ranges(form, at_end=True)}
            described = {r for r in text_ranges(lm.description or "") if r[1] < r[2]}
            for unit, lo, hi in sorted(named or described):
                out.setdefault(unit, []).append((lo, hi, lm.name))
        return out

    def _number_owner(self, unit: str, value: int) -> str | None:
        """The one landmark whose range of the unit (else of its sibling unit) holds the number."""
        ranges = self._number_ranges
        for u in (unit, SIBLING_UNITS.get(unit)):
            owners = {name for lo, hi, name in ranges.get(u or "", []) if lo <= value <= hi}
            if owners:
                return next(iter(owners)) if len(owners) == 1 else None
        return None

    REPAIRED_NUMBER_WORDS = frozenset({"sorry", "no", "correction", "mean", "make", "that", "er", "um", "uh", "wait",
                                       "or", "rather", "actually", "scratch"})

    def _numbered_places(self, toks: Tokens, norms: tuple[str, ...], taken: set[int]) -> list[PlaceMention]:
        """"fire on floor ten", "the seventh floor", "bay 14": a number the KB's numbered ranges place in exactly
        one landmark ("floors 9-12"); a bare number that repairs one just said ("floor six -- sorry, sixteen")
        keeps its unit."""
        ranges = self._number_ranges
        if not ranges:
            return []
        out: list[PlaceMention] = []
        last: tuple[str, int] | None = None  # the unit of the last numbered mention and where it ended
        i = 0
        while i < len(norms):
            hit: tuple[int, int, str, int] | None = None
            unit = UNITS.get(norms[i]) or UNITS.get(toks.tokens[i].text.lower())
            if i not in taken and unit is not None and (unit in ranges or SIBLING_UNITS.get(unit) in ranges):
                n = number_at(norms, i + 1) if i + 1 < len(norms) and not toks.clause_start[i + 1] else None
                if n is not None:
                    hit = (i, n[1], unit, n[0])  # "floor ten", "level 3"
                elif i > 0 and is_ordinal(norms[i - 1]):
                    # "the seventh floor", "10th floor", "twenty first floor" (two words, from i - 2)
                    for a in (i - 2, i - 1):
                        got = number_at(norms, a) if a >= 0 else None
                        if got is not None and got[1] == i:
                            hit = (a, i + 1, unit, got[0])
                            break
            elif i not in taken and last is not None and is_number(norms[i]) and i - last[1] <= 5 \
                    and not any(toks.sentence_start[t] for t in range(last[1], i + 1)) \
                    and (i + 1 >= len(norms) or UNITS.get(norms[i + 1]) is None) \
                    and (any(d in toks.gaps[t] for t in range(last[1], i + 1) for d in ("-", "—", "–"))
                         or any(norms[t] in self.REPAIRED_NUMBER_WORDS for t in range(last[1], i))):
                got = number_at(norms, i)
                if got is not None:
                    hit = (i, got[1], last[0], got[0])  # "floor six -- sorry, sixteen"
            if hit is None:
                i += 1
                continue
            a, b, unit, value = hit
            owner = self._number_owner(unit, value)
            if owner is not None and not taken.intersection(range(a, b)):
                out.append(self._mention(toks, a, b, owner))
            last = (unit, b)
            i = b
        return out

    def _modifier_ones(self, toks: Tokens, norms: tuple[str, ...], places: list[PlaceMention]) -> list[PlaceMention]:
        """"west jetty ... Actually no, that's the east one": "the X one" names the landmark whose name is X and
        a head; where several are (the east jetty, the east portal), the one whose head was said before."""
        if not hasattr(self, "_modifiers"):
            mods: dict[str, set[str]] = {}
            for lm in self.kb.landmarks:
                for form in lm.surface_forms:
                    words = name_words(form)
                    if len(words) >= 2 and words[0].isalpha() and len(words[0]) >= 3 \
                            and words[0] not in lx.GENERIC_HEADS and words[0] not in lx.FUNCTION_WORDS:
                        mods.setdefault(words[0], set()).add(lm.name)
            self._modifiers = mods
        out: list[PlaceMention] = []
        taken = {i for p in places for i in range(p.start_tok, p.end_tok)}
        for i in range(1, len(norms) - 1):
            names = self._modifiers.get(norms[i])
            if not names or norms[i - 1] != "the" or norms[i + 1] != "one" or {i - 1, i, i + 1} & taken \
                    or toks.clause_start[i + 1]:
                continue  # (not "Crew Two on the roof. One of the IBC tanks ...": a new sentence's "one")
            said = set(norms[:i - 1])
            if len(names) > 1:
                names = {n for n in names if name_words(n)[-1] in said}
            elif norms[i] in _PLAIN_ADJECTIVES and any(
                    p.landmark not in names and p.end_tok < i and toks.sentence_of[p.start_tok] == toks.sentence_of[i]
                    and toks.tokens[p.end_tok - 1].text.lower().endswith("s")
                    and not toks.tokens[p.end_tok - 1].text.lower().endswith(("'s", "’s", "ss")) for p in places):
                # "the generators are on fire, flames out the side of the big one": one of those just said, no "big
                # catapult" whose head was never said
                names = {n for n in names if any(name_words(f)[:1] == (norms[i],) and name_words(f)[-1] in said
                                                 for f in self.kb.landmark_by_name[n].surface_forms)}
            if len(names) != 1:
                continue
            out.append(replace(self._mention(toks, i - 1, i + 2, next(iter(names))), reason=f"the '{norms[i]}' one"))
            taken.update(range(i - 1, i + 2))
        return out

    def _head_groups(self) -> dict[str, set[str]]:
        """Head words several landmarks' names end in ("portal": east and west portal; "bay": refuge bay 4 and
        7, the head before the number), with those landmarks."""
        if not hasattr(self, "_shared_heads"):
            owners: dict[str, set[str]] = {}
            for lm in self.kb.landmarks:
                for head in filter(None, map(_name_head, lm.surface_forms)):
                    owners.setdefault(head, set()).add(lm.name)
            for lm in self.kb.landmarks:  # ("the block" for the seg beside "e block", "education block")
                for words in (name_words(f) for f in lm.surface_forms):
                    if len(words) == 1 and len(owners.get(words[0], ())) >= 2:
                        owners[words[0]].add(lm.name)
            self._shared_heads = {w: names for w, names in owners.items() if len(names) >= 2}
        return self._shared_heads

    def _shared_head_group(self, norms: tuple[str, ...], p: PlaceMention) -> set[str]:
        """The landmarks whose names share the one word ``p`` was said as, when its own is among them ("the
        block": the seg's alias, e block, education block); else none."""
        if p.end_tok - p.start_tok != 1 or p.reason:
            return set()
        group = self._head_groups().get(norms[p.start_tok], set())
        return group if p.landmark in group else set()

    def _definite_heads(self, toks: Tokens, norms: tuple[str, ...], places: list[PlaceMention]) -> list[PlaceMention]:
        """"Hydrant pressure's gone at the west portal ... that portal's full of smoke": "the" / "that" and a
        head word several landmarks' names end in ("east portal", "west portal") is the one of them named
        last before it, by name or (in a second pass, once they are resolved) by a description. A head that goes on into a longer noun phrase or a relative clause ("the portal
        that has the lay-by", "the field the shower block backs onto") is a description, not this."""
        shared = self._head_groups()
        out: list[PlaceMention] = []
        taken = {i for p in places for i in range(p.start_tok, p.end_tok)}
        for i in range(1, len(norms)):
            if norms[i - 1] in ("my", "our", "his", "her", "their") and i not in taken and norms[i].isalpha() \
                    and len(norms[i]) >= 3 and norms[i + 1:i + 2] not in (
                        ("gone",), ("come",), ("been",), ("just",), ("said",), ("says",), ("coming",), ("going",)):
                # (not "our doctor's gone out to him": a person; nor "Stan's stuck out on his shed roof": a roof
                # of someone else's own shed)
                if norms[i - 1] in ("his", "her", "their") and norms[i + 1:i + 2] and norms[i + 1] in lx.STOREY_WORDS:
                    continue
                # "Mrs Kay from the village shop here, the place my shop is tucked in beside": the speaker's own,
                # named before; "a firefighter at the fire hall reports ... across the road from his station"
                mine = [p for p in places if p.end_tok <= i - 1 and p.status == "active" and any(
                    name_words(f)[-1:] == (norms[i],) for f in self.kb.landmark_by_name[p.landmark].surface_forms)]
                sided = norms[i] in lx.SIDE_WORDS | {"back", "side"} and norms[i + 1:i + 2] in (("wall",), ("side",), ("gable",))
                part = sided or norms[i] in ("wall", "gable")  # "the little shop built onto our east wall"
                if not mine and norms[i - 1] in ("my", "our") and (part or norms[i] in (
                        "building", "place", "premises", "storeroom", "stockroom", "kitchen", "cellar", "shop",
                        "caravan", "tent", "pitch", "motorhome", "camper")):
                    # ("I'm at the campsite ... he's had a fall by our caravan": a pitch there)
                    # "I'm at the pharmacy. The shop our building's built onto": where the speaker is
                    mine = [p for p in places if p.end_tok <= i - 1 and p.status == "active"
                            and self._speaker_here(norms, p)]
                    own = self._trade_place(toks, norms) if not mine else None
                    if own is not None:
                        out.append(replace(self._mention(toks, i - 1, i + 1, own),
                                           reason=f"the speaker's '{norms[i]}', where they work"))
                        taken.update(range(i - 1, i + 1))
                        continue
                if mine:
                    last = max(mine, key=lambda p: p.end_tok)
                    end = i + 2 if sided else i + 1
                    out.append(replace(self._mention(toks, i - 1, end, last.landmark),
                                       reason=f"the speaker's '{' '.join(norms[i:end])}', '{last.text}'"))
                    taken.update(range(i - 1, end))
                    continue
            names = shared.get(norms[i])
            relative_anchor = False
            if i >= 3 and norms[i - 1] in ("the", "that") and norms[i - 3] == "the" and norms[i - 2].isalpha() \
                    and norms[i - 2] not in lx.FUNCTION_WORDS and i + 1 < len(norms) and i not in taken \
                    and (norms[i + 1] in self._relation_verbs or self._relations.match_at(norms, i + 1) is not None):
                # "the road the field opens onto", "car park field" said before: the anchor of a relative clause,
                # by the last word of the one place just named with it (a word too plain to name it alone)
                said = {p.landmark for p in places if p.end_tok <= i - 3 and p.status == "active" and p.via is None
                        and norms[p.end_tok - 1] == norms[i] and (not names or p.landmark in names)}
                if len(said) == 1:
                    names, relative_anchor = said, True
            selfsame = norms[i + 1:i + 2] in (("itself",), ("themselve",))
            if not names and (selfsame or norms[i - 1] in ("that", "this") and i not in taken and norms[i].isalpha()
                              and norms[i] not in lx.FUNCTION_WORDS):
                # the places said before whose last word this is: "the roundels themselves" after "the five roundels"
                # (any of them); "the compound at the back of the toilets. And that compound's smoking" (the one)
                ended_so = {p.landmark for p in places if p.end_tok <= i - 1 and norms[p.end_tok - 1] == norms[i]}
                if selfsame or len(ended_so) == 1:
                    names = ended_so
            if not names or i in taken or (i - 1) in taken or norms[i - 1] not in ("the", "that", "this"):
                continue
            end = i + 1
            goes_on = False  # the head goes on into a longer noun phrase or a clause of its own
            if end < len(norms) and norms[end] in ("itself", "themselve"):
                end += 1
            else:
                goes_on = end < len(norms) and not toks.clause_start[end] \
                    and (norms[end] not in lx.COPULAS | lx.ANAPHOR_VERBS
                         # ("the well just downhill of it": where it stands, said of it)
                         or norms[end] in ("just", "right") and self._relations.match_at(norms, end + 1) is not None) \
                    and not toks.tokens[i].text.lower().endswith(("'s", "’s"))
            if goes_on and not relative_anchor and not (norms[i - 1] in ("that", "this") and (norms[end] in self._relation_verbs
                                                                      or self._relations.match_at(norms, end) is not None)):
                continue  # (but "the yard that shed takes its plate from": the shed just said, anchoring a relation)
            before = [p for p in places if p.end_tok <= i - 1 and p.landmark in names]
            if goes_on and not relative_anchor:
                # (the demonstrative before a relation: a place itself said, not a description's reference point)
                before = [p for p in before if p.status == "active" and not any(
                    self._relations.match_at(norms, k) is not None for k in (p.end_tok, p.end_tok + 1) if k < len(norms))]
            if not before:
                continue
            raw = toks.tokens[i].text.lower()
            exact = [p for p in before if any(f.lower().split()[-1:] == [raw]
                                              for f in self.kb.landmark_by_name[p.landmark].surface_forms)]
            last = max(exact or before, key=lambda p: p.end_tok)  # ("the sheds": the cattle sheds, not the hay shed)
            if not exact and raw.endswith("s") and not raw.endswith(("ss", "'s", "’s")) \
                    and raw not in self.kb.landmark_by_name[last.landmark].description.lower().split():
                continue  # "sheeting all over the bays": many bays, not the one "fuel bay" said a while before
            if i >= 2 and norms[i - 2] in ("not", "no") and last.end_tok >= i - 6:
                # "he's in the tea warehouse, not the shed": said against the one just named, the other one
                other = [p for p in (exact or before) if p.landmark != last.landmark]
                if other:
                    last = max(other, key=lambda p: p.end_tok)
            out.append(replace(self._mention(toks, i - 1, end, last.landmark),
                               reason=f"the '{norms[i]}' named last, '{last.text}'"))
            taken.update(range(i - 1, end))
        return out

    def _trade_place(self, toks: Tokens, norms: tuple[str, ...]) -> str | None:
        """"Pharmacist here.", "Librarian here,": a speaker who names their trade, and the one landmark the trade
        is named after (the word and a name's word share their first six letters)."""
        for i in range(len(norms) - 1):
            # ("Pharmacist. The building our shop is joined on to ...": the trade said as a sentence of its own)
            if toks.sentence_start[i] and (norms[i + 1] == "here" or toks.sentence_start[i + 1] and i == 0) \
                    and len(norms[i]) >= 6 and norms[i].isalpha():
                owners = self._name_word_owners
                hits = {lm for w, lms in owners.items() if len(w) >= 6 and w[:6] == norms[i][:6] and w != norms[i]
                        for lm in lms}
                return next(iter(hits)) if len(hits) == 1 else None
        return None

    def _description_heads_again(self, ex: Extraction, norms: tuple[str, ...]) -> list[PlaceMention]:
        """"the bit of green across from the apartment block ... the green's flooded": the head noun of a
        relational description, said again with "the", is the place the description reached."""
        toks = ex.tokens
        out: list[PlaceMention] = []
        taken = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        for p in ex.places:
            h = p.start_tok
            while h + 1 < p.end_tok and norms[h] in lx.ARTICLES:
                h += 1  # ("the grass across from the doctors' ... that grass")
            head = norms[h]
            if p.via is None or head in lx.UNNAMING_HEADS or head in lx.DETERMINERS \
                    or not head.isalpha() or len(head) < 4 or self._place_head_word(head):
                continue
            for i in range(p.end_tok + 1, len(norms)):
                if i in taken or norms[i] != head or norms[i - 1] not in ("the", "that"):
                    continue
                if i + 1 < len(norms) and not toks.clause_start[i + 1] and norms[i + 1] not in lx.COPULAS \
                        and norms[i + 1] not in ("has", "have", "had") \
                        and not toks.tokens[i].text.lower().endswith(("'s", "’s")):
                    continue  # "the green door": a longer noun phrase
                out.append(replace(self._mention(toks, i - 1, i + 1, p.landmark),
                                   reason=f"the '{head}' of '{p.text}'"))
                taken.update(range(i - 1, i + 1))
        return out

    def _place_head_word(self, word: str) -> bool:
        """Is the word the last word of a landmark's name or alias (so a name finder reads it already)?"""
        return word in self._head_groups() or any(
            name_words(f)[-1:] == (word,) for lm in self.kb.landmarks for f in lm.surface_forms)

    def _name_keys(self) -> list[tuple[str, str]]:
        """(letters of a name or alias run together, articles left out; landmark), for every surface form:
        what misheard and typed slips of a name are compared with."""
        return [("".join(name_words(form)), lm.name)
                for lm in self.kb.landmarks for form in lm.surface_forms]

    MISHEARD_MIN_RATIO = 0.85
    MISHEARD_MIN_CHARS = 8

    def _one_word_aliases(self) -> dict[str, str]:
        """The word of each alias said "the <word>" ("the condensers"), where one landmark has it."""
        if not hasattr(self, "_one_word_alias_cache"):
            seen: dict[str, set[str]] = {}
            for lm in self.kb.landmarks:
                for f in lm.surface_forms:
                    ws = name_words(f)
                    if len(ws) == 1 and ws[0].isalpha() and len(ws[0]) >= 4:
                        seen.setdefault(ws[0], set()).add(lm.name)
            self._one_word_alias_cache = {w: next(iter(ns)) for w, ns in seen.items() if len(ns) == 1
                                          and len(self._name_word_owners.get(w, set())) == 1
                                          and w not in lx.GENERIC_HEADS}
        return self._one_word_alias_cache

    def _described_modifier(self, toks: Tokens, norms: tuple[str, ...], i: int, taken: set[int],
                            name: str | None = None) -> bool:
        """"off the roof condensers both": "the", a word of the landmark's own description, then its head word."""
        m = i - 1
        if i < 2 or norms[i - 2] != "the" or m in taken or toks.clause_start[m] or toks.clause_start[i] \
                or not norms[m].isalpha() or norms[m] in lx.FUNCTION_WORDS \
                or len(self._name_word_owners.get(norms[m], ())) == 1 or self._cues.match_at(norms, m) is not None:
            # (a word of one other landmark's name names that one: "the church hall"; a word that several names share
            # names none of them: "the ferry ramp" where "ferry quay" and "ferry queue" are two places)
            return False
        name = name or self._heads[norms[i]]
        own = self._description_words().get(name, set())
        return norms[m] in own and not any(norms[m] in ws for other, ws in self._description_words().items()
                                           if other != name and norms[i] in ws)

    def _misheard_names(self, toks: Tokens, norms: tuple[str, ...], taken: set[int],
                        cue_tokens: set[int]) -> list[PlaceMention]:
        """Speech-to-text slips: "hanger two", "taxi way alfa", "the lie brary". One to three words whose
        letters, run together, are close to one landmark name's (difflib ratio >= ``MISHEARD_MIN_RATIO``,
        at least ``MISHEARD_MIN_CHARS`` letters, same first letter) and clearly closer than to any other."""
        if not hasattr(self, "_spellings"):
            spell: dict[str, str] = {}
            for key, name in self._name_keys():
                if len(key) >= self.MISHEARD_MIN_CHARS and key.isalnum():
                    spell.setdefault(key, name)
            self._spellings = spell
        if not self._spellings:
            return []
        closed = lx.DETERMINERS | lx.FILLERS | lx.PREPOSITIONS | lx.COPULAS | lx.PRONOUNS | lx.COORDINATORS
        out: list[PlaceMention] = []
        i = 0
        while i < len(norms):
            best: tuple[float, int, str] | None = None
            for n in (3, 2, 1):
                span = range(i, i + n)
                if i + n > len(norms) or any(j in taken or (norms[j] in closed and not (
                        j > i and norms[j] in lx.GENERIC_HEADS)) for j in span) \
                        or any(toks.clause_start[j] for j in range(i + 1, i + n)):
                    continue  # ("fuel from" is not "fuel farm"; "the munisipal building" is the municipal one)
                word = "".join(norms[j] for j in span)  # ("hanger two's": the keys drop the "'s")
                if n == 1 and i > 0 and (norms[i - 1] in ("that", "which", "who") or norms[i - 1] in lx.WHATEVER) \
                        and norms[i + 1:i + 2] in (
                        ("up",), ("out",), ("off",), ("down",), ("over",)):
                    continue  # "the place that patches up its casualties": a verb and its particle, no "the patch"
                if self._cut_off_here(toks, i + n - 1):
                    continue  # "outside the hote-- outside the bank": a word cut off, for ``_false_starts``
                if n == 1 and i > 0 and norms[i - 1] in ("have", "has", "had", "ve", "havent", "hasnt", "hadnt"):
                    continue  # "Harker's have rung in": a verb after its auxiliary, no "the ring"
                typo = self._typo_of(word, [norms[j] for j in span],
                                     raw=toks.tokens[i].text.lower() if n == 1 else None)
                if typo is None and n > 1 and word in self._spellings and len(word) >= 8 \
                        and not any(norms[j] in closed for j in span) and any(
                            name_words(f) == (word,) for f in self.kb.landmark_by_name[self._spellings[word]].surface_forms):
                    typo = self._spellings[word]  # "the super market": a one-word name split in two
                if typo is not None and i > 0 and norms[i - 1] in ("a", "an") and i + n < len(norms) \
                        and not toks.clause_start[i + n] and norms[i + n] not in lx.FUNCTION_WORDS:
                    typo = None  # "clipped by a bale clamp": a thing counted and named by what it is for, no "baler"
                if typo is not None and n == 1 and i > 0 and norms[i - 1] in ("his", "her", "my", "your") \
                        and word not in self._spellings:
                    typo = None  # "dangling off it by his risers": a thing of a person's own, no slip of "the river"
                if typo is not None and n == 1 and i > 0 and (norms[i - 1] in lx.NUMBER_WORDS or is_number(norms[i - 1])):
                    typo = None  # "about three bales deep": things counted, no slip of "the baler"
                if typo is not None and not all(j in cue_tokens for j in span):
                    # ("the fire staytion": one slipped word keeps the name, a cue word in it or not)
                    if best is None or 0.99 > best[0]:
                        best = (0.99, n, typo)
                    continue
                if not word.isalnum() or len(word) < self.MISHEARD_MIN_CHARS - 1 or any(j in cue_tokens for j in span):
                    continue
                if i > 0 and (norms[i - 1] in ("a", "an", "another", "one") or norms[i - 1] in lx.NUMBER_WORDS):
                    continue  # "a stillman is missing": a counted thing, no slip of a name ("St Fillan's")
                head = norms[i]
                scores = sorted(((difflib.SequenceMatcher(None, word, key).ratio(), name)
                                 for key, name in self._spellings.items()
                                 if key[0] == word[0] and abs(len(key) - len(word)) <= 1
                                 and word not in key and key not in word  # a slip, not part of a name
                                 # "a water bowser" is no "water tower": after a first word said right,
                                 # a slip keeps the next word's first sound (a log's vowel-less
                                 # shorthand, "straddle wkshp", need not)
                                 and not (n > 1 and key.startswith(head) and len(key) > len(head)
                                          and key[len(head)] != word[len(head)]
                                          and any(ch in "aeiouy" for ch in word[len(head):]))), reverse=True)
                if not scores or scores[0][0] < self.MISHEARD_MIN_RATIO or scores[0][0] >= 1.0:
                    continue
                if any(sc > scores[0][0] - 0.05 and nm != scores[0][1] for sc, nm in scores[1:]):
                    continue
                if best is None or scores[0][0] > best[0]:
                    best = (scores[0][0], n, scores[0][1])
            if best is not None:
                _, n, name = best
                out.append(self._mention(toks, i, i + n, name, reason=f"misheard name ({best[0]:.2f})"))
                taken.update(range(i, i + n))
                i += n
                continue
            i += 1
        return out

    RESPELL_MIN_CHARS = 5

    def _respell(self, toks: Tokens) -> Tokens:
        """Typed and transcribed slips of the words descriptions are built from: "the bilding in frunt of
        the bus station", "the shop atached to it". A word that is no English word (not in MiniLM's
        vocabulary) and one edit from exactly one relation or place-noun word is read as that word. And a search
        for a word said aloud ("in the, what's it called, the building ...") is a hesitation."""
        toks = _searched_words(toks)
        if self.embedder is None:
            return toks
        if not hasattr(self, "_respellings"):
            words = {w for bucket in self._relations._by_first.values() for key, _ in bucket for w in key}
            words |= set(lx.GENERIC_HEADS)
            # and the danger and person words of the vocabulary ("an old man colapsed by the counter")
            cue_words = {w for key in self._cue_keys() for w in key}
            words |= {w for w in cue_words if len(w) >= 6}
            named = {key for key, _ in self._name_keys()} | {
                w for lm in self.kb.landmarks for form in lm.surface_forms for w in name_words(form)}
            self._respellings = sorted(w for w in words - named if len(w) >= self.RESPELL_MIN_CHARS and w.isalpha())
            self._named_words = named
            self._vocabulary_words = cue_words  # ("bedding down" is no slip of "bending")
            self._to_after = {key[i] for bucket in self._relations._by_first.values() for key, _ in bucket
                              for i in range(len(key) - 1) if key[i + 1] == "to"}
        known = self.embedder.vocabulary()
        fixed = list(toks.tokens)
        for t in toks.tokens:
            w = t.norm
            if w.endswith("in") and len(w) >= 5 \
                    and toks.text[t.end:t.end + 1] in ("'", "’") and not toks.text[t.end + 1:t.end + 2].isalpha():
                fixed[t.i] = replace(t, norm=w + "g")  # "yon fuel store's still burnin'": a dropped g
                continue
            if t.i + 1 < len(toks) and toks.gaps[t.i + 1][:1] in ("-", "—", "–") and len(w) >= 2 \
                    and toks.tokens[t.i + 1].norm.startswith(w) and toks.tokens[t.i + 1].norm != w:
                fixed[t.i] = replace(t, norm="uh")  # "downed power lin— line": the cut-off word said again whole
                continue
            if w in lx.ABBREVIATIONS and w not in self._named_words:
                fixed[t.i] = replace(t, norm=lx.ABBREVIATIONS[w])  # "the bldg nxt to town hall", "mkt sq"
                continue
            if w == "too" and t.i > 0 and fixed[t.i - 1].norm in self._to_after and not toks.clause_start[t.i]:
                fixed[t.i] = replace(t, norm="to")  # "the building next too the clinic"
                continue
            if len(w) < self.RESPELL_MIN_CHARS or not w.isalpha() or w in known or t.text.lower() in known \
                    or w in self._named_words or w in self._vocabulary_words:
                continue
            past = next((f for f in (w[:-1] + "ed", w[:-1] + w[-2:-1] + "ed") if f in self._vocabulary_words), None) \
                if w.endswith("d") and not w.endswith("ed") and len(w) >= 5 else None
            if past is not None:
                fixed[t.i] = replace(t, norm=past)  # texted: "my dad is trapd", "the stairs hav collapsd"
                continue
            if _derived_word(w, known, ("ed",) + _DERIVING_ENDINGS):
                continue  # "the marisol is beached below": a known word with an ending, no slip of "breached"
            hits = [r for r in self._respellings if r[0] == w[0] and abs(len(r) - len(w)) <= 1 and _one_edit(w, r)
                    and not w.startswith(r) and not r.startswith(w)]  # ("fenced" is no slip of "fence")
            if len(hits) == 1:
                fixed[t.i] = replace(t, norm=hits[0])
        return replace(toks, tokens=tuple(fixed)) if fixed != list(toks.tokens) else toks

    TYPO_MIN_CHARS = 4

    def _typo_of(self, word: str, words: list[str], raw: str | None = None) -> str | None:
        """A typed slip: "libary", "chruch", "gargae", "twn hall". One of the words is no English word
        (not in MiniLM's vocabulary) and the letters are one edit (a transposition counts as one) from
        exactly one landmark name's."""
        if self.embedder is None or len(word) < self.TYPO_MIN_CHARS or not word.isalpha():
            return None
        known = self.embedder.vocabulary()
        if not hasattr(self, "_kb_prose_words"):
            # (the words the KB itself writes its descriptions in are words, not slips: "the fryer's gone up" where
            # the cafe has "a deep-fat fryer" is no slip of "the foyer")
            self._kb_prose_words = {w for lm in self.kb.landmarks for w in norm_phrase(lm.description)} \
                - {w for lm in self.kb.landmarks for f in lm.surface_forms for w in name_words(f)}
        if all(w in known or _derived_word(w, known) or w in self._kb_prose_words or w in lx.BUILDING_PART_WORDS
               or len(words) > 1 and w in self._name_word_owners for w in words):
            return None  # (nor a known word with an ending: "the heaters going" is no slip of "the header")
            # (nor a word of the KB's names said right: "sulphur gas" is no slip of "sulphur face")
        if not hasattr(self, "_typo_spellings"):
            self._typo_spellings = {key: name for key, name in self._name_keys()
                                    if len(key) >= self.TYPO_MIN_CHARS and key.isalpha()}
        hits = {name for key, name in self._typo_spellings.items()
                if key[0] == word[0] and abs(len(key) - len(word)) <= 1 and _one_edit(word, key)
                and (raw is None or len(key) >= 5 or raw == word or _one_edit(raw, key))}
        if not hits:
            # a transcribed sound: "farmacy" for "pharmacy", "fire stayshun", "the polis station", "the bakerie"
            if not hasattr(self, "_typo_sounds"):
                self._typo_sounds = {}
                for lm in self.kb.landmarks:
                    for form in lm.surface_forms:
                        ws = name_words(form)
                        written = "".join(ws)
                        if len(written) >= 5 and written.isalpha():
                            self._typo_sounds[("".join(_sound_of(w) for w in ws), written)] = lm.name
            sound = "".join(_sound_of(w, heard=True) for w in words)
            hits = {name for (k, written), name in self._typo_sounds.items()
                    if k[0] == sound[0] and abs(len(k) - len(sound)) <= 1 and (k == sound or _one_edit(sound, k))
                    and written != word and not _one_edit(written, word)}
            # (a name's own spelling, or one slip of it, is for the name finder and the rule above: "pillbox" for
            # "the pillbox" keeps that name's need of its article)
        # (a short name is one letter from the stem of too many plurals: "sills" is no slip of "silo")
        return next(iter(hits)) if len(hits) == 1 else None

    def _cue_keys(self) -> list[tuple[str, ...]]:
        return [key for bucket in self._cues._by_first.values() for key, _ in bucket]

    def _cut_off_here(self, toks: Tokens, t: int) -> bool:
        """Token ``t`` is cut off by a dash and begins, but is not, a word of some landmark's names."""
        gap = toks.gaps[t + 1] if t + 1 < len(toks) else toks.text[toks.tokens[t].end:]
        frag = toks.tokens[t].text.lower()
        return gap[:1] in ("-", "—", "–") and frag.isalpha() and frag not in self._name_word_owners \
            and any(w.startswith(frag) for w in self._name_word_owners)

    def _false_starts(self, toks: Tokens, taken: set[int]) -> list[PlaceMention]:
        """Cut-off words ("the fire st— at the police station") that begin a landmark name."""
        out = []
        norms = toks.norms(0, len(toks))
        for t in toks.tokens:
            nxt_gap = toks.gaps[t.i + 1] if t.i + 1 < len(toks) else toks.text[t.end:]
            if t.i in taken or nxt_gap[:1] not in ("-", "—", "–") or len(t.text) > 9:
                continue
            frag = t.text.lower()
            if frag in lx.FUNCTION_WORDS or frag in ("he", "she", "we", "i", "me", "you", "him", "her", "my"):
                continue  # "he- he fell": a stutter on a pronoun is no cut-off name
            if nxt_gap == "-" and t.i + 1 < len(toks) and toks.tokens[t.i + 1].text[:1].isalpha() \
                    and not toks.tokens[t.i + 1].text.lower().startswith(frag):
                continue  # "the engineers have green-tagged it": a hyphenated word, nothing cut off
            if t.norm == "uh" and frag != "uh" and nxt_gap[:1] == "-" and t.i + 1 < len(toks) \
                    and not any(ch.isspace() for ch in nxt_gap):
                continue  # "ember sh-shower": the next word said again whole (``_respell``), no name begun
            if t.i + 1 < len(toks) and norms[t.i + 1].startswith(frag) and norms[t.i + 1] != frag \
                    and norms[t.i + 1] not in self._name_word_owners and norms[t.i + 1] not in lx.FUNCTION_WORDS:
                continue  # "we need the the bo-- boats down there": the next word said whole, no name begun
            j = t.i + 1
            while j < len(toks) and j - t.i <= 3 and (norms[j] in lx.ARTICLES or norms[j] in lx.HESITATIONS):
                j += 1
            if j < len(toks) and j > t.i + 1 and norms[j].startswith(frag) and norms[j] != frag and j not in taken:
                continue  # "the leach-- the leachate's come through the hedge": the word said whole names no place
            if t.i > 0 and any((hit := self._cues.match_at(norms, k)) is not None
                               and hit[0] == t.i + 1 and k < t.i for k in range(max(0, t.i - 3), t.i)):
                continue  # "the bank's on fire— wait": a cue said whole, not "fire st—"
            best: tuple[int, str] | None = None  # (words said before the cut-off one, landmark)
            for lm in self.kb.landmarks:
                for form in lm.surface_forms:
                    words = list(name_words(form))
                    for n in range(1, len(words) + 1):
                        start = t.i - (n - 1)
                        if start < 0 or any(i in taken for i in range(start, t.i + 1)):
                            continue
                        if list(toks.norms(start, t.i)) == words[: n - 1] and words[n - 1].startswith(frag) \
                                and words[n - 1] != frag and (n > 1 or len(frag) >= 3 or len(frag) == 2 and (
                                    t.i == 0 or norms[t.i - 1] != "to")) and (best is None or n > best[0]):
                            # ("the ba-- the bakery"; not "it's safe to br— no, ...": a verb begun; the name the most
                            # words said fit: "the engine ha--" begins "engine hall", not "halt")
                            best = (n, lm.name)
            if best is not None:
                start = t.i - (best[0] - 1)
                rest = [w for w in norms[t.i + 1:t.i + 4] if w not in lx.HESITATIONS]
                if rest[:2] in (["up", "there"], ["down", "there"]):
                    # "a bloke's been bitten up at the cem-- up there": the name begun, then only "there" for it
                    out.append(self._mention(toks, start, t.i + 1, best[1], reason="name begun, then 'there'"))
                    taken.update(range(start, t.i + 1))
                    continue
                out.append(self._mention(toks, start, t.i + 1, best[1], status="retracted",
                                         reason="false start (word cut off)"))
                taken.update(range(start, t.i + 1))
        return out

    @staticmethod
    def _mention(toks: Tokens, a: int, b: int, landmark: str, **kw: object) -> PlaceMention:
        start, end = toks.tokens[a].start, toks.tokens[b - 1].end
        return PlaceMention(a, b, start, end, toks.text[start:end], landmark, **kw)  # type: ignore[arg-type]

    def _find_markers(self, toks: Tokens, blocked: set[int]) -> list[tuple[int, int, bool]]:
        norms = toks.norms(0, len(toks))
        out: list[tuple[int, int, bool]] = []
        for a, b, strong in self._markers.find_all(norms, blocked):
            words = norms[a:b]
            nxt = norms[b] if b < len(norms) else None
            pause_after = b >= len(norms) or toks.clause_start[b]
            if words[-1:] == ("wrong",) and nxt in ("word", "words"):
                continue  # "gas leak, sorry, gas leak, wrong word": said of the word already repaired
            if len(words) == 2 and words[1] == "that" and a > 0 and norms[a - 1] in lx.DETERMINERS \
                    and not toks.clause_start[a] and toks.gaps[a].strip() == "":
                continue  # "bin hang-up in the bin that feeds the top station": a noun and its relative clause
            if words == ("back", "up") and a > 0 and not toks.clause_start[a] and norms[a - 1] not in lx.FILLERS:
                continue  # "she can't climb back up", "the power's back up": no "back up, start again"
            if words == ("wrong",) and nxt in ("side", "end", "bank") and norms[b + 1:b + 2] == ("of",) and a > 0 \
                    and norms[a - 1] == "the":
                continue  # "I'm looking at it from the wrong side of the green": where from, no repair
            if words == ("disregard",) and (b >= len(norms) or toks.sentence_start[b]
                                            or not pause_after and nxt in lx.FALSE_ALARM_OBJECTS):
                continue  # "that's not smoke, it's steam, disregard. The tower's still leaking": it closes its sentence
            if words == ("no", "no") and b < len(norms) and not pause_after and self._cues.match_at(norms, b) is not None:
                b -= 1  # "No, no fire.": the second "no" negates the cue; the first answers
                words, nxt, pause_after = words[:1], norms[b], True
            if words[-1:] == ("right",) and not (pause_after and nxt in ("its", "it", "thats", "the")):
                continue  # "she's right outside the cafe": where she is; "okay she's right, it's the library": a repair
            if words in (("second", "voice"), ("voice", "behind"), ("voice", "in", "background"),
                         ("voice", "in", "the", "background"), ("background", "voice"), ("another", "voice")) \
                    and nxt not in ("its", "it", "thats", "the", "no", "not"):
                continue  # "[second voice: it's the library, Jean!]": another speaker correcting
            if words == ("wrong",) and a > 0 and norms[a - 1] in ("nothing", "anything", "something", "whats"):
                continue  # "Nothing wrong on our job at the library": no repair
            if words[-1:] == ("no",) and a >= 2 and norms[a - 2:a] in (("i", "think"), ("i", "thought")) \
                    and norms[b:b + 2] in (("i", "know"), ("im", "sure"), ("i", "am"), ("definitely",)):
                continue  # "and I think — no, I know — it's smouldering too": surer, nothing taken back
            if words in (("correction",),) and nxt in ("on", "about", "regarding", "re") \
                    and toks.sentence_start[a]:
                continue  # "Correction on the sports hall as well: ...": news of that place, no repair of the last
            if words[-1:] in (("no",), ("nope",)) and all(w in lx.FILLERS for w in words[:-1]):
                # ("uh no casualties": a filler before it changes nothing)
                # "no, the bakery" / "no no" is a repair; "no fire" / "no one" is negation;
                # "the warehouse no the library" (no pause) is a repair when a place precedes
                # ("trapped worker in unit 3 no unit 4": a place right after "no", one just before it, is a repair)
                if nxt in lx.VOCATIVES and b + 1 < len(norms) and toks.clause_start[b + 1]:
                    b += 1  # "no Dad, it's the plank": the person spoken to belongs to the repair word
                    nxt, pause_after = norms[b], True
                named_next = b in blocked and any(i in blocked for i in range(max(0, a - 3), a))
                if nxt in ("nobody", "noone", "nothing", "none", "no") or norms[b:b + 2] == ("no", "one"):
                    continue  # "we've got, er, no, nobody under it": an answer, not a repair
                said_again = nxt in ("im", "at", "in", "on", "by", "were") \
                    and any(i in blocked for i in range(b + 1, min(len(norms), b + 4))) \
                    and any(i in blocked for i in range(max(0, a - 8), a))
                # ("im at the wind tunnel um no im at the market hall": the frame said again, another place in it)
                if not (pause_after or named_next or said_again
                        or nxt in ("no", "wait", "sorry", "the", "its", "it", "i", "actually",
                                   "make", "he", "hes", "she", "shes", "they", "theyre")):
                    continue
                if nxt == "the" and not (a > 0 and toks.clause_start[a]):
                    ahead = [i for i in (b + 1, b + 2) if i < len(norms)]
                    if not any(i in blocked or norms[i] in lx.GENERIC_HEADS for i in ahead):
                        continue
                    if not any(i in blocked for i in range(max(0, a - 8), a)):
                        continue
            elif words in (("wait",), ("actually",), ("rather",), ("hang", "on"), ("hold", "on")):
                # only a repair mid-sentence, set off as a pause, or "actually the X"; or a sentence of its own ("Hang on.")
                if toks.sentence_start[a] and words != ("wait",) and not (b >= len(norms) or toks.sentence_start[b]):
                    continue
                if not (toks.clause_start[a] or pause_after or nxt in ("the", "its", "it", "make")):
                    continue
                if words == ("wait",) and not toks.clause_start[a] and a > 0 \
                        and norms[a - 1] in lx.PLAN_WORDS | {"and", "please", "just", "we", "they", "you", "people"} \
                        and nxt in ("it", "for", "in", "at", "here", "there", "inside"):
                    continue  # "people can wait it out in the storehouse", "we'll wait for you at the gate": the verb
            out.append((a, b, strong))
        # adjacent markers ("no, actually", "sorry, I mean", "no, sorry") act as one
        merged: list[tuple[int, int, bool]] = []
        for a, b, strong in out:
            gap = range(merged[-1][1], a) if merged else range(0)
            aside = merged and 0 < len(gap) <= 5 and not any(toks.sentence_start[i] for i in range(gap.start, a + 1)) \
                and not any(i in blocked or self._cues.match_at(norms, i) is not None for i in gap)
            if merged and (all(norms[i] in lx.FILLERS for i in gap) or aside):
                # "no, sorry, I'm reading this wrong": markers with only an aside between act as one
                pa, _, ps = merged[-1]
                merged[-1] = (pa, b, ps or strong)
            else:
                merged.append((a, b, strong))
        return merged

    def _resolve_relations(self, ex: Extraction) -> None:
        """Replace relational descriptions by the place the KB relation leads to.

        * "the shop attached to the bakery" / "the one next to it" (generic head + relation + anchor)
        * "casualties round the back of the hardware store" (a cue, then relation + anchor)
        * "the one the garage sits behind" (inverse: head + anchor + relation)
        Chains ("the cafe next to the shop attached to the bakery") resolve right to left; the
        anchor becomes a reference point, not a claim.
        """
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        place_tokens = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        marker_tokens = {i for ma, mb, _ in ex.markers for i in range(ma, mb)}
        self._marker_cache = marker_tokens
        rel_hits = self._relations.find_all(norms, place_tokens)
        # "the pond that's topped up by — by the station ...": the last word said twice is said once
        # (a one-word relation only across a dash: "down by, by, uh, the police station" is where it is)
        def _said_again(a: int, b: int) -> int:
            j = b
            while j < len(norms) and (norms[j] in lx.HESITATIONS or norms[j] in lx.ARTICLES and j == b) and j - b < 2:
                j += 1  # "the local for, er, for whatever ...", "the tenter ground of the, of whatever's ..."
            if j < len(norms) and norms[j] == norms[b - 1] and norms[j] in lx.RELATION_ENDINGS \
                    and (b - a >= 2 or any(d in toks.gaps[b] for d in ("—", "–", "--", " - "))):
                return j + 1
            return b
        rel_hits = [(a, _said_again(a, b), h) for a, b, h in rel_hits]
        # "the park's under water": a word of a danger phrase, not a relation
        rel_hits = [h for h in rel_hits if not (h[1] - h[0] == 1 and (m := self._cues.match_at(norms, h[0])) is not None
                                                and m[0] > h[1])]
        # "Beet Six to control: ...": the radio's addressee, not ``controls_the_points_of``
        rel_hits = [h for h in rel_hits if not (h[1] - h[0] == 1 and norms[h[0]] == "control" and (
            h[0] > 0 and norms[h[0] - 1] in ("to", "from", "calling") or h[1] < len(norms) and ":" in toks.gaps[h[1]]))]
        # "sand boils all along the back of it": a part of the place, not ``backs_onto``
        rel_hits = [h for h in rel_hits if not (norms[h[0]] in ("back", "front") and h[0] >= 2
                                                and norms[h[0] - 1] == "the"
                                                and norms[h[0] - 2] in ("along", "on", "across", "over", "down", "up"))]
        if self.kb.relations:
            cue_tokens = self._claim_cue_tokens(norms, place_tokens | marker_tokens)
            covered = place_tokens | marker_tokens | {i for a, b, _ in rel_hits if b - a > 1 for i in range(a, b)}
            known = {i for a, b, _ in rel_hits for i in range(a, b)}
            extra = self._keyword_hits(toks, norms, covered, cue_tokens, known)
            extra_tokens = {i for a, b, _ in extra for i in range(a, b)}
            rel_hits = [self._remap_absent_group(norms, h) for h in rel_hits
                        if not extra_tokens.intersection(range(h[0], h[1]))] + extra
        # ("the street that funnels people away from the gift row": ``funnels the crowd away from`` found twice,
        # "that funnels" and "people away from", is one phrase)
        merged: list[tuple[int, int, tuple[str, bool]]] = []
        for h in sorted(rel_hits, key=lambda h: h[0]):
            if merged and merged[-1][1] == h[0] and merged[-1][2] == h[2] and not toks.clause_start[h[0]] \
                    and (norms[h[0]] not in norm_phrase(h[2][0].replace("_", " ")) or norms[h[0]] in lx.ARTICLES):
                # (not where the second begins with the relation's own words: "that shares its | back lanes with";
                # but an article is no word of its own: "that catches | the seepage from" for ``catches_the_seepage_below``)
                merged[-1] = (merged[-1][0], h[1], h[2])
            else:
                merged.append(h)
        rel_hits = merged
        ordered = sorted(rel_hits, key=lambda h: -h[0])
        self._rel_tokens = {i for a, b, _ in rel_hits for i in range(a, b)}
        pronouns = ("it", "they", "its")

        def again(inverse_passes: tuple[bool, ...] = (False,), on_pronouns: bool = False) -> None:
            """Every description once more, now that more places are resolved that may anchor them."""
            for a, b, (phrase, flipped) in ordered:
                if on_pronouns and not (a > 0 and norms[a - 1] in pronouns):
                    continue
                for inverse in inverse_passes:
                    if inverse and any(p.via is not None and f" {phrase} ".replace("_", " ") in f" {p.via} ".replace("_", " ")
                                       and p.start_tok <= a <= p.end_tok + 1 for p in ex.places):
                        continue  # ("where XP1 is the first escape door": the words read already, into that description)
                    self._resolve_one(ex, toks, norms, a, b, phrase, flipped, place_tokens, marker_tokens,
                                      inverse_pass=inverse)

        # forward descriptions, then inverse ones, then forward ones that anchor on an inverse one
        # (an inverse one on a pronoun twice: "the field it plays its games on" after "the school that the prims
        # lend ... to", resolved later in the same pass)
        for round_no, pass_no in enumerate((1, 2, 3, 1)):
            for a, b, (phrase, flipped) in ordered:
                if pass_no == 3 and not (a > 0 and norms[a - 1] in pronouns):
                    continue
                if round_no == 0 and norms[b:b + 1] in (("it",), ("them",)):
                    last = max((p for p in ex.places if p.end_tok <= a and p.status == "active"),
                               key=lambda p: p.end_tok, default=None)
                    if last is not None and any(a2 == last.end_tok and a2 < a for a2, _, _ in ordered):
                        continue  # ("the field the chapel overlooks ..., the building that overlooks it": "it" is the
                        # field, not the chapel that says which field, known once that description is read)
                if pass_no == 2 and a > 0 and norms[a - 1] in pronouns and any(
                        b2 < a and "and" in norms[b2:a] for _, b2, _ in ordered):
                    continue  # ("the straight the esses run into — ..., and the corner it runs into": "it" is
                    # the straight, known once the description before it is resolved, in the pass after)
                self._resolve_one(ex, toks, norms, a, b, phrase, flipped, place_tokens, marker_tokens,
                                  inverse_pass=pass_no in (2, 3))
        if self.kb.relations and self._resolve_shared_heads(ex, toks, norms, place_tokens, marker_tokens):
            # "the orchard owned by the farm whose tractors sit in the boneyard": a description so resolved may
            # anchor the one before it, or an inverse one around it ("the station that the line ending at
            # lakeside halt sets out from")
            again((False, True))
        if self.embedder is not None and self.kb.relations:
            cue_tokens = self._claim_cue_tokens(norms, place_tokens | marker_tokens)
            described = sum(p.via is not None for p in ex.places)
            self._resolve_open(ex, toks, norms, place_tokens, marker_tokens, cue_tokens)
            self._resolve_open_inverse(ex, toks, norms, place_tokens, marker_tokens, cue_tokens)
            self._resolve_open_ours(ex, toks, norms, place_tokens, marker_tokens, cue_tokens)
            self._resolve_by_partners(ex, toks, norms, place_tokens, marker_tokens, cue_tokens)
            if sum(p.via is not None for p in ex.places) > described:
                # "the building the new maltings malts its barley for ..., and the pub it casts its shadow over": a
                # place so described may be the "it" of a description after it
                again((False, True), on_pronouns=True)
                # ("the cell that's being dug out below whatever the working face is pushed into": or the anchor of
                # a description before it, read forwards)
                again((False,))
            if self._resolve_related(ex, toks, norms, place_tokens, marker_tokens, cue_tokens):
                # "the path that winds down to the row after the A cabins": a description so resolved may anchor
                # a listed one, or an inverse one ("the station that the line ending at lakeside halt sets out from")
                again((False, True))
                # (or one read by meaning around it: "the tank supplying the shed that answers to the control tower")
                self._resolve_by_partners(ex, toks, norms, place_tokens, marker_tokens, cue_tokens)
        if self.kb.relations and rel_hits:
            self._unresolved_own_heads(ex, toks, norms, rel_hits)
            self._both_anchors(ex, toks, norms, rel_hits)
        self._restated_anchors(ex, toks, norms)
        self._shared_tail_itself(ex, toks, norms)
        if self.kb.relations:
            self._named_contact_clauses(ex, toks, norms)
        self._coordinated_anchors(ex, toks, norms)
        self._nearest_points(ex, toks, norms)
        if self.kb.relations:
            self._contact_clause_subjects(ex, toks, norms)
            self._agreeing_clauses(ex, toks, norms)
        if self.kb.relations:
            self._possessive_roles(ex, toks, norms)
        for d in [p for p in ex.places if p.via is not None and p.status == "active"]:
            for idx, p in enumerate(ex.places):
                if p.via is None and p.status == "active" and d.start_tok <= p.start_tok and p.end_tok <= d.end_tok:
                    # "the landing it faces": the head word named the place the description reaches
                    ex.places[idx] = replace(p, status="reference", reason=f"part of the description '{d.text}'")
        for idx, p in enumerate(ex.places):
            if p.status == "active" and p.via is not None and norms[p.start_tok] not in lx.DETERMINERS and any(
                    r.status == "reference" and r.landmark == p.landmark and r.end_tok <= p.start_tok <= r.end_tok + 1
                    and r.reason.startswith("reference point") for r in ex.places):
                # "the hill that overlooks the heaps they truck in from the dead horse": a clause with no head of its
                # own says which the anchor just said is, no claim of its own
                ex.places[idx] = replace(p, status="reference", reason="says which the place before it is")
        # "the pub that's back to back with the wharf Thornlow's ships its salt from": the outer description took the
        # name as its anchor before the inner one was read; the inner one, the same place, is still only its anchor
        for idx, p in enumerate(ex.places):
            if p.status != "active" or p.via is None:
                continue
            ref = next((q for q in ex.places if q.status == "reference" and q.landmark == p.landmark and q.via is None
                        and p.start_tok <= q.start_tok < p.end_tok and q.reason.startswith("reference point:")
                        and any(r.status == "active" and r.via is not None and r.end_tok == q.end_tok
                                and r.start_tok < p.start_tok for r in ex.places)), None)
            if ref is not None:
                ex.places[idx] = replace(p, status="reference", reason=ref.reason)
        # "the river whose source is the resurgence": a place named to say what the one before it is
        for idx, q in enumerate(ex.places):
            if q.status != "active":
                continue
            k = q.start_tok
            while k > 0 and norms[k - 1] in lx.DETERMINERS and q.start_tok - k < 2:
                k -= 1
            w = next((j for j in range(max(0, k - 5), k) if norms[j] == "whose"), None)
            if w is not None and norms[k - 1] in ("is", "was", "s") and all(norms[j].isalpha() for j in range(w + 1, k)) \
                    and any(p.end_tok == w and p.status == "active" and p.landmark != q.landmark for p in ex.places):
                ex.places[idx] = replace(q, status="reference", reason="what the place before it is said to have: no claim")

    @functools.cached_property
    def _role_relations(self) -> dict[tuple[str, ...], list[Relation]]:
        """The KB's relations named "is the <noun> of" (or "for"), by their noun ("drinking hole" of ``is the drinking
        hole of``, "fire water" of ``is the fire water for``)."""
        roles: dict[tuple[str, ...], list[Relation]] = {}
        for rel in self.kb.relations:
            words = norm_phrase(rel.phrase)
            if len(words) >= 4 and words[0] in ("is", "are") and words[1] in lx.ARTICLES and words[-1] in ("of", "for"):
                roles.setdefault(tuple(words[2:-1]), []).append(rel)
        return roles

    def _possessive_roles(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"the corrie's drinking hole": for a relation named "is the drinking hole of", a place's own
        "drinking hole" is the one the KB says is the drinking hole of it."""
        roles = self._role_relations
        if not roles:
            return
        for p in list(ex.places):
            if p.status != "active" or p.via is not None \
                    or not toks.tokens[p.end_tok - 1].text.lower().replace("’", "'").endswith(("'s", "s'")):
                continue
            for noun, rels in roles.items():
                end = p.end_tok + len(noun)
                if norms[p.end_tok:end] != noun:
                    continue
                subjects = {r.subject for r in rels if r.object == p.landmark}
                if len(subjects) != 1:
                    continue
                target = next(iter(subjects))
                rel = next(r for r in rels if r.object == p.landmark)
                via = f"{rel.subject} {rel.relation} {rel.object}"
                ex.places[ex.places.index(p)] = replace(p, status="reference", reason=f"reference point: {via}")
                ex.places.append(self._mention(toks, p.start_tok, end, target, via=via))
                break

    @functools.cached_property
    def _relation_words(self) -> dict[str, frozenset[str]]:
        """Each KB relation name's words, normalised."""
        return {rel.phrase: frozenset(norm_phrase(rel.phrase)) for rel in self.kb.relations}

    def _agreeing_clauses(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"the stack that takes the smoke off the kiln is leaning": a named place, then "that" and a clause that says
        one of its own KB relations (two or more of the relation's content words, "smoke" and "off" of `draws the smoke
        off`). The clause only says which place is meant: its words are no cues, and a place it names as the
        relation's other end is a reference point."""
        for p in [q for q in ex.places if q.status == "active" and (q.via is None or q.via.startswith("description of"))]:
            k = p.end_tok
            # ("the shed where they pump water up to the waterfall": a name read out of its own "where" clause)
            inner = next((j for j in range(p.start_tok + 1, p.end_tok) if norms[j] in ("where", "that", "which")), None)
            if inner is not None:
                k = inner
            elif k + 2 >= len(norms) or norms[k] not in ("that", "which", "where") or toks.clause_start[k] \
                    or toks.clause_start[k + 1]:
                continue
            e = k + 1
            while e < len(norms) and e - k <= 10 and not toks.clause_start[e] and norms[e] not in lx.COPULAS - {"s"} \
                    and norms[e] not in ("has", "have", "had"):
                e += 1
            said = {w for w in norms[k + 1:e] if w not in lx.FUNCTION_WORDS | lx.ARTICLES}
            for rel in self.kb.relations:
                if p.landmark not in (rel.subject, rel.object):
                    continue
                words = self._relation_words[rel.phrase] - lx.ARTICLES
                other = rel.object if rel.subject == p.landmark else rel.subject
                named = [idx for idx, q in enumerate(ex.places)
                         if q.status == "active" and q.landmark == other and max(k, p.end_tok) <= q.start_tok < e]
                if len(said & words) < 2 or not said & words - lx.FUNCTION_WORDS:
                    # one word of the relation's own, where the clause names the relation's other end: "the pump shed
                    # that sends water up to the waterfall" (``pipes water into``)
                    if not named or not any(_same_stem(w, r) for w in said if len(w) >= 4
                                            for r in words - lx.FUNCTION_WORDS - lx.RELATION_NAME_STOPWORDS if len(r) >= 4):
                        continue
                ex.relation_tokens.update(range(k, e))
                for idx in named:
                    q = ex.places[idx]
                    ex.places[idx] = replace(q, status="reference",
                                             reason=f"reference point: {rel.subject} {rel.phrase} {rel.object}")
                break

    def _contact_clause_subjects(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"the line-up the water cart keeps topped up has three engines ...": a named place, then at once a
        clause whose subject is another named place and whose verb follows it, with no "that" between or one. Where
        the KB relates the second to the first (subject to object), the second only says which: a reference point."""
        # (the first may be a reference point already: "inside the wall the top road runs along - the passage buried
        # in it")
        named = sorted((p for p in ex.places if p.status in ("active", "reference") and p.via is None),
                       key=lambda p: p.start_tok)
        for first, second in zip(named, named[1:], strict=False):
            between = norms[first.end_tok:second.start_tok]
            if second.status != "active" or between not in (("the",), ("that", "the"), ("which", "the")) \
                    or toks.clause_start[second.start_tok - 1] or second.end_tok >= len(norms):
                # ("the trench that the deluge tank fills": "that" may open the clause)
                continue
            verb = norms[second.end_tok]
            rels = [r for r in self.kb.relations if r.subject == second.landmark and r.object == first.landmark]
            if toks.clause_start[second.end_tok] or verb in lx.COPULAS | lx.FUNCTION_WORDS | lx.COORDINATORS \
                    or verb in ("has", "have", "had", "got") or not verb.isalpha():
                continue
            if not rels and first.status == "active":
                # "The car park the goods-in bay opens onto is upwind": the name said is the generic one ("the car
                # park"), and the place meant the one the KB relates the clause's subject to whose names end alike
                head = name_words(first.text)[-1:]
                k = second.end_tok  # (past a word of the name left out: "the goods-in bay" for "goods-in")
                if k + 1 < len(norms) and not toks.clause_start[k + 1] and norms[k] in self._description_words().get(
                        second.landmark, ()) and norms[k] not in lx.FUNCTION_WORDS:
                    k += 1
                verb = norms[k]
                meant = [r for r in self.kb.relations if r.subject == second.landmark and r.object != first.landmark
                         and verb in self._relation_words[r.phrase] and head and any(
                             name_words(f)[-1:] == head for f in self.kb.landmark_by_name[r.object].surface_forms)]
                if len(meant) == 1:
                    r = meant[0]
                    ex.relation_tokens.add(k)
                    ex.places[ex.places.index(first)] = replace(
                        first, landmark=r.object, via=f"{r.subject} {r.relation} {r.object} (named alike)")
                    ex.places[ex.places.index(second)] = replace(
                        second, status="reference", reason=f"subject of a clause describing '{first.text}': reference point")
                continue
            if not rels:
                continue
            if self._cues.match_at(norms, second.end_tok) is None or any(
                    verb in self._relation_words[r.phrase] for r in rels):  # ("the channel the old lido spills into")
                ex.relation_tokens.add(second.end_tok)  # (the relation's verb, no cue: "spills" is no chemical spill)
                idx = ex.places.index(second)
                ex.places[idx] = replace(second, status="reference",
                                         reason=f"subject of a clause describing '{first.text}': reference point")

    def _singular_of_plurals(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"only the shed roofs showing", where every name of the weaving sheds is plural: a noun said in the
        singular before the roofs or walls it has is any such thing's, no name of that place."""
        for idx, p in enumerate(ex.places):
            e = p.end_tok
            if p.status != "active" or p.via is not None or e >= len(norms) or p.end_tok - p.start_tok > 2 \
                    or toks.clause_start[e] or toks.tokens[e].text.lower() not in _PART_PLURALS:
                continue
            raw = toks.tokens[e - 1].text.lower()
            forms = self.kb.landmark_by_name[p.landmark].surface_forms
            if not raw.endswith("s") and all(f.lower().rstrip().endswith(raw + "s") for f in forms
                                             if name_words(f)[-1:] == (norms[e - 1],)) \
                    and any(name_words(f)[-1:] == (norms[e - 1],) for f in forms):
                ex.places[idx] = replace(p, status="reference", reason=f"'{raw}' of many things ('{raw} {toks.tokens[e].text}')")

    def _nearest_points(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """Places said only to say where: "flashover in the north-lights, end bay nearest the river" (a part of the
        place said before it, picked out by the place it is nearest to) and "the weir's right below him" (where the
        place is from a person)."""
        for idx, p in enumerate(ex.places):
            if p.status != "active" or p.via is not None:
                continue
            e = p.end_tok + (p.end_tok < len(norms) and norms[p.end_tok] in ("is", "s"))
            e += e < len(norms) and norms[e] in ("right", "just", "directly", "straight")
            if e + 1 < len(norms) and (e > p.end_tok or toks.tokens[p.end_tok - 1].text.lower().endswith(("'s", "’s"))) \
                    and norms[e] in ("below", "under", "beneath", "underneath", "above", "behind", "beside") \
                    and norms[e + 1] in ("him", "her", "them", "us", "me") and not toks.clause_start[e]:
                # "he's hanging onto the railing and the weir's right below him": where the place is, said of no one
                ex.places[idx] = replace(p, status="reference", reason="where it is from a person: no claim")
                continue
            k = p.start_tok
            while k > 0 and norms[k - 1] in lx.ARTICLES | {"to"} and k > p.start_tok - 2:
                k -= 1
            b = k - 1 - (k >= 2 and norms[k - 2] in ("just", "right"))
            if b >= 1 and norms[k - 1] in ("past", "beyond") and toks.clause_start[b] \
                    and (p.end_tok == len(norms) or toks.clause_start[p.end_tok]) \
                    and not any(toks.clause_start[j] for j in range(b + 1, p.end_tok)):
                # "stuck out on the flats, past the pools, ...": a clause of its own that only says where the place
                # said just before it lies
                q = next((q for q in ex.places if q.status == "active" and q.end_tok == b and q.landmark != p.landmark
                          and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok]), None)
                if q is not None:
                    ex.places[idx] = replace(p, status="reference", reason=f"reference point for '{q.text}'")
                    continue
            if k >= 3 and norms[k - 1] in ("past", "beyond") and norms[k - 2] in ("out", "further", "farther", "way") \
                    and (p.end_tok >= len(norms) or toks.clause_start[p.end_tok]
                         or norms[p.end_tok:p.end_tok + 1] in (("thing",), ("bit",))) \
                    and any(self._role_cue_at(norms, m, Role.CRITICAL) for m in range(max(0, k - 10), k - 2)
                            if toks.sentence_of[m] == toks.sentence_of[p.start_tok]):
                # "a little boy stuck in the mud like out past the ramp thing": somewhere beyond it, not there
                ex.places[idx] = replace(p, status="reference", reason="a place beyond it ('out past'): no claim")
                continue
            if k < 2 or norms[k - 1] not in ("nearest", "closest") or not norms[k - 2].isalpha() \
                    or norms[k - 2] in lx.FUNCTION_WORDS or norms[k - 2] in lx.COPULAS \
                    or any(toks.clause_start[j] for j in range(k - 1, p.start_tok + 1)):
                continue
            sent = toks.sentence_of[p.start_tok]
            before = [q for q in ex.places if q.status == "active" and q.end_tok <= k - 2 and q.landmark != p.landmark
                      and toks.sentence_of[q.start_tok] == sent and k - 2 - q.end_tok <= 4]
            if before:
                ex.places[idx] = replace(p, status="reference", reason=f"reference point for '{before[-1].text}'")

    def _coordinated_anchors(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"the place that sends the drays out to the market hall and the Mow": a second anchor joined to a
        description's own by "and", that the KB relates to the place described by the same relation, is a
        reference point too, not a place claimed."""
        for d in [p for p in ex.places if p.status == "active" and p.via is not None]:
            rel = next((r for r in self.kb.relations if d.via.startswith(f"{r.subject} {r.relation} {r.object}")), None)
            if rel is None:
                continue
            for idx, q in enumerate(ex.places):
                k = d.end_tok
                if k < len(norms) and norms[k] == "and":
                    k += 1
                while k < len(norms) and norms[k] in lx.ARTICLES:
                    k += 1
                if q.status != "active" or q.via is not None or q.start_tok != k or k == d.end_tok \
                        or norms[d.end_tok] != "and" or toks.clause_start[d.end_tok]:
                    continue
                if {"both", "are", "were", "too", "itself", "themselve", "themselves"} & set(norms[q.end_tok:q.end_tok + 3]) \
                        or any(r.landmark == q.landmark and d.start_tok <= r.start_tok < d.end_tok for r in ex.places):
                    continue  # ("the shop next to the bakery and the chemist are both alight": two places; "... from
                    # the halt and the halt itself is the RVP": the anchor said again, of its own)
                if any(r.relation == rel.relation and {r.subject, r.object} == {d.landmark, q.landmark}
                       for r in self.kb.relations):
                    ex.places[idx] = replace(q, status="reference", reason=f"a second reference point: {rel.relation}")

    def _restated_anchors(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"the tunnel that's dug under the straight, the straight that runs flat out into chapel bend": a
        relation's object, said again with a description of its own to say which one, is that relation's
        reference point, not a place claimed."""
        for idx, q in enumerate(ex.places):
            if q.status != "active" or q.via is None:
                continue
            h = q.start_tok
            while h < q.end_tok - 1 and norms[h] in lx.ARTICLES:
                h += 1
            s0 = q.start_tok - 1 if q.start_tok > 0 and norms[q.start_tok - 1] in lx.ARTICLES else q.start_tok
            k = s0 - 1
            while k > 0 and (norms[k] in lx.FILLERS or norms[k - 1:k + 1] in (("you", "know"), ("i", "mean"))):
                k -= 2 if norms[k] in ("know", "mean") and norms[k - 1] in ("you", "i") else 1
            # ("the pontoon tied off the pier — you know, the pier the lifeboat house sits at the end of —")
            if k < 2 or not toks.clause_start[s0] or norms[k] != norms[h] or norms[k - 1] not in lx.ARTICLES \
                    or not (norms[k - 2] in lx.RELATION_ENDINGS or norms[k - 2] in ("under", "beneath", "below", "above")):
                continue
            if any(p.start_tok <= k < p.end_tok and not (p.status == "reference" and p.landmark == q.landmark)
                   and not (p.via is not None and p.end_tok == k + 1 and p.via.endswith(f" {q.landmark}"))
                   for p in ex.places):
                continue  # (the word said before is a place of its own: its own rules)
            if not any(p.start_tok <= k < p.end_tok for p in ex.places) and (k - 2) not in self._rel_tokens:
                continue  # ("three casualties on the pad, the pad above the trench": no relation's anchor said before,
                # a word that names no one place said again to say which)
            ex.places[idx] = replace(q, status="reference", reason=f"the anchor said again to say which: {q.via}")
        for idx, q in enumerate(ex.places):
            # "the loft leaning against the stack that carries hollins' boiler smoke": the relative clause only
            # agrees with the reference point it follows
            if q.status == "active" and q.via is not None and any(
                    r.status == "reference" and r.landmark == q.landmark and r.via is None
                    and r.end_tok < q.start_tok <= r.end_tok + 3 and norms[r.end_tok] in ("that", "which")
                    for r in ex.places):
                ex.places[idx] = replace(q, status="reference", reason=f"a relative clause of a reference point: {q.via}")

    def _unresolved_own_heads(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...],
                              rel_hits: list[tuple[int, int, tuple[str, bool]]]) -> None:
        """"the cabin that calls the classes for the ring": a head word only one landmark's name ends in, then a
        relative clause saying one of that landmark's own KB relations, whose anchor did not resolve (two
        rings). The head names the place; the description only agrees with it."""
        heads = getattr(self, "_heads", {})
        covered = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        for i in range(1, len(norms) - 1):
            w = norms[i]
            if w not in heads or i in covered or norms[i - 1] != "the" or norms[i + 1] not in ("that", "which") \
                    or toks.gaps[i + 1].strip() or w in lx.UNNAMING_HEADS:
                continue
            name = heads[w]
            said = [(a, phrase, flipped) for a, _b, (phrase, flipped) in rel_hits if i + 1 <= a <= i + 4
                    and not any(toks.gaps[k].strip() for k in range(i + 2, a + 1))]
            agreeing = [(a, rel) for a, phrase, flipped in said for rel in self.kb.relations
                        if rel.phrase == phrase and (rel.object if flipped else rel.subject) == name]
            if not agreeing:
                continue
            ex.places.append(replace(self._mention(toks, i - 1, i + 1, name),
                                     reason=f"'{toks.tokens[i].text}' names it; the description after it only agrees"))
            covered.update((i - 1, i))
            for a, rel in agreeing:
                other = rel.subject if rel.object == name else rel.object
                for idx, q in enumerate(ex.places):
                    if q.status == "active" and q.via is None and q.landmark == other and a < q.start_tok <= a + 8 \
                            and not any(toks.clause_start[m] for m in range(a + 1, q.start_tok + 1)):
                        # "the cart that tops up the engines on the big lines": the clause's anchor, no claim
                        ex.places[idx] = replace(q, status="reference",
                                                 reason=f"reference point: {rel.subject} {rel.phrase} {rel.object}")
                    elif q.status == "active" and q.via is None and a < q.start_tok <= a + 6 and any(
                            norms[m] in lx.WHATEVER for m in range(max(a, q.start_tok - 2), q.start_tok)) \
                            and not any(toks.clause_start[m] for m in range(a + 1, q.start_tok + 1)):
                        # "the gate that holds back whatever the goit fills": the anchor's own description's anchor
                        ex.places[idx] = replace(q, status="reference", reason="reference point of the description's "
                                                                             f"anchor ({rel.subject} {rel.phrase} {rel.object})")

    def _said_whole(self, p: PlaceMention) -> bool:
        """Is the place said by a whole name of its landmark ("tower five" for ``pylon five``), not a part or a slip of
        one ("Father Christmas sits" for "father christmas's hut")?"""
        said = name_words(p.text)
        return any(name_words(f) == said for f in self.kb.landmark_by_name[p.landmark].surface_forms)

    def _both_anchors(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...],
                      rel_hits: list[tuple[int, int, tuple[str, bool]]]) -> None:
        """"the room that feeds both battery rooms": an anchor said in the plural after "both" (or "all the"), the
        name several landmarks end in; where the relation leads from each of them to the one same place, that
        place is meant."""
        covered = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        for a, b, (phrase, _flipped) in rel_hits:
            if a < 2 or norms[a] not in ("that", "which") or norms[a - 2] not in lx.ARTICLES or (a - 1) in covered:
                continue
            k = b
            if k < len(norms) and norms[k] in ("both", "all", "the", "two"):
                k += 1
            while k < len(norms) and norms[k] in ("the", "two", "of"):
                k += 1
            if k == b or not any(norms[m] in ("both", "all", "two") for m in range(b, k)):
                continue
            for n in (2, 1):
                tail = norms[k:k + n]
                if len(tail) < n or any(m in covered for m in range(k, k + n)) \
                        or not toks.tokens[k + n - 1].text.lower().endswith("s"):
                    continue
                owners = {lm.name for lm in self.kb.landmarks for f in lm.surface_forms
                          if len(ws := name_words(f)) > n and any(ws[m:m + n] == tail for m in range(len(ws) - n + 1))}
                if len(owners) < 2:
                    continue
                targets = {self._follow(o, phrase, toks.tokens[a - 1].text)[0] for o in owners}
                if len(targets) == 1 and None not in targets and not targets & owners:
                    target = next(iter(targets))
                    ex.places.append(self._mention(toks, a - 2, k + n, target, via=f"{target} {phrase} {' and '.join(sorted(owners))}"))
                    covered.update(range(a - 2, k + n))
                break

    def _shared_tails(self) -> dict[tuple[str, ...], set[str]]:
        """Last words of names that several landmarks share ("escalator shaft": main and deep escalator
        shaft; "stairs": the Kingsway stairs and the Foundry Lane stairs), with the landmarks."""
        if getattr(self, "_tails_cache", None) is None:
            self._tails_cache = {k: v for k, v in self._tail_owners.items() if len(v) >= 2 and k[-1].isalpha()
                                 and len(k[-1]) >= 4 and not set(k) & lx.GENERIC_HEADS}
        return self._tails_cache

    def _resolve_shared_heads(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                              marker_tokens: set[int]) -> bool:
        """"the escalator shaft that comes down into the link passage": a name several landmarks share,
        then a linking phrase to a named place. Of the landmarks the name fits, the one the KB relates to
        that place (by any relation) is meant; the named place is its reference point."""
        tails = self._shared_tails()
        if not tails:
            return False
        found_any = False
        for anchor in [p for p in ex.places if p.status == "active" and p.via is None]:
            j = anchor.start_tok
            while j > 0 and norms[j - 1] in lx.DETERMINERS and anchor.start_tok - j < 2:
                j -= 1
            if j == 0 or norms[j - 1] not in lx.RELATION_ENDINGS | {"into", "in", "at", "onto"}:
                continue
            for k in range(j - 1, max(0, j - 6), -1):
                if (k - 1) in place_tokens or (k - 1) in marker_tokens or toks.clause_start[k]:
                    break
                found = None
                for n in (3, 2, 1):
                    a = k - n
                    if a < 1 or norms[a - 1] != "the" or any(i in place_tokens for i in range(a - 1, k)):
                        continue
                    if norms[a:k] in tails:
                        found = (a, norms[a:k])
                        break
                if found is None:
                    continue
                a, key = found
                if norms[k] in lx.CALLER_ROLES:
                    break  # "the fence judge at the trakehner": a person named by where they work, no place
                if k == j - 1 and norms[k] in ("in", "at"):
                    break  # "fell down the steps in the gods": the steps of the place itself, where it is
                related: dict[str, str] = {}  # landmark -> the first KB relation joining it to the anchor
                for c in tails[key]:
                    for r in self.kb.relations:
                        if {r.subject, r.object} == {c, anchor.landmark}:
                            related.setdefault(c, f"{r.subject} {r.relation} {r.object}")
                if len(related) != 1:
                    break
                target, via = next(iter(related.items()))
                idx = ex.places.index(anchor)
                ex.places[idx] = replace(anchor, status="reference", reason=f"reference point: {via}")
                ex.places.append(self._mention(toks, a - 1, anchor.end_tok, target,
                                               via=f"{via} (the '{' '.join(key)}' related to {anchor.landmark})"))
                place_tokens.update(range(a - 1, anchor.end_tok))
                found_any = True
                break
        return found_any

    OPEN_RELATION_MIN_SIM = 0.55
    OPEN_RELATION_HINT_SIM = 0.35

    def _relation_texts(self) -> tuple[np.ndarray, list[tuple[str, bool]]]:
        """Embedded surface forms of the KB's relations, each with its direction."""
        if getattr(self, "_rel_cache", None) is None:
            forms: dict[str, tuple[str, bool]] = {}
            for rel in self.kb.relations:
                for form, inverse in _relation_forms(rel.phrase):
                    forms.setdefault(form, (rel.phrase, inverse))
                for canon, syns in lx.RELATION_SYNONYMS.items():
                    if rel.phrase == canon or rel.phrase in syns:
                        for syn in syns:
                            forms.setdefault(syn, (rel.phrase, False))
            texts = sorted(forms)
            assert self.embedder is not None
            self._rel_cache = (self.embedder.embed_fixed(texts), [forms[t] for t in texts])
        return self._rel_cache

    @functools.cached_property
    def _relation_words_of(self) -> dict[str, frozenset[str]]:
        """Per landmark, the words of the names of the KB relations it stands in ("yard" of
        ``belongs_to_the_yard_of``)."""
        words: dict[str, set[str]] = {}
        for rel in self.kb.relations:
            for end in (rel.subject, rel.object):
                words.setdefault(end, set()).update(norm(w) for w in rel.phrase.replace("_", " ").split())
        return {name: frozenset(ws) for name, ws in words.items()}

    def _link_similarities(self, link: str) -> np.ndarray:
        """MiniLM similarity of an unlisted linking phrase to each KB relation form (``_relation_texts``)."""
        mat, _ = self._relation_texts()
        return mat @ self.embedder.embed_one(link)  # type: ignore[union-attr]

    OPEN_RELATION_MARGIN = 0.1
    OPEN_RELATION_SOLE_MIN_SIM = 0.1
    # a relation of the anchor's far ahead of its others needs less: "whatever's built against the khan" for
    # ``camel pens lean against caravanserai`` (0.52, the next 0.08)
    OPEN_RELATION_CLEAR_MIN_SIM = 0.45
    OPEN_RELATION_CLEAR_MARGIN = 0.3

    def _follow_link(self, anchor: str, link: str, head: str, inverse: bool,
                     sims: np.ndarray | None = None, partners: bool = True) -> tuple[str | None, str | None]:
        """Follow an unlisted linking phrase from ``anchor``: of the KB relation forms close to it
        (within ``OPEN_RELATION_MARGIN`` of the best), the closest one the anchor takes part in,
        in the direction the phrase reads, wins ("whatever taxiway alpha comes out onto":
        ``leads_onto``, which taxiway alpha is the subject of, not ``opens_onto``); if none does,
        the best form is followed as before; if that leads nowhere either, the anchor's own relations are read by
        ``_partner_by_meaning`` (unless ``partners`` is False). ``sims``: the phrase's ``_link_similarities``, if known."""
        _, meta = self._relation_texts()
        if sims is None:
            sims = self._link_similarities(link)
        order = np.argsort(-sims, kind="stable")
        best = float(sims[order[0]])
        if best < self.OPEN_RELATION_MIN_SIM:
            if best >= self.OPEN_RELATION_HINT_SIM:
                found = self._related_by_head(anchor, head)
                if found[0] is not None or not partners:
                    return found
            return self._partner_by_meaning(anchor, link, head, link_subject=inverse) if partners else (None, None)
        for i in order:
            if sims[i] < max(self.OPEN_RELATION_MIN_SIM, best - self.OPEN_RELATION_MARGIN):
                break
            phrase, inv = meta[int(i)]
            target, via = self._follow(anchor, phrase, head, inverse=_reads_backwards(link, phrase, inv) != inverse,
                                       _loose=True)
            if target is not None:
                # ("the tower the overland drops its ore into": a head word that names the one place related to the
                # anchor with it in its names, "transfer tower", names the place meant)
                return self._head_named_neighbour(anchor, norm(head), target, via) if head.isalpha() else (target, via)
        phrase, inv = meta[int(order[0])]
        # (a link MiniLM only guesses at is read no further by height: "the gardens the Imperial looks out on"; nor
        # the other way round where its last word says the other way, "draws its fuel from" for ``pumps fuel out to``)
        found = self._follow(anchor, phrase, head, inverse=_reads_backwards(link, phrase, inv) != inverse, _vertical=False,
                             _loose=_ends_opposite(link, phrase))
        return found if found[0] is not None or not partners \
            else self._partner_by_meaning(anchor, link, head, link_subject=inverse)

    PARTNER_MIN_SCORE = 0.55
    PARTNER_MARGIN = 0.08

    def _partner_by_meaning(self, anchor: str, link: str, head: str, min_score: float | None = None,
                            margin: float | None = None,
                            anchor_is_object: bool | None = None,
                            link_subject: bool | None = None) -> tuple[str | None, str | None]:
        """A linking phrase no relation form is close to, read among the anchor's own relations only, where the link
        has a word that may be its verb: each place the KB relates to the anchor scores the MiniLM similarity of the
        link to that relation's name plus that of the head noun to the place's best name or description ("the high
        ground the mast is anchored to": ``is_guyed_to`` the summit ridge, not ``relays the radio for`` the ranger
        station; "the concrete box the hut gets its water from": the water intake that ``pipes_water_down_to`` it).
        The best wins if it scores ``PARTNER_MIN_SCORE`` (or ``min_score``) and leads the next by ``PARTNER_MARGIN``
        (or ``margin``). ``anchor_is_object`` says where the anchor stands to an active verb of supply in the link
        ("the building that feeds the tank": its object); only relations that way round are read then.
        ``link_subject`` says whether the anchor is the link's subject ("wherever the pump house draws its fuel
        from"); a relation whose name ends the other way ("pumps fuel out to") is read only with the anchor at its
        other end then."""
        assert self.embedder is not None
        words = link.split()
        if not any(_verb_like(w) or w in _SUBJECT_PRONOUNS and k + 1 < len(words)
                   or w in ("looks", "look", "got") and k + 1 < len(words) and words[k + 1] != "like"
                   for k, w in enumerate(words)):
            return None, None  # ("the hill road past the caravan park", "full of": no verb, no relation said; but "looks
            # out over", "that's got the tunnel through to": verbs, though function words in "looks like")
        scored: dict[str, tuple[float, str]] = {}
        v_link = self.embedder.embed_one(link)
        v_head = self.embedder.embed_one(head)
        # ("the tank that's fed by the bore": a passive link says which end the anchor is, the relation's doer)
        passive = len(words) >= 2 and words[-1] == "by" and any(
            w.endswith("ed") or w in _IRREGULAR_PARTICIPLES for w in words[:-1])
        # ("the building that feeds the tank": a verb of supply said actively, the anchor its object, is read only
        # among the relations that supply the anchor, not those it supplies)
        flowing = anchor_is_object is not None and not passive and any(
            w.lower() in _SUPPLY_VERBS for w in words[:2])
        for rel in self.kb.relations:
            if anchor not in (rel.subject, rel.object) or rel.subject == rel.object:
                continue
            if passive and (rel.subject == anchor) == _named_passive(rel.phrase):
                continue  # (a relation named in the passive itself, "is fed by", has its doer as object)
            if flowing and _anchor_receives(rel, anchor) != anchor_is_object:
                continue
            if link_subject is not None and _ends_opposite(link, rel.phrase) and (rel.subject == anchor) == link_subject:
                continue
            other = rel.object if rel.subject == anchor else rel.subject
            score = float(self._partner_relation_vectors[rel.phrase] @ v_link) \
                + float(np.max(self._partner_name_vectors[other] @ v_head))
            if score > scored.get(other, (-1.0, ""))[0]:
                scored[other] = (score, f"{rel.subject} {rel.relation} {rel.object}")
        if not scored:
            return None, None
        ranked = sorted(scored.items(), key=lambda kv: -kv[1][0])
        best_score = ranked[0][1][0]
        min_score = self.PARTNER_MIN_SCORE if min_score is None else min_score
        if passive and len(ranked) == 1:
            min_score = min(min_score, self.PARTNER_MIN_SCORE)  # (one relation the right way round: the lower bar)
        margin = self.PARTNER_MARGIN if margin is None else margin
        if best_score < min_score or len(ranked) > 1 and best_score - ranked[1][1][0] < margin:
            return None, None
        return ranked[0][0], ranked[0][1][1]

    PARTNER_CLAUSE_MIN_SCORE = 0.65
    PARTNER_CLAUSE_MARGIN = 0.1

    def _partner_heads(self) -> frozenset[str]:
        """Nouns that may head a description of a place read by ``_resolve_by_partners``."""
        # (and a few nouns for things and berths: "the machine that travels along the top of the powerhouse", "the
        # moorings you reach through the lock")
        return self._place_nouns() | lx.DESCRIPTION_HEADS | _WATER_HEADS | lx.GROUND_HEADS | lx.AREA_HEADS \
            | {"machine", "contraption", "rig", "mooring", "moorings", "berth", "berths", "pontoon", "pontoons"}

    def _resolve_by_partners(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                             marker_tokens: set[int], cue_tokens: set[int]) -> None:
        """A relative clause no relation form reads, around a place said in it: "the tower they send people down
        the kamikaze from", "the water the rapids bridge goes over", "the shed that backs up the control room's
        power". A head noun after an article, then within one clause the anchor and other words (a clause that ends
        on a preposition after the anchor, or on the anchor itself), is read among the places the KB relates to the
        anchor by ``_partner_by_meaning``, with a higher bar (``PARTNER_CLAUSE_MIN_SCORE``, ``PARTNER_CLAUSE_MARGIN``)
        since no relation word was found."""
        heads = self._partner_heads()
        n = len(norms)
        # (a place read already from its own description anchors one around it: "the tank supplying the shed that
        # answers to the control tower")
        # (and one the MiniLM link reading left unresolved: "the lift that goes up from the valley station")
        anchors = sorted([p for p in ex.places if p.status == "active" and (
            p.via is None or norms[p.start_tok] in lx.ARTICLES and p.end_tok - p.start_tok >= 4)
            or p.status == "reference" and p.via is None and p.reason.startswith("reference point of an unresolved")],
            key=lambda p: -p.start_tok)
        for anchor in anchors:  # (grows: a description read here anchors the one around it, read after it)
            if anchor not in ex.places or norms[anchor.start_tok] in lx.PRONOUNS:
                continue
            a0, a1 = anchor.start_tok, anchor.end_tok
            # the clause's end: the anchor's own end, or a preposition ending the clause up to six words on
            end = a1 if a1 == n or toks.clause_start[a1] or norms[a1] in lx.COPULAS else None
            # ("the shed that backs up the control room's power -": the anchor's own thing ends the clause)
            own = a1 + 1 if a1 < n and norms[a1] == "s" else a1 if toks.tokens[a1 - 1].text.lower().endswith(("'s", "’s")) else None
            for e in range(own + 1, min(own + 2, n) + 1) if own is not None and end is None else ():
                if end is None and (e == n or toks.clause_start[e]) \
                        and all(norms[i].isalpha() and norms[i] not in lx.FUNCTION_WORDS for i in range(own, e)):
                    end = e
            closing = end is not None  # (the anchor closes the clause, or its own thing does)
            # (a place said as where the anchor is, no claim of its own, stands in the clause: "the building the
            # pipes from the pepperpot run down into"; a danger word may stand in it: "the ponds the pump house
            # pushes the water back up to")
            inner = {i for p in ex.places if p.status != "active" and p.start_tok >= a1 for i in range(p.start_tok, p.end_tok)}
            for e in range(a1 + 1, min(a1 + 7, n) + 1) if end is None else ():
                if e - 1 in place_tokens and e - 1 not in inner or toks.clause_start[e - 1]:
                    break
                if norms[e - 1] in lx.RELATION_ENDINGS | {"into", "for", "up", "down", "out", "along", "across", "around"} and (
                        e == n or toks.clause_start[e] or norms[e] in lx.COPULAS):
                    end = e
                    break
            # ("the whole hall that battery B keeps alive,": "that", the anchor, and a verb ending the clause)
            verb_end = False
            for e in range(a1 + 1, min(a1 + 4, n) + 1) if end is None else ():
                if any(i in place_tokens or i in marker_tokens or i in cue_tokens or toks.clause_start[i]
                       for i in range(a1, e)):
                    break
                if (e == n or toks.clause_start[e]) and any(_verb_like(toks.tokens[i].text) for i in range(a1, e)):
                    end, verb_end = e, True
                    break
            if end is None:
                continue
            # the head: an article, at most one word, a head noun, up to eight words before the anchor
            h = None
            for k in range(a0 - 1, max(0, a0 - 9), -1):
                if k in place_tokens or toks.clause_start[k + 1] and k + 1 < a0 or norms[k] in lx.COORDINATORS:
                    break  # (not across "and": "a holding area and er the zigzag's blocked by a mudflow halfway down")
                if norms[k] in lx.WHATEVER and k + 1 < a0 and norms[k] != "where" \
                        and norms[k + 1] not in lx.DETERMINERS | lx.PRONOUNS and k + 1 not in place_tokens:
                    h = k  # ("whatever pushes water up to the tower": the head is "whatever" itself, its verb next;
                    break  # not "whatever the pump house draws its fuel from", read by the relation's words)
                if norms[k] in heads and (norms[k - 1] in lx.ARTICLES or k >= 2 and norms[k - 2] in lx.ARTICLES
                                          and norms[k - 1].isalpha() and norms[k - 1] not in _NOT_HEADS) \
                        and not (k + 1 < n and norms[k + 1] in lx.PREPOSITIONS and k + 2 == a0) \
                        and not (k + 2 < n and norms[k + 1] in lx.PREPOSITIONS and norms[k + 2] in lx.DETERMINERS
                                 and k + 3 == a0):
                    h = k
                    break
            if h is None or toks.clause_start[h + 1] or any(toks.clause_start[i] for i in range(h + 1, a0)):
                continue
            if verb_end and not (norms[h + 1] in ("that", "which") and all(norms[i] in lx.DETERMINERS for i in range(h + 2, a0))):
                continue  # ("the shed that battery B keeps alive", not "the shed battery B keeps", a claim of its own)
            if closing and not (norms[h + 1] in ("that", "which", "who", "whose") or _reduced_relative_opener(toks.tokens[h + 1].text)
                                or norms[h] in lx.WHATEVER
                                or norms[h + 1] in ("you", "they", "we") and h + 2 < a0 and norms[h + 2].isalpha()
                                and len(norms[h + 2]) >= 3 and norms[h + 2] not in lx.FUNCTION_WORDS | lx.HEARSAY_VERBS
                                | lx.COPULAS | {"can", "could", "will", "would", "should", "must", "might"}):
                # ("the moorings you reach through the lock": a contact clause with a subject of its own)
                continue  # ("the mill race wall has collapsed into the bobbin mill": a clause of its own, no relative one)
            link_idx = [i for i in range(h + 1, end) if not (a0 <= i < a1)
                        and not (i < a0 and all(norms[j] in lx.DETERMINERS for j in range(i, a0)))
                        and norms[i] not in ("that", "which", "who", "where") and norms[i] not in lx.HESITATIONS]
            content = [i for i in link_idx if norms[i] not in lx.FUNCTION_WORDS and norms[i].isalpha()]
            if not content or len(link_idx) > 9 or toks.tokens[h].text.lower().endswith(("'s", "’s")):
                continue  # ("the river's ripping through at the weir": "is", no relative clause)
            if closing and norms[h + 1] not in ("that", "which") and any(i in cue_tokens for i in link_idx):
                continue  # ("the street saying his missus is trapped in the flats": a claim, no description; but "the
                # pond that spills over onto the hillside", a relative clause whose verb is a danger word, describes)
            if norms[h] in lx.ROUTE_HEADS and all(norms[i] in lx.ROUTE_LINKS for i in link_idx):
                continue
            link = " ".join(toks.tokens[i].text.lower() for i in link_idx)
            if norms[h + 1] == "who" and link_idx and link_idx[0] == h + 2 and norms[h] not in _PEOPLE_OR_GROUPS:
                # "the trail who go up from the horse barn": a learner's "who" for a thing, and the verb as said
                v = toks.tokens[h + 2].text.lower()
                if v.isalpha() and len(v) >= 2 and not v.endswith("s") and v not in lx.FUNCTION_WORDS:
                    link = (v + ("es" if v.endswith(("o", "sh", "ch", "x")) else "s")) + link[len(v):]
            head_start = h if norms[h] in lx.WHATEVER else h - 1 if norms[h - 1] in lx.ARTICLES else h - 2
            head = " ".join(toks.tokens[i].text.lower() for i in range(min(head_start + 1, h), h + 1))
            verbs = [i for i in link_idx if norms[i] in _SUPPLY_VERBS]
            target, via = self._partner_by_meaning(anchor.landmark, link, head, self.PARTNER_CLAUSE_MIN_SCORE,
                                                   self.PARTNER_CLAUSE_MARGIN,
                                                   anchor_is_object=(verbs[0] < a0) if verbs else None)
            if target is None or target == anchor.landmark or anchor.via is not None and via in anchor.via:
                continue  # (a description's own relation read again: "the ward linked by the bridge to the south wing")
            idx = ex.places.index(anchor)
            ex.places[idx] = replace(anchor, status="reference", reason=f"reference point: {via} (read '{link}')")
            ex.places.append(self._mention(toks, head_start, end, target, via=f"{via} ~ '{link}' (by meaning)"))
            place_tokens.update(range(head_start, end))
            if norms[head_start] in lx.ARTICLES and end - head_start >= 4:
                anchors.append(ex.places[-1])
        self._partners_of_pronoun(ex, toks, norms, place_tokens, marker_tokens, cue_tokens, heads)

    def _named_contact_clauses(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...]) -> None:
        """"trapped on the bank the old bunker is cut into": a place named, then straight on in its clause another
        the KB relates to it and a verb ending on a preposition. The second only says which the first is: a reference
        point, whatever words the relation is said in."""
        n = len(norms)
        for idx, q in enumerate(ex.places):
            s0 = q.start_tok - 1
            if q.status != "active" or q.via is not None or s0 < 1 or norms[s0] not in lx.ARTICLES:
                continue
            p = next((p for p in ex.places if p.status == "active" and p.end_tok == s0 and p is not q), None)
            if p is None or (p.landmark, q.landmark) not in self._related_pairs or toks.clause_start[s0] \
                    or toks.clause_start[q.start_tok]:
                continue
            e = q.end_tok
            endings = lx.RELATION_ENDINGS | {"into", "onto", "in", "up", "down"}
            while e < n and not toks.clause_start[e] and e - q.end_tok < 5 and not (
                    e > q.end_tok + 1 and norms[e - 1] in endings and norms[e] in lx.COPULAS | {"has", "have", "had"}):
                e += 1  # (up to the main clause's verb: "the ponds the pilas drain into have burst their wall")
            after = norms[q.end_tok:e]
            if not after or not (e == n or toks.clause_start[e] or norms[e] in lx.COPULAS | {"has", "have", "had"}) \
                    or after[-1] not in endings \
                    or not any(_verb_like(toks.tokens[i].text) for i in range(q.end_tok, e - 1)) and not (
                        # ("the ponds the pilas drain into": a plural subject's verb has no "s")
                        q.text.lower().endswith("s") and len(after) == 2 and after[0].isalpha()
                        and after[0] not in lx.FUNCTION_WORDS and len(after[0]) >= 3) \
                    or any(r.start_tok < e and r.end_tok > q.end_tok for r in ex.places if r is not q):
                continue
            ex.places[idx] = replace(q, status="reference", reason=f"reference point of a named place ('{p.text}')")
            ex.relation_tokens.update(range(q.end_tok, e))

    def _partners_of_pronoun(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                             marker_tokens: set[int], cue_tokens: set[int], heads: frozenset[str]) -> None:
        """"Fire alarm at the Alpenblick was false. But the plant that heats it is on fire": a relative clause on
        "that"/"which" that ends on "it"/"there"/"them" (the clause's end, or a verb after it) is read as
        ``_resolve_by_partners`` reads one around a name, the pronoun standing for the one place named last, in an
        earlier clause, with no other place said since. The antecedent keeps its own claims. So is a clause whose
        subject is "it", right after its head ("but the place it keeps cold, that's still thick with fumes"), the words
        after the pronoun up to the clause's end its link."""
        n = len(norms)

        def read(h: int, k: int, end: int, link: str) -> None:
            """The description from the article before head ``h`` to ``end``, the pronoun at ``k``, read by meaning
            around the pronoun's antecedent."""
            ante = _sole_antecedent(ex, toks, h, k)
            if ante is None:
                return  # (none, or another place said since: which one the pronoun means is not sure)
            target, via = self._partner_by_meaning(ante.landmark, link, toks.tokens[h].text.lower(),
                                                   self.PARTNER_CLAUSE_MIN_SCORE, self.PARTNER_CLAUSE_MARGIN)
            if target is None or target == ante.landmark:
                return
            ex.places.append(self._mention(toks, h - 1, end, target,
                                           via=f"{via} ~ '{link}' (by meaning, '{norms[k]}' = {ante.landmark})"))
            place_tokens.update(range(h - 1, end))

        for k in range(4, n):
            if norms[k] not in ("it", "there", "them") or k in place_tokens or k in marker_tokens:
                continue
            if not (k + 1 == n or toks.clause_start[k + 1] or norms[k + 1] in lx.COPULAS or (k + 1) in cue_tokens):
                continue
            h = next((j for j in range(k - 2, max(0, k - 9), -1) if norms[j + 1] in ("that", "which")
                      and norms[j] in heads and norms[j - 1] in lx.ARTICLES), None)
            if h is None or any(toks.clause_start[i] for i in range(h + 1, k + 1)) \
                    or any(i in place_tokens or i in marker_tokens or i in cue_tokens for i in range(h - 1, k)):
                continue
            link_idx = [i for i in range(h + 2, k) if norms[i] not in lx.HESITATIONS]
            if any(norms[i] not in lx.FUNCTION_WORDS and norms[i].isalpha() for i in link_idx):
                read(h, k, k + 1, " ".join(toks.tokens[i].text.lower() for i in link_idx))
        for k in range(3, n - 1):
            # "the compressor room ... but the place it keeps cold, that's still thick with fumes": the pronoun is the
            # clause's subject, the words after it up to the clause's end its link
            if norms[k] != "it" or k in place_tokens or k in marker_tokens or toks.clause_start[k]:
                continue
            h = k - 2 if norms[k - 1] in ("that", "which") else k - 1
            if h < 1 or norms[h] not in heads or norms[h - 1] not in lx.ARTICLES or toks.clause_start[h + 1]:
                continue
            e = next((i for i in range(k + 1, min(n, k + 7)) if toks.clause_start[i] or norms[i] in lx.COPULAS), None)
            if e is None and n - k <= 6:
                e = n
            if e is None or e - k < 2 or any(i in place_tokens or i in marker_tokens or i in cue_tokens
                                              for i in range(h - 1, e)):
                continue
            link = " ".join(toks.tokens[i].text.lower() for i in range(k + 1, e) if norms[i] not in lx.HESITATIONS)
            if link and _verb_like(link.split()[0]):  # (not only hesitations: "the place it um is full of smoke")
                read(h, k, e, link)

    @functools.cached_property
    def _partner_relation_vectors(self) -> dict[str, np.ndarray]:
        """MiniLM vectors of the KB's relation names as words, for ``_partner_by_meaning`` (embedded once)."""
        assert self.embedder is not None
        phrases = sorted({rel.phrase for rel in self.kb.relations})
        return dict(zip(phrases, self.embedder.embed_fixed([p.replace("_", " ") for p in phrases]), strict=True))

    @functools.cached_property
    def _partner_name_vectors(self) -> dict[str, np.ndarray]:
        """Per landmark, MiniLM vectors of its names and its description, as ``_partner_by_meaning`` compares a head
        noun to them (embedded once)."""
        assert self.embedder is not None
        texts = {lm.name: list(lm.surface_forms) + ([lm.description] if lm.description else []) for lm in self.kb.landmarks}
        flat = [t for ts in texts.values() for t in ts]
        mat = self.embedder.embed_fixed(flat)
        out, k = {}, 0
        for name, ts in texts.items():
            out[name] = mat[k:k + len(ts)]
            k += len(ts)
        return out

    def _related_by_head(self, anchor: str, head: str) -> tuple[str | None, str | None]:
        """"the quay that the ice plant makes the ice for": a linking phrase MiniLM only half knows, and a head word
        that names exactly one of the places the anchor has a relation with (the fish quay), is that place."""
        key = norm_phrase(head)
        if len(key) != 1 or key[0] in ("place", "building", "one", "spot", "bit", "area", "site", "thing", "side", "end") \
                or len(key[0]) < 3:
            return None, None
        found = {other: via for other, (via, _) in self._related_to(anchor).items()
                 if any(key[0] in name_words(f) for f in self.kb.landmark_by_name[other].surface_forms)}
        if not found and len(key[0]) >= 5:
            # "the drain that feeds the gumbo": no name says "drain", but the one relation the anchor has that
            # the head word's stem names (``brine ditch drains into mud sink``) does
            found = {other: via for other, (via, phrase) in self._related_to(anchor).items()
                     if any(_same_stem(key[0], w) for w in norm_phrase(phrase))}
        if len(found) != 1:
            return None, None
        other, via = next(iter(found.items()))
        return other, via

    def _related_to(self, anchor: str) -> dict[str, tuple[str, str]]:
        """The landmarks the KB relates to ``anchor``, either way round, each with the first relation joining them:
        as the KB states it ("ice plant chills_the_catch_for fish quay") and its phrase."""
        out: dict[str, tuple[str, str]] = {}
        for rel in self.kb.relations:
            if anchor in (rel.subject, rel.object) and rel.subject != rel.object:
                other = rel.object if rel.subject == anchor else rel.subject
                out.setdefault(other, (f"{rel.subject} {rel.relation} {rel.object}", rel.phrase))
        return out

    def _resolve_open(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                      marker_tokens: set[int], cue_tokens: set[int]) -> None:
        """"the place sharing a wall with the mill": an unknown linking phrase between a generic
        head and a place, matched to the KB's relation forms with MiniLM (antonyms flip direction); then
        once more from the places so found ("the space just aft of the space just aft of the ECR")."""
        first = len(ex.places)
        # (a description the phrase tables read backwards anchors one too: "the hostel that houses the crews for the
        # dome the mirror shop recoats"; not one read forwards, "the bridge to the south wing", a relation's own tail)
        self._resolve_open_from(ex, toks, norms, place_tokens, marker_tokens, cue_tokens,
                                [p for p in ex.places if p.status == "active"
                                 and (p.via is None or p.via.endswith(f" {p.landmark}")
                                      or norm_phrase(p.text)[:2] in (("the", "one"), ("the", "place")))])
        # (and one read forwards that is a noun phrase of its own: "the shed leaning on the one behind the bunkhouse")
        self._resolve_open_from(ex, toks, norms, place_tokens, marker_tokens, cue_tokens,
                                [p for p in ex.places[first:] if p.status == "active"])

    def _resolve_open_from(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                           marker_tokens: set[int], cue_tokens: set[int], anchors: list[PlaceMention]) -> None:
        def verb_after_head(i: int) -> bool:  # ("the shed leaning on ...": an "-ing" word right after "the" and a noun)
            return norms[i].endswith("ing") and i >= 2 and norms[i - 1] in lx.GENERIC_HEADS | self._place_nouns() \
                and norms[i - 2] in lx.ARTICLES and (i - 1) not in place_tokens | cue_tokens

        for anchor in sorted(anchors, key=lambda p: -p.start_tok):
            j = anchor.start_tok
            while j > 0 and norms[j - 1] in lx.DETERMINERS and anchor.start_tok - j < 2:
                j -= 1
            # ("keeps the keys to the, um, the hut": the article said again after a hesitation)
            while j >= 2 and norms[j - 1] in lx.HESITATIONS and norms[j - 2] in lx.ARTICLES and anchor.start_tok - j < 4:
                j -= 2
            if j == 0 or norms[j - 1] not in lx.RELATION_ENDINGS | {"for"}:
                continue  # ("the building that keeps a key for the boat station")
            # walk back over the linking words to a generic head noun
            k = j - 1
            open_k = None  # the nearest plain noun after "the", if no generic head stands further back
            while k > 0 and j - k < 6:
                w = norms[k - 1]
                # (a participle right after "the" and a head noun is the link's verb, though a cue word: "the shed
                # leaning on the one behind the bunkhouse")
                participle = verb_after_head(k - 1) or k >= 4 and verb_after_head(k - 2) \
                    and w in _VERB_PARTICLES  # ("the road coming down out of")
                if (k - 1) in place_tokens or (k - 1) in marker_tokens or (k - 1) in cue_tokens and not participle \
                        or toks.clause_start[k]:
                    break
                if w in lx.GENERIC_HEADS and k - 1 > 0 and norms[k - 2] in lx.DETERMINERS:
                    break
                if open_k is None and j - k >= 2 and self._open_head(norms, k - 1):
                    open_k = k
                k -= 1
            if open_k is not None and (k == 0 or norms[k - 1] not in lx.GENERIC_HEADS):
                k = open_k
            if k == 0 or not (norms[k - 1] in lx.GENERIC_HEADS or self._open_head(norms, k - 1)) or j - k < 2 \
                    or toks.clause_start[k] or (k - 1) in place_tokens or (k - 1) in cue_tokens:
                continue
            if norms[k - 1] == "one" and norms[k] == "of":
                continue  # "one of my riders came off on widowmaker": one of them, no place
            if norms[k] in _PEOPLE_OR_GROUPS:
                continue  # "the school group have been moved across to the tea room": people the noun says whose
            if norms[k - 1] in lx.ROUTE_HEADS and all(w in lx.ROUTE_LINKS for w in norms[k:j]):
                continue  # "the road down to the boatyard is impassable": the way to the place, no relation
            link = " ".join(toks.tokens[i].text.lower() for i in range(k, j))
            if self._relations.match_at(norms, k) is not None:
                continue  # a known phrase: the table-driven pass owns it
            if norms[j - 1] == "of" and set(norms[k - 1:j]) & (lx.STOREY_WORDS | lx.PART_NOUNS | lx.LOCATIVE_PARTS):
                continue  # "on the ground floor of the chemistry annexe": a part of the place, in it
            if norms[k - 1] in _SEGMENT_HEADS | {"chunk", "piece", "bit", "part"} and norms[k:j] == ("out", "of"):
                continue  # "a landslip has taken a section out of the rim path": a part of the place itself
            sims = self._link_similarities(link)
            sim = float(sims.max())
            head_start = k - 1
            while head_start > 0 and norms[head_start - 1] in lx.DETERMINERS and (head_start - 1) not in marker_tokens:
                head_start -= 1
            if norms[j - 1] in ("to", "onto", "into") and head_start > 0 and norms[k - 1] not in lx.GENERIC_HEADS and (
                    norms[head_start - 1] in ("off", "from")
                    or set(norms[k:j]) <= {"over", "across", "up", "down", "back", "out", "round", "to", "onto", "into"}
                    and _verb_like(toks.tokens[head_start - 1].text)):
                continue  # "fell off the lighting bar onto the platform", "moving the queue over to the big ring":
                # what moves, from where, to the place; no description of a place
            idx = ex.places.index(anchor)
            # (a plain noun's description, "the figure cut into the slope below ...", only where MiniLM reads a
            # relation: "the waiting room of the health centre" is in it, no description to leave unresolved)
            plain = norms[k - 1] not in lx.GENERIC_HEADS
            if plain and norms[j - 1] == "of":
                continue  # ("the back doors of the library": a part of it)
            if sim < self.OPEN_RELATION_MIN_SIM:
                if sim >= self.OPEN_RELATION_HINT_SIM and not plain and anchor.via is None:
                    ex.places[idx] = replace(anchor, status="reference",
                                             reason=f"reference point of an unresolved description ('{link}')")
                continue
            # (not across a comma or a dash: "the stretch they sit below, the walk itself" says the place again)
            apart = any(c in toks.gaps[i] for i in range(j, anchor.start_tok + 1) for c in ",;—–-")
            target, via = self._follow_link(anchor.landmark, link, toks.tokens[k - 1].text, inverse=False, sims=sims,
                                            partners=not apart)
            if target is None:
                if not plain and anchor.via is None:  # (a description read already stays what it was read as)
                    ex.places[idx] = replace(anchor, status="reference", reason=f"reference point of an unresolved '{link}'")
                continue
            ex.places[idx] = replace(anchor, status="reference", reason=f"reference point: {via} (matched '{link}')")
            ex.places.append(self._mention(toks, head_start, anchor.end_tok, target, via=f"{via} ~ '{link}'"))
            place_tokens.update(range(head_start, anchor.end_tok))

    def _open_head(self, norms: tuple[str, ...], i: int) -> bool:
        """"the figure cut into the slope below the ramparts": a plain noun after "the" that may head a description
        MiniLM reads (no person, vehicle, floating thing or word of a danger)."""
        w = norms[i]
        return i > 0 and norms[i - 1] == "the" and w.isalpha() and len(w) >= 4 and w not in lx.FUNCTION_WORDS \
            and w not in _NOT_HEADS and w not in _PEOPLE_WORDS and w not in lx.VEHICLE_WORDS \
            and w not in lx.FLOATING_THINGS and w not in self._single_cue_words and w not in lx.STOREY_WORDS \
            and w not in lx.PART_NOUNS and w not in lx.LOCATIVE_PARTS and w not in lx.ROUTE_HEADS \
            and w not in ("slope", "hillside", "face", "edge", "middle", "whole", "back") \
            and w not in lx.ENTRANCE_PARTS and w not in lx.ROOMS_OF_A_BUILDING and w not in lx.PREMISES_PARTS \
            and w not in lx.SIDE_WORDS

    def _resolve_open_inverse(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                              marker_tokens: set[int], cue_tokens: set[int]) -> None:
        """"the shop the pharmacy is fixed to": a generic head, the anchor, then an unknown linking
        phrase ending the clause, matched to the KB's relation forms with MiniLM and read backwards (the anchor may be a
        place's own part: "the stream that the boiler room's pool overflows into")."""
        for anchor in [p for p in ex.places if p.status == "active" and (p.via is None or p.via.startswith("owned: "))]:
            k = anchor.start_tok
            while k > 0 and norms[k - 1] in lx.DETERMINERS | {"that", "which"} and anchor.start_tok - k < 2:
                k -= 1
            h = k
            while h > 0 and norms[h - 1] in lx.DETERMINERS | lx.FILLERS and anchor.start_tok - h < 5:
                h -= 1
            if h > 0 and h < k and norms[h - 1] in lx.WHATEVER and any(norms[i] in lx.FILLERS for i in range(h, k)):
                k = h  # "whatever the, er, the grain store is built against": past the hesitation
            # ("where the bottom gate opens out onto, that's the safe refuge": "where" opening the clause, as "wherever")
            # ("two kids stuck out where the tide gate drains to": after a word of where, too)
            whatever = lx.WHATEVER | ({"where"} if k > 0 and norms[k - 1] == "where" and (
                toks.clause_start[k - 1] or k >= 2 and norms[k - 2] in ("out", "down", "up", "over", "back", "round",
                                                                        "to", "from", "near")) else set())
            if k == 0 or (k == anchor.start_tok and norms[k - 1] not in whatever and not (k >= 2 and norms[k - 2] in lx.ARTICLES)) \
                    or (k - 1) in place_tokens \
                    or toks.clause_start[k] or not (norms[k - 1] in lx.GENERIC_HEADS | whatever or self._plain_head(norms, k - 1)):
                continue
            hs = k - 1
            if hs >= 2 and norms[hs - 2] in lx.ARTICLES and norms[hs - 1].isalpha() and norms[hs - 1] not in _NOT_HEADS \
                    and (hs - 1) not in place_tokens and norms[hs] in self._place_nouns():
                hs -= 1  # ("the car park the lorry park spills into": a head of two words)
            while hs > 0 and norms[hs - 1] in lx.DETERMINERS and (hs - 1) not in marker_tokens:
                hs -= 1
            if hs >= k - 2 and norms[hs] not in whatever and norms[hs] not in lx.DETERMINERS:
                continue  # "the shop the pharmacy ...", not "shop the pharmacy"
            e = anchor.end_tok
            m = None
            verb_s = e < len(norms) and toks.tokens[e].text.lower().endswith("s") \
                and not toks.tokens[e].text.lower().endswith(("'s", "’s"))
            for end in range(e + 2, min(e + 6, len(norms)) + 1):
                # (a cue word as the clause's verb is a verb: "the car park the lorry park spills into")
                if any(i in place_tokens or i in marker_tokens or (i > e and toks.clause_start[i])
                       or i in cue_tokens and not (i == e and verb_s or i == e + 1 and verb_s and norms[i] in _VERB_PARTICLES)
                       for i in range(e, end)):
                    # (a cue word as the clause's verb, with its particle: "up where the skid road comes down from")
                    break
                # ("the quay that the ice plant makes the ice for -", "the car park the lorry park spills into when
                # it's full": a preposition that ends the clause)
                if norms[end - 1] in lx.RELATION_ENDINGS | {"into", "for", "along", "alongside", "beneath", "underneath"} and (
                        end == len(norms) or toks.clause_start[end] or norms[end] in lx.COPULAS | {"as", "now", "theres", "when"}
                        or norms[end:end + 2] in (("there", "s"), ("there", "is"), ("there", "are"))
                        or end in cue_tokens):
                    m = end
                    break
            if m is None:
                continue
            link = " ".join(toks.tokens[i].text.lower() for i in range(e, m) if norms[i] not in lx.INVERSE_VERBS) \
                or " ".join(toks.tokens[i].text.lower() for i in range(e, m))
            if self._relations.match_at(norms, m - 1) is not None and m - e <= 2:
                continue  # a known phrase: the table-driven passes own it
            head = toks.tokens[k - 1].text
            target, via = self._follow_link(anchor.landmark, link, head, inverse=True)
            if target is None:
                # (read among the anchor's own relations, the anchor their doer: "whatever the tide gate drains to")
                target, via = self._follow_by_meaning(anchor.landmark, toks, e, m, inverse=True, sole=True)
            if target is None:
                continue
            idx = ex.places.index(anchor)
            ex.places[idx] = replace(anchor, status="reference", reason=f"reference point: {via} (matched '{link}')")
            ex.places.append(self._mention(toks, hs, m, target, via=f"{via} ~ '{link}'"))
            place_tokens.update(range(hs, m))

    def _resolve_open_ours(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                           marker_tokens: set[int], cue_tokens: set[int]) -> None:
        """"Landlord at the Bull here. We've opened up the hall we do the bar for": a head noun, "we", and a
        linking phrase that ends the clause, from the place the speaker said they are at; the place meant is one
        the KB relates to it, named by the head noun or read by MiniLM."""
        here = self._speaker_places(ex, norms)
        if len(here) != 1:
            return
        ours = here[0]
        for i in range(3, len(norms) - 2):
            if norms[i] not in ("we", "i") or i in place_tokens or i < ours.end_tok \
                    or norms[i - 2] not in lx.ARTICLES or not self._plain_head(norms, i - 1) or toks.clause_start[i]:
                continue
            m = None
            for end in range(i + 3, min(i + 7, len(norms)) + 1):
                if any(t in place_tokens or t in marker_tokens or t in cue_tokens or toks.clause_start[t]
                       for t in range(i + 1, end)):
                    break
                if norms[end - 1] in lx.RELATION_ENDINGS | {"into", "for"} and (
                        end == len(norms) or toks.clause_start[end] or norms[end] in lx.COPULAS | {"as", "now"}):
                    m = end
                    break
            if m is None:
                continue
            link = " ".join(toks.tokens[t].text.lower() for t in range(i + 1, m))
            target, via = self._follow_link(ours.landmark, link, toks.tokens[i - 1].text, inverse=True)
            if target is None or target == ours.landmark:
                continue
            ex.places.append(self._mention(toks, i - 2, m, target, via=f"{via} ~ '{link}' (from where the speaker is)"))
            place_tokens.update(range(i - 2, m))

    def _speaker_places(self, ex: Extraction, norms: tuple[str, ...]) -> list[PlaceMention]:
        """The named places (no descriptions) the speaker says they are at, not taken back: the anchors of "the hall we
        do the bar for" and of a relation left without its object ("the place directly opposite is going up")."""
        return [p for p in ex.places if p.status != "retracted" and p.via is None and self._speaker_here(norms, p)]

    RELATED_MARGIN = 0.04

    def _place_nouns(self) -> frozenset[str]:
        """Nouns that can head a description of a place: the generic ones and the head words of the KB's names
        ("portal", "meadow"; not their modifiers: "lorry" of "lorry park" is no place in "a lorry cab")."""
        if getattr(self, "_place_noun_cache", None) is None:
            heads = (_name_head(f) or "".join(name_words(f)[-1:]) for lm in self.kb.landmarks for f in lm.surface_forms)
            words = {head for head in heads if head.isalpha() and len(head) >= 3 and head not in lx.FUNCTION_WORDS}
            words |= {w for lm in self.kb.landmarks if (w := _description_head(lm.description or ""))}
            self._place_noun_cache = frozenset(words | lx.GENERIC_HEADS | {"track", "tracks", "houses", "homes"})
            # ("the pool the header tank feeds": a body of water heads one too)
            # ("the tracks the brick yard sends its loads down": a tramway's; "the houses whose back gardens ...")
        return self._place_noun_cache

    def _resolve_related(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], place_tokens: set[int],
                         marker_tokens: set[int], cue_tokens: set[int]) -> bool:
        """The last resort for a description no phrase table or MiniLM link reading resolved: "the place you
        row out to from the boat jetty", "the tube the shaft draws from". A place noun heads it, the
        anchor sits inside it after linking words (a verb, a relative clause, a preposition that is no
        mere "of" / "at" / "in"), or right after it before a verb. The anchor is then only a reference
        point, and the place meant is one the KB relates to it: the only one, else the one whose name has
        the head noun, else the relation MiniLM reads closest to the description, if it stands clearly
        first. Where none stands out, nothing is claimed there rather than the anchor. True where it found any."""
        nouns = self._place_nouns() | _WATER_HEADS
        found = False
        blocked = place_tokens | marker_tokens | cue_tokens
        pronoun_anchors = self._pronoun_anchors(ex, toks, norms, blocked)
        ex.places.extend(pronoun_anchors)
        # (a name that only modifies a noun may still anchor one: "the cottages they built for the bobbin mill's workers")
        for anchor in [p for p in ex.places if p.via is None and (p.status == "active" or p.status == "reference"
                                                                  and p.reason.startswith(("reference point of an unresolved",
                                                                                           "modifier of '")))
                       or p.via is not None and p.status == "active"]:
            # (a resolved description anchors one only by a head that names its one relative: "the bridge over the
            # drain the tin shed drinks from")
            if anchor not in ex.places:
                continue  # (taken up already as the outer description of another anchor)
            described_anchor = anchor.via is not None
            a = anchor.start_tok
            while a > 0 and norms[a - 1] in lx.DETERMINERS and anchor.start_tok - a < 2:
                a -= 1
            if a == anchor.start_tok and a >= 2 and norms[a - 1] in _SITE_MODIFIERS and norms[a - 2] in lx.ARTICLES:
                a -= 2  # ("the houses whose back gardens go right up to the factory car park")
            head = None
            for h in range(a - 1, max(-1, a - 9), -1):
                if h in blocked and not (h in cue_tokens and h not in place_tokens and "whose" in norms[max(0, h - 2):h]) \
                        or toks.clause_start[h + 1] and toks.gaps[h + 1] != "-" or norms[h] in lx.COORDINATORS:
                    break  # (a hyphen inside a word, "cross-passage", ends no clause; "whose old stables": no cue)
                if norms[h] == "one" and norms[h - 1] in ("second", "third", "fourth", "another", "next"):
                    break  # "big hot spot in the dutch barn, and a second one in the roof of the machinery shed"
                if toks.gaps[h + 1] == "-" and norms[h + 1] in lx.FUNCTION_WORDS:
                    continue  # "the walk-in freezer in the kitchens": the first half of a compound heads nothing
                if norms[h] in ("end", "edge", "foot", "head") and norms[h + 1:h + 2] == ("of",) and h >= 4 \
                        and norms[h - 1] == "the" and norms[h - 2] in ("at", "off", "on", "by") \
                        and any(norms[g] in nouns and norms[g - 1] in lx.ARTICLES for g in range(max(1, h - 6), h - 2)):
                    continue  # "the jetty tied up at the end of the harbour ...": where the head is, not the head
                if norms[h] in nouns and h > 0 and (norms[h - 1] in lx.ARTICLES | lx.WHATEVER or h > 1
                                                    and norms[h - 2] in lx.ARTICLES and norms[h - 1].isalpha()
                                                    and (h - 1) not in blocked) or norms[h] in lx.WHATEVER:
                    # (one modifier may stand between: "the cross-passage right before RB7", "that little bay")
                    if norms[h + 1:h + 2] == ("of",) and h >= 4 and norms[h - 2] in lx.PREPOSITIONS \
                            and norms[h] in self._relation_words_of.get(anchor.landmark, ()) and norms[h - 3] in nouns \
                            and norms[h - 4] in lx.ARTICLES and not {h - 3, h - 2, h - 1} & blocked \
                            and not toks.clause_start[h - 2]:
                        h -= 3  # "the oast in the yard of the farm ...": the relation's own noun, the head before it
                    w = next((w for w in range(h - 2, max(-1, h - 5), -1) if norms[w] in lx.WHATEVER
                              and _verb_like(toks.tokens[w + 1].text) and w + 1 < h
                              and not any(toks.clause_start[i] or i in blocked for i in range(w + 1, h))), None)
                    head = h if w is None else w  # ("whatever drags the logs back out of it": the noun is its object)
                    break
            if head is None:
                continue
            if norms[head] == "building" and norms[head + 1:head + 2] == ("up",) and head >= 1 and norms[head - 1] not in lx.ARTICLES:
                continue  # "a jam building up at the rollway": a verb, the jam building up there; no building
            if norms[head] == "ground" and norms[max(0, head - 2):head] == ("on", "the"):
                continue  # "he's on the ground at the bottom of it": where he lies, by the anchor, no other place
            if norms[head] in ("lot", "load") and norms[head + 1:head + 2] == ("of",) and head >= 1 \
                    and norms[head - 1] in ("a", "another"):
                continue  # "a lot of water coming out the rain tanks": how much, no parking lot
            if norms[head] == norms[anchor.end_tok - 1] and all(norms[i] in lx.DETERMINERS | lx.FILLERS
                                                                for i in range(head + 1, anchor.start_tok)):
                continue  # "the hut the toll hut's roof is half off": the speaker starts again on a fuller name
            if norms[head] in lx.PART_NOUNS | lx.LOCATIVE_PARTS | {"back", "middle", "edge"} and norms[head + 1:head + 2] == ("of",) \
                    and not any(p.start_tok >= head + 2 and all(w in lx.DETERMINERS | _PLAIN_ADJECTIVES
                                                                for w in norms[head + 2:p.start_tok]) for p in ex.places):
                continue  # "water pouring out the back of the aquarium into the service yard": a part of something
                # no landmark, and the place after it is where the water goes
            linked = [i for i in range(head + 1, a) if norms[i] not in lx.FILLERS
                      or norms[i] == "over" and i + 1 < len(norms) and norms[i + 1] in lx.DETERMINERS]
            # (the radio's "over" is a filler; "the bridge over the sixteen foot" is no radio)
            between = [norms[i] for i in linked]
            end = anchor.end_tok
            locative = False
            said_which: PlaceMention | None = None
            if norms[head] in _WATER_HEADS and norms[head] not in self._place_nouns() \
                    and (between or head == 0 or norms[head - 1] != "the"):
                continue  # a body of water heads only "the pool the header tank feeds" (not "the canal off the
                # pontoons", where someone slipped in, nor "like a river")
            if between and between[0] == "whose":
                pass  # "the chapel whose old vicarage is now Dinsdale's", "the farm whose old stables the team hut was"
            elif between:
                if between[0] == "with" and len(between) == 1 and anchor.via is None \
                        and anchor.end_tok - anchor.start_tok == 1 and norms[head] in lx.UNNAMING_HEADS \
                        and norms[anchor.start_tok] in norm_phrase(self.kb.landmark_by_name[anchor.landmark].description) \
                        and norms[anchor.start_tok] not in name_words(anchor.landmark) \
                        and (anchor.end_tok == len(norms) or toks.clause_start[anchor.end_tok]
                             or norms[anchor.end_tok] in ("and", "is", "s")):
                    continue  # "the visitor place with the café": a place by what it has, the one whose own café it is
                if between == ["with"] and norms[head] in lx.GENERIC_HEADS and norms[head - 1:head] == ("the",) \
                        and anchor.via is None and anchor.status == "active" \
                        and (anchor.end_tok == len(norms) or toks.clause_start[anchor.end_tok]):
                    continue  # "the place with the horses, the stables": the place said by what it has, itself
                if any(w in lx.COPULAS - {"s"} for w in between) or any(
                        between[m] == "its" and between[m + 1] in ("like", "a", "an", "all", "not", "just")
                        for m in range(len(between) - 1)):
                    continue  # (and a texted "its like a river": a clause of its own)
                if set(between) <= lx.LOCATIVE_LINKS:
                    # "the roof of the bakery", "the kiosk at the services": where it is, not another place (unless
                    # the head names the one landmark the KB relates to it: "the bridge over the sixteen foot")
                    locative = True
                if not (between[0] in lx.PREPOSITIONS | lx.RELATION_ENDINGS | lx.DESCRIPTION_OPENERS
                        or between[0].endswith(("s", "ed", "ing"))
                        or _verb_like(toks.tokens[linked[0]].text) and toks.tokens[linked[0]].text.lower().endswith("s")
                        and between[0] not in lx.HEARSAY_VERBS
                        and linked[0] + 1 < len(norms) and norms[linked[0] + 1] in lx.DETERMINERS | {"it", "them"}
                        # (a verb and its object, not a plural noun: "the top floor windows of the barracks")
                        # ("whatever drags the logs back out of it": a verb's "s" the key drops; not "a neighbour says")
                        or between[0] in ("they", "we", "you") and len(between) >= 2 and not toks.clause_start[head + 1]):
                    continue  # "a tank wagon on the siding": the noun goes on, it heads nothing (but "the tower they send
                    # people down the kamikaze from": a clause with a subject of its own describes it)
                if between[0] == "past":
                    continue  # "gritting the hill road past the caravan park": a way that goes by it, no relation
                if set(between) & {"call", "calls", "called", "name", "names", "named", "know", "knows"}:
                    continue  # "the one they call the cripple shed": the place named, not one related to it
                if set(between) & {"keep", "keeps", "kept", "store", "stores", "stored", "house", "houses", "housed"} \
                        and norms[head] in lx.DESCRIPTION_HEADS | _SHED_HEADS and not self._said_whole(anchor) and any(
                            name_words(f)[-1:] and name_words(f)[-1] in lx.DESCRIPTION_HEADS | _SHED_HEADS
                            for f in self.kb.landmark_by_name[anchor.landmark].surface_forms):
                    continue  # "the shed where they keep the sprinkler pumps": the building the anchor's name says, itself
                    # (said by no whole name of it: a place named in full and kept in a shed is another place)
                if len(between) >= 2 and between[0] in lx.PREPOSITIONS and between[1] in ("them", "him", "us", "me"):
                    continue  # "the turnstiles got a tree on them the lodge gate is blocked": the preposition's own object
                    # (not "her", a possessive as often: "the building across the road from her cafe")
                if between in (["into"], ["onto"]) and any(
                        norms[i] in lx.FALLEN_VERBS | {"jumped", "slipped", "thrown", "knocked"}
                        and not any(toks.clause_start[m] for m in range(i + 1, head + 1)) for i in range(max(0, head - 8), head)):
                    continue  # "he fell off the roof of the boat into the top pound": where he fell, no description
                if norms[head] in _SEGMENT_HEADS | {"chunk", "piece", "bit", "part"} and between == ["out", "of"]:
                    continue  # "a landslip has taken a section out of the rim path": a part of the anchor itself
                if norms[head] == "corner" and between[0] == "from":
                    continue  # "the Red Lion, round the corner from the square": somewhere near it, no relation
                if between[-1] in ("from", "of") and set(between) & _PEOPLE_WORDS \
                        and not set(between) & {"where", "that", "which", "whose", "who"}:
                    continue  # "a warm place for the old folk from Tanrallt": the people are from it, not the place
            else:
                # "the tube the shaft draws from": the linking verb comes after the anchor
                # ("whatever the creek empties into": read like "the place the creek empties into" where the phrase
                # tables and the link reading found nothing)
                if head == 0 and norms[head] not in lx.WHATEVER \
                        or norms[head] not in lx.WHATEVER and norms[head - 1] not in lx.ARTICLES and not (
                        head >= 2 and norms[head - 2] in lx.ARTICLES and norms[head - 1].isalpha()
                        and (head - 1) not in blocked and norms[anchor.start_tok] == "it"):
                    continue  # (an adjective may stand between: "the old building it was built out from")
                # ("the chamber that the tunnel from reception opens into": a place that only says which tunnel)
                said_which = next((q for q in ex.places if q is not anchor and q.via is None
                                   and _says_which_after(toks, norms, anchor.end_tok, q)), None) \
                    if norms[head - 1:head + 1] != ("the", "one") and norms[head + 1:head + 2] in (("that",), ("which",)) \
                    and anchor.end_tok < len(norms) and anchor.via is None else None
                start = end = said_which.end_tok if said_which is not None else end
                while end < len(norms) and end - start < 6 and end not in blocked \
                        and not toks.clause_start[end] and norms[end] not in lx.COORDINATORS:
                    end += 1
                after = norms[start:end]
                if end < len(norms) and toks.clause_start[end] and any(
                        q.status == "active" and q.via is None and end <= q.start_tok <= end + 2
                        and all(norms[i] in ("the", "a", "an") for i in range(end, q.start_tok)) for q in ex.places):
                    continue  # "on the bit it runs straight into, the north portal": the place named after says which
                    # (not "the building the long flue comes off -- that's the smelter": the same place, confirmed)
                # a verb closes the description: the last word of the clause or one before a preposition ("the building
                # the boiler house runs,": key "run"; not "the surgery's windows are all blown in")
                verb = any((w.endswith("s") or w.endswith("ed")) and (i + 1 == end or norms[i + 1] in lx.RELATION_ENDINGS | {"into"})
                           for i in range(anchor.end_tok, end) if (w := toks.tokens[i].text.lower()).isalpha()
                           and norms[i] not in lx.FUNCTION_WORDS | lx.CLAUSE_SUBJECTS | {"there", "here"})
                verb = verb or bool(after) and after[-1] in lx.IRREGULAR_PARTICIPLES and end - 1 > anchor.end_tok \
                    and (end >= len(norms) or toks.clause_start[end])  # "the chapel that the mill owners built."
                purpose = len(after) == 4 and after[0] in lx.COPULAS and after[2] == "to" \
                    and after[1] in ("there", "meant", "supposed", "built", "designed", "put", "dug", "made") \
                    and after[3].isalpha() and after[3] not in lx.FUNCTION_WORDS \
                    and (end >= len(norms) or toks.clause_start[end])  # "the magazine the blast bank is there to protect"
                stop = next((j for j in range(2, len(after)) if after[j] in lx.RELATION_ENDINGS
                             and (j + 1 == len(after) or after[j + 1] in lx.COPULAS | {"has", "have", "had"})), None)
                passive = stop is not None and after[0] in ("was", "is", "been") and norms[anchor.start_tok] == "it" \
                    and (toks.tokens[anchor.end_tok + 1].text.lower().endswith("ed") or after[1] in _IRREGULAR_PARTICIPLES)
                if passive:  # ("the old building it was built out from has got people trapped inside")
                    end = anchor.end_tok + stop + 1
                if not purpose and not passive and (not after or after[0] in lx.COPULAS | lx.PREPOSITIONS or not (
                        verb or any(w.endswith("s") or w.endswith("ed") or w in lx.RELATION_ENDINGS | {"into"} for w in after))):
                    continue  # ("a tank wagon on the loading siding is leaking": the anchor's own predicate)
            if between and end < len(norms) and not toks.clause_start[end] and (
                    norms[end] in ("its", "their") or norms[end] == "the" and norms[anchor.start_tok] in ("it", "them")):
                # ("Whatever feeds it the electric": what it gives the place the pronoun takes up, too)
                # "the place that feeds the auction hall its ice": what it gives the anchor is part of the description
                e2 = end + 1
                while e2 < len(norms) and e2 - end <= 3 and not toks.clause_start[e2] and norms[e2].isalpha() \
                        and e2 not in blocked and norms[e2] not in lx.FUNCTION_WORDS:
                    e2 += 1
                if e2 > end + 1 and (e2 == len(norms) or toks.clause_start[e2]):
                    end = e2
            outer = next((q for q in ex.places if q is not anchor and q.via is not None and q.status == "active"
                          and q.start_tok <= anchor.start_tok and anchor.end_tok <= q.end_tok), None)
            if outer is not None:
                anchor = outer  # "the house overlooking the lawn the north gate opens onto": the lawn so described
            joined = self._related_to(anchor.landmark)
            related = {other: via for other, (via, _) in joined.items()}
            phrases = {other: phrase for other, (_, phrase) in joined.items()}
            idx = ex.places.index(anchor)
            if not related:
                continue
            hword = norms[head]
            if anchor.via is None and name_words(anchor.text) and not self._said_whole(anchor) and any(
                    hword in name_words(f) and len(name_words(f)) >= 3
                    and set(name_words(f)) - {hword} <= set(name_words(anchor.text))
                    for f in self.kb.landmark_by_name[anchor.landmark].surface_forms):
                # (not where the anchor is said by a whole name of its own: "the pylon that feeds the cable up to
                # tower five" is another pylon, though "pylon five" is one of its names)
                continue  # "the hut where Father Christmas sits": the anchor's own name is "father christmas's hut"
            if hword == "one" and head >= 3 and norms[head - 1] == "the" and toks.clause_start[head - 1] \
                    and norms[head - 3] == "the" and norms[head - 2].isalpha():
                hword = norms[head - 2]  # "the terrace, the one where the bottling hall's workers lodge"
            named = {n: v for n, v in related.items() if hword in name_words(n)
                     or any(hword in name_words(f) for f in self.kb.landmark_by_name[n].surface_forms)}
            if not toks.tokens[head].text.lower().endswith("s"):
                # ("the ride it powers": one ride, not the fairground only ever called "the rides")
                named = {n: v for n, v in named.items() if any(
                    hword in name_words(f) and not any(w.lower().rstrip("'’").endswith("s") and norm(w) == hword
                                                       for w in f.split()) for f in self.kb.landmark_by_name[n].surface_forms)}
            if not named and not described_anchor and not locative and _weighty(hword) \
                    and hword not in lx.UNNAMING_HEADS | lx.GENERIC_HEADS:
                # "the pond where the lagoon's stuff ends up once it's been through the treatment plant": no place
                # the KB relates to the anchor has the head noun in its names, but one two relations away does
                hops: dict[str, str] = {}
                for mid, (via1, _) in joined.items():
                    for far, (via2, _) in self._related_to(mid).items():
                        if far != anchor.landmark and far not in related and any(
                                hword in name_words(f) for f in self.kb.landmark_by_name[far].surface_forms):
                            hops.setdefault(far, f"{via1}; {via2}")
                if len(hops) == 1:
                    named = hops
                    related = {**related, **hops}
            if locative and (len(named) != 1 or between[0] in ("of", "at", "in", "inside")):
                continue
            relative = len(between) == 2 and between[0] in ("that", "which") \
                and toks.tokens[linked[1]].text.lower().endswith("s") and between[1] not in lx.COPULAS
            # ("the water station that feeds the arch at the bottom of heartbreak hill": a verb of its own)
            # ("the place the building facing the souk gets its washing water from": a generic head and a verb after
            # the described anchor read it among the anchor's relations like a named one)
            generic_after = described_anchor and not between and not named and norms[head] in lx.GENERIC_HEADS \
                and norms[anchor.start_tok] == "the"
            # ("the conveyor coming off whatever's fed from the ROM pad": a verb of motion and its particle)
            moving = len(between) == 2 and between[0].endswith("ing") and between[0] not in lx.FUNCTION_WORDS \
                and (between[1] in lx.PREPOSITIONS or between[1] in _TO_PARTICLES)
            # ("the jetty tied up at the end of the harbour that's ...": the last words of ``is moored off the end of``)
            worded = len(named) == 1 and 2 < len(between) <= 7 \
                and _ends_on_own_words(between, phrases.get(next(iter(named)), ""))  # (none for a place two hops away)
            if described_anchor and not generic_after:
                # a described anchor is read so only where one named place fits and the words between are a
                # preposition, a relative verb, a verb of motion or the relation's own words (but "the oast in the
                # yard of the farm whose ...": the words of the relation's own name)
                own = phrases.get(next(iter(named)), "").replace("_", " ").split() if len(named) == 1 else []
                linked_by = bool(between) and (between[0] in lx.PREPOSITIONS | lx.PLACE_PREPOSITIONS or relative
                                               or moving or worded)
                opened = norms[anchor.start_tok] == "the" or moving and norms[anchor.start_tok] in lx.WHATEVER
                short = len(between) <= 2 or len(between) <= 4 and all(w in lx.FUNCTION_WORDS or w in own
                                                                         for w in between) or worded
                if len(named) != 1 or not linked_by or not opened or not short:
                    continue
            if norms[head] in lx.ROOMS_OF_A_BUILDING and not named:
                continue  # "the room above the market hall": a room of it, no landmark of its own
            if not named and between in (["to"], ["into"], ["onto"], ["over", "to"], ["across", "to"], ["down", "to"],
                                         ["up", "to"], ["back", "to"], ["out", "to"]) \
                    and any(norms[k] in lx.MOVING_VERBS | lx.BRING_VERBS
                                                       for k in range(max(0, head - 5), head)):
                continue  # "we're taking the walking ones to the osteria": where people are taken, no place by it
            if norms[head] in lx.ROUTE_HEADS and not named and len(between) == 1 \
                    and between[0] in ("below", "above", "beneath", "under", "behind", "beside", "near"):
                continue  # "I live on the lane below the bund": a way by it, no landmark it leads to
            if norms[head] in lx.ROUTE_HEADS and not named and between and set(between) <= lx.ROUTE_LINKS | {"around"}:
                ex.places[idx] = replace(anchor, status="reference", reason=f"the {toks.tokens[head].text} about it: no claim")
                continue  # "the streets round the bus station": the ways about it, no landmark
            said = self._relations.match_at(norms, linked[0]) if linked else None
            if not named and said is not None and not said[1][1] and any(rel.phrase == said[1][0] for rel in self.kb.relations) \
                    and norms[head] not in lx.UNNAMING_HEADS and not any(
                    _same_stem(norms[head], d) for n in related for d in self._description_words()[n]):
                # "a man trapped in a cottage behind St Mary's": a relation the phrase tables read, and nothing
                # stands so to it; another of its relations would be a guess
                ex.places[idx] = replace(anchor, status="reference",
                                         reason=f"reference point of the description headed by '{toks.tokens[head].text}'")
                continue
            kinds = (norms[head], *lx.PLACE_KIND_SYNONYMS.get(norms[head], ()))
            head_described = {n: v for n, v in related.items() if norms[head] not in lx.UNNAMING_HEADS
                              and any(_same_stem(k, d) for k in kinds for d in self._description_words()[n])}
            modifier = norms[head - 1] if head >= 2 and norms[head - 2] in lx.ARTICLES and norms[head - 1].isalpha() \
                and norms[head - 1] not in lx.FUNCTION_WORDS and (head - 1) not in blocked else None
            if not head_described and modifier is not None and norms[head] in lx.UNNAMING_HEADS:
                # ("the flat ground at the end of the swing bridge": an unnaming head with its adjective, both words of
                # the one related place's description, "flat dirt football pitch, the only level open ground")
                head_described = {n: v for n, v in related.items()
                                  if {norms[head], modifier} <= self._description_words()[n]}
            # ("the pub that's the local for caulkers' terrace": the one its description calls a pub)
            pool = named or head_described or related
            if not between and end > anchor.end_tok:
                # ("whatever the pump house draws its fuel from": not the place it ``pumps fuel out to``, a relation
                # whose name ends the other way round, with the anchor its subject)
                said = " ".join(norms[anchor.end_tok:end])
                pool = {n: v for n, v in pool.items() if not (n in phrases and _ends_opposite(said, phrases[n]) and any(
                    r.subject == anchor.landmark and r.object == n and r.phrase == phrases[n] for r in self.kb.relations))} \
                    or pool  # (a place named outright has no phrase of its own: nothing to read backwards)
            if len(pool) > 1 and any(w in _SUPPLY_VERBS for w in between[:3]) and "by" not in between:
                # "the building that feeds the tank": a verb of supply before the anchor, the anchor its object; only
                # a place that supplies the anchor (not one the anchor supplies)
                supplying = {n: v for n, v in pool.items() if any(
                    {r.subject, r.object} == {n, anchor.landmark} and _anchor_receives(r, anchor.landmark)
                    for r in self.kb.relations)}
                if supplying:
                    pool = supplying
            if not named and not head_described and norms[head] in _BUILDING_HEADS and len(pool) > 1:
                # "the building at the shore end of it": a building, not the float or the barge moored there
                built = {n: v for n, v in pool.items() if not self._never_a_building(n)}
                if built:
                    pool = built
            target = None
            linking = [norms[i] for i in range(head + 1, end) if not anchor.start_tok <= i < anchor.end_tok
                       and _weighty(norms[i]) and norms[i].isalpha() and norms[i] not in lx.FUNCTION_WORDS
                       and norms[i] not in lx.DESCRIPTION_STOPWORDS]
            described = {n: sum(any(_same_stem(w, d) for d in self._description_words()[n]) for w in linking)
                         for n in pool} if len(pool) > 1 else {}
            best = max(described.values(), default=0)
            outside = " " + " ".join(norms[i] for i in range(head + 1, end) if not anchor.start_tok <= i < anchor.end_tok) + " "
            worded = [n for n in pool if len(pool) > 1 and len(key := norm_phrase(phrases.get(n, "").replace("_", " "))) >= 2
                      and f" {' '.join(key)} " in outside]
            if len(pool) == 1:
                target = next(iter(pool))
            elif len(worded) == 1:
                # "the place that house looks down on": the words of one of the anchor's own relations, said whole
                # (not a description word: the "lookout" of the bluff's names for "looks")
                target = worded[0]
            elif best > 0 and list(described.values()).count(best) == 1:
                # "the building that heats the Thermae": the boiler house's description says it heats them
                target = next(n for n, v in described.items() if v == best)
            elif self.embedder is not None:
                # the linking words against the relation names, the anchor said as "it": names in both would
                # only measure how alike the places' names are ("the boat jetty" and "the boathouse")
                first = head
                while first > 0 and norms[first - 1] in lx.ARTICLES:
                    first -= 1
                text = " ".join("it" if i == a else toks.tokens[i].text for i in range(first, end)
                                if not a < i < anchor.end_tok)
                names = sorted(pool)
                vecs = self.embedder.embed([text] + [phrases.get(n, n) for n in names])
                sims = vecs[1:] @ vecs[0]
                order = np.argsort(-sims)
                if float(sims[order[0]] - sims[order[1]]) >= self.RELATED_MARGIN:
                    target = names[int(order[0])]
            ex.places[idx] = replace(anchor, status="reference",
                                     reason=f"reference point of the description headed by '{toks.tokens[head].text}'")
            if target is None:
                continue
            hs = head
            while hs > 0 and norms[hs - 1] in lx.DETERMINERS and (hs - 1) not in marker_tokens:
                hs -= 1
            via = related[target]
            ex.places.append(self._mention(toks, hs, end, target, via=f"{via} (related to {anchor.landmark})"))
            place_tokens.update(range(hs, end))
            if said_which is not None and said_which in ex.places:
                ex.places[ex.places.index(said_which)] = replace(said_which, status="reference",
                                                                 reason=f"says which '{anchor.text}'")
            found = True
        if found:  # ("The pool the header tank feeds ..., and whatever that pool drains into": the description just
            # resolved is what "that pool" takes up)
            spans = {(q.start_tok, q.end_tok) for q in ex.places}
            later = [q for q in self._pronoun_anchors(ex, toks, norms, place_tokens | marker_tokens | cue_tokens)
                     if q.reason.startswith(_THAT_MODIFIER) and (q.start_tok, q.end_tok) not in spans]
            ex.places.extend(later)
            pronoun_anchors.extend(later)
        for p in pronoun_anchors:
            if p in ex.places and not (p.reason.startswith(_THAT_MODIFIER) and p.status == "reference"
                                       and p.end_tok < len(norms) and self._relations.match_at(norms, p.end_tok) is not None):
                ex.places.remove(p)  # (a pronoun no description took up as its anchor; but "whatever that pool drains
                # into" may still be read from it, the relation said right after it)
            elif p in ex.places:
                found = True
        return found

    def _names_anchor(self, toks: Tokens, norms: tuple[str, ...], start: int, taken: Collection[int]) -> bool:
        """Does the clause from ``start`` (to its end, at most eight words) name a place, a pronoun or a relation?"""
        end = min(len(norms), start + 8)
        for j in range(start, end):
            if toks.clause_start[j]:
                break
            if j in taken or norms[j] in lx.PRONOUNS or self._relations.match_at(norms, j) is not None:
                return True
        return False

    def _pronoun_anchors(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...],
                         blocked: set[int]) -> list[PlaceMention]:
        """"the big ear's smouldering, and the hostel where its crews sleep": "its" in a relative clause anchors the
        description on the place named last before it, in an earlier clause. Each comes back as a reference
        mention of that place on the pronoun, for :meth:`_resolve_related` to take up or drop."""
        out = []
        for k in range(3, len(norms)):
            raw = toks.tokens[k].text.lower()
            adjective = k >= 4 and norms[k - 3] in lx.ARTICLES and norms[k - 2].isalpha() \
                and (norms[k - 2] not in lx.FUNCTION_WORDS or norms[k - 2] in _PLAIN_ADJECTIVES | {"old", "new"}) \
                and (k - 2) not in blocked and not toks.clause_start[k - 2]
            passive = k + 2 < len(norms) and norms[k + 1] in ("was", "is", "s", "been") \
                and (toks.tokens[k + 2].text.lower().endswith("ed") or norms[k + 2] in _IRREGULAR_PARTICIPLES)
            contact = raw == "it" and k + 1 < len(norms) and (norms[k - 2] in lx.ARTICLES or adjective) \
                and norms[k - 1] in self._place_nouns() and (toks.tokens[k + 1].text.lower().endswith(("s", "ed"))
                                                             and norms[k + 1] not in lx.COPULAS | lx.FUNCTION_WORDS
                                                             or passive) and not toks.clause_start[k + 1]
            # ("the trailer they refuel": "they", a plain verb, and a place said in the plural before)
            plural = raw == "they" and k + 1 < len(norms) and norms[k - 2] in lx.ARTICLES \
                and norms[k - 1] in self._place_nouns() and toks.tokens[k + 1].text.isalpha() \
                and norms[k + 1] not in lx.COPULAS | lx.FUNCTION_WORDS | lx.FILLERS and not toks.clause_start[k + 1] \
                and (k + 2 == len(norms) or toks.clause_start[k + 2] or norms[k + 2] in lx.COPULAS
                     or norms[k + 2] in lx.RELATION_ENDINGS)
            # ("the ride it powers": the place the one said before powers; "the old building it was built out from")
            # ("the boardwalk's gone under, and the plant at the far end of it is flooding": a place noun, then where
            # it stands, ending on "of it"; "a guy's hurt up on whatever drags the logs back out of it")
            ends = raw == "it" and norms[k - 1] == "of" and (k + 1 == len(norms) or toks.clause_start[k + 1]
                                                               or norms[k + 1] in lx.COPULAS) \
                and any((norms[h] in self._place_nouns() and norms[h - 1] in lx.ARTICLES
                         and norms[h + 1] in lx.PREPOSITIONS and norms[h + 1] != "of"
                         or norms[h] in lx.WHATEVER and _verb_like(toks.tokens[h + 1].text))
                        and not any(toks.clause_start[i] or i in blocked for i in range(h - 1, k))
                        for h in range(max(1, k - 7), k - 3))
            # ("the wooden tank is leaning, and whatever supplies it from the creek is washed out": "whatever", a verb)
            whatever_of = raw == "it" and norms[k - 2] in lx.WHATEVER and _verb_like(toks.tokens[k - 1].text)
            # ("the bit of land their causeway runs out to is the only dry spot left": a possessive opening a contact
            # clause right after a place noun)
            owned = raw in ("its", "their") and norms[k - 1] in self._place_nouns() | lx.GROUND_HEADS | {"land"} \
                and (norms[k - 2] in lx.ARTICLES or norms[k - 2] == "of" and norms[k - 4:k - 2] in (("the", "bit"),)) \
                and k + 2 < len(norms) and _verb_like(toks.tokens[k + 2].text) and not toks.clause_start[k + 1]
            # ("the cable line is down, and the station where it ends has half collapsed": "where", then the pronoun)
            where_it = raw == "it" and norms[k - 1] == "where" and norms[k - 3] in lx.ARTICLES \
                and norms[k - 2] in self._place_nouns() | lx.GENERIC_HEADS and k + 1 < len(norms) \
                and toks.tokens[k + 1].text.lower().endswith(("s", "ed")) and toks.tokens[k + 1].text.isalpha() \
                and norms[k + 1] not in lx.COPULAS | lx.FUNCTION_WORDS and not toks.clause_start[k + 1]
            contact = contact or ends or whatever_of or owned or plural or where_it
            if not contact and (raw not in ("its", "their") or norms[k - 1] not in ("where", "that", "which")) \
                    or k in blocked or toks.clause_start[k] or toks.clause_start[k - 1]:
                continue
            # (the clause may open its sentence on the head itself: "Flashover in the plant. Whatever feeds it the
            # electric -- that's alight too")
            last = _sole_antecedent(ex, toks, k - 1 if whatever_of or contact and not (ends or owned) else k - 2, k)
            if where_it:
                # (the place spoken of, not a reference point of its description: "the bridge over the lusk has lost
                # its handrail, and the field where it comes down on the other bank is under")
                last = max((p for p in ex.places if p.end_tok <= k - 3 and p.status == "active"
                            and toks.sentence_of[p.start_tok] == toks.sentence_of[k]
                            and not (p.start_tok >= 4 and norms[p.start_tok - 1] in lx.ARTICLES
                                     and norms[p.start_tok - 2] in lx.PREPOSITIONS
                                     and norms[p.start_tok - 3] not in lx.FUNCTION_WORDS
                                     and norms[p.start_tok - 4] in lx.ARTICLES)),
                           key=lambda p: p.end_tok, default=None)
            if last is None:
                continue  # (none, or another place said between: which one "its" means is not sure)
            if plural and (not last.text.lower().rstrip("'’").endswith("s") or any(
                    norms[j] in _PEOPLE_OR_GROUPS or norms[j] in lx.PERSON_SUBJECTS or norms[j] in lx.WORKER_PERSONS
                    for j in range(k) if toks.sentence_of[j] == toks.sentence_of[k])):
                continue  # ("the shed they built", "the marshals ... the trailer they use": people, not the place)
            out.append(self._mention(toks, k, k + 1, last.landmark, status="reference", reason=f"modifier of '{raw}'"))
        # "the building the laundry's built onto ... And the playground that building looks out over": "that" and
        # the head of a description said before take it up again
        heads = lx.GENERIC_HEADS | lx.DESCRIPTION_HEADS | self._place_nouns() | _WATER_HEADS
        # ("... whatever the inlet sends its flow to, and the next stage those tanks send their flow on to": the
        # head of the name of the place a description found, with "those")
        for k in range(3, len(norms) - 1):
            if norms[k - 1] not in ("that", "those") or k in blocked or (k - 1) in blocked or toks.clause_start[k] \
                    or norms[k] not in heads and norms[k - 1] == "that" or norms[k + 1] in lx.COPULAS \
                    or toks.clause_start[k + 1] or not toks.tokens[k + 1].text.isalpha():
                continue
            said = {p.landmark: p for p in ex.places if p.status == "active" and p.via is not None and p.end_tok <= k - 1
                    and (norm_phrase(p.text)[:2] == ("the", norms[k]) if norms[k - 1] == "that"
                         else name_words(p.landmark)[-1:] == (norms[k],))}
            if len(said) == 1:
                out.append(self._mention(toks, k - 1, k + 1, next(iter(said)), status="reference",
                                         reason=f"{_THAT_MODIFIER}{norms[k]}'"))
        for k in range(3, len(norms)):
            # "the yard the incline runs down from ... the sheds at the foot of that slope": "that" and a word of the
            # description of one place said before, closing a relation's object
            if norms[k - 1] != "that" or norms[k - 2] not in lx.PREPOSITIONS or k in blocked or (k - 1) in blocked \
                    or norms[k] in heads or not norms[k].isalpha() or norms[k] in lx.FUNCTION_WORDS \
                    or norms[k] in lx.WAY_NOUNS | lx.MEMBER_WORDS | {"side", "one", "lot", "bit", "place", "time"} \
                    or not (k + 1 == len(norms) or toks.clause_start[k + 1]):
                continue
            said = {p.landmark for p in ex.places if p.end_tok <= k - 2 and p.status in ("active", "reference")
                    and any(_same_stem(norms[k], d) for d in self._description_words()[p.landmark])}
            if len(said) == 1:
                out.append(self._mention(toks, k - 1, k + 1, next(iter(said)), status="reference",
                                         reason=f"{_THAT_MODIFIER}{norms[k]}'"))
        return out

    def _head_names_target(self, anchor: str, phrase: str, head_text: str, flipped: bool, head: str) -> bool:
        """"stones have come down onto the pad below it": the place the relation leads to from the place "it" means
        is one a name of which ends in the head noun (the landing pad), so a bare "below" is the KB's relation."""
        target = self._follow(anchor, phrase, head_text, inverse=flipped)[0]
        return target is not None and any(name_words(f)[-1:] == (head,)
                                          for f in self.kb.landmark_by_name[target].surface_forms)

    @staticmethod
    def _names_other_object(toks: Tokens, norms: tuple[str, ...], b: int) -> bool:
        """"people trapped behind the shelving": the relation has an object of its own, no place of the KB."""
        if b + 2 < len(norms) and not toks.clause_start[b] and norms[b] in ("at", "by", "outside") \
                and norms[b + 1] in lx.ARTICLES and not toks.clause_start[b + 1]:
            return True  # "the flooding is across the road at the bank": the place said after, not one related
        return b + 1 < len(norms) and not toks.clause_start[b] and norms[b] in lx.DETERMINERS \
            and norms[b + 1].isalpha() and norms[b + 1] not in lx.FILLERS and not toks.clause_start[b + 1]

    def _resolve_one(self, ex: Extraction, toks: Tokens, norms: tuple[str, ...], a: int, b: int, phrase: str,
                     flipped: bool, place_tokens: set[int], marker_tokens: set[int], inverse_pass: bool) -> None:
        if any(i in place_tokens for i in range(a, b)):
            return  # already inside a resolved description
        if b - a == 1 and (a == 0 or toks.sentence_start[a]) and toks.tokens[a].text[:1].isupper() \
                and norms[a] not in lx.NOT_VERBS and not norms[a].endswith(("s", "ed", "ing")):
            return  # "Open the lawn that the slope ... looks down on as a cooling station": an order, no ``opens onto``
        unit = next((i for i in range(a, b) if norms[i] in lx.MEASURE_UNITS), None)
        if unit is not None and unit > 0 and (norms[unit - 1] in ("a", "an", "one") or is_number(norms[unit - 1])
                                              or norms[unit - 1] in lx.NUMBER_WORDS):
            return  # "the caravans are standing in a foot of it": how deep, not "the foot of" a place
        anchor, anchor_end, pronoun = self._anchor_after(ex, norms, b, phrase)
        if anchor is not None and not pronoun and norms[a] in ("bottom", "top", "foot", "head") and any(
                q.landmark == anchor.landmark and q is not anchor and q.status == "active" and 0 <= a - q.end_tok <= 1
                for q in ex.places):
            return  # "at the slipway, bottom of the slip": a part of the place just named, said after it
        if anchor is not None and not pronoun and anchor.status == "active" and anchor.via is None \
                and set(norms[a:b]) & _COMPASS and not self._compass_relations:
            # "a landslip just east of the lift line": a bearing from a place the KB relates nothing to by compass;
            # the place only says where
            ex.places[ex.places.index(anchor)] = replace(anchor, status="reference",
                                                         reason="reference point of a compass bearing")
            ex.relation_tokens.update(range(a, b))
            return
        if anchor is not None and not pronoun and anchor.via is not None and not inverse_pass \
                and f" {phrase.replace('_', ' ')} " in f" {anchor.via.replace('_', ' ')} " \
                and anchor.start_tok <= b + 1 and a > 0 and norms[a - 1] in lx.WHATEVER | {"that", "which"} \
                and next((w for w in norms[anchor.start_tok:anchor.end_tok] if w not in lx.DETERMINERS), "") in {
                    norm(w) for w in phrase.replace("_", " ").split()}:
            # "whatever controls the points on the siding": the relation's verb said before its own noun phrase, one
            # description of the signal box, not the relation followed twice
            h = a - 1 if norms[a - 1] in lx.WHATEVER else a - 2 if a >= 2 and norms[a - 2] in lx.GENERIC_HEADS else None
            if h is not None:
                ex.places[ex.places.index(anchor)] = replace(anchor, start_tok=h, start=toks.tokens[h].start,
                                                             text=toks.text[toks.tokens[h].start:toks.tokens[anchor.end_tok - 1].end])
                place_tokens.update(range(h, anchor.end_tok))
                return
        if pronoun and anchor is not None and anchor.end_tok < a and ex.tokens.clause_start[anchor.end_tok] \
                and a - anchor.end_tok <= 4 and norms[anchor.end_tok] in lx.ARTICLES \
                and all(w in lx.DETERMINERS or w.isalpha() for w in norms[anchor.end_tok:a]):
            # "the chemist's, the one built onto it": an aside that says which place was meant; "it" is the place
            # said before it, the one the relation leads from to the place named
            earlier = [p for p in ex.places if p.end_tok <= anchor.start_tok and p.landmark != anchor.landmark
                       and p.status != "retracted"]
            if earlier:
                prev = max(earlier, key=lambda p: p.end_tok)
                if self._follow(prev.landmark, phrase, "", inverse=flipped)[0] == anchor.landmark:
                    anchor = prev
        implicit = norms[a:b] in lx.IMPLICIT_ANCHOR or "its" in norms[a:b] and (
            _shares_a_noun_with(phrase) or norms[b - 1] != "of" and _noun_of(phrase) is not None
            and phrase.split()[0] in _STATE_VERBS)
        if anchor is None and "our" in norms[a:b] and _shares_a_noun_with(phrase) and not inverse_pass:
            here = [p for p in ex.places if p.end_tok <= a and p.status != "retracted" and p.via is None and (
                self._speaker_here(norms, p) or any(norms[k:k + 2] in _CALLING_FROM
                                                    for k in range(max(0, p.start_tok - 3), p.start_tok - 1)))]
            if len({p.landmark for p in here}) == 1:
                # "I'm calling from the fishing village - the shed that shares our fence": the speaker's place
                anchor, anchor_end, pronoun = here[-1], b, True
        # ("the dock that's dug into its yard": whose yard, the place said before)
        # ("the hall that shares its vestry wall": whose wall, the place said before)
        if anchor is None and implicit and (b >= len(norms) or ex.tokens.clause_start[b]
                                                                    or not any(p.start_tok == b for p in ex.places)) \
                and not self._names_other_object(toks, norms, b):
            # "the building next door": the anchor is the place last spoken of (not the reference point of its
            # description: "the wall holding back the albufeira is cracking. And the shed at its foot")
            before = [p for p in ex.places if p.end_tok <= a and p.status != "retracted"]
            before = [p for p in before if p.status != "reference" or p.via is not None] or before
            if before and max(before, key=lambda p: p.end_tok).end_tok == a and not ex.tokens.clause_start[a] \
                    and norms[a:b] != ("next", "door") and not (
                        toks.tokens[a - 1].text.lower().replace("’", "'").endswith("'s")
                        and self._inverse_anchor(ex, norms, a)):  # (but "the building the park's behind")
                return  # "the problem's the flats across the way": the place named, where it is from the speaker
            if before and not self._inverse_anchor(ex, norms, a):
                anchor, anchor_end, pronoun = max(before, key=lambda p: p.end_tok), b, True
                earlier = [p for p in before if p.end_tok <= anchor.start_tok and p.landmark != anchor.landmark]
                if earlier and ex.tokens.clause_start[anchor.end_tok] and anchor.end_tok < a \
                        and all(w in lx.DETERMINERS or w.isalpha() for w in norms[anchor.end_tok:a]) \
                        and a - anchor.end_tok <= 5:
                    # "not the chippy, it's Rossi's, the ice cream place next door": an aside that says again
                    # which place was meant, next door to the one said before it
                    prev = max(earlier, key=lambda p: p.end_tok)
                    if self._follow(prev.landmark, phrase, "", inverse=flipped)[0] == anchor.landmark:
                        anchor = prev
        if anchor is not None and not pronoun and anchor.start_tok >= b and anchor.via is None \
                and any(d in toks.gaps[k] for k in range(b, anchor.start_tok + 1) for d in ("—", "–", "--", " - ")) \
                and (found := self._inverse_anchor(ex, norms, a, phrase)) is not None \
                and (found[2] is False and found[0].end_tok < a and found[1] < found[0].start_tok
                     or found[2] == "pronoun"):  # ("the row it carries the shift over from -- er, felt row --")
            # "the shop the chemist's is stuck onto -- the bread place --": the relation ends its clause; the place
            # after the pause says which place was meant, it anchors nothing
            anchor = None
        if anchor is None and any(p.reason.startswith("reference point for '") and b <= p.start_tok <= b + 5
                                  and not any(toks.clause_start[t] for t in range(b, p.start_tok + 1))
                                  for p in ex.places):
            return  # ("the plastic dryer tacked onto the side of the warehouse": read forwards already, the dryer named)
        if (anchor is None) != inverse_pass:
            return
        head_end = a
        if norms[max(0, a - 2) : a] in lx.RELATIVE_COPULAS and a >= 3:
            head_end = a - 2  # "the place that is behind the warehouse": the relative clause's head
        elif a >= 2 and toks.tokens[a - 1].text.lower().replace("’", "'") in ("that's", "thats", "which's"):
            head_end = a - 1
        elif a >= 2 and norms[a - 2] in lx.WHATEVER and norms[a - 1] in ("is", "was"):
            head_end = a - 1  # "across from whatever is behind the warehouse": "whatever" heads it
        elif a >= 3 and norms[a - 3] in lx.WHATEVER and norms[a - 2] in ("is", "was", "s") \
                and norms[a - 1] in ("standing", "sitting", "lying", "stood", "sat"):
            head_end = a - 2  # "whatever was standing underneath it": the posture says no more than "is"
        elif a >= 3 and norms[a - 3] in lx.WHATEVER and norms[a - 2] == "it" and norms[a - 1] in ("is", "s", "was"):
            head_end = a - 2  # "the dock or whatever it is that's moored off the harbour wall"
        elif a >= 3 and norms[a - 1] in ("that", "which") and (norms[a - 2] in lx.GENERIC_HEADS or (
                phrase in lx.RELATION_SYNONYMS and self._plain_head(norms, a - 2))):
            head_end = a - 1  # "the hall that faces onto it"; "the mound that overlooks pad one" (a synonym's verb)
        elif a >= 3 and norms[a - 1] in ("they", "we", "you") and pronoun and not toks.clause_start[a - 1] \
                and any(p.end_tok == a - 1 and p.status == "active" and p.via is None for p in ex.places):
            head_end = a - 1  # "the cages they tend from it": a named head, then a clause with its own subject
        elif (k := next((k for k in (1, 2) if a > k and all(w in _WHERE_ADVERBS for w in norms[a - k:a])
                         and not any(toks.clause_start[j] for j in range(a - k, a + 1))
                         and any(p.end_tok == a - k and p.status == "active" and p.via is None for p in ex.places)),
                        None)) is not None:
            head_end = a - k  # "the big pine out west by the quarry": a named head, then where it stands
        elif a >= 4 and norms[a - 1] in _TUCKED_PARTICLES and toks.tokens[a - 2].text.lower().endswith("ed") \
                and not any(toks.clause_start[j] for j in range(a - 3, a + 1)):
            # "the harbour that's tucked in behind the ferry dock", "the hut that is set back from the road": a
            # participle and its particle before the relation say no more than "is"
            if toks.tokens[a - 3].text.lower().replace("’", "'") in ("that's", "thats", "which's"):
                head_end = a - 3
            elif a >= 5 and norms[a - 4:a - 2] in lx.RELATIVE_COPULAS:
                head_end = a - 4
        head_place = next((p for p in ex.places if p.end_tok == head_end and p.status == "active"), None)
        if head_place is not None and (toks.sentence_start[head_end] or toks.clause_start[head_end] and pronoun):
            head_place = None  # "I'm at the warehouse. Behind it there's flooding": the place ends another clause
            # ("not the station, in front of it, the big open place": and so does a place before a comma)
        if pronoun and head_place is not None and anchor is head_place:
            # "the hall that faces onto them": the pronoun is not the head it follows, but the place before
            before = [p for p in ex.places if p.end_tok <= head_place.start_tok and p.status not in ("retracted", "reference")]
            if before:
                anchor = max(before, key=lambda p: p.end_tok)
        if head_place is not None and anchor is not None and (group := self._shared_head_group(norms, head_place)):
            # "the row of cabins that carries on from the A row": a head word several names share heads the
            # description; the relation, not a guess between the names, says which
            tgt = self._follow(anchor.landmark, phrase, "", inverse=flipped)[0] \
                or self._follow_by_meaning(anchor.landmark, toks, a, b, inverse=flipped)[0]
            if tgt is not None and tgt in group:
                ex.places.remove(head_place)
                place_tokens.difference_update(range(head_place.start_tok, head_place.end_tok))
                head_place = None
        if head_place is not None and anchor is not None and head_place.end_tok - head_place.start_tok == 1 \
                and toks.tokens[head_place.start_tok].text.lower() not in {
                    f.lower() for f in self.kb.landmark_by_name[head_place.landmark].surface_forms} \
                and (reached := self._follow(anchor.landmark, phrase, toks.tokens[head_place.start_tok].text,
                                             inverse=flipped)[0]) is not None \
                and (norms[head_place.start_tok] in lx.GENERIC_HEADS
                     or reached != head_place.landmark and head_place.landmark not in self._related_to(anchor.landmark)
                     and anchor.start_tok - b <= 2 and anchor.landmark != head_place.landmark
                     or anchor.landmark == head_place.landmark and reached != head_place.landmark
                     and anchor.start_tok - b <= 2 and not pronoun and anchor.via is None):
            # ("the ride at the foot of the castle", "castle ride" one of the castle's names: no place stands at the
            # foot of itself)
            # ("the trees hanging over the wellhouse": "trees", the head word of "the olive trees" only, and the
            # relation reaches the pine wood: the relation says which trees)
            # (kept when the relation leads nowhere from its anchor: "the bridge below it's been hit")
            # "the hall that faces onto it" is no mention of "halls of residence": only the plural's key
            # matched, and a generic noun heading a relation describes the place the relation reaches
            ex.places.remove(head_place)
            place_tokens.difference_update(range(head_place.start_tok, head_place.end_tok))
            head_place = None
        if anchor is not None and head_place is not None:
            # "the pharmacy next to the bakery": the place is named; the anchor is only a reference
            broken = anchor.via is not None and anchor.start_tok >= b and any(
                m in toks.gaps[i] for i in range(b, anchor.start_tok + 1) for m in ("--", "—", "–", "...", "…"))
            # ("the boxes the quay cranes feed -- er, the stack they feed": a repair, not the relation's anchor)
            denied = "not" in norms[max(0, head_place.start_tok - 4):head_place.start_tok] \
                and any(toks.clause_start[i] for i in range(head_place.end_tok, a + 1))
            # ("no, not by the lake, by our caravan": the place denied, then the one meant; no description)
            if broken and not pronoun and any(q.landmark == head_place.landmark and q is not head_place
                                              and q is not anchor and q.via is None
                                              and anchor.start_tok <= q.start_tok < anchor.end_tok for q in ex.places):
                # "the hangar opens onto... the thing the hangar opens onto": the speaker broke off and said it again
                # as a description; the place the clause began with is only its reference point
                idx = ex.places.index(head_place)
                ex.places[idx] = replace(head_place, status="reference", reason="restarted as a description's anchor")
                return
            if not pronoun and not broken and not denied:
                ex.relation_tokens.update(range(a, b))  # ("the loft leaning against the stack": no cue "leaning")
                idx = ex.places.index(anchor)
                ex.places[idx] = replace(anchor, status="reference", reason=f"reference point for '{head_place.text}'")
            return
        head_start, words = self._head_before(toks, norms, head_end, place_tokens, marker_tokens)
        if not words and a >= 3 and norms[a] in ("back", "front", "side", "end", "top") and norms[a - 1] == "the" \
                and norms[a - 2] in ("onto", "into", "to", "on") and _verb_like(toks.tokens[a - 3].text) \
                and not toks.clause_start[a - 2]:
            return  # "the little shed they built onto the back of the distillery": a verb's own words, read whole
        head_text = " ".join(toks.tokens[j].text for j in range(head_start, head_end))
        generic = bool(words) and any(w in lx.GENERIC_HEADS for w in words[-2:]) \
            and self._cues.match_at(norms, head_end - 1) is None
        after_article = head_start > 0 and (norms[head_start - 1] in lx.ARTICLES or head_start > 1 and norms[head_start - 2]
                                            in lx.ARTICLES and norms[head_start - 1] in lx.DETERMINERS | lx.NAME_ADJECTIVES)
        # ("the old workings overlooking the holiday park": an adjective between)
        if not after_article and words and len(words) <= 2 and (head_start == 0 or toks.sentence_start[head_start]
                                                                  and toks.tokens[head_start].text[:1].isupper()) and not any(
                    w in lx.LAY_PERSONS or w in lx.WORKER_PERSONS or w in lx.PERSON_NOUNS or w in _PEOPLE_WORDS
                    or w in lx.ANIMAL_WORDS or w in lx.VEHICLE_WORDS or w in lx.FLOATING_THINGS for w in words) \
                and any(words[-1] in ws for ws in self._description_words().values()):
            # (a word the KB's places are described by)
            after_article = True  # a log's "Platform overlooking the breeder pens is cleared": the article left off
        if not generic and words and len(words) <= 3 and after_article \
                and (norms[a:b] not in lx.AMBIGUOUS_HEADLESS or (words[-1],) in self._shared_tails()
                     or words[-1] in _SEGMENT_HEADS  # ("cracked along the stretch by the pump house")
                     or pronoun and anchor is not None and self._head_names_target(anchor.landmark, phrase, head_text,
                                                                                   flipped, words[-1])):
            # ("the platform underneath us": a word several names end in heads a description even before
            # a bare "underneath")
            # "the stretch seaward of the fish market": any plain noun after an article heads a description
            closed = lx.PREPOSITIONS | lx.COPULAS | lx.FILLERS | lx.PRONOUNS | lx.INVERSE_VERBS
            if len(words) == 1 and words[0] in self._name_word_owners:
                closed = closed - {words[0]}  # "the stand that butts up against it": a word names end in, a noun here
            # (nor a noun a cue ends on: "person in the water downstream of the weir" is in the water there)
            generic = all(w.isalpha() and w not in closed for w in words) and len(words[-1]) >= 3 \
                and not any((m := self._cues.match_at(norms, j)) is not None and m[0] > head_start
                            and not (m[0] > head_end and b - a >= 4) for j in range(max(0, head_start - 3), head_end))
            # (but a cue that runs on into a long relation phrase is none: "the water lapping at the back doors of")
        if generic and norms[a] == "off" and any(w in ("fell", "fallen", "jumped", "slipped", "fall") for w in words) \
                and any(w in lx.LAY_PERSONS or w in lx.PERSON_NOUNS or w in lx.WORKER_PERSONS for w in words):
            generic = False  # "A kid fell off the end of the jetty": a person and where they fell, no place's head
        if generic and anchor is None and any(p.end_tok == a and p.start_tok < head_end
                                              and p.reason.startswith(_THAT_MODIFIER) for p in ex.places):
            generic = False  # "whatever that pool drains into": "that pool" is the anchor, read backwards
        if not generic and anchor is not None and words and words[-1] in lx.STOREY_WORDS | {"rooms", "room", "storeys"} \
                and self._follow(anchor.landmark, phrase, head_text, inverse=flipped)[0] is not None:
            generic = True  # "people trapped on the floor above the corn exchange", where the KB puts a place above it
        if anchor is None and head_place is not None and head_place.start_tok > 1 \
                and norms[head_place.start_tok - 1] in ("that", "which") and self._plain_head(norms, head_place.start_tok - 2):
            generic = False  # "the road that gully empties onto": "that" opens a relative clause, the gully its subject
        if anchor is None:
            # inverse: "the one (that) the garage sits behind", "the row it shares a wall with"
            if generic and not (words and words[-1] in ("it", "they", "theyre", "we", "i")):
                here = [p for p in self._speaker_places(ex, norms) if p.end_tok <= head_start]
                if len(here) == 1 and b < len(norms) and (norms[b] in lx.COPULAS | {"has", "have"}) \
                        and head_start > 0 and norms[head_start - 1] in lx.ARTICLES:
                    # "I'm on the steps of St Mary's and the place directly opposite is going up": a relation left
                    # without its object is said from where the speaker is
                    target, via = self._follow(here[0].landmark, phrase, head_text, inverse=flipped)
                    if target is not None and target != here[0].landmark:
                        ex.places.append(self._mention(toks, head_start - 1, b, target,
                                                       via=f"{via} (from where the speaker is)"))
                        place_tokens.update(range(head_start - 1, b))
                        idx = ex.places.index(here[0])
                        ex.places[idx] = replace(here[0], status="reference", reason=f"reference point: {via}")
                return
            if b - a == 1 and b < len(norms) and norms[b] in ("is", "s", "has", "was") \
                    and toks.tokens[a].text.lower() in ("face", "front", "side", "back"):
                return  # "the quarry face is coming away": a part of the place, no verb of a relation
            k = b
            while k < len(norms) and norms[k] in lx.ARTICLES and not toks.clause_start[k]:
                k += 1
            if k > b and any(p.start_tok == k for p in ex.places):
                return  # "the park across from the flats": the relation has its object, it is not left stranded
            found = self._inverse_anchor(ex, norms, a, phrase)
            if found is None:
                return
            anchor_p, hs, named = found
            head_p = next((p for p in ex.places if p.start_tok == hs and p.status == "active"), None) \
                if named is True else None
            if head_p is not None and head_p.end_tok - head_p.start_tok == 1 and hs > 0 and norms[hs - 1] == "the" \
                    and norms[hs:hs + 1] not in {name_words(f) for f in self.kb.landmark_by_name[head_p.landmark].surface_forms}:
                target, via = self._follow(anchor_p.landmark, phrase, toks.tokens[hs].text, inverse=not flipped)
                if target is not None and target != head_p.landmark \
                        and self._follow(anchor_p.landmark, phrase, "", inverse=not flipped)[0] == target \
                        and norms[hs] in self._description_words().get(target, ()) \
                        and (anchor_p.landmark, head_p.landmark) not in self._related_pairs:
                    # "The bank the pumping station is built into": one word of a name ("the far bank") heads a
                    # description whose relation reaches another place
                    ex.places.remove(head_p)
                    ex.places[ex.places.index(anchor_p)] = replace(anchor_p, status="reference",
                                                                   reason=f"reference point: {via}")
                    ex.places.append(self._mention(toks, hs - 1, b, target, via=via))
                    place_tokens.update(range(hs - 1, b))
                    ex.relation_tokens.update(range(a, b))
                    return
            if head_p is not None and head_p.landmark == anchor_p.landmark and head_p.via is None \
                    and head_p.end_tok - head_p.start_tok == 1 and anchor_p.via is None \
                    and not set(norms[head_p.start_tok:head_p.end_tok]) & set(norms[anchor_p.start_tok:anchor_p.end_tok]) \
                    and all(toks.gaps[k].strip() == "" for k in range(head_p.end_tok, anchor_p.start_tok + 1)):
                # "the tank the big whites pump up to", where "the tanks" is also a name of the big whites: a place is
                # not described by its own relation to itself; the head word names the other end (one word, said
                # straight on, no word of the anchor's: not a restart, "the barn, the hay barn the ...")
                target, via = self._follow(anchor_p.landmark, phrase, toks.tokens[hs].text, inverse=not flipped)
                if target is not None and target != anchor_p.landmark \
                        and norms[head_p.start_tok] in self._description_words().get(target, ()):
                    # (the head word names the other end too: "the top tank" is the reservoir's)
                    ex.places.remove(head_p)
                    ex.places[ex.places.index(anchor_p)] = replace(anchor_p, status="reference",
                                                                   reason=f"reference point: {via}")
                    start = hs - 1 if hs > 0 and norms[hs - 1] in lx.DETERMINERS else hs
                    ex.places.append(self._mention(toks, start, b, target, via=via))
                    place_tokens.update(range(start, b))
                    ex.relation_tokens.update(range(a, b))
                    return
            if named is True:
                ex.places[ex.places.index(anchor_p)] = replace(anchor_p, status="reference",
                                                               reason="reference point of a named place")
                ex.relation_tokens.update(range(a, b))
                return
            head_words = " ".join(toks.tokens[j].text for j in range(hs, min(anchor_p.start_tok, a)))
            target, via = self._follow(anchor_p.landmark, phrase, head_words, inverse=not flipped)
            if named == "pronoun" \
                    and self._follow(anchor_p.landmark, phrase, head_words, inverse=not flipped, _loose=True)[0] is None:
                # "Follow the ditch the electric pump empties into, right up to the building it feeds": "it" is the
                # place the clause was about, not the subject of the clause that described it, when only that one
                # stands in the relation as named
                main = max((p for p in ex.places if p.end_tok <= anchor_p.start_tok and p.status == "active"
                            and p.landmark != anchor_p.landmark), key=lambda p: p.end_tok, default=None)
                if main is not None and toks.sentence_of[main.start_tok] == toks.sentence_of[anchor_p.start_tok] \
                        and (anchor_p.status == "reference" or norms[main.end_tok:anchor_p.start_tok] == ("the",)):
                    exact = self._follow(main.landmark, phrase, head_words, inverse=not flipped, _loose=True)
                    if exact[0] is not None:
                        target, via = exact
            if target is None and named == "pronoun":
                # "the crane on the quay. the shed it looms over": the pronoun takes up the place before the last
                # one when only that one stands in the relation
                for other in sorted((p for p in ex.places if p.end_tok <= hs and p is not anchor_p
                                     and p.status != "retracted" and p.landmark != anchor_p.landmark),
                                    key=lambda p: -p.end_tok)[:3]:
                    target, via = self._follow(other.landmark, phrase, head_words, inverse=not flipped)
                    if target is not None:
                        break
            if target is None:
                target, via = self._follow_by_meaning(anchor_p.landmark, toks, a, b, inverse=not flipped)
            if target is None:
                if named is False and norms[hs:anchor_p.start_tok][-2:-1] == ("one",) \
                        and sum(self._relation_matches(rel, phrase) and anchor_p.landmark in (rel.subject, rel.object)
                                for rel in self.kb.relations) >= 2:
                    # "the other one the brine pits undermine": two places stand so to it, the words say which
                    # elsewhere; the anchor is only a reference point
                    ex.places[ex.places.index(anchor_p)] = replace(
                        anchor_p, status="reference", reason=f"reference point of an unresolved '{phrase}' description")
                return
            if named != "pronoun":
                ex.places[ex.places.index(anchor_p)] = replace(anchor_p, status="reference",
                                                               reason=f"reference point: {via}")
            head_p = next((p for p in ex.places if p.end_tok == hs and p.status == "active" and p.via is None), None)
            if head_p is not None and target in self._shared_head_group(norms, head_p):
                # "the block that takes its overflow": a head word several names share ("the block" is the seg,
                # "e block" a block too) heads the description; the relation says which
                ex.places.remove(head_p)
                hs = head_p.start_tok
                while hs > 0 and norms[hs - 1] in lx.DETERMINERS:
                    hs -= 1
            new = self._mention(toks, hs, b, target, via=via)
            ex.places.append(new)
            place_tokens.update(range(hs, b))
            return
        if not generic:
            if pronoun and toks.sentence_start[a] and norms[anchor_end - 1] in ("me", "us") \
                    and not self._cue_between(norms, a, next((t for t in range(anchor_end, len(norms))
                                                              if toks.sentence_start[t]), len(norms))):
                return  # "It's the bank. Across the road from me.": where the place just named is, not another
            # a cue (or nothing) before the relation: "man down across the street from the fire station"
            if norms[a:a + 2] == ("at", "the") and b > a + 2 and norms[a + 2] in lx.LOCATIVE_PARTS and not any(
                    rel.phrase.startswith("at the") and _link_stems(norms[a + 2]) & {
                        st for v in rel.phrase.split()[2:] for st in _link_stems(v)}
                    for rel in self.kb.relations):
                # "a bloke lying unconscious at the foot of the ops tower", "pile-up at the front of stage one":
                # where it is, unless the KB names a relation so ("at_the_foot_of")
                return
            at = a if norms[a] in lx.POSITION_VERBS else head_end - len(words)
            if (norms[a] in lx.POSITION_VERBS or words and set(words) <= lx.POSITION_VERBS) and at > 0 \
                    and self._cue_before(toks, norms, at) and (at - 1) not in place_tokens:
                return  # "Vapour cloud sitting over the wagon park": where the danger is, not a description
            participle = head_end > 1 and norms[head_end - 1].endswith(("ed", "ing")) \
                and self._is_cue_end(norms, head_end - 1)  # "Live conductor exposed behind the medical centre"
            cue_end = head_end
            while cue_end > 0 and head_end - cue_end < 2 and norms[cue_end - 1] in lx.SENTENCE_ADVERBS:
                cue_end -= 1  # "our casualty's actually round the back of the hardware store"
            if cue_end < head_end and cue_end > 0 and self._is_cue_end(norms, cue_end):
                words = []
            s0 = a
            while s0 > 0 and not toks.sentence_start[s0]:
                s0 -= 1
            appositive = toks.clause_start[a] and any(s0 <= q.start_tok and q.end_tok <= a for q in ex.places)
            bare = norms[a + 1:b] if b - a >= 2 and norms[a] in lx.RELATION_ADVERBS and not appositive else norms[a:b]
            # ("a runner down right under the finish arch", "it's right under the snake bridge now"; not "flare-up on
            # the black hill, right above the frog pool": a phrase of its own that says where the place before it is)
            if bare in (("by",), ("near",)) and anchor.status == "active" and anchor.via is None:
                s1 = max((t for t in range(a + 1) if toks.clause_start[t]), default=0)
                cue_end = max((h[0] for k in range(s1, a) if (h := self._cues.match_at(norms, k)) is not None
                               and h[0] <= a), default=None)
                if cue_end is not None and all(w in ("down", "up", "along", "out", "over", "just", "right", "round")
                                               for w in norms[cue_end:a]) \
                        and any(p.status == "active" and p.via is None and s1 <= p.start_tok and p.end_tok < cue_end
                                for p in ex.places):
                    # "the shore track's under water down by the factory": where along the place the clause claims
                    # something of; the place after "by" only says where
                    ex.places[ex.places.index(anchor)] = replace(anchor, status="reference",
                                                                 reason="reference point: where along the place claimed")
                    return
            if bare in lx.AMBIGUOUS_HEADLESS or (words and not self._is_cue_end(norms, head_end) and not participle
                                                       and not set(words) <= lx.HEADLESS_OK
                                                       and words[-1] not in lx.LAY_PERSONS | {"folk", "folks"}):
                # ("there's folk over the road from the brewery coughing": people placed by the relation; "a runner
                # down right under the finish arch": where he lies)
                return
            head_start, head_text = a, ""
        target, via = self._follow(anchor.landmark, phrase, head_text, inverse=flipped)
        own = self._places.match_at(norms, head_start) if pronoun and head_text else None
        if own is not None and own[0] == head_end and own[1] in self.kb.landmark_by_name and target is not None \
                and own[1] != target and own[1] != anchor.landmark \
                and not set(norms[head_start:head_end]) & set(name_words(target)):
            # "diesel at the far end of the lorry yard, and the scales at the entrance to it": the head names the
            # weighbridge, so "it" is the place said before that the weighbridge stands so to (the lorry yard)
            for other in sorted(ex.places, key=lambda p: -p.end_tok):
                if other.end_tok <= head_start and other.landmark != anchor.landmark and other.status != "retracted":
                    hit = self._follow(other.landmark, phrase, head_text, inverse=flipped)
                    if hit[0] == own[1]:
                        anchor, (target, via) = other, hit
                        break
            else:
                if not any(p.start_tok <= head_start < p.end_tok for p in ex.places):
                    ex.places.append(self._mention(toks, head_start, head_end, own[1]))
                    place_tokens.update(range(head_start, head_end))
                return  # the place named, and no place said before that stands so to it
        if target is not None and generic and words:
            said = toks.tokens[head_end - 1].text.lower()
            target, via = self._head_named_neighbour(anchor.landmark, words[-1], target, via,
                                                     plural=said.endswith("s") and not words[-1].endswith("s"))
        if target is None and pronoun and generic and any(
                w.isalpha() and w not in lx.PREPOSITIONS and w not in lx.RELATION_ADVERBS and w not in lx.SPATIAL_WORDS
                for w in norms[a:b]):
            # "the wall the top road runs along - the passage buried in it": the pronoun takes up the place before
            # the last one when only that one stands in the relation (as for inverse descriptions; a verb of the
            # relation said, not only where: "the torrent's right over it")
            for other in sorted((p for p in ex.places if p.end_tok <= anchor.start_tok
                                 and (p.status == "active" or p.status == "reference" and p.reason.startswith(
                                     ("reference point", "subject of a clause")))
                                 and p.landmark != anchor.landmark and p.via is None
                                 and toks.sentence_of[p.start_tok] >= toks.sentence_of[a] - 1),
                                key=lambda p: -p.end_tok)[:2]:
                target, via = self._follow(other.landmark, phrase, head_text, inverse=flipped)
                if target is not None and target != anchor.landmark:
                    anchor = other
                    break
                target, via = None, None
        if target is None and (generic or pronoun):
            target, via = self._follow_by_meaning(anchor.landmark, toks, a, b, inverse=flipped)
        if target is None and not pronoun and words and head_text:
            # "the terraces below the barn ...": a relation that leads nowhere from its anchor, and a head word that
            # names one of the places the KB relates to it (``tractor barn sits_at_the_head_of lower terraces``)
            target, via = self._related_by_head(anchor.landmark, words[-1])
        if not pronoun:
            idx = ex.places.index(anchor)
            if target is None:
                if not generic and self._cue_before(ex.tokens, norms, a):
                    return  # "a vapour cloud sitting over the reactor building": where the danger is, not a description
                if norms[a:a + 2] == ("at", "the") and b > a + 2 and norms[a + 2] in lx.LOCATIVE_PARTS:
                    return  # "a man lying at the foot of the water tower": where he lies, when nothing lies below it
                if norms[a:a + 2] == ("in", "the") and norms[a + 2:a + 4] in (("middle", "of"), ("centre", "of")) \
                        and any((h := self._cues.match_at(norms, k)) is not None and h[1][1] != "neutral"
                                for k in range(max((t for t in range(a + 1) if toks.sentence_start[t]), default=0), a)):
                    return  # "person in the water, mid-loch, right out in the middle of the sea loch": where, when the
                    # KB's "stands in the middle of" leads nowhere from it
                if norms[a:b] in (("inside",), ("inside", "of"), ("within",)) and generic \
                        or norms[a:b] in (("just", "inside"), ("right", "inside"), ("well", "inside")) \
                        or norms[a:b] == ("inside",) and a > 0 and norms[a - 1] in ("just", "from", "right", "well"):
                    return  # "trapped under a fallen stall inside the corn exchange": in it, when nothing is built into it
                    # ("Guide speaking from just inside the grotto")
                if anchor.end_tok < len(norms) and norms[anchor.end_tok] in lx.ENTRANCE_PARTS:
                    return  # "a person lying on the ground by the bus station doors": at its doors
                k = a - 1
                while k >= 0 and norms[k] in lx.FILLERS:
                    k -= 1
                if k >= 0 and (norms[k] in ("were", "im") and "'" in toks.tokens[k].text.replace("’", "'")
                               or norms[k] in ("re", "m") or norms[k - 1:k + 1] in (("we", "are"), ("i", "am"))):
                    return  # "we're, uh, alongside the east quay with two survivors": where the crew is
                if norms[b - 1] == "of" and set(norms[a:b]) & (lx.PART_NOUNS | lx.LOCATIVE_PARTS | lx.STOREY_WORDS):
                    return  # "acid spill on the ground floor of the chemistry annexe": a part of it, so in it
                if norms[b - 1] == "of" and {"back", "front", "side"} & set(norms[a:b]) \
                        and (norms[a] in ("out", "from", "through") or next(
                            (w for w in reversed(norms[max(0, a - 3):a]) if w not in lx.ARTICLES | lx.FILLERS), "")
                             in ("out", "from", "through")):
                    return  # "flames coming out the back of the granary": out of its back, so at it
                h = a - 1
                while h >= 0 and (norms[h].endswith("ed") or norms[h] in lx.FILLERS) and a - h <= 2:
                    h -= 1
                if h >= 0 and norms[h] in lx.FLOATING_THINGS | lx.VEHICLE_WORDS:
                    return  # "a car swept against the Mitre Arch": where a thing is, no description of a place
                if h >= 0 and norms[h] in lx.LAY_PERSONS | lx.WORKER_PERSONS | {"she", "he", "they", "someone", "somebody"}:
                    return  # "a nurse climbed up onto the big wall": where a person went, no description of a place
                if any(norms[i] in lx.LAY_PERSONS | lx.WORKER_PERSONS and norms[i + 1:i + 2] in (("on",), ("in",), ("at",))
                       and toks.tokens[i].text.lower().endswith("s") for i in range(max(0, a - 1), b - 1)):
                    return  # "one of the ring builders on the back-up": where people are, no description of a place
                if any(norms[i] in lx.MOVING_VERBS and i > 0 and norms[i - 1] in ("been", "being", "was", "were", "get", "got")
                       for i in range(a, b)):
                    return  # "the school group have been moved across to the tea room": where people were taken
                if anchor.via is not None and b < len(norms) and norms[b] in ("that", "which"):
                    return  # "the rock face that looks down over the holiday park": the place resolved already; the
                    # word before its "that" ("face", as in "facing") is its head, no relation of its own
                if a > 0 and norms[a - 1] in lx.ROOMS_OF_A_BUILDING:
                    return  # "the room above the market hall": a room of it, when nothing lies above it
                if a > 0 and norms[a - 1] in lx.ROUTE_HEADS | {"ground", "floor", "surface", "tarmac", "concrete", "earth"} \
                        and norms[a] in ("under", "underneath", "beneath", "below"):
                    return  # "road under the scales is gone": the ground it stands on, when nothing lies below it
                    # ("I live on the lane below the bund. There's a long crack along the top of it")
                if any(norms[i] in ("heading", "headed") and norms[i + 1:i + 2] in (
                        ("to",), ("for",), ("towards",), ("toward",), ("back",), ("down",), ("up",), ("over",), ("out",), ("off",))
                       for i in range(a, b)):
                    return  # "we're heading to the rope line": where people go, not ``sits at the head of``
                at = next((i for i in range(a, b) if norms[i] in ("at", "on", "along", "by")), a)
                if set(norms[at:b]) & {"edge", "end", "side", "corner"} and set(norms[at:b]) <= {
                        "at", "on", "along", "by", "the", "edge", "end", "side", "corner", "of", "far", "near", "shore",
                        "north", "south", "east", "west", "top", "bottom", "back", "front"} \
                        and at - a <= 2 and all(norms[i].isalpha() and norms[i] not in self._place_nouns()
                                                for i in range(a, at)) \
                        and (a == 0 or norms[a - 1] not in self._place_nouns()):
                    return  # "a pickup went through at the edge of the ice lot": a part of the place, in it, where no
                    # place before it is described
                r = a - 1
                while r >= 0 and (norms[r] in lx.FILLERS or norms[r] in lx.ARTICLES) and a - r <= 4:
                    r -= 1
                if b - a == 1 and r >= 0 and r < a - 1 and norms[r] == norms[a] and norms[a] in lx.PREPOSITIONS:
                    return  # "fuel slick on the, erm, on the long acre": the preposition said again, no description
                named_words = set(norm_phrase(phrase))
                if b - a >= 3 and any(
                        (m := self._cues.match_at(norms, i)) is not None and m[1][0]
                        and self.kb.category_by_name[m[1][0]].role == Role.UNDESIRABLE
                        and not set(norms[i:m[0]]) & named_words for i in range(a, b)):
                    return  # "we've got rocks peeling off the quarry face": a danger said of the place, found by a
                    # word of ``spills its rocks onto``, no description of another
                ex.places[idx] = replace(anchor, status="reference",
                                         reason=f"reference point of an unresolved '{phrase}' description")
                return
            ex.places[idx] = replace(anchor, status="reference", reason=f"reference point: {via}")
        elif target is None:
            return
        det_start = head_start
        while det_start > 0 and norms[det_start - 1] in lx.DETERMINERS and not toks.clause_start[det_start] \
                and head_text and (det_start - 1) not in marker_tokens:
            det_start -= 1
        w = next((k for k in range(det_start - 1, max(-1, det_start - 3), -1) if norms[k] == "whose"), None)
        if w is not None and w >= 2 and norms[w - 2] in lx.ARTICLES and (w - 1) not in place_tokens \
                and all(norms[k].isalpha() and k not in place_tokens for k in range(w + 1, det_start)):
            # "the one whose cooling floor the stowage barn leans on": the floor read as the relation's own noun
            # ("leans on the cooling floor of"), the place is the one whose floor it is
            det_start = w - 2
        new = self._mention(toks, det_start, anchor_end, target, via=via)
        ex.places.append(new)
        place_tokens.update(range(det_start, anchor_end))
        if pronoun and anchor in ex.places and anchor.status == "active" and anchor.end_tok <= det_start \
                and toks.sentence_of[anchor.start_tok] == toks.sentence_of[det_start]:
            # "Below the chapel — the building directly downhill of it — fire": a place said only to
            # lead to the one described (nothing said of it before the description, and no predicate
            # shared with it: "the town hall and the building next to it are both clear") is its
            # reference point
            lo = max(t for t in range(0, anchor.start_tok + 1) if toks.sentence_start[t])
            between = norms[anchor.end_tok:det_start]
            shared = {"both", "all", "each", "either"} & set(norms[anchor_end:anchor_end + 4])
            speaker = norms[anchor_end - 1] in ("us", "me", "here")  # "From our church steps I can see the place
            # directly across from us: ...": where the speaker stands, whatever is said between
            inner = norms[a:b][-1:] in (("in",), ("inside",), ("within",)) and any(
                d in toks.gaps[det_start] for d in ("—", "–", "--", " - ")) and not {"too", "also", "and"} & set(
                norms[anchor_end:anchor_end + 3])  # ("from inside the wall ... - the passage buried in it, that's where")
            if not shared and (speaker or inner or all(w in lx.FILLERS or w in lx.DETERMINERS or w in ("and", "so")
                                              or i in marker_tokens for i, w in enumerate(between, start=anchor.end_tok))) \
                    and (inner or not any(self._cues.match_at(norms, i) is not None for i in range(lo, det_start)
                                          if not anchor.start_tok <= i < anchor.end_tok)):
                ex.places[ex.places.index(anchor)] = replace(anchor, status="reference",
                                                             reason=f"reference point: {via}")

    def _follow_by_meaning(self, anchor: str, toks: Tokens, a: int, b: int,
                           inverse: bool, sole: bool = False) -> tuple[str | None, str | None]:
        """The words said for a relation found none of the KB's from ``anchor``: of the relations ``anchor``
        takes part in, on the side the description reads, the one MiniLM puts closest to the words said
        ("the row of cabins that carries on from the A row" for ``cabin row B runs_on_from cabin row A``),
        if close enough and clearly closer than the next, by the bounds ``_follow_link`` reads unlisted links by.
        (``_follow_link`` ranks every relation form of the KB and would take "carries overflow from" here.)
        With ``sole``, where the anchor has only one relation at all, on the side read, and the words have a verb,
        that relation needs only ``OPEN_RELATION_SOLE_MIN_SIM`` ("where the tide gate drains to")."""
        if self.embedder is None:
            return None, None
        words = [t.text for t in toks.tokens[a:b]]
        rel_start = max((i + 1 for i, w in enumerate(words) if w.lower() in ("that", "which", "where")), default=0)
        said = " ".join(words[rel_start:])  # ("of cabins that carries on from": the relation's own words)
        spatial = lx.PREPOSITIONS | set(lx.RELATION_ADVERBS) | lx.SPATIAL_WORDS | lx.PRONOUNS | lx.FILLERS
        if not any(len(w) >= 4 and w.isalpha() and w.lower() not in spatial for w in words[rel_start:]):
            return None, None  # ("right under it": only where, no verb for MiniLM to tell relations apart by)
        # (not a relation whose name ends the other way round: "whatever the pump house draws its fuel from" is no
        # place it ``pumps fuel out to``)
        cands = [(rel.subject if not inverse else rel.object, rel) for rel in self.kb.relations
                 if (rel.object if not inverse else rel.subject) == anchor and not _ends_opposite(said.lower(), rel.phrase)]
        if not cands:
            return None, None
        vecs = self.embedder.embed([said] + [rel.phrase for _, rel in cands])
        sims = vecs[1:] @ vecs[0]
        top = int(np.argmax(sims))
        best = float(sims[top])
        target, rel = cands[top]
        # the closest relation that leads somewhere else
        runner = max((float(v) for (t, _), v in zip(cands, sims, strict=True) if t != target), default=0.0)
        # ("two kids stuck out where the tide gate drains to": the one relation the anchor has at all, the right way
        # round, is the one a description reading it so can mean)
        sole = sole and any(_verb_like(w) and w.lower() not in lx.COPULAS for w in words[rel_start:])
        floor = self.OPEN_RELATION_SOLE_MIN_SIM if sole and len(cands) == 1 and sum(
            anchor in (r.subject, r.object) for r in self.kb.relations) == 1 else self.OPEN_RELATION_MIN_SIM
        if best - runner >= self.OPEN_RELATION_CLEAR_MARGIN and rel.phrase not in _TABLE_RELATIONS:
            # (only a relation no phrase table reads: "across the street from it" is no "behind", however close)
            floor = min(floor, self.OPEN_RELATION_CLEAR_MIN_SIM)
        if best < floor or best - runner < self.OPEN_RELATION_MARGIN:
            return None, None
        return target, f"{rel.subject} {rel.relation} {rel.object} (by meaning {best:.2f})"

    def _head_named_neighbour(self, anchor: str, head: str, target: str, via: str | None,
                              plural: bool = False) -> tuple[str, str | None]:
        """"the stack that takes the vent off the cracker", where the words read as ``sulphur recovery unit takes the
        sour gas off cat cracker``: a head noun that is a word of one landmark's names only ("flare stack"), and not a
        word of the place the relation reached (its names or description), names the place meant, when that landmark
        stands in a KB relation with the anchor. Heads that name no kind ("place", "building") name no one place; other
        generic heads only as the head of a landmark's own name ("the tower ..." for "transfer tower"). A head word
        several names end in names the one of them the KB relates to the anchor ("the tunnel powered off ...")."""
        owners = self._name_word_owners.get(head)
        if head in lx.UNNAMING_HEADS or not owners or target in owners:
            return target, via
        if head in lx.GENERIC_HEADS and not any(name_words(o)[-1:] == (head,) for o in owners):
            return target, via  # (a generic head names a place only as the head of its own name: "transfer tower")
        if len(owners) > 1:
            # ("the tunnel powered off the yard ...": of the two tunnels, the one the KB relates to the anchor)
            owners = {o for o in owners if o != anchor and (anchor, o) in self._related_pairs
                      and name_words(o)[-1:] == (head,)}  # (the head of its own name, not a word of an alias)
            if len(owners) != 1:
                return target, via
        other = next(iter(owners))
        if plural and not any(w.endswith("s") and norm_phrase(w) == (head,)
                              for f in self.kb.landmark_by_name[other].surface_forms for w in f.lower().split()):
            return target, via  # "the trees at the bottom of the slope": many, not the one "lightning tree"
        if other == anchor or (anchor, other) not in self._related_pairs \
                or head in self._description_words().get(target, ()):
            return target, via
        rel = next(r for r in self.kb.relations if {r.subject, r.object} == {anchor, other})
        return other, f"{rel.subject} {rel.relation} {rel.object} (named by its head, '{head}')"

    def _description_words(self) -> dict[str, set[str]]:
        """Per landmark, the content words of its description, name and aliases."""
        if getattr(self, "_desc_cache", None) is None:
            self._desc_cache = {
                lm.name: {w for w in norm_phrase(" ".join([lm.description, *lm.surface_forms]))
                          if w not in lx.DESCRIPTION_STOPWORDS and not w.isdigit()}
                for lm in self.kb.landmarks}
        return self._desc_cache

    def _resolve_descriptions(self, ex: Extraction) -> None:
        """"the building with the two engine bays", "the five-storey building on the south road":
        a noun phrase that names no landmark but shares two or more content words with exactly one
        landmark's description (more than with any other) refers to that landmark."""
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        place_tokens = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        marker_tokens = {i for a, b, _ in ex.markers for i in range(a, b)}
        relation_spans = [(a, b) for a, b, _ in self._relations.find_all(norms, place_tokens)]
        relation_starts = {a for a, _ in relation_spans}
        # ("the ship the hydra pad lifts its blocks off": the relation's own noun heads no description)
        inside_relation = {i for a, b in relation_spans if b - a >= 3 for i in range(a + 1, b)}
        cue_tokens = self._claim_cue_tokens(norms, place_tokens)
        stop = place_tokens | marker_tokens | cue_tokens | inside_relation
        desc = self._description_words()
        closed = lx.PREPOSITIONS | lx.COPULAS | lx.FILLERS | lx.PRONOUNS | lx.COORDINATORS | lx.NEGATORS
        i = 0
        while i < len(norms):
            if norms[i] not in lx.DESCRIPTION_HEADS or i in stop or norms[i] == "room" and not (
                    norms[i + 1:i + 2] in (("where",), ("that",), ("which",))
                    or norms[i + 1:i + 3] in _THERE_ADVERBS and norms[i + 3:i + 4] == ("where",)) \
                    or norms[i] == "one" and toks.tokens[i].text[:1] == "O" and i > 0 and toks.tokens[i - 1].text[:1].isupper():
                i += 1  # ("Control, Cave Rescue One at the bear pit": a call sign, no description)
                continue
            s_ = i
            while s_ > 0 and i - s_ < 4 and not toks.clause_start[s_] and (s_ - 1) not in stop \
                    and norms[s_ - 1] not in closed and norms[s_ - 1] not in lx.DETERMINERS:
                s_ -= 1
            has_det = s_ > 0 and norms[s_ - 1] in lx.DETERMINERS and not toks.clause_start[s_]
            if not (has_det or toks.clause_start[s_]) or ("one", "of") in (norms[s_ - 3:s_ - 1], norms[s_ - 2:s_]):
                i += 1  # ("one of the anchor blocks on the east bank": one of many things, no landmark)
                continue
            if i > s_ and (norms[i - 1] in lx.NUMBER_WORDS or is_number(norms[i - 1])) \
                    and toks.tokens[i].text.lower().endswith("s") and norms[i + 1:i + 2] == ("of",):
                i += 1  # ("the top three rows of benches": things counted, parts of something; no landmark)
                continue
            e = i + 1
            if norms[e:e + 2] in _THERE_ADVERBS and norms[e + 2:e + 3] == ("where",) and not toks.clause_start[e]:
                e += 2  # "the room down there where the teams lock their rifles away"
            if e < len(norms) and e not in relation_starts and norms[e] in lx.DESCRIPTION_LINKS \
                    and not toks.clause_start[e]:
                e += 1
                while e < len(norms) and e - i < 9 and not toks.clause_start[e] and e not in stop \
                        and e not in relation_starts and (norms[e] not in lx.COPULAS - {"s"} or norms[e - 1] == "with") \
                        and (norms[e] not in lx.COORDINATORS or norms[e] == "and" and e + 1 < len(norms)
                             and norms[e + 1] not in lx.DETERMINERS | closed and e + 1 not in stop
                             and not toks.clause_start[e + 1]) \
                        and not (  # ("the barn with all the hay in"; "where they keep the oxygen and acetylene bottles")
                            e + 1 < len(norms) and norms[e + 1] in lx.PREPOSITIONS and norms[e - 1] not in ("that", "which")
                            and toks.tokens[e].text.lower().endswith("s") and self._keyword_relation(norms[e]) is not None):
                    e += 1  # (not into a relation's verb: "the canal that the building with the big brick chimney pumps
                    # into")
                # "the hut where they keep the explosives is on fire": a danger word as what the place keeps, the
                # object of the description's own verb, is a word of the description too (the cue stays a cue)
                if e < len(norms) and e in cue_tokens and e not in place_tokens | marker_tokens | inside_relation \
                        and norms[i + 1] == "where" and norms[e - 1] in lx.DETERMINERS \
                        and e - 1 > i + 2 and any(norms[e] in ws for ws in desc.values()) \
                        and (e + 1 >= len(norms) or toks.clause_start[e + 1] or norms[e + 1] in lx.COPULAS):
                    e += 1
            words = {w for w in norms[s_:e] if w not in lx.DESCRIPTION_STOPWORDS and w not in closed}
            scores = sorted(((len(words & ws), name) for name, ws in desc.items()), reverse=True)
            owner = getattr(self, "_heads", {}).get(norms[s_]) if s_ == i - 1 and e == i + 1 else None
            if owner is not None and scores and scores[0][1] != owner and norms[i] in lx.UNNAMING_HEADS \
                    and norms[i] not in desc[owner] and not toks.tokens[s_].text.lower().endswith(("'s", "’s", "s'")) \
                    and scores[0][0] == 2 and norms[s_] in desc[scores[0][1]]:
                # "School hall is our dry muster": the school's own hall, not the institute whose description says
                # it has a hall "beside the school"
                a = s_ - 1 if has_det else s_
                ex.places.append(self._mention(toks, a, e, owner))
                stop.update(range(a, e))
                i = e
                continue
            head_of = {name for name, ws in desc.items() if norms[i] in ws} if norms[i] not in lx.DESCRIPTION_STOPWORDS else set()
            if scores and head_of and scores[0][1] not in head_of and not (
                    norms[i] in lx.UNNAMING_HEADS | _SHED_HEADS and scores[0][0] >= 2
                    and all(n < scores[0][0] for n, name in scores if name in head_of)):
                # (but a generic head says less than two words another place's description has and no shed's has:
                # "the shed where they keep the oxygen and acetylene bottles")
                i += 1  # "the pub that watches over whatever lets the water down": a pub, whatever else it shares
                continue
            if scores and norms[i] not in lx.UNNAMING_HEADS | _SHED_HEADS | lx.DESCRIPTION_STOPWORDS \
                    and norms[i] not in desc[scores[0][1]]:
                i += 1  # "the pub where the drainage board lads ...": the depot's words, but no pub
                continue
            if scores and scores[0][0] >= 2 and len(scores) > 1 and scores[0][0] == scores[1][0] and e > i + 2:
                # "the shed where they keep the snowcats": of the places whose descriptions say as much, the one
                # whose own name the head word is in (not the helipad "on the snowcat shed's roof")
                named = [sc for sc in scores if sc[0] == scores[0][0] and any(
                    norms[i] in name_words(f) for f in self.kb.landmark_by_name[sc[1]].surface_forms)]
                if len(named) == 1:
                    scores = named
            if scores and scores[0][0] >= 2 and i + 2 < len(norms) and norms[i + 1] in ("that", "which") \
                    and not any(toks.clause_start[t] for t in range(i + 1, min(len(norms), i + 5))) \
                    and any(self._keyword_relation(norms[t]) is not None for t in range(i + 3, min(len(norms), i + 6))) \
                    and any(p.status == "active" and i + 4 <= p.start_tok <= i + 9 and not any(
                        toks.clause_start[t] for t in range(i + 1, p.start_tok + 1)) for p in ex.places):
                i += 1  # "the fenced yard that runs the fans in the long tunnel": its clause says a relation of the KB
                continue  # (``keeps_the_fans_running_in``) to a place named after it, for the relations to read
            if scores and scores[0][0] >= 2 and (len(scores) == 1 or scores[0][0] > scores[1][0]):
                a = s_ - 1 if has_det else s_
                while e - 1 > i and norms[e - 1] in lx.DETERMINERS:
                    e -= 1
                ex.places.append(self._mention(toks, a, e, scores[0][1], via=f"description of {scores[0][1]}"))
                stop.update(range(a, e))
                for idx, p in enumerate(ex.places):
                    if p.status == "active" and p.via is None and e <= p.start_tok <= e + 3 \
                            and toks.sentence_of[p.start_tok] == toks.sentence_of[e - 1] \
                            and (p.start_tok <= e + 1 and all(norms[t] in lx.DETERMINERS for t in range(e, p.start_tok))
                                 or norms[e] in lx.PREPOSITIONS and all(norms[t] in lx.DETERMINERS for t in range(e + 1, p.start_tok))
                                 and not any(toks.clause_start[t] for t in range(e, p.start_tok + 1))):
                        # ("the shed where they mix the clay before it goes to the drying sheds": where it goes)
                        # "the station with the crash road out to the two seven end": the place ends the description
                        ex.places[idx] = replace(p, status="reference", reason=f"part of the description of {scores[0][1]}")
                        for jdx, q in enumerate(ex.places):
                            if q.status == "active" and q.via is None and _says_which_after(toks, norms, p.end_tok, q):
                                # ("the shed that cooks for the huts at the bottom of the top garden": which huts)
                                ex.places[jdx] = replace(q, status="reference",
                                                         reason=f"part of the description of {scores[0][1]}")
                i = e
                continue
            i += 1

    def _resolve_itself(self, ex: Extraction) -> None:
        """"the shop itself has a guy with burns": a head noun with "itself" names the landmark an
        earlier description used as its reference point."""
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        for i in range(2, len(norms)):
            if norms[i] not in ("itself", "themselve") or any(p.start_tok < i <= p.end_tok for p in ex.places):
                continue
            if norms[i - 1] not in lx.GENERIC_HEADS or norms[i - 2] not in lx.DETERMINERS:
                continue
            anchors = [p for p in ex.places if p.end_tok <= i - 2 and p.status in ("reference", "retracted")
                       and p.reason.startswith("reference point")]  # (also of a description taken back: "the lagoons
            # below Vic Terrace -- no, scratch that, he's fallen down a cellar in the terrace itself")
            if not anchors:
                continue
            anchor = max(anchors, key=lambda p: p.end_tok)
            ex.places.append(self._mention(toks, i - 2, i + 1, anchor.landmark))

    def _apposed_part(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"Smoke coming out from under the stadium, the room down there where the teams lock their rifles away":
        a place said after "under" (or "behind", "beneath" ...) and then, after a comma, a description of a place
        the KB relates to it: the description says which place is meant, the first only where it is."""
        toks = ex.tokens
        for idx, p in enumerate(ex.places):
            k = p.start_tok - 1
            while k >= 0 and norms[k] in lx.DETERMINERS:
                k -= 1
            if p.status != "active" or p.via is not None or k < 0 or norms[k] not in _UNDER_WORDS \
                    or p.end_tok >= len(norms) or not toks.clause_start[p.end_tok]:
                continue
            q = next((q for q in ex.places if q.start_tok == p.end_tok and q.status == "active"
                      and (q.via or "").startswith("description of") and q.landmark != p.landmark
                      and (q.landmark, p.landmark) in self._related_pairs), None)
            if q is not None:
                ex.places[idx] = replace(p, status="reference", reason=f"where '{q.text}' is")

    def _resolve_between(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"stranded riders hanging between the valley station and the Gratalm": the one landmark the KB relates
        to both ends (the gondola that runs up from the one and tops out at the other) is the place meant, and the
        ends are only where it is. Not where a place is named just before ("the footbridge between ...")."""
        toks = ex.tokens

        def place_at(i: int) -> PlaceMention | None:
            while i < len(norms) and norms[i] in lx.DETERMINERS:
                i += 1
            return next((p for p in ex.places if p.start_tok == i and p.status == "active" and p.via is None), None)

        for k in range(1, len(norms) - 3):
            if norms[k] != "between":
                continue
            named = next((p for p in ex.places if p.end_tok == k and p.status == "active"), None)
            if named is None and any(p.end_tok == k or p.start_tok <= k < p.end_tok for p in ex.places):
                continue
            a = place_at(k + 1)
            if a is None or norms[a.end_tok:a.end_tok + 1] not in (("and",), ("&",)):
                continue
            b = place_at(a.end_tok + 1)
            if b is None or b.landmark == a.landmark or toks.clause_start[a.end_tok]:
                continue
            if named is not None:
                # "slush on the ice road between the launch and shack town": the stretch of the place named before,
                # the two ends only where it is
                if named.landmark not in (a.landmark, b.landmark):
                    for idx, p in enumerate(ex.places):
                        if p is a or p is b:
                            ex.places[idx] = replace(p, status="reference", reason=f"an end of the stretch of {named.landmark}")
                continue
            linked = {lm.name for lm in self.kb.landmarks if lm.name not in (a.landmark, b.landmark)
                      and (lm.name, a.landmark) in self._related_pairs and (lm.name, b.landmark) in self._related_pairs}
            if len(linked) != 1:
                continue
            name = next(iter(linked))
            for idx, p in enumerate(ex.places):
                if p is a or p is b:
                    ex.places[idx] = replace(p, status="reference", reason=f"an end of {name}, said to lie between")
            ex.places.append(self._mention(toks, k, b.end_tok, name, via=f"{name} links {a.landmark} and {b.landmark}"))

    def _resolve_possessives(self, ex: Extraction) -> None:
        """"the church's opposite number", "the health centre's neighbour", "its twin"."""
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        said = [(a, b) for a, b, _ in self._relations.find_all(norms)
                if norms[a] in ("that", "which") or a > 0 and norms[a - 1] in ("that", "which", "s", "thats")]
        for k in range(1, len(norms)):
            if toks.tokens[k - 1].text.lower() not in ("its", "their") or any(p.start_tok <= k < p.end_tok for p in ex.places):
                continue
            if any(a < k - 1 and b > k for a, b in said):
                continue  # "the dock that's dug into its yard": a relative clause's relation, said of the place before
            if any((hit := self._cues.match_at(norms, j)) is not None and hit[0] > k for j in range(max(0, k - 4), k)):
                continue  # "the canal has come over its banks": a cue's own words, no place
            # a noun phrase of its own ("..., its twin, ...", "in their sister hangar"), not an object ("sharing its wall")
            if toks.clause_start[k - 1] or (k >= 2 and norms[k - 2] in lx.PREPOSITIONS):
                before = [p for p in ex.places if p.end_tok < k]
                if before:
                    self._possessive_keyword(ex, -1, max(before, key=lambda p: p.end_tok), k)
        for idx, p in enumerate(list(ex.places)):
            last = toks.tokens[p.end_tok - 1].text.lower()
            plural = last.endswith("s") and p.end_tok < len(norms) and toks.gaps[p.end_tok].startswith(("'", "’"))
            if p.status != "active" or not (last.endswith(("'s", "’s")) or plural):  # ("the flats' opposite number")
                continue
            for key, phrase in sorted(lx.POSSESSIVE_RELATIONS.items(), key=lambda kv: -len(kv[0])):
                if norms[p.end_tok : p.end_tok + len(key)] == key:
                    target, via = self._follow(p.landmark, phrase, "")
                    if target is None:
                        break
                    ex.places[idx] = replace(p, status="reference", reason=f"reference point: {via}")
                    ex.places.append(self._mention(toks, p.start_tok, p.end_tok + len(key), target, via=via))
                    break
            else:
                if self._possessive_keyword(ex, idx, p, p.end_tok):
                    continue
                if self._possessive_tail(ex, idx, p, norms):
                    continue
                # "the church's across-the-road neighbour": a relation phrase used as a modifier
                hit = self._relations.match_at(norms, p.end_tok) if p.end_tok < len(norms) else None
                if hit is None or hit[0] >= len(norms) or norms[hit[0]] not in lx.GENERIC_HEADS:
                    continue
                phrase, flipped = hit[1]
                target, via = self._follow(p.landmark, phrase, toks.tokens[hit[0]].text, inverse=flipped)
                if target is None:
                    continue
                ex.places[idx] = replace(p, status="reference", reason=f"reference point: {via}")
                ex.places.append(self._mention(toks, p.start_tok, hit[0] + 1, target, via=via))

    def _possessive_tail(self, ex: Extraction, idx: int, p: PlaceMention, norms: tuple[str, ...]) -> bool:
        """"the café's car park": after a possessive, the last words of landmarks' names ("car park": upper and
        lower car park), of which the KB relates exactly one to the owner."""
        for n in (3, 2, 1):
            key = norms[p.end_tok:p.end_tok + n]
            if len(key) < n or any(q.start_tok < p.end_tok + n and q.end_tok > p.end_tok for q in ex.places):
                continue
            owners = self._tail_owners.get(key, set())
            if len(owners) < (1 if n == 1 else 2):
                continue
            if n == 1 and (key[0] in lx.GENERIC_HEADS | lx.STOREY_WORDS | lx.PART_NOUNS or len(key[0]) < 4
                           or p.end_tok + 1 < len(norms) and not ex.tokens.clause_start[p.end_tok + 1]
                           and norms[p.end_tok + 1] in self._place_nouns()):
                continue  # ("the smelter's flue": one head word; not "the mill's roof", nor "the mill's flue pipe")
            related = {other for rel in self.kb.relations for other in (rel.subject, rel.object)
                       if p.landmark in (rel.subject, rel.object) and other != p.landmark and other in owners}
            if len(related) != 1:
                return False
            target = next(iter(related))
            ex.places[idx] = replace(p, status="reference", reason=f"reference point: the {' '.join(key)} of it")
            ex.places.append(self._mention(ex.tokens, p.start_tok, p.end_tok + n, target,
                                           via=f"{_OWNED} {' '.join(key)} of {p.landmark}"))
            return True
        return False

    def _possessive_keyword(self, ex: Extraction, idx: int, p: PlaceMention, k: int) -> bool:
        """"hangar two's sister hangar", "its twin": a possessive, then a noun that names a KB relation."""
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        if k >= len(norms):
            return False
        word = toks.tokens[k].text.lower()
        participle = word.endswith(("ed", "ing")) or word in lx.IRREGULAR_PARTICIPLES  # "the Co-op's built against"
        hit = self._keyword_relation(word) if norms[k].isalpha() and not participle else None
        if hit is None:
            return False
        verb = hit[0].split()[0]
        if hit[1] == "active" and _link_stems(word, synonyms=False) & _link_stems(verb, synonyms=False):
            return False  # "hangar two's open": the relation's verb, not a noun for the other place
        if any(norms[k] in name_words(f) for f in self.kb.landmark_by_name[p.landmark].surface_forms):
            return False  # "the yorkies' camp": the head of the place's own name ("yorkist camp"), not ``is_camped_at``
        end = k + 1
        if end < len(norms) and (norms[end] in lx.GENERIC_HEADS or norms[end] == p.text.split()[0].lower()) \
                and not toks.clause_start[end]:
            end += 1  # "sister hangar"
        elif end < len(norms) and not toks.clause_start[end] and norms[end].isalpha() and len(norms[end]) >= 4 \
                and norms[end] not in lx.FUNCTION_WORDS and not norms[end].endswith(("ing", "ed")) \
                and norms[end] not in self._single_cue_words and self._cues.match_at(norms, end) is None \
                and norms[end] not in lx.COPULAS | lx.ANAPHOR_VERBS and norms[end] not in self._place_nouns() \
                and norms[end] in self._description_words()[p.landmark]:
            return False  # "through its overflow basin": a thing of its own, the word only a modifier
        target, via = self._follow(p.landmark, hit[0], " ".join(norms[k:end]), inverse=hit[1] == "passive")
        if target is None or target == p.landmark:
            return False
        start = p.start_tok if idx >= 0 else k - 1
        v = start - 1
        if v >= 3 and norms[v] == "the" and norms[v - 1] in ("up", "out", "off", "down", "over"):
            v -= 1  # ("patches up the assault course's casualties")
        if v >= 2 and norms[v] in ("up", "out", "off", "down", "over") and norms[v - 1].isalpha():
            v -= 1  # ("whatever patches up the assault course's casualties": the verb's particle)
        if idx >= 0 and v >= 1 and hit[1] == "active" and _link_stems(norms[v]) & _link_stems(verb):
            # "the oast that dries cherry hill's hops": the head and its relative clause name the place, so that a
            # relation said of it ("the barn that leans on the oast that ...") anchors on the whole
            h = v - 1 if norms[v - 1] in ("that", "which") else v
            if h >= 2 and norms[h - 1].isalpha() and norms[h - 1] not in lx.FUNCTION_WORDS \
                    and norms[h - 2] in lx.ARTICLES and not any(q.start_tok <= h - 1 < q.end_tok for q in ex.places):
                start = h - 2
            elif norms[v - 1] in lx.WHATEVER and not any(q.start_tok <= v - 1 < q.end_tok for q in ex.places):
                start = v - 1  # "the casevac pad for whatever patches up the assault course's casualties"
        if idx >= 0:
            ex.places[idx] = replace(p, status="reference", reason=f"reference point: {via}")
        ex.places.append(self._mention(toks, start, end, target, via=via))
        return True

    def _cue_at(self, norms: tuple[str, ...], a: int) -> bool:
        """Is the place at token ``a`` the object of a cue's preposition ("frostbite case at the berghaus")?"""
        j = a
        while j > 0 and norms[j - 1] in lx.DETERMINERS:
            j -= 1
        if j == 0 or norms[j - 1] not in ("at", "in", "on", "inside"):
            return False
        return any((hit := self._cues.match_at(norms, k)) is not None and hit[0] == j - 1 and hit[1][1] != "neutral"
                   for k in range(max(0, j - 5), j - 1))

    def _cue_before(self, toks: Tokens, norms: tuple[str, ...], a: int) -> bool:
        """Does a cue end at most four words before token ``a``, in its clause ("a vapour cloud is still |sitting
        over")?"""
        for k in range(max(0, a - 8), a):
            hit = self._cues.match_at(norms, k)
            if hit is not None and a - 4 <= hit[0] <= a and hit[1][1] != "neutral" \
                    and not any(toks.clause_start[i] for i in range(hit[0], a + 1)):
                return True
        return False

    def _is_cue_end(self, norms: tuple[str, ...], end: int) -> bool:
        """Does a cue phrase end right before token ``end`` (allowing prepositions in between)?"""
        j = end
        while j > 0 and norms[j - 1] in lx.PREPOSITIONS | lx.DETERMINERS | lx.FILLERS and end - j < 3:
            j -= 1
        for k in range(max(0, j - 4), j):
            hit = self._cues.match_at(norms, k)
            if hit is not None and hit[0] == j:
                return True
        return False

    def _anchor_after(self, ex: Extraction, norms: tuple[str, ...], b: int,
                      phrase: str = "") -> tuple[PlaceMention | None, int, bool]:
        """The landmark a relation phrase points at: a place right after it, or a pronoun.

        ``phrase`` is the KB relation read: a noun of its name may follow a possessive ("the place that backs
        onto its lot" for ``backs onto the lot of``)."""
        own_nouns = {w for w in norm_phrase(phrase)[1:] if len(w) >= 3 and w not in lx.FUNCTION_WORDS}
        j = b
        if norms[j : j + 1] in (("the",), ("its",)) and j + 2 < len(norms) and norms[j + 1] in lx.PART_NOUNS \
                and norms[j + 2] == "of" and (norms[j] == "the" or any(p.end_tok <= b for p in ex.places)):
            j += 3  # "built onto the side of the mill": the part of the anchor
            b = j
        elif norms[j:j + 2] == ("top", "of") and phrase and "top" not in norm_phrase(phrase):
            j = b = j + 2  # "the block stacked on top of them" for ``stacked_on``
        if _past_approach(norms, j) > j and not any(p.start_tok == j + 1 for p in ex.places):
            j = b = _past_approach(norms, j)  # "the post guarding the way into reception": the anchor after
        # "the shop attached to it's got a live wire": "it's" right after the relation is "it has", the pronoun
        its = b < len(norms) and norms[b] == "its" and any(q in ex.tokens.tokens[b].text for q in ("'", "’"))
        while j < len(norms) and (norms[j] in lx.DETERMINERS or norms[j] in lx.FILLERS or norms[j] in ("my", "your")
                                  or j > b and _after_same(norms, j + 1)
                                  or j > b and norms[j - 1] in lx.ARTICLES | _PLAIN_ADJECTIVES
                                  and norms[j] in _PLAIN_ADJECTIVES)\
                and j - b < 4:  # ("moored off the big stone harbour wall")
            if norms[j] in ("that", "this") and (j + 1 >= len(norms) or ex.tokens.clause_start[j + 1]
                                                 or norms[j + 1] in lx.COPULAS
                                                 or norms[j + 1] in ("there", "theres", "someone", "somebody")):
                # ("in the building across from that there's a woman on a balcony")
                break  # "the building across from that has people trapped": the pronoun is the anchor
            if j == b and its:
                break
            j += 1
        place = next((p for p in ex.places if p.start_tok == j or (p.start_tok >= b and p.start_tok <= j and p.status == "active")), None)
        if place is not None and place.status == "reference":
            # ("below the café's car park": the place the possessive names, not its owner)
            place = next((p for p in ex.places if p.start_tok == place.start_tok and p.status == "active"
                          and (p.via or "").startswith(_OWNED) and p.end_tok > place.end_tok), place)
        if place is not None and any(ex.tokens.sentence_start[t] or ";" in ex.tokens.gaps[t]
                                     for t in range(b, place.start_tok + 1)):
            place = None  # "diesel all over the road. Toll plaza is ...": a relation does not reach into the next sentence
            # (nor past a semicolon: "the field it backs onto; the camp itself has smoke")
        elif place is not None and norms[b - 1] in ("road", "lane", "street", "way"):
            # "across the lane the surgery's windows are blown in": said where it is ("across the lane" from the
            # speaker); without "from" the place after it is what is described, not the anchor
            place = None
        elif place is not None and b < len(norms) and "," in ex.tokens.gaps[b] and norms[b] not in lx.FILLERS:
            # "the place the chemist's is built on the side of, the bread place": past the comma the speaker
            # names the place described, not the relation's anchor
            place = None
        if place is not None and place.status in ("active", "retracted", "negated"):
            if place.status == "active" or place.start_tok == j:
                return place, place.end_tok, False
        if j > b and norms[j - 1] in ("its", "their") and j < len(norms) and (norms[j] in (
                "side", "back", "wall", "rear", "front", "end", "corner", "gable", "left", "right", "north", "south", "east",
                "west") or norms[j] in own_nouns):
            # "the shop attached to its side": the possessive points back to the last place (the place spoken of,
            # not the reference point of its description: "the wall holding back the albufeira ... the shed at its foot")
            before = [p for p in ex.places if p.end_tok <= b]
            before = [p for p in before if p.status != "reference"] or before
            if before:
                return max(before, key=lambda p: p.end_tok), j + 1, True
        if j > b and norms[j - 1] in ("that", "this", "same") and j < len(norms) and norms[j] in lx.UNNAMING_HEADS \
                and not any(ex.tokens.clause_start[t] for t in range(b, j)) \
                and (j + 1 >= len(norms) or ex.tokens.clause_start[j + 1] or norms[j + 1] in lx.COPULAS | lx.COORDINATORS):
            # "smoke in the building behind the hardware store ... someone trapped in the shop in front of that
            # building": the place just spoken of
            before = [p for p in ex.places if p.end_tok <= b and p.status == "active"]
            if self._awaits_description(ex, norms, before, b):
                return None, b, False  # (the place spoken of is a description not read yet: it waits for it)
            if before:
                return max(before, key=lambda p: p.end_tok), j + 1, True
        if j > b and norms[j - 1] == "same" and j < len(norms) and norms[j].isalpha() \
                and not any(ex.tokens.clause_start[t] for t in range(b, j + 1)):
            # "a second one in the pile stacked up beside that same track": the place of that name said before
            same = [p for p in ex.places if p.end_tok <= b and p.status != "retracted" and any(
                name_words(f)[-1:] == (norms[j],) for f in self.kb.landmark_by_name[p.landmark].surface_forms)]
            if same:
                return max(same, key=lambda p: p.end_tok), j + 1, True
        its = its and j == b
        if j < len(norms) and (norms[j] in ("it", "them", "that", "there") + lx.SPEAKER_ANCHORS or its) \
                and not ex.tokens.clause_start[j]:
            if norms[j] in ("that", "there") and j + 1 < len(norms) and not ex.tokens.clause_start[j + 1] \
                    and norms[j + 1] not in lx.COPULAS \
                    and not (norms[j] == "that" and norms[j + 1] in ("there", "theres", "someone", "somebody")):
                return None, b, False
            before = [p for p in ex.places if p.end_tok <= b]
            if norms[j] in lx.SPEAKER_ANCHORS:  # the speaker's own position ("across the street from here", "from mine")
                before = [p for p in before if p.reason.startswith("in transit") or self._speaker_at(norms, p)] \
                    or before
            # "the park behind the warehouse. Across the street from it": the pronoun takes up the place
            # spoken of, not the reference point of its description
            before = [p for p in before if p.status != "reference"] or before
            # (nor the reference point of a description taken back: "the place that serves the stage door of the
            # concert hall— no, sorry, in the room next to that": the place described, taken back)
            before = [p for p in before if p.reason != "reference point of a retracted place"] or before
            # (nor one said as the object of a relation after a named place, its description not read yet: "cracks
            # across the ramp that runs down from the hangar ... a mechanic fell on the pad next to it")
            before = [p for p in before if not self._named_relation_object(ex, norms, p)] or before
            if self._awaits_description(ex, norms, before, b):
                # "The tank standing over the baler shed has split, and the shed underneath it is flooding": a place
                # said as another's reference point, that one not yet read, and a new clause on "and"; the pronoun
                # waits for it (not in an aside, "the terraces above lavender row, the ones that step down to it", nor
                # after a repair, whose "it" keeps the anchor: "the room under the exam hall — sorry, not under,
                # across from it")
                return None, b, False
            if norms[j] == "them":  # "the arches Del's gym is on the end of -- and the yard that backs onto them"
                before = [p for p in before if p.text.lower().endswith("s")
                          and not p.text.lower().replace("’", "'").endswith("'s")] or before
            if before:
                ante = max(before, key=lambda p: p.end_tok)
                def stands(name: str) -> bool:  # (by the relation's own name: `_relation_matches`, which takes
                    # the synonym groups too, moves two control reports, so it is not used here yet)
                    return any(r.phrase == phrase and name in (r.subject, r.object) for r in self.kb.relations)
                if phrase and norms[j] == "it" and ante.via is not None and not stands(ante.landmark):
                    # "the area outside the main gate is our muster station, and ... the hut just inside it": the
                    # place spoken of is none of the relation's; its reference point, said with it, is
                    ref = [p for p in ex.places if p.end_tok <= b and p.status == "reference" and p.via is None
                           and ante.start_tok <= p.start_tok < ante.end_tok and stands(p.landmark)]
                    if len(ref) == 1:
                        return ref[0], j + 1, True
                return ante, j + 1, True
        return None, b, False

    @staticmethod
    def _addressed_list(norms: tuple[str, ...], segs: list[tuple[int, int]], k: int,
                        seg_places: dict[int, list[PlaceMention]]) -> bool:
        """Is segment ``k`` (or the list it belongs to) the people a call addresses, by where they are, before it
        tells them where to go: "Passengers in the waiting cabin, the cafe and the car park, please make your way to
        the pilots' lodge"?"""
        def bare(j: int) -> bool:  # a list member: its place and "and", "the", "or" only
            taken = {i for p in seg_places.get(j, []) for i in range(p.start_tok, p.end_tok)}
            return bool(taken) and all(norms[i] in ("and", "or", "the", "a") or norms[i] in lx.FILLERS or i in taken
                                       for i in range(*segs[j]))
        j = k
        while j > 0 and bare(j):
            j -= 1
        if not seg_places.get(j):
            return False
        first = min(p.start_tok for p in seg_places[j])
        opening = [w for w in norms[segs[j][0]:first] if w not in lx.FILLERS]
        if opening[:1] in (["all"], ["any"]):
            opening = opening[1:]
        if len(opening) < 3 or opening[0] not in _PEOPLE_OR_GROUPS | {"everyone", "everybody", "anyone", "anybody"} \
                or opening[1] not in ("in", "at", "on", "inside") or opening[2] not in lx.ARTICLES or len(opening) > 3:
            return False
        m = k + 1
        while m < len(segs) and bare(m):
            m += 1
        told = [w for w in norms[segs[m][0]:segs[m][1]] if w not in lx.FILLERS] if m < len(segs) else []
        return told[:1] == ["please"] or told[:3] == ["make", "your", "way"] \
            or told[:1] in (["proceed"], ["evacuate"]) or told[:2] in (["head", "to"], ["go", "to"], ["move", "to"])

    def _named_relation_object(self, ex: Extraction, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """Is ``p`` the object of a relation phrase said right after another place named in the same clause ("the ramp
        that runs down from the hangar": the hangar), that is, the reference point of a description of a named place?"""
        toks = ex.tokens
        for q in ex.places:
            if q is p or q.status != "active" or q.landmark == p.landmark or not 0 < p.start_tok - q.end_tok <= 7 \
                    or any(toks.clause_start[t] for t in range(q.end_tok, p.start_tok + 1)):
                continue
            for t in range(q.end_tok, p.start_tok):
                h = self._relations.match_at(norms, t)
                if h is not None and p.start_tok - h[0] <= 1 and all(norms[i] in lx.ARTICLES for i in range(h[0], p.start_tok)):
                    return True
        return False

    def _awaits_description(self, ex: Extraction, norms: tuple[str, ...], before: list[PlaceMention], b: int) -> bool:
        """Should a pronoun ending at ``b`` wait for a description not read yet? Its one antecedent so far is said as
        another's reference point, and a new clause on "and" (no repair) stands between."""
        return len(before) == 1 and "and" in norms[before[0].end_tok:b] and self._relation_object(ex, norms, before[0]) \
            and not any(before[0].end_tok <= ma < b for ma, _, _ in ex.markers)

    def _relation_object(self, ex: Extraction, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """Does a relation phrase end right before ``p`` (its article aside), after a noun that could head a
        description, in the same clause ("the tank standing over the baler shed")?"""
        k = _noun_phrase_start(norms, p)
        for m in range(max(1, k - 6), k):
            hit = self._relations.match_at(norms, m)
            if hit is not None and hit[0] == k and norms[m - 1] in self._place_nouns() \
                    and not any(ex.tokens.clause_start[t] for t in range(m - 1, k + 1)):
                return True
            if norms[m] in ("that", "which") and norms[m - 1] in lx.GENERIC_HEADS and m >= 2 and norms[m - 2] in lx.ARTICLES \
                    and k - m <= 4 and not any(ex.tokens.clause_start[t] for t in range(m - 1, k + 1)):
                return True  # "the place that feeds the auction hall its ice": a description not read yet
        return False

    @staticmethod
    def _speaker_at(norms: tuple[str, ...], p: PlaceMention) -> bool:
        """"I'm at the chemist", "I am in the coffee shop": the place the speaker is at."""
        j = p.start_tok - 1
        while j >= 0 and norms[j] in lx.DETERMINERS | lx.FILLERS:
            j -= 1
        if j >= 2 and norms[j] == "of" and norms[j - 1] in lx.LOCATIVE_PARTS | lx.PART_NOUNS | {"steps", "step"}:
            j -= 2  # "I'm on the steps of St Mary's": at a part of it
            while j >= 0 and norms[j] in lx.DETERMINERS | lx.FILLERS:
                j -= 1
        if j >= 1 and norms[j] == "is" and norms[j - 1] == "this":
            return True  # "This is the pumping station. The building right below us ..."
        if j < 1 or norms[j] not in ("at", "in", "inside", "outside", "on", "by"):
            return False
        if j >= 2 and norms[j - 1] == "up" and norms[j - 2] == "parked":
            j -= 2  # "we're parked up at the bus station": where the crew is
        elif norms[j - 1] in ("parked", "sat", "sitting", "stood", "standing", "stopped"):
            j -= 1  # "we're parked at", "I'm sat in"
        return norms[j - 1] in ("im", "were") or norms[j - 2 : j] in (("i", "am"), ("we", "are"))

    @classmethod
    def _speaker_here(cls, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """The place the speaker says they are at: "I'm at the pharmacy", "Coastguard lookout here"."""
        if cls._speaker_at(norms, p) or norms[p.end_tok:p.end_tok + 1] == ("here",):
            return True
        if p.end_tok < len(norms) and norms[p.end_tok] in ("reporting", "calling", "relaying") \
                and all(w in lx.FILLERS | lx.DETERMINERS for w in norms[:p.start_tok]):
            return True  # "Coastguard hut reporting, the station we look down on ...": who calls, from where
        if p.end_tok + 1 < len(norms) and norms[p.end_tok + 1] == "here" and norms[p.end_tok] in lx.WORKPLACE_ROLES:
            return True  # "Tea room manager here, the place we get our bread from ...": where the speaker works
        if norms[p.end_tok:p.end_tok + 1] == ("to",) and norms[p.end_tok + 1:p.end_tok + 2] in lx.CALL_RECEIVERS \
                and all(w in lx.DETERMINERS | lx.FILLERS for w in norms[:p.start_tok]):
            return True  # a call sign opening the report: "St John's tent to control: ..."
        j = p.start_tok - 1
        while j >= 0 and norms[j] in lx.DETERMINERS | lx.FILLERS:
            j -= 1
        if j >= 1 and norms[j] == "from" and norms[j - 1:j] in lx.CALL_RECEIVERS \
                and all(w in lx.DETERMINERS | lx.FILLERS for w in norms[:j - 1]):
            return True  # "Control from hut two. ... the building we keep watch on": the place that calls
        if j >= 2 and norms[j] in ("at", "in") and norms[j - 1] in ("work", "live") and norms[j - 2] in ("i", "we"):
            return True  # "I work at the chemist's. The shop we're built onto ...": where the speaker works or lives
        if j < 0 and p.end_tok + 1 < len(norms) and norms[p.end_tok] in lx.CALLER_ROLES | {"reception", "desk"} \
                and norms[p.end_tok + 1] in lx.ARTICLES | {"we", "i", "weve", "ive", "were", "im"}:
            return True  # "Clinic reception. The building next door to us ...": the place that calls
        if j >= 3 and norms[j] in ("at", "from") and norms[j - 1].isalpha() and norms[j - 1] not in lx.FUNCTION_WORDS \
                and ("this", "is") in {norms[k:k + 2] for k in range(max(0, j - 5), j - 1)}:
            return True  # "This is the caretaker at Fenside School": where the speaker works
        # "I run the ironmonger's", "we manage the hotel": the speaker's own place
        return j >= 1 and norms[j] in ("run", "own", "manage", "keep") and norms[j - 1] in ("i", "we")

    def _head_before(self, toks: Tokens, norms: tuple[str, ...], head_end: int, place_tokens: set[int],
                     marker_tokens: set[int]) -> tuple[int, list[str]]:
        head_start = head_end
        while head_start > 0 and head_end - head_start < 4 and not toks.clause_start[head_start]:
            prev = head_start - 1
            w = norms[prev]
            if w in lx.PREPOSITIONS or w in lx.COPULAS or prev in place_tokens or prev in marker_tokens \
                    or prev in getattr(self, "_rel_tokens", ()):
                break
            head_start -= 1
            if w in lx.DETERMINERS or w in lx.WHATEVER:
                break  # ("a bench fall off whatever towers over the pit": the description opens on "whatever")
        words = [norms[j] for j in range(head_start, head_end)]
        while words and (words[0] in lx.DETERMINERS or words[0] in lx.FILLERS):
            words.pop(0)
            head_start += 1
        return head_start, words

    def _inverse_anchor(self, ex: Extraction, norms: tuple[str, ...], a: int,
                        phrase: str = "") -> tuple[PlaceMention, int, bool] | None:
        """"the one (that) the garage sits behind": (anchor, start of the description, head is a named place).

        ``phrase`` is the KB relation read; its own verb may stand between the anchor and the matched words
        ("the tower it huddles under" for ``huddles_in_the_lee_of``)."""
        verb = phrase.split()[0] if phrase and "_" not in phrase.split()[0] else ""
        j = a
        while j > 0 and (norms[j - 1] in lx.INVERSE_VERBS | {"a", "an"}
                         or verb and j == a and len(norms[j - 1]) >= 4 and _same_stem(norms[j - 1], verb.rstrip("s"))) \
                and a - j < 3 and not any(p.end_tok == j and p.status == "active" for p in ex.places):
            j -= 1  # (not past a name's own last word: "car park A lies downhill of")
        anchor = next((p for p in ex.places if p.end_tok == j and (p.status == "active" or p.status == "reference"
                                                                   and p.reason.startswith(_THAT_MODIFIER))), None)
        # ("whatever that pool drains into": the place "that pool" takes up)
        if anchor is None:
            # "the building that the park across from the flats sits behind": the anchor is the place the
            # reference point before the verb only said where it is
            ref = next((p for p in ex.places if p.end_tok == j and p.status == "reference"
                        and p.reason.startswith("reference point for '")), None)
            owner = max((p for p in ex.places if ref is not None and p.status == "active" and p.via is None
                         and p.end_tok <= ref.start_tok), key=lambda p: p.end_tok, default=None)
            if ref is not None and owner is not None and ref.start_tok - owner.end_tok <= 6:
                anchor = owner  # ("the field that the platform at the top of the gondola looks out over")
        we_are = j > 1 and norms[j - 1] == "were" and "'" in ex.tokens.tokens[j - 1].text.replace("’", "'")
        if anchor is None and j > 1 and (norms[j - 1] in ("it", "its", "they", "theyre", "we", "i") or we_are) \
                and (norms[j - 2] in lx.GENERIC_HEADS | {"that", "which"} or self._plain_head(norms, j - 2)):
            # "the building it sits next to": the pronoun is the anchor; "Coastguard lookout here. The building
            # we share the headland with": the speaker's place is
            hs = j - 2
            while hs > 0 and norms[hs] in ("that", "which"):
                hs -= 1
            while hs > 0 and norms[hs - 1] in lx.DETERMINERS and not (norms[hs - 1] == "its" and (
                    "'" in ex.tokens.tokens[hs - 1].text.replace("’", "'") or norms[hs] in lx.ARTICLES)):
                hs -= 1  # (not "it's the shop it's stuck onto", "its the shop its on")
            if norms[j - 1] in ("we", "i") or we_are:  # ("the ring we're tucked in the lee of")
                at = [p for p in ex.places if p.end_tok <= hs and p.status != "retracted" and self._speaker_here(norms, p)]
                return (max(at, key=lambda p: p.end_tok), hs, "pronoun") if at else None  # type: ignore[return-value]
            # the antecedent is spoken before the head ("the landing it faces": not the landing)
            before = [p for p in ex.places if p.end_tok <= hs and p.status != "reference"]
            if before:
                ante = max(before, key=lambda p: p.end_tok)
                if norms[hs] in lx.GENERIC_HEADS or (hs + 1 < len(norms) and norms[hs + 1] in lx.GENERIC_HEADS) \
                        or (hs + 1 < len(norms) and self._plain_head(norms, hs + 1)) or self._plain_head(norms, hs):
                    return ante, hs, "pronoun"  # type: ignore[return-value]
        if anchor is None:
            return None
        k = anchor.start_tok
        while k > 0 and norms[k - 1] in lx.DETERMINERS | {"that", "which", "where"} and anchor.start_tok - k < 3:
            k -= 1
        # (not a place that ends the sentence before: "at the boatyard. The paint shed at the back of Tarrant's")
        named = next((p for p in ex.places if p.end_tok == k and p.status == "active" and p is not anchor
                      and not ex.tokens.sentence_start[k]), None)
        if named is not None and k < anchor.start_tok:
            # "the green the abbey overlooks": the head is named, the anchor is a reference
            return anchor, named.start_tok, True
        if k < anchor.start_tok and norms[k] == "where" and (k == 0 or norms[k - 1] not in lx.PREPOSITIONS):
            return anchor, k, False  # "where the back lane runs down to, that's a raging torrent"
        hs = k
        while hs > 0 and k - hs < 3 and norms[hs - 1] not in lx.PREPOSITIONS | lx.COPULAS | lx.COORDINATORS \
                and not ex.tokens.clause_start[hs] \
                and not (hs == k and ex.tokens.tokens[hs - 1].text.lower().replace("’", "'").endswith("'s")):
            # ("the problem's the flats across the way": "'s" is a verb, "problem" heads nothing)
            hs -= 1
            if norms[hs] in lx.GENERIC_HEADS or (hs == k - 1 and self._plain_head(norms, hs)):
                if hs == k - 1 and hs > 1 and norms[hs] not in lx.GENERIC_HEADS and norms[hs - 2] in lx.ARTICLES \
                        and norms[hs - 1] in lx.NAME_ADJECTIVES | _HEAD_ADJECTIVES:
                    hs -= 1  # ("the open water the lifeboat slip drops into": its adjective too)
                while hs > 0 and norms[hs - 1] in lx.DETERMINERS and (hs - 1) not in self._marker_cache:
                    hs -= 1
                return anchor, hs, False
        if hs == k - 1 and hs >= 3 and norms[hs - 1] == "of" and norms[hs - 3] in lx.ARTICLES and norms[hs].isalpha() \
                and len(norms[hs]) >= 4 and norms[hs] not in lx.FUNCTION_WORDS and self._plain_head(norms, hs - 2) \
                and not any(p.start_tok <= hs < p.end_tok for p in ex.places):
            return anchor, hs - 3, False  # "the stretch of boundary the vets are built up against": "<noun> of <noun>"
        return None

    def _plain_head(self, norms: tuple[str, ...], i: int) -> bool:
        """A plain noun right after an article ("the taxiway it opens onto"), which may head a description; or
        a KB's head word one modifier after it ("the cross-passage it opens into")."""
        w = norms[i]
        if i > 1 and norms[i - 2] in lx.ARTICLES and w in self._place_nouns() and norms[i - 1].isalpha():
            return True
        if i > 1 and norms[i - 2] in lx.ARTICLES and norms[i - 1] in lx.NAME_ADJECTIVES | _HEAD_ADJECTIVES \
                and w.isalpha() and len(w) >= 3 and w not in _NOT_HEADS and self._cues.match_at(norms, i) is None:
            return True  # "the open water the lifeboat slip drops into": an adjective between
        return i > 0 and norms[i - 1] in lx.ARTICLES and w.isalpha() and len(w) >= 3 and (
            w not in _NOT_HEADS or w in lx.INVERSE_VERBS and self._place_head_word(w)) \
            and self._cues.match_at(norms, i) is None  # ("the stand the fan zone is set up behind": the KB's noun)

    def _relation_matches(self, rel: Relation, phrase: str) -> bool:
        rp = rel.phrase
        if rp == phrase:
            return True
        core = _relation_core(rp)  # "directly_above" is an "above" relation
        words = rp.split()
        # ("stands round the back of" is a "behind" relation: a posture verb, then a phrase of the group)
        rest = " ".join(words[1:]) if len(words) >= 3 and words[0] in _POSTURE_VERBS | {"is", "are"} else None
        for canon, syns in lx.RELATION_SYNONYMS.items():
            if phrase == canon and (rp == canon or rp in syns or core == canon or core in syns or rest in syns):
                return True
        return False

    def _follow(self, anchor: str, phrase: str, head: str, inverse: bool = False,
                _loose: bool = False, _vertical: bool = True) -> tuple[str | None, str | None]:
        """Landmarks standing in relation ``phrase`` to ``anchor``; ties broken by the head noun.

        ``X phrase anchor`` normally; with ``inverse`` the description reads ``anchor phrase X``.
        An inverse phrase ("in front of" for "behind") reads the KB relation backwards.
        """
        cands: list[tuple[str, str]] = []
        opposite = lx.INVERSE_PHRASES.get(phrase)
        for rel in self.kb.relations:
            desc = f"{rel.subject} {rel.relation} {rel.object}"
            symmetric = any(h in rel.phrase for h in lx.SYMMETRIC_HINTS)
            if self._relation_matches(rel, phrase) or self._fuzzy_relation(rel.phrase, phrase):
                forward_hit = rel.subject if rel.object == anchor else None
                backward_hit = rel.object if rel.subject == anchor else None
                if inverse:
                    forward_hit, backward_hit = backward_hit, forward_hit
                if forward_hit:
                    cands.append((forward_hit, desc))
                elif backward_hit and symmetric:
                    cands.append((backward_hit, desc))
            elif opposite and self._relation_matches(rel, opposite):
                hit = rel.object if rel.subject == anchor else None
                if inverse:
                    hit = rel.subject if rel.object == anchor else None
                if hit:
                    cands.append((hit, desc))
        if not cands and phrase in lx.LOOSE_EQUIVALENTS and not inverse:
            loose, _ = self._follow(anchor, lx.LOOSE_EQUIVALENTS[phrase], head, inverse=False, _loose=True) \
                if not _loose else (None, None)
            if loose is not None:
                return self._follow(anchor, lx.LOOSE_EQUIVALENTS[phrase], head, inverse=False, _loose=True)
        # a description must lead somewhere: a relation the KB states only the other way round ("the building
        # across the skybridge from A&E" for "radiology linked_by_skybridge_to A&E") is read that way round; but
        # first another relation the same words name, read the way they are said ("the houses below the visitor
        # centre": ``is downhill of``, not ``car park sits above visitor centre``), then one that says which place is
        # higher ("the room above it"; not for a link MiniLM only guessed, ``_vertical`` False)
        named = phrase not in lx.INVERSE_PHRASES and phrase not in lx.RELATION_SYNONYMS
        if not cands and not _loose and named:
            found: dict[str, tuple[str | None, str | None]] = {}
            for other, mine, theirs in self._shared_forms.get(phrase, ()):
                hit = self._follow(anchor, other, head, inverse=inverse ^ mine ^ theirs, _loose=True)
                if hit[0] is not None:
                    found.setdefault(hit[0], hit)
            if len(found) == 1:
                return next(iter(found.values()))
        if not cands and not _loose and _vertical:
            vertical = self._vertical_follow(anchor, phrase, head, inverse)
            if vertical[0] is not None:
                return vertical
        if not cands and not _loose and named:
            back, via = self._follow(anchor, phrase, head, inverse=not inverse, _loose=True)
            if back is not None:
                return back, via
        if not cands and not _loose:
            cands = self._sibling_relations(anchor, phrase, inverse)
        if not cands:
            cands = self._grid_relation(anchor, phrase)
        uniq = {c[0]: c for c in cands}
        if not uniq:
            return None, None
        if len(uniq) == 1:
            return next(iter(uniq.values()))
        worded = self._by_relation_words(list(uniq.values()), phrase)
        if worded is not None:
            return worded
        return self._pick_by_head(list(uniq.values()), head)

    def _by_relation_words(self, cands: list[tuple[str, str]], phrase: str) -> tuple[str, str] | None:
        """"the station at the bottom of the rails", where the KB has ``sits at the head of`` and ``sits_at_the_foot_of``
        the rails: of relations matched alike, the one alone whose name has the phrase's own words (or a part's other
        name: the foot, the bottom, the base)."""
        said = {w for w in norm_phrase(phrase.replace("_", " ")) if w not in lx.FUNCTION_WORDS}
        if not said:
            return None
        by_desc = {f"{r.subject} {r.relation} {r.object}": r for r in self.kb.relations}
        scored = []
        for c in cands:
            rel = by_desc.get(c[1])
            if rel is None:
                return None
            words = set(norm_phrase(rel.phrase.replace("_", " ")))
            words |= {x for w in list(words) for x in _PART_SYNONYMS.get(w, ())}
            scored.append((len(said & words), c))
        best = max(n for n, _ in scored)
        top = [c for n, c in scored if n == best]
        return top[0] if best > 0 and len(top) == 1 else None

    def _vertical_follow(self, anchor: str, phrase: str, head: str, inverse: bool) -> tuple[str | None, str | None]:
        """"the room below the library" for ``library is_built_over chapter house``: of the KB's other relations that
        say which place is higher, the one place they put where the words put the place described."""
        mine = _vertical_sense(phrase)
        if mine is None:
            return None, None
        said = mine if not inverse else -mine
        found: dict[str, tuple[str | None, str | None]] = {}
        for rel in self.kb.relations:
            theirs = _vertical_sense(rel.phrase)
            if rel.phrase == phrase or theirs is None or rel.subject == rel.object:
                continue
            # the place described is the subject where the relation puts its subject as the words put it, else the
            # object (the KB's own statement, no looser reading of the relation's name)
            if theirs == said and rel.object == anchor:
                found.setdefault(rel.subject, (rel.subject, f"{rel.subject} {rel.relation} {rel.object}"))
            elif theirs != said and rel.subject == anchor:
                found.setdefault(rel.object, (rel.object, f"{rel.subject} {rel.relation} {rel.object}"))
        return next(iter(found.values())) if len(found) == 1 else (None, None)

    @functools.cached_property
    def _shared_forms(self) -> dict[str, list[tuple[str, bool, bool]]]:
        """KB relation -> the direction relations that share a direction word's form with it ("below" of ``sits above``
        and of ``is downhill of``), each with the direction that form has in the one and in the other."""
        forms = {rel.phrase: {norm_phrase(f): inv for f, inv in _relation_forms(rel.phrase)} for rel in self.kb.relations}
        out: dict[str, list[tuple[str, bool, bool]]] = {}
        for phrase, mine in forms.items():
            for other, theirs in forms.items():
                if other == phrase or not set(norm_phrase(other)) & (set(lx.DIRECTION_FAMILIES) | lx.BARE_DIRECTIONS):
                    continue  # (the other a direction's own relation: "is downhill of", not "looks out over")
                shared = {(mine[k], theirs[k]) for k in mine.keys() & theirs.keys() if k[0] in _DIRECTION_BARE}
                if len(shared) == 1:
                    out.setdefault(phrase, []).append((other, *next(iter(shared))))
        return out

    def _sibling_relations(self, anchor: str, phrase: str, inverse: bool) -> list[tuple[str, str]]:
        """The relation a word names may be another of the KB's than the one its stem was given to: "the
        building the substation feeds" is ``supplies_power_to`` (the substation's), not ``fed_by_the_
        hydrant_main_from`` (which has "fed" itself). Relations that share a link stem with ``phrase`` and
        take part with ``anchor``; a passive name ("supplied by") read against an active one turns the direction."""
        stems = {st for w in phrase.split() if len(w) >= 3 and w not in lx.RELATION_NAME_STOPWORDS
                 for st in _link_stems(w)}
        out: list[tuple[str, str]] = []
        for rel in self.kb.relations:
            if rel.phrase == phrase or rel.subject != anchor and rel.object != anchor:
                continue
            if not stems & {st for w in rel.phrase.split() if len(w) >= 3 and w not in lx.RELATION_NAME_STOPWORDS
                            for st in _link_stems(w)}:
                continue
            flip = inverse != (_passive_name(rel.phrase) != _passive_name(phrase))
            hit = (rel.object if rel.subject == anchor else None) if flip else (rel.subject if rel.object == anchor else None)
            if hit:
                out.append((hit, f"{rel.subject} {rel.relation} {rel.object}"))
        return out

    def _fuzzy_relation(self, kb_phrase: str, phrase: str) -> bool:
        """An unknown KB relation name ("abuts") against a report phrase, via MiniLM."""
        if kb_phrase in _TABLE_RELATIONS or _relation_core(kb_phrase) in _TABLE_RELATIONS or self.embedder is None:
            return False
        v = self.embedder.embed([kb_phrase, phrase])
        return float(v[0] @ v[1]) >= 0.6

    def _grid_relation(self, anchor: str, phrase: str) -> list[tuple[str, str]]:
        deltas = {"north of": (-1, 0), "south of": (1, 0), "east of": (0, 1), "west of": (0, -1)}
        if phrase not in deltas:
            return []
        dr, dc = deltas[phrase]
        owner = self.kb.cell_owner
        out = []
        for r, c in self.kb.landmark_by_name[anchor].cells:
            name = owner.get((r + dr, c + dc))
            if name and name != anchor:
                out.append((name, f"{name} {phrase.replace(' ', '_')} {anchor} (grid)"))
        return out

    def _pick_by_head(self, cands: list[tuple[str, str]], head: str) -> tuple[str | None, str | None]:
        head_keys = set(norm_phrase(head)) - lx.DETERMINERS - {"one", "place", "building", "thing", "spot"}
        scored = []
        for name, via in cands:
            lm = self.kb.landmark_by_name[name]
            words = set(norm_phrase(" ".join(lm.surface_forms) + " " + lm.description))
            scored.append((len(head_keys & words), name, via))
        scored.sort(key=lambda s: -s[0])
        if scored[0][0] > 0 and (len(scored) == 1 or scored[0][0] > scored[1][0]):
            return scored[0][1], scored[0][2]
        if self.embedder is not None and head_keys:
            texts = [head] + [f"{self.kb.landmark_by_name[n].name}: {self.kb.landmark_by_name[n].description}" for n, _ in cands]
            v = self.embedder.embed(texts)
            sims = v[1:] @ v[0]
            order = np.argsort(-sims)
            if sims[order[0]] - sims[order[1]] >= 0.05:
                return cands[int(order[0])]
        return None, None

    def _desirable_cue_in_sentence(self, toks: Tokens, norms: tuple[str, ...], start: int) -> bool:
        """A cue of the desirable role follows ``start`` in its sentence ("the school is unaffected and we're using it
        as the rest centre": said to be untouched and then used, not the place denied)."""
        sent = toks.sentence_of[start] if start < len(norms) else None
        for k in range(start, len(norms)):
            if toks.sentence_of[k] != sent:
                return False
            if self._role_cue_at(norms, k, Role.DESIRABLE):
                return True
        return False

    def _apply_place_negation(self, ex: Extraction) -> None:
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        for idx, p in enumerate(ex.places):
            if p.status != "active":
                continue
            j = p.start_tok - 1
            while j >= 0 and (norms[j] in lx.DETERMINERS or norms[j] in lx.PREPOSITIONS or norms[j] in lx.FILLERS
                              or norms[j] in ("whole", "entire") and j > 0 and norms[j - 1] == "the") \
                    and p.start_tok - j <= 4 and not toks.clause_start[j + 1] \
                    and not (norms[j] == "its" and norms[j + 1] in lx.ARTICLES):  # "it's not it's the X": a new clause
                j -= 1  # ("not the whole fair")
            if p.via is not None and norms[p.start_tok] == "not":
                j = p.start_tok  # "the building across from the church -- no, scratch that, not across from it"
            tail = norms[p.end_tok : p.end_tok + 4]
            if tail[:1] == ("itself",):  # "Square itself unaffected."
                tail = norms[p.end_tok + 1 : p.end_tok + 5]
            untouched = tail[:1] in (("untouched",), ("unaffected",)) \
                or tail[:2] in ((v, w) for v in ("is", "was", "s") for w in ("untouched", "unaffected"))
            not_the_one = tail[:3] in (("isnt", "the", "one"), ("wasnt", "the", "one"), ("aint", "the", "one")) \
                or tail[:4] in (("is", "not", "the", "one"), ("s", "not", "the", "one"), ("was", "not", "the", "one")) \
                or untouched and not self._desirable_cue_in_sentence(toks, norms, p.end_tok) \
                or tail[:2] in ((v, w) for v in ("isnt", "wasnt", "arent", "werent", "not") for w in ("affected", "involved")) \
                or tail[:3] in ((v, "not", w) for v in ("is", "was", "s", "are", "were", "re") for w in ("affected", "involved"))
            m = p.end_tok
            while m < len(norms) and m - p.end_tok < 6 and (norms[m] in lx.FILLERS or norms[m] in (
                    "we", "weve", "ve", "have", "i", "ive", "checked", "searched", "looked", "in", "at")):
                m += 1
            if m > p.end_tok and any(norms[i] in ("checked", "searched") for i in range(p.end_tok, m)) \
                    and norms[m:m + 2] == ("nothing", "there") and (m + 2 >= len(norms) or toks.clause_start[m + 2]):
                ex.places[idx] = replace(p, status="negated", reason="negated by 'checked, nothing there'")
                continue  # "and uh the instrument stores we checked, uh, nothing there"
            # ("it's not the camp, the camp's not the problem, it's the clinic")
            problem = tail[:4] in ((v, "not", "the", w) for v in ("is", "s", "was") for w in ("problem", "issue")) \
                or tail[:3] in ((v, "the", w) for v in ("isnt", "wasnt", "not") for w in ("problem", "issue"))
            if problem and (j < 0 or toks.clause_start[j + 1]):
                ex.places[idx] = replace(p, status="negated", reason="negated by 'not the problem'")
                continue
            if j < 0 and not_the_one:
                ex.places[idx] = replace(p, status="negated", reason="negated by 'not the one'")
                continue  # "the school isn't the one with people trapped, it's the library"
            if j < 0 or any(toks.sentence_start[i] for i in range(j + 1, p.start_tok + 1)) \
                    or norms[p.start_tok] in ("its", "thats"):
                continue  # ("... and it isn't. The cafe is, though": the negation ends with its sentence; "it's
                # not it's the one next to it": a new clause)
            neg = norms[j] in ("not", "nt", "isnt", "wasnt") or norms[j] in lx.RETRACT_VERBS and not any(
                (m := self._cues.match_at(norms, i)) is not None and i < j < m[0] for i in range(max(0, j - 3), j)) \
                and not (j > 0 and norms[j - 1] in lx.ARTICLES | {"lightning", "direct"}) or (  # ("took a lightning strike")
                norms[j] == "negative" and norms[j + 1] == "on"  # "negative on the quarry, it's the campsite"
            ) or (
                # "from the school, no, the post office, negative the school": said again only to deny it
                norms[j] == "negative" and not toks.clause_start[j + 1]
                and any(q.landmark == p.landmark and q.end_tok <= j for q in ex.places)
            ) or (
                j > 0 and norms[j - 1 : j + 1] in (("rather", "than"), ("instead", "of"))
            ) or (
                j > 0 and norms[j - 1 : j + 1] == ("no", "longer")  # "the rest centre is no longer the town hall"
            ) or (
                norms[j] == "wrong" and j > 0 and norms[j - 1] == "nothing"  # "nothing wrong at the police station"
            ) or norms[j] == "instead" or (
                norms[j] in ("rule", "ruled", "ruling") and norms[j + 1] == "out"  # "rule out the park"
            ) or (
                norms[j] == "nothing" and any(norms[i] in ("at", "in", "inside", "on") for i in range(j + 1, p.start_tok))
            )  # "nothing at the bus depot, it's the supermarket"; "nothing on the quarry floor"
            if neg and norms[j] == "instead" and toks.clause_start[j + 1]:
                neg = False  # "use the school instead, the school's the rest centre": the clause before ends there
            if neg and norms[j] == "not" and j > 0 and norms[j - 1] in ("do", "dont", "does", "did") \
                    and any(d in toks.gaps[j + 1] for d in ("—", "–", "--", " - ")):
                neg = False  # "the harbour road, do not — the harbour road is buried": an order broken off
            # "not the school" but not "not on fire at the school" (that negates a cue)
            after = norms[p.end_tok : p.end_tok + 2]
            if norms[j] in ("take", "taking", "took") and after[:1] and after[0] in ("off", "out", "back", "away"):
                neg = True  # "take the garage off that list"
            if neg and norms[j] in ("isnt", "wasnt", "arent", "werent") and (any(
                    d in toks.gaps[i] for i in range(j + 1, p.start_tok + 1) for d in ("—", "–", "--", " - "))
                    or toks.clause_start[j + 1] and j > 0 and norms[j - 1] in ("it", "that", "this", "they")):
                neg = False  # "says the bridge is the safe way but it isn't - the crossing below the mill is cracking";
                # "no it isn't, the stadium's one sheet of black ice": "it isn't" answers, and a clause of its own follows
            if neg and norms[j] == "not" and toks.clause_start[j + 1] and j > 0 \
                    and norms[j - 1] in ("absolutely", "definitely", "certainly", "course", "really", "no", "surely"):
                neg = False  # "no, no, absolutely not, the lodge is brimming over": an answer, then a clause of its own
            if neg and norms[j] == "not" and toks.clause_start[j + 1] and j > 0 and (
                    norms[j - 1] == "its" or j > 1 and norms[j - 2:j] in (("it", "s"), ("it", "is"), ("that", "s"))):
                neg = False  # "the res is... it's fine, no wait, it's not, the dam's cracked": a word taken back
            if neg and norms[j] == "not" and norms[j + 1:j + 2] == ("that",) and j + 2 < len(norms) \
                    and toks.clause_start[j + 2]:
                neg = False  # "no -- wait -- not that, the pad below the car park": "that" is the place said before
            if not_the_one:
                neg = True  # "the school isn't the one"
            if neg and any(ma <= j < mb for ma, mb, _ in ex.markers) and norms[j + 1 : j + 2] == ("that",):
                neg = False  # "scratch that its the physics block": the marker repairs, it does not negate the place
            if neg and not self._cue_between(norms, j + 1, p.start_tok):
                ex.places[idx] = replace(p, status="negated", reason=f"negated by '{toks.tokens[j].text}'")
                if norms[j] == "not" and self._relations.match_at(norms, j + 1) is not None:
                    # "the building across from the park has collapsed — no wait, not across from the park, the park
                    # itself": the description is taken back, and the place said next takes its claims
                    n = toks.sentence_of[j]
                    described = [q for q in ex.places if q.status == "active" and q.via is not None and q.end_tok <= j
                                 and f" {p.landmark}" in f" {q.via}" and toks.sentence_of[q.start_tok] >= n - 1]
                    nxt = next((r for r in sorted(ex.places, key=lambda r: r.start_tok) if r.status == "active"
                                and p.end_tok <= r.start_tok <= p.end_tok + 6), None)
                    if described and nxt is not None:
                        self._take_back(ex, max(described, key=lambda q: q.start_tok), nxt,
                                        f"then 'not {toks.span_text(j + 1, p.end_tok)}'")
                    if described:
                        continue
                    # ("a fall by the lake, no, not by the lake, by our caravan": only where, the place taken back)
                # "the clinic ... no, not the clinic, the police station": the earlier mention is retracted
                sent_start = max(t for t in range(0, p.start_tok + 1) if toks.sentence_start[t])
                marker_toks = {i for a, b, _ in ex.markers for i in range(a, b)}
                if sent_start > 0 and all(i in marker_toks or norms[i] in lx.FILLERS for i in range(sent_start, j)):
                    # "... and the school. Sorry — not the school, the post office.": the repair opens
                    # its sentence, so it reaches back into the one before
                    sent_start = max(t for t in range(0, sent_start) if toks.sentence_start[t])
                earlier = [q for q in ex.places if q.status == "active" and q.landmark == p.landmark
                           and sent_start <= q.start_tok < p.start_tok]
                corrects = not earlier and (norms[j] in lx.RETRACT_VERBS or any(
                    i in marker_toks or norms[i] in lx.CORRECTION_WORDS for i in range(min(sent_start, max(0, j - 6)), j)))
                # ("scratch the clinic in what I said, she's at the police station": a retraction corrects too)
                nxt = min((q for q in ex.places if q.status == "active" and q.start_tok >= p.end_tok
                           and q.landmark != p.landmark
                           and (q.start_tok - p.end_tok <= 3 or q.start_tok - p.end_tok <= 8 and not any(
                               toks.sentence_start[i] for i in range(p.end_tok, q.start_tok + 1)))),
                          key=lambda q: q.start_tok, default=None)
                if not earlier and not corrects and norms[j] == "not" and j > 0 \
                        and norms[j - 1] in ("its", "s", "is", "was", "thats") and nxt is not None \
                        and set(norms[p.end_tok:nxt.start_tok]) & {"its", "it", "thats"}:
                    corrects = True  # "Fire at the bank. ... he says it's not the bank, it's the bakery": said as
                    # a correction, of the bank said before
                if not earlier and not corrects and norms[j] == "nothing" and nxt is not None \
                        and set(norms[p.end_tok:nxt.start_tok]) & {"its", "it", "thats"}:
                    corrects = True  # "fumes at the brewery. Second caller ... says no, nothing at the brewery, it's
                    # the tannery beside it"
                if not earlier and (not corrects or nxt is None) and norms[j] == "not":
                    said = next((q for q in ex.places if q.status == "active" and j - 2 <= q.end_tok <= j
                                 and q.landmark != p.landmark and toks.sentence_of[q.start_tok] == toks.sentence_of[j]
                                 and [w for w in norms[max(0, q.start_tok - 3):q.start_tok] if w not in lx.ARTICLES][-1:]
                                 in (["its"], ["thats"])), None)
                    if said is not None and any(q.status == "active" and q.landmark == p.landmark
                                                and toks.sentence_of[q.start_tok] < toks.sentence_of[j] for q in ex.places):
                        corrects, nxt = True, said  # "Live wire at the hotel. ... it's the bank, not the hotel"
                if corrects:
                    # "16:12 T2 corrects previous msg: NOT lower field, it was the upper caravan field": a
                    # correction retracts the place from any earlier sentence when a place said next, in this
                    # sentence or the one after, takes over its claims
                    if nxt is None:
                        nxt = min((q for q in ex.places if q.status == "active"
                                   and p.end_tok <= q.start_tok <= p.end_tok + 12
                                   and sum(toks.sentence_start[i] for i in range(p.end_tok, q.start_tok + 1)) <= 1),
                                  key=lambda q: q.start_tok, default=None)
                    earlier = [q for q in ex.places if q.status == "active" and q.landmark == p.landmark
                               and q.start_tok < sent_start] if nxt is not None else []
                for q in [q for q in earlier if q.anaphor == "ordinal"]:
                    # "that second one I gave you, that was the clinic not the police station": the list item
                    # the ordinal names is what the repair takes back
                    item = max((r for r in ex.places if r.status == "active" and r.landmark == q.landmark
                                and r.start_tok < q.start_tok and r.anaphor is None), key=lambda r: r.start_tok, default=None)
                    if item is not None and item not in earlier:
                        earlier.append(item)
                contrast = next((q for q in ex.places if q.status == "active" and j - 3 <= q.end_tok <= j
                                 and q.landmark != p.landmark), None)
                if contrast is not None and not corrects:
                    # "girders down in the transit shed ..., and the injured porter, he's in the tea warehouse,
                    # not the shed": said against the place just named, not a repair of an earlier claim
                    hits = [(ca, c) for ca, _, (c, _) in self._cues.find_all(norms)]

                    def cats(a: int, b: int, hits: list[tuple[int, str]] = hits) -> set[str]:
                        return {c for ca, c in hits if a <= ca < b}
                    said_here = cats(max(0, contrast.start_tok - 6), j)
                    # (a claim of another kind: "... the hotel is on fire, not the bank" repairs the bank's fire)
                    earlier = [q for q in earlier if not (
                        q.end_tok <= contrast.start_tok and said_here
                        and not said_here & cats(max(0, q.start_tok - 6), min(q.end_tok + 4, contrast.start_tok - 6))
                        and not any(q.end_tok <= i < j for i in marker_toks))]
                for q in earlier:
                    ex.places[ex.places.index(q)] = replace(q, status="retracted", reason=f"then '{toks.tokens[j].text} {p.text}'")
                # ("not the school, they moved it, it's the library now": the next place in the sentence)
                if earlier and nxt is None:
                    # "correction, all of that's at the town hall, not the bank": the place said just before
                    nxt = next((q for q in ex.places if q.status == "active" and j - 3 <= q.end_tok <= j
                                and q.landmark != p.landmark and q.start_tok > earlier[-1].start_tok), None)
                if earlier and nxt is not None and nxt.replaces is None:
                    ex.places[ex.places.index(nxt)] = replace(nxt, replaces=earlier[-1].start_tok)
                elif corrects and nxt is not None and nxt.replaces is None \
                        and (f := next((t for t in range(nxt.start_tok - 1, max(-1, nxt.start_tok - 4), -1)
                                        if norms[t] not in lx.DETERMINERS), None)) is not None \
                        and toks.sentence_start[f] and norms[f] == "from":
                    # "I correct: the smoke is not from the school. From the library!": what was said of the
                    # place denied is said of the one given instead
                    ex.places[ex.places.index(nxt)] = replace(nxt, replaces=p.start_tok)

    @staticmethod
    def _take_back(ex: Extraction, old: PlaceMention, new: PlaceMention | None, reason: str) -> None:
        """``old`` is retracted for ``reason``; ``new``, said in its stead, takes its claims (unless it already
        repairs another place). Both are found by their span, so a copy made earlier still finds them."""
        def same(a: PlaceMention, b: PlaceMention) -> bool:
            return (a.start_tok, a.end_tok, a.landmark, a.via) == (b.start_tok, b.end_tok, b.landmark, b.via)

        for i, r in enumerate(ex.places):
            if same(r, old):
                ex.places[i] = replace(r, status="retracted", reason=reason)
            elif new is not None and same(r, new) and r.replaces is None:
                ex.places[i] = replace(r, replaces=old.start_tok)

    @staticmethod
    def _bare_places(ex: Extraction, norms: tuple[str, ...]) -> Iterator[tuple[int, PlaceMention, int]]:
        """(index, place, where its noun phrase starts, past its determiners) for each place still active and named
        directly (no relational description): what the words right before it say of it."""
        for idx, p in enumerate(ex.places):
            if p.status != "active" or p.via is not None:
                continue
            j = p.start_tok
            while j > 0 and norms[j - 1] in lx.DETERMINERS:
                j -= 1
            yield idx, p, j

    def _apply_mistaken_first(self, ex: Extraction, norms: tuple[str, ...]) -> None:
        """"I thought it was the pit but it's, it's the pump house": what the speaker first took it for is taken
        back, and the place after "but it's" takes its claims. "she's at the doctors', no, she's at home, ... in the
        almshouses": a repair to a place the KB does not name takes the one before back all the same."""
        toks = ex.tokens
        for ma, mb, _ in ex.markers:
            k = mb
            while k < len(norms) and (norms[k] in lx.FILLERS or norms[k] in lx.PERSON_SUBJECTS | {"were", "im", "is", "s"}):
                k += 1
            if norms[k:k + 2] not in (("at", "home"), ("in", "bed"), ("at", "work")):
                continue
            last = max((q for q in ex.places if q.status == "active" and q.end_tok <= ma and ma - q.end_tok <= 3
                        and toks.sentence_of[q.start_tok] == toks.sentence_of[ma]), key=lambda q: q.end_tok, default=None)
            if last is not None:
                nxt = min((q for q in ex.places if q.status == "active" and k + 2 <= q.start_tok <= k + 10
                           and q.landmark != last.landmark and toks.sentence_of[q.start_tok] == toks.sentence_of[ma]),
                          key=lambda q: q.start_tok, default=None)
                self._take_back(ex, last, nxt, f"self-repair: '{norms[k]} {norms[k + 1]}', no place the KB names")
        for p in sorted((q for q in ex.places if q.status == "active"), key=lambda q: q.start_tok):
            j = p.start_tok
            while j > 0 and norms[j - 1] in lx.DETERMINERS:
                j -= 1
            if not (j >= 3 and norms[j - 3:j] in (("thought", "it", "was"), ("thought", "that", "was"),
                                                   ("thought", "it", "s"), ("assumed", "it", "was"))):
                continue
            after = norms[p.end_tok:p.end_tok + 3]
            if after[:1] != ("but",) or not ({"its", "it", "thats"} & set(after[1:])):
                continue
            nxt = min((q for q in ex.places if q.status == "active" and q.landmark != p.landmark
                       and p.end_tok < q.start_tok <= p.end_tok + 10
                       and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok]),
                      key=lambda q: q.start_tok, default=None)
            if nxt is not None:
                self._take_back(ex, p, nxt, f"mistaken at first, then '{nxt.text}'")

    @staticmethod
    def _struck_tokens(toks: Tokens) -> set[int]:
        """Tokens inside a span struck through in a written log: "~~gas at the hall~~"."""
        spans = [(m.start(), m.end()) for m in re.finditer(r"~~[^~]+?~~", toks.text)]
        return {i for i, t in enumerate(toks.tokens) if any(a < t.start < b for a, b in spans)}

    @staticmethod
    def _apply_written_corrections(ex: Extraction) -> None:
        """Corrections typed rather than spoken: "fire at the bank *bakery" (an asterisk before the right word),
        "fire at the ~~bank~~ bakery" (a word struck through): the place corrected is taken back and the
        place after it takes its claims."""
        toks = ex.tokens

        def active() -> list[PlaceMention]:
            return sorted((p for p in ex.places if p.status == "active"), key=lambda p: p.start_tok)

        struck = ReportAnalyzer._struck_tokens(toks)
        for p in active():
            if p.start_tok in struck:
                end = p.end_tok
                while end in struck:
                    end += 1  # "~~smoke in the east stand~~ smoke in the west stand": past the whole struck span
                nxt = next((q for q in active() if q.start_tok >= end), None)
                ReportAnalyzer._take_back(ex, p, nxt, "struck through")
        for q in active():
            if "*" not in toks.gaps[q.start_tok] or q.start_tok == 0:
                continue
            prev = [p for p in active() if p.end_tok <= q.start_tok and p.landmark != q.landmark
                    and toks.sentence_of[p.start_tok] == toks.sentence_of[q.start_tok]]
            if prev:
                ReportAnalyzer._take_back(ex, max(prev, key=lambda p: p.start_tok), q, f"corrected by '*{q.text}'")

    @staticmethod
    def _apply_pronoun_negation(ex: Extraction, norms: tuple[str, ...]) -> None:
        """"gas leak at the school - well, not at it, at the place next door to it": the place said before
        "not (at) it" is taken back, and the place said next takes its claims."""
        toks = ex.tokens
        for j in range(len(norms) - 1):
            if norms[j] not in ("not", "nt"):
                continue
            k = j + 1
            if norms[k] in lx.PREPOSITIONS and k + 1 < len(norms):
                k += 1
            if norms[k] not in ("it", "there") or not (k + 1 >= len(norms) or toks.clause_start[k + 1]):
                continue
            n = toks.sentence_of[j]
            before = [q for q in ex.places if q.status == "active" and q.end_tok <= j and toks.sentence_of[q.start_tok] == n]
            after = [r for r in ex.places if r.status == "active" and k < r.start_tok <= k + 8
                     and toks.sentence_of[r.start_tok] == n]
            if not before or not after:
                continue
            q, r = max(before, key=lambda q: q.end_tok), min(after, key=lambda r: r.start_tok)
            if r.landmark != q.landmark:
                ReportAnalyzer._take_back(ex, q, r, f"then '{toks.span_text(j, k + 1)}'")

    def _cue_between(self, norms: tuple[str, ...], a: int, b: int) -> bool:
        return any(self._cues.match_at(norms, k) is not None for k in range(a, b))

    def _called_station(self, toks: Tokens, norms: tuple[str, ...], p: PlaceMention,
                        places: Sequence[PlaceMention] = ()) -> bool:
        """"Red Watch to TCC, we're at the east portal": a call sign, "to", the station called, a pause.
        Also the station that calls everyone ("Race Control to all posts: ..."): a broadcast, said of others."""
        a = p.start_tok
        # "uh base this is Sue at Heron Court": the station called, then who calls; or the station called twice,
        # "reception, reception, this is Ahmed" (either time it is said)
        twin_before = next((q for q in places if q.landmark == p.landmark and q.end_tok == a), None)
        twin_after = next((q for q in places if q.landmark == p.landmark and q.start_tok == p.end_tok), None)
        first, last = twin_before or p, twin_after or p
        if (twin_before is None or twin_after is None) and toks.sentence_of[a] == 0 \
                and norms[last.end_tok:last.end_tok + 2] == ("this", "is") \
                and all(w in lx.FILLERS | lx.DETERMINERS for w in norms[:first.start_tok]):
            return True
        if toks.sentence_of[a] == 0 and all(w in lx.FILLERS | lx.DETERMINERS for w in norms[:a]) \
                and norms[p.end_tok:p.end_tok + 2] == ("to", "all") and p.end_tok + 4 <= len(norms) \
                and any(toks.clause_start[i] for i in range(p.end_tok + 2, p.end_tok + 5) if i < len(norms)) \
                and not {"this", "here", "we", "our", "us", "were", "weve", "ours"} & {
                    norms[i] for i in range(p.end_tok, len(norms)) if toks.sentence_of[i] == toks.sentence_of[a]
                    and not (norms[i] == "our" and norms[i - 1] in ("is", "s", "as"))}:
            # (not "the main restaurant is our cyclone shelter": what the other place is to them all)
            # ("Police post to all units: this building ... is now the cold zone": its own place, said of)
            return True  # "Race Control to all posts: the south grandstand is on fire": who broadcasts
        t = a - 1  # ("dive centre to the, the clinic, we got ...": the article said twice)
        while t > 1 and a - t <= 3 and (norms[t] in lx.ARTICLES or norms[t] in lx.HESITATIONS):
            t -= 1
        if t < 1 or norms[t] != "to":
            t = a - 1
        if a < 2 or norms[t] != "to" or toks.sentence_of[a] != 0 or p.end_tok >= len(norms) \
                or not toks.clause_start[p.end_tok]:
            return False
        before = range(0, t)
        caller = next((q for q in places if q.start_tok <= 1 and q.end_tok == t
                       and all(w in lx.FILLERS for w in norms[:q.start_tok])), None)
        # ("Fuel bay to race control, we've got ...": a place calling by its own name)
        numbered = len(before) >= 2 and (is_number(norms[t - 1]) or norms[t - 1] in lx.NUMBER_WORDS)
        # ("Fire Two to rally office: ...": a call sign's word and number, no fire)
        return len(before) <= 4 and (caller is not None or all(toks.tokens[i].text[:1].isupper() or toks.tokens[i].text.isdigit()
                                                               for i in before)) \
            and (numbered or not any(self._cues.match_at(norms, i) for i in before))

    @staticmethod
    def _calls_by_name(toks: Tokens, norms: tuple[str, ...], p: PlaceMention, places: list[PlaceMention]) -> bool:
        """"Tower to Rescue One: the flying club ... is safe": a place that opens the message calling a station
        by name is who calls; unless the message speaks of its own place ("we", "our building"), it claims nothing."""
        a, e = p.start_tok, p.end_tok
        everyone = norms[e + 1:e + 2] == ("all",) and e + 2 < len(norms) and norms[e + 2] in (
            "units", "unit", "stations", "station", "call", "callsigns", "teams", "crews", "channels", "parties",
            "boats", "boat", "vessels", "vessel", "posts", "post", "marshals", "marshal", "stewards", "steward")
        if toks.sentence_of[a] != 0 or not all(w in lx.FILLERS | lx.DETERMINERS for w in norms[:a]) \
                or norms[e:e + 1] != ("to",) or e + 1 >= len(norms) \
                or not (toks.tokens[e + 1].text[:1].isupper() or norms[e + 1] in lx.STATIONS_CALLED or everyone):
            return False  # ("Marshal hut to control. Chair evac in progress ...")
        k = e + 1
        if everyone:  # "Top station to all units: the sky restaurant is ... , we're using it as ...": a broadcast
            k = e + 3 + (norms[e + 2] == "call" and norms[e + 3:e + 4] in (("signs",), ("sign",)))
            first = next((m for m in range(k + 1, len(norms)) if toks.clause_start[m]), len(norms))
            # (its message opens on another place it tells of; "X to all units: we have ..." is news of X)
            return k < len(norms) and toks.clause_start[k] and any(
                q.landmark != p.landmark and k <= q.start_tok < min(first, k + 4) for q in places) \
                and not {"our", "us", "ours", "my", "here", "this"} & set(norms[k:])
        if norms[k] in lx.STATIONS_CALLED and not toks.tokens[k].text[:1].isupper():
            k += 1
        while k < len(norms) and k - e <= 4 and not toks.clause_start[k] and (
                toks.tokens[k].text[:1].isupper() or toks.tokens[k].text.isdigit()):
            k += 1
        if k >= len(norms) or not toks.clause_start[k]:
            return False
        return not {"we", "our", "us", "were", "weve", "ours", "i", "im", "my", "ive", "here", "this"} & set(norms[k:])

    @staticmethod
    def _from_label(toks: Tokens, norms: tuple[str, ...], p: PlaceMention, places: Sequence[PlaceMention] = ()) -> bool:
        """"From the pump house: ...", "Relay from a station on the east ridge: ...": who is calling."""
        k = _noun_phrase_start(norms, p)
        if k >= 2 and norms[k - 1] == "at" and toks.sentence_start[k - 2] and norms[k - 2] in lx.ROLE_LABELS \
                and p.end_tok < len(norms) and toks.gaps[p.end_tok].strip().startswith(":"):
            return True  # "Marshal at post nine: the rainbow bridge is secure": who is calling, from where
        j = k - 1
        if j >= 3 and norms[j] == "at" and norms[j - 2:j] == ("at", "the"):
            j -= 2  # ("Steward at the — at the front gate, ...": the words said twice)
        if j >= 1 and norms[j] == "at" and toks.sentence_start[j - 1] and norms[j - 1] in lx.ROLE_LABELS \
                and p.end_tok < len(norms) and toks.gaps[p.end_tok].strip().startswith(",") \
                and not {"here", "us", "our", "we", "were"} & set(norms[p.end_tok:]) \
                and any(q.start_tok > p.end_tok and q.landmark != p.landmark and q.status != "negated" for q in places) \
                and toks.tokens[j - 1].text[:1].isupper():
            return True  # "Steward at the front gate, um, there's a bloke collapsed at the coal mill": who calls, from where
        if k == 2 and norms[0] in lx.STATIONS_CALLED and norms[1] == "from" and p.end_tok < len(norms) \
                and (toks.sentence_start[p.end_tok] or toks.gaps[p.end_tok].strip()[:1] in (",", ":")
                     and norms[p.end_tok] == "over"):
            return True  # "Control from tower one, over. Cafe kitchen's on fire": who is calling, from where
        if 2 <= k <= 3 and norms[k - 1] == "from" and not any(toks.sentence_start[i] for i in range(1, k)) \
                and (p.end_tok == len(norms) or toks.sentence_start[p.end_tok]) and toks.tokens[0].text[:1].isupper() \
                and all(w.isalpha() and w not in lx.FUNCTION_WORDS and w not in lx.FILLERS for w in norms[:k - 1]) \
                and (norms[0] in lx.ROLE_LABELS or norms[0] in _PERSON_KEYS or norms[0].endswith(("er", "ist", "man", "or"))):
            return True  # "Fitter from the workshop. Bund failure on the red diesel ...": who is calling, a sentence of its own
        if k < 1 or norms[k - 1] != "from" or p.end_tok >= len(norms) or not toks.gaps[p.end_tok].strip().startswith(":"):
            return False
        opener = k - 1
        while opener > 0 and not toks.sentence_start[opener] and k - opener <= 3 \
                and norms[opener - 1] in ("relay", "relayed", "relaying"):
            opener -= 1  # "Relay from ...:" (not "Report from the doctor's office:" nor "One from Willow Court:",
            # the place reported on)
        return bool(toks.sentence_start[opener])

    @staticmethod
    def _members_said_next(toks: Tokens, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """"... the coastguard cottages and, er, the end one, one of them's got a chimney come through": one of the
        place's own buildings, said right after it in the same sentence, is what the news is about."""
        n = toks.sentence_of[p.start_tok]
        window = [i for i in range(p.end_tok, min(len(norms), p.end_tok + 8)) if toks.sentence_of[i] == n]
        for i in window:
            if norms[i:i + 3] == ("one", "of", "them") \
                    or norms[i] == "the" and norms[i + 1:i + 2] and norms[i + 1] in lx.MEMBER_WORDS \
                    and norms[i + 2:i + 3] == ("one",):
                return True
        return False

    @staticmethod
    def _part_said_next(toks: Tokens, norms: tuple[str, ...], p: PlaceMention, places: list[PlaceMention]) -> bool:
        """"we're at the halt and the waiting room's ...": the next clause opens on a part of the place the crew is
        at ("the waiting room", "the kitchen"), no other place named before it."""
        k = p.end_tok
        while k < len(norms) and (norms[k] in lx.FILLERS or norms[k] in ("and", "now", "where", "so")) and k - p.end_tok < 5:
            k += 1
        if k + 1 >= len(norms) or norms[k] != "the" or not any(toks.clause_start[i] or norms[i] == "and"
                                                               for i in range(p.end_tok, k + 1)):
            return False
        if any(q.start_tok <= k + 2 and q.end_tok > k for q in places):
            return False
        return norms[k + 1] in lx.PREMISES_PARTS or norms[k + 1:k + 3] in lx.PREMISES_ROOMS

    @staticmethod
    def _watch_point(toks: Tokens, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """"From the abbey tower I can see the green is under water": where the speaker looks from."""
        k = _noun_phrase_start(norms, p)
        see = (("i", "can", "see"), ("we", "can", "see"))
        if k >= 4 and norms[k - 1] == "from" and any(norms[k - 4 - d:k - 1 - d] in see for d in range(2)):
            return True  # "What I can see from the gate is smoke ... coming out of the sawmill"
        if k >= 4 and norms[k - 1] == "from" and any(
                norms[i] in ("i", "we", "you") and norms[i + 1] in ("can", "could") and norms[i + 2] in ("hear", "see", "smell")
                and norms[i + 3] in ("it", "them", "that", "this") and (k - 1 - (i + 3) <= 2 or k - 1 - (i + 3) <= 5 and all(
                    w in ("right", "all", "the", "way", "over", "across", "out", "even", "up", "down", "here", "there")
                    for w in norms[i + 4:k - 1]))
                and not any(toks.clause_start[j] for j in range(i + 1, k)) for i in range(max(0, k - 10), k - 3)):
            return True  # "it's sparking, you can hear it cracking from the lodge", "you can smell it right across
            # from the mess room": where the listener is
        return k >= 1 and norms[k - 1] == "from" and bool(toks.sentence_start[k - 1]) and any(
            norms[p.end_tok + d:p.end_tok + d + 3] in see for d in range(3))

    @staticmethod
    def _kin_waiting_at(toks: Tokens, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """"two kids missing in the dorms ... their mum is at the lodge": where a lost one's people wait, in a
        sentence that says someone is lost; nothing is said of the place."""
        k = _noun_phrase_start(norms, p)
        if k < 3 or norms[k - 1] not in ("at", "in", "by", "outside"):
            return False
        waiting = any(
            norms[m] in _KIN and all(norms[t] in ("is", "s", "are", "waiting", "now", "still", "sat", "sitting", "stood",
                                                  "standing", "with", "us", "me")  # ("her mother is waiting with us at")
                                     or t == m + 1 and toks.tokens[m].text.lower().endswith(("'s", "’s"))
                                     for t in range(m + 1, k - 1))
            and (m == 0 or norms[m - 1] in ("their", "his", "her", "my", "the", "and", "whose") or toks.clause_start[m])
            for m in range(max(0, k - 7), k - 1))
        here = toks.sentence_of[p.start_tok]
        said_safe = any(norms[m] in ("safe", "secure", "warm", "checked", "clear") for m in range(p.end_tok, len(norms))
                        if toks.sentence_of[m] == here)
        with_caller = any(norms[m] == "with" and norms[m + 1:m + 2] in (("us",), ("me",)) for m in range(max(0, k - 7), k))
        return waiting and any(norms[c] in _LOST_WORDS for c in range(0, k)
                               if toks.sentence_of[c] == here
                               or toks.sentence_of[c] == here - 1 and with_caller and not said_safe)
        # (or the sentence before, where they wait with the caller: "... last seen at the inflatables. Her mother is
        # waiting with us at the medical tent."; not "The parents are waiting at the jeep stand, which police say is
        # safe")

    @staticmethod
    def _everyone_from(toks: Tokens, norms: tuple[str, ...], p: PlaceMention, places: list[PlaceMention]) -> bool:
        """"Everyone from the screens and the stacker, muster there": the people are named by where they are now, and
        told to go elsewhere; nothing is said of those places."""
        k = _noun_phrase_start(norms, p)
        while k >= 2 and norms[k - 1] in ("and", "or") and (q := next(
                (q for q in places if q.end_tok == k - 1 and q is not p), None)) is not None:
            k = _noun_phrase_start(norms, q)  # ("from the screens and the stacker")
        if k < 2 or norms[k - 1] != "from" or norms[k - 2] not in ("everyone", "everybody", "anyone", "anybody", "all"):
            return False
        end = p.end_tok
        while end < len(norms) and norms[end] in ("and", "or") or any(q.start_tok <= end < q.end_tok for q in places):
            end += 1
        return end < len(norms) and toks.clause_start[end] and any(
            norms[i] in ("muster", "go", "head", "move", "report", "gather", "assemble", "make")
            for i in range(end, min(len(norms), end + 3)))

    @staticmethod
    def _person_from(toks: Tokens, norms: tuple[str, ...], p: PlaceMention, places: list[PlaceMention]) -> bool:
        """"The old boy from the smokehouse is lying in the shed": a person known by their place, said to be in
        another place right after."""
        k = _noun_phrase_start(norms, p)
        if k < 2 or norms[k - 1] != "from" or norms[k - 2] not in _PERSON_KEYS or p.end_tok >= len(norms) \
                or norms[p.end_tok] not in ("is", "s", "was", "are", "were", "has", "had") or toks.clause_start[p.end_tok]:
            return False
        n = toks.sentence_of[p.start_tok]
        # ("a fisherman from the kampung has been pulled out of the water under the wharf": in the same clause)
        return any(q.status == "active" and q.landmark != p.landmark and toks.sentence_of[q.start_tok] == n
                   and (p.end_tok < q.start_tok <= p.end_tok + 5
                        or norms[p.end_tok] == "has" and p.end_tok + 5 < q.start_tok <= p.end_tok + 10
                        and not any(toks.clause_start[t] for t in range(p.end_tok, q.start_tok + 1))) for q in places)

    @staticmethod
    def _locates_other(norms: tuple[str, ...], p: PlaceMention, places: list[PlaceMention]) -> str:
        """"the Red Lion, round the corner from the square", "the coffee house on the east side of the square":
        a place named only to say where another is; the reason, or ""."""
        k = _noun_phrase_start(norms, p)
        if k >= 4 and norms[k - 3:k] == ("the", "corner", "from") and norms[k - 4] in ("round", "around"):
            return "near it ('round the corner from'): no claim"
        if k >= 3 and norms[k - 3:k] in (("not", "that", "thats"), ("not", "that", "that")):
            return "what the place taken back was ('not that, that's X'): no claim"
        if k < 3 or norms[k - 1] != "of" or norms[k - 2] not in ("side", "end", "edge", "rim"):
            return ""
        for q in places:
            if q is p or q.status not in ("active", "reference") or not q.end_tok < k - 2:
                continue
            m = q.end_tok
            if norms[m:m + 1] == ("of",) and m + 1 < k and norms[m + 1].isalpha() \
                    and norms[m + 1] not in lx.FUNCTION_WORDS:
                m += 2  # "the pile of rocks out on the rim of the gumbo": what the place is made of
            m += norms[m:m + 1] in (("out",), ("over",), ("up",), ("down",))
            if k - m <= 6 and norms[m] in ("on", "at") and all(w in _SIDE_WORDS for w in norms[m:k]):
                return f"where '{q.text}' stands ('{' '.join(norms[q.end_tok:k])}'): no claim"
        return ""

    def _teller_at(self, toks: Tokens, norms: tuple[str, ...], p: PlaceMention, places: list[PlaceMention]) -> bool:
        """"Echo One at the fire station: the building across from our station ...", "Officers at the bank report the
        building across the street from them ...": where the one telling is, then the anchor of the place told of."""
        j = _noun_phrase_start(norms, p)
        e = p.end_tok
        if j < 2 or norms[j - 1] not in ("at", "in", "inside", "outside") or e >= len(norms) \
                or not (toks.gaps[e].strip().startswith(":") or norms[e] in lx.TELLING_VERBS):
            return False
        c = j - 1
        while c > 0 and not toks.clause_start[c]:
            c -= 1
        if any(self._cues.match_at(norms, i) is not None for i in range(c, j - 1)):
            return False  # "fire at the bakery: the building next to it ...": the place claimed, then another
        n = toks.sentence_of[p.start_tok]
        return any(q.status == "active" and q.start_tok >= e and toks.sentence_of[q.start_tok] <= n + 1
                   and _anchored_at(q, p.landmark) for q in places)

    def _apply_transit(self, ex: Extraction) -> None:
        """"heading to the bakery", "passing the church": the team moves; nothing is claimed there."""
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        supposed = self._conditional_tokens(toks, norms)
        for idx, p in enumerate(ex.places):
            if p.status == "active" and (p.via or "").startswith("description of"):
                if self._from_label(toks, norms, p):
                    ex.places[idx] = replace(p, status="reference", reason="who is calling ('From X:'): no claim")
                    continue
                if p.start_tok == 0 and self._calls_by_name(toks, norms, p, ex.places):
                    # ("Harbour office to all boats, the yard is a safe landing": a name said without its article)
                    ex.places[idx] = replace(p, status="reference", reason="who is calling ('X to Y:'), said of no more")
                    continue
                if toks.sentence_start[p.start_tok] and norms[p.end_tok:p.end_tok + 1] == ("reporting",) and any(
                        q.landmark != p.landmark and q.status == "active" and q.start_tok > p.end_tok
                        and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok] for q in ex.places):
                    # ("Coastguard hut reporting smoke from the pump shed": a caller named by its description)
                    ex.places[idx] = replace(p, status="reference", reason="who is calling ('X reporting'): no claim")
                    continue
            if p.status != "active" or p.via is not None:
                continue
            if p.start_tok in supposed:
                ex.places[idx] = replace(p, status="reference", reason="named in a condition ('if ...'): no claim")
                continue
            if self._called_station(toks, norms, p, ex.places):
                ex.places[idx] = replace(p, status="reference", reason="the station called ('X to Y,'): no claim")
                continue
            if p.end_tok < len(norms) and toks.clause_start[p.end_tok] and not toks.sentence_start[p.end_tok] \
                    and self._this_is_who_at(toks, norms, p, ex.places):
                # ("this is Ahmed at the front desk, a lady fainted in the restaurant": who calls, from where)
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('this is X at Y,'): no claim")
                continue
            if self._calls_by_name(toks, norms, p, ex.places):
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('X to Y:'), said of no more")
                continue
            j = _noun_phrase_start(norms, p)
            if j >= 2 and norms[j - 1] == "by" and norms[j - 2] in _CHECKED_BY \
                    and any(q.landmark != p.landmark and q.status == "active" and q.end_tok <= j - 2
                            and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok] for q in ex.places):
                # "The train depot has been checked by the fire department": who checked it, not a place spoken of
                ex.places[idx] = replace(p, status="reference", reason="who did it ('checked by X'): no claim")
                continue
            k = j - 1 if j >= 1 and norms[j - 1] in ("up", "at", "in", "on", "down", "from", "by") else j
            if k >= 4 and norms[k - 1] in lx.LAY_PERSONS | lx.WORKER_PERSONS and norms[k - 2] in ("a", "an", "the") \
                    and norms[k - 3] == "from" and norms[k - 4] in _CALL_NOUNS \
                    and not any(toks.clause_start[m] for m in range(k - 3, p.start_tok + 1)) \
                    and any(q.start_tok > p.end_tok and q.landmark != p.landmark and q.status == "active" for q in ex.places):
                # (only where the call tells of another place: "a call from a resident on Cinder Row: her neighbour ...
                # has had a fall" is news of the row)
                ex.places[idx] = replace(p, status="reference", reason="where a caller is ('a call from a lady up "
                                                                      "the terrace'): no claim")
                continue
            if j >= 3 and norms[j - 1] == "from" and norms[j - 2] in ("up", "down", "in", "over", "back", "out") \
                    and norms[j - 3] in lx.BRING_VERBS:
                ex.places[idx] = replace(p, status="reference", reason="where people are brought from: no claim")
                continue  # "a rest point for anyone you bring up from the river end"
            if 0 < j <= 3 and toks.sentence_of[p.start_tok] == 0 and all(w in lx.STATIONS_CALLED | lx.FILLERS for w in norms[:j]) \
                    and norms[0] in lx.STATIONS_CALLED and p.end_tok + 1 < len(norms) and norms[p.end_tok] in lx.ARTICLES \
                    and not toks.tokens[p.end_tok].text[:1].isupper() and not any(
                        toks.gaps[i].strip() for i in range(1, p.end_tok + 1)) and any(
                        q.start_tok == p.end_tok + 1 and q.status == "active" for q in ex.places):
                # "control control tower two the old pool is full of brown water": the station called, who calls,
                # then the place told of, unpunctuated
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('control X'): no claim")
                continue
            if 0 < j <= 3 and toks.sentence_of[p.start_tok] == 0 and norms[0] in lx.STATIONS_CALLED \
                    and all(w in lx.STATIONS_CALLED | lx.FILLERS for w in norms[:j]) \
                    and [w for w in norms[p.end_tok:p.end_tok + 4] if w not in lx.FILLERS][:1] in (["we"], ["i"]) \
                    and any(q.status != "retracted" and q.landmark != p.landmark and q.start_tok > p.end_tok
                            and toks.sentence_of[q.start_tok] == 0 for q in ex.places):
                # "control marshal hut er we have a casualty at the ford": the station called, who calls, then "we"
                # and the place told of
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('control X, we ...'): no claim")
                continue
            if (p.start_tok == 0 or toks.sentence_start[p.start_tok]) and norms[p.end_tok:p.end_tok + 1] == ("to",) \
                    and norms[p.end_tok + 1:p.end_tok + 2] and norms[p.end_tok + 1] in lx.STATIONS_CALLED \
                    and p.end_tok + 2 < len(norms) and toks.clause_start[p.end_tok + 2] \
                    and [w for w in norms[p.end_tok + 2:p.end_tok + 6] if w not in lx.FILLERS][:1] in (
                        ["we"], ["weve"], ["i"], ["ive"]) \
                    and any(q.status != "retracted" and q.landmark != p.landmark and q.start_tok > p.end_tok
                            for q in ex.places):
                # "First aid post to control, we've had a lost child reported, ... last seen at the inflatables":
                # who calls whom, then the news of another place
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('X to control, we ...'): no claim")
                continue
            if toks.sentence_start[p.start_tok] and p.end_tok + 1 < len(norms) \
                    and norms[p.end_tok] in ("reporting", "calling", "speaking") and (toks.clause_start[p.end_tok + 1] \
                    and any(q.landmark != p.landmark and q.status in ("active", "negated", "reference") for q in ex.places)
                    # ("Coastguard hut reporting smoke from the pump shed": what it reports is of the place named after)
                    or norms[p.end_tok] == "reporting" and any(
                        q.landmark != p.landmark and q.status == "active" and q.start_tok > p.end_tok
                        and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok] for q in ex.places)):
                # (with no other place told of, the news is its own: "Pascoe's yard reporting, two boats blown off
                # their cradles")
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('X reporting,'): no claim")
                continue
            if self._from_label(toks, norms, p, ex.places) and not (
                    (norms[_noun_phrase_start(norms, p) - 1] == "at"
                     or {"our", "we", "were", "weve", "us"} & set(norms[p.end_tok:p.end_tok + 8]))
                    and not any(q.landmark != p.landmark and q.status != "retracted" for q in ex.places)):
                # ("From the OB compound: two of our riggers down with heat stroke": its own people, its own news)
                # ("Paramedic at the mission hut: two lads brought in": no other place told of, the news is its own)
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('From X:'): no claim")
                continue
            if toks.sentence_start[p.start_tok] and p.end_tok < len(norms) and ":" in toks.gaps[p.end_tok] \
                    and (norms[p.end_tok - 1].isdigit() or norms[p.end_tok - 1] in lx.NUMBER_WORDS) \
                    and any(q.status == "active" and q.landmark != p.landmark and q.via is None
                            and (q.start_tok == p.end_tok or q.start_tok == p.end_tok + 1 and norms[p.end_tok] in lx.ARTICLES)
                            and not toks.sentence_start[q.start_tok] for q in ex.places):
                ex.places[idx] = replace(p, status="reference", reason="who is calling ('X: Y flooded'): no claim")
                continue  # "Post four: esses flooded": the caller's label, another place said of at once
            if self._watch_point(toks, norms, p):
                ex.places[idx] = replace(p, status="reference", reason="where the speaker looks from ('From X I can see')")
                continue
            if self._kin_waiting_at(toks, norms, p):
                ex.places[idx] = replace(p, status="reference", reason="where the lost one's people wait: no claim")
                continue
            if self._everyone_from(toks, norms, p, ex.places):
                ex.places[idx] = replace(p, status="reference", reason="where the people told to move are from: no claim")
                continue
            if self._person_from(toks, norms, p, ex.places):
                ex.places[idx] = replace(p, status="reference", reason="where the person is from, not where they are")
                continue
            k = _noun_phrase_start(norms, p)
            if k >= 2 and norms[k - 1] == "off" and any(
                    norms[t] in lx.SEND_VERBS and not any(toks.clause_start[m] for m in range(t + 1, k))
                    for t in range(max(0, k - 6), k - 1)):
                ex.places[idx] = replace(p, status="reference", reason="where people are sent from: no claim")
                continue  # "we're sending the families off the tourer field in there to wait it out"
            e = p.end_tok + (norms[p.end_tok:p.end_tok + 1] in (("up",), ("down",), ("over",), ("across",), ("back",)))
            if k >= 1 and norms[k - 1] in ("moved", "move", "moving", "relocated", "shifted") \
                    and norms[e:e + 1] in (("to",), ("into",)) and e + 1 < len(norms) and norms[e + 1] in lx.ARTICLES:
                ex.places[idx] = replace(p, status="reference", reason="what was moved to another place: no claim")
                continue  # "we've moved the office up to the warden's bungalow": the office goes, no news of its place
            where = self._locates_other(norms, p, ex.places)
            if where:
                ex.places[idx] = replace(p, status="reference", reason=where)
                continue
            if self._teller_at(toks, norms, p, ex.places):
                ex.places[idx] = replace(p, status="reference", reason="where the teller is, the anchor of the place described")
                continue
            j = p.start_tok
            while j > 0 and norms[j - 1] in lx.DETERMINERS | lx.FILLERS | {"at", "to", "by", "the", "from"} \
                    and p.start_tok - j < 5 and (not toks.clause_start[j] or norms[j - 1] in lx.ARTICLES | lx.FILLERS
                                                  | {"to", "at", "by"}):
                j -= 1  # ("heading to the, er, the bus station": past a hesitation that broke the phrase)
            if j >= 3 and norms[j] == "at" and toks.tokens[j - 1].text.lower().replace("’", "'").endswith("'s") \
                    and norms[j - 2] in ("my", "his", "her", "our", "their"):
                j -= 2  # "on my way to my mom's at Willow Court": to someone's home there
            if self._crew_position(norms, p.start_tok) and not any(
                    norms[i] == "both" and toks.clause_start[i] and toks.sentence_of[i] == toks.sentence_of[p.start_tok]
                    for i in range(p.end_tok, min(len(norms), p.end_tok + 8))):
                # (not "Crews are at the tavern and the clinic, both buildings are safe refuges": said of both)
                ex.places[idx] = replace(p, status="reference", reason=_CREW_POSITION)
                continue
            if self._evacuated_to(toks, norms, p.end_tok):
                ex.places[idx] = replace(p, status="reference", reason="evacuated to another place: no claim")
                continue
            w = k - 1  # (the word before the noun phrase)
            if w >= 1 and norms[w] in ("at", "in") and (norms[w - 1] in ("whoever", "whoevers") or w >= 2 and norms[
                    w - 2:w] == ("whoever", "is")) and (p.end_tok == len(norms) or toks.clause_start[p.end_tok]):
                # "Whoever's at the radio shack, the sled that powers your hut is on fire": who is called, no claim
                ex.places[idx] = replace(p, status="reference", reason="whoever is there is called: no claim")
                continue
            if j >= 2 and norms[j] == "at" and norms[j - 1] in ("look", "stare", "gawp") and norms[j - 2] == "to":
                # "he went to the gardens to look at the tip and he's not come back": what he went to see
                ex.places[idx] = replace(p, status="reference", reason="what was looked at: no claim")
                continue
            prep = j if norms[j] in ("at", "in", "on") else j - 1
            if prep >= 1 and norms[prep] in ("at", "in", "on") and norms[prep - 1] in ("were", "was") \
                    and norms[p.end_tok:p.end_tok + 1] in (("before",), ("earlier",)) and any(
                        norms[m] == "now" and any(q.start_tok > m and q.landmark != p.landmark for q in ex.places)
                        for m in range(p.end_tok + 1, len(norms))):
                # "we were at the camp before, uh, now we're up at the helipad": where the speaker was
                ex.places[idx] = replace(p, status="reference", reason="where the speaker was before: no claim")
                continue
            mover = next((m for m in range(j - 2, max(-1, j - 9), -1) if norms[m] in _ON_THE_MOVE), None) \
                if j >= 2 and norms[j - 1] in ("towards", "toward") else None
            if mover is not None and not any(toks.clause_start[i] for i in range(mover + 1, j)):
                # "it's running along the top wall towards the threshing floor": where the danger is heading
                ex.places[idx] = replace(p, status="reference", reason="in transit ('towards'): no claim")
                continue
            if any(norms[k:k + 2] == ("last", "seen") for k in range(max(0, j - 7), j)):
                continue  # "Last seen going into the still house": where the missing were last, no passing through
            if j >= 5 and norms[j - 3:j] in (("coming", "out", "of"), ("walking", "out", "of")) \
                    and norms[j - 4] in _PEOPLE_WORDS | {"visitors", "crowds", "crowd", "people", "families"} \
                    and norms[j - 5] in ("the", "for", "all") \
                    and not any(toks.clause_start[i] for i in range(j - 3, j + 1)):
                # "assembly points for the visitors coming out of the engine hall": where people leave from
                ex.places[idx] = replace(p, status="reference", reason="where people come out of: no claim")
                continue
            for k in range(max(0, j - 5), j):
                hit = self._transit.match_at(norms, k)
                if hit is not None and norms[k] == "were" and "'" not in toks.tokens[k].text.replace("’", "'") \
                        and not toks.sentence_start[k] and norms[k - 1] != "we":
                    continue  # "my son and his friend were at the gym": "were", not "we're"
                if hit is not None and hit[1].startswith("route ") and k > 0 and not toks.clause_start[k]:
                    continue  # "evacuation route through the square is clear": a route said to be safe; "route via" orders
                if hit is not None and hit[1] == "in off the" and k > 0 and norms[k - 1] in (
                        "gone", "went", "fallen", "fell", "slipped", "jumped", "go"):
                    continue  # "a fisherman's gone in off the weir": into the water there, no one passing
                if hit is not None and hit[1].split()[0] in ("came", "come", "coming") and len(hit[1].split()) == 3 \
                        and not any(norms[m] in lx.MOVING_PEOPLE | lx.WORKER_PERSONS | _MOVING_VEHICLES | lx.CREW_NOUNS
                                    or norms[m] in lx.CALLER_ROLES for m in range(max(0, k - 4), k)):
                    continue  # "debris came down from the roof": a thing fallen, not people who came from there (but
                    # "ambulance is coming in through the car park": a crew on its way)
                if hit is not None and j <= hit[0] <= p.start_tok and not any(toks.clause_start[i] for i in range(k + 1, min(hit[0], p.start_tok) + 1) if i < p.start_tok):
                    if norms[k] in ("passing", "past", "going", "driving", "walking", "passed") \
                            and (norms[p.end_tok:p.end_tok + 2] in lx.SEEN_THERE
                                 or norms[p.end_tok:p.end_tok + 1] in lx.SEEN_THERE
                                 or "past" in hit[1].split() + [hit[1]] and self._sighting_after(ex, norms, p)):
                        break  # "going past the town hall there was loads of people hurt": what was seen there
                    if any(norms[i] in ("dont", "never") or norms[i:i + 2] == ("do", "not") for i in range(max(0, k - 2), k)):
                        break  # "dont go to the bakery, theres a fire": a warning about the place, not a move
                    if norms[p.end_tok:p.end_tok + 1] == ("where",) and hit[1].split()[0] in ("heading", "headed", "going") \
                            and any(self._role_cue_at(norms, m, Role.CRITICAL) for m in range(p.end_tok + 1, min(len(norms), p.end_tok + 9))):
                        break  # "we're heading to the rope line where a guy's got heat stroke": who is hurt there
                    if norms[p.end_tok:p.end_tok + 2] in (("which", "is"), ("which", "s"), ("which", "has")) \
                            and hit[1].split()[0] in ("diverting", "diverted", "rerouting", "relocating", "moving",
                                                      "heading", "headed", "going", "evacuating", "sending", "taking"):
                        break  # "they're diverting to the cow field, which is clear and safe": said of where they go
                    if hit[1].split()[0] in ("keep", "stay") and "away" in hit[1].split() and self._sighting_after(ex, norms, p):
                        break  # "keep everyone away from the cookhouse, one of the gas bottles is leaking": why
                    if self._members_said_next(toks, norms, p):
                        break  # "heading for the coastguard cottages and, er, the end one, one of them's got ...": news of it
                    if hit[1] in ("we're at", "we are at", "currently at") and self._part_said_next(toks, norms, p, ex.places):
                        break  # "now we're at the halt and the waiting room's being used as a warm-up station": its room
                    ex.places[idx] = replace(p, status="reference", reason=f"in transit ('{hit[1]}'): no claim")
                    break
        # "that long shed in front of the park — the park the flats look across at": the reference point said again
        # to describe it is still only the reference point
        for idx, p, j in self._bare_places(ex, norms):
            ref = next((q for q in ex.places if q.status == "reference" and q.landmark == p.landmark and q.via is None
                        and 0 <= j - q.end_tok <= 4 and all(norms[i] in lx.FILLERS or norms[i:i + 2] == ("you", "know")
                                                            or norms[i - 1:i + 1] == ("you", "know") for i in range(q.end_tok, j))
                        and any(d in toks.gaps[i] for i in range(q.end_tok, j + 1) for d in ("—", "–", "--", " - ", ","))
                        and q.reason.startswith("reference point:")), None)
            own = p.end_tok >= len(norms) or norms[p.end_tok] in lx.COPULAS | lx.ANAPHOR_VERBS | {"itself"} \
                or toks.tokens[p.end_tok - 1].text.lower().endswith(("'s", "’s")) or toks.clause_start[p.end_tok]
            if ref is not None and not own:  # (not "..., the park is safe though": said of it)
                ex.places[idx] = replace(p, status="reference", reason=f"the reference point said again ({ref.text})")
        # "the fire circle at the edge of the glamping field, the one you reach through the car park": an aside that
        # says which the reference point is, described, is still only the reference point
        for idx, p in enumerate(ex.places):
            if p.status != "active" or p.via is None or norms[p.start_tok:p.start_tok + 2] != ("the", "one"):
                continue
            ref = next((q for q in ex.places if q.status == "reference" and q.landmark == p.landmark and q.via is None
                        and q.reason.startswith("reference point") and 0 <= p.start_tok - q.end_tok <= 1
                        and any(d in toks.gaps[i] for i in range(q.end_tok, p.start_tok + 1) for d in ("—", "–", "--", ","))),
                       None)
            if ref is not None:
                ex.places[idx] = replace(p, status="reference", reason=f"the reference point said again ({ref.text})")
        # "we've got twenty folk from the almshouses in already", "kids from the primary": where people came from is
        # no claim, unless what follows says what is wrong with them there ("the kids from the school are stuck
        # on the first floor")
        starts = {q.start_tok for q in ex.places}
        for idx, p, j in self._bare_places(ex, norms):
            if j >= 2 and norms[j - 1] == "than" and norms[j - 2] in lx.COMPARATIVES:
                ex.places[idx] = replace(p, status="reference", reason="a comparison: no claim")
                continue  # "flames going higher than the arches"
            if j >= 2 and norms[j - 1] == "from" and norms[j - 2] in _PEOPLE_WORDS and any(
                    q.status == "active" and q.start_tok >= p.end_tok and q.landmark != p.landmark
                    and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok]
                    and any(norms[m] in ("hes", "shes", "theyre") or norms[m] in ("he", "she", "they")
                            and norms[m + 1] in ("s", "is", "are", "re") for m in range(max(p.end_tok, q.start_tok - 5), q.start_tok))
                    for q in ex.places):
                # "A lad from the burger place got burned trying to put it out, he's sitting in the yard": where he
                # works, not where he is
                ex.places[idx] = replace(p, status="reference", reason="where people came from: no claim")
                continue
            if not (j >= 2 and norms[j - 1] == "from" and (norms[j - 2] in lx.ORIGIN_PEOPLE or (
                    is_number(norms[j - 2]) and not is_ordinal(norms[j - 2])
                    and (j < 3 or norms[j - 3] not in ("the", "number", "no"))))):
                continue  # (and a head count: "about forty from the dam houses up there already")
            ahead = range(p.end_tok, min(len(norms), p.end_tok + 12))
            stop = next((i for i in ahead if i in starts or toks.sentence_start[i]), ahead.stop)
            if any(self._person_cue_at(norms, i) for i in range(p.end_tok, stop)):
                continue
            if stop < len(norms) and toks.sentence_start[stop] and stop not in starts:
                nxt = range(stop, next((i for i in range(stop + 1, len(norms)) if toks.sentence_start[i]), len(norms)))
                it = next((i for i in nxt if norms[i] in ("it", "its")), None)
                if it is not None and not any(i in starts for i in range(stop, it)) and not any(
                        q is not p and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok] for q in ex.places) \
                        and any(self._cues.match_at(norms, i) is not None for i in range(it, nxt.stop)):
                    continue  # "Everyone from the bunkhouse is accounted for. We're using it as the rest point"
            ex.places[idx] = replace(p, status="reference", reason="where people came from: no claim")
        # "and the deanery, well, we haven't been to the deanery yet": a place not visited yet, and the same
        # place said just before as what the clause is about, claim nothing
        for idx, p, j in self._bare_places(ex, norms):
            if not any(norms[max(0, j - len(k)):j] == k for k in lx.NOT_VISITED):
                continue
            ex.places[idx] = replace(p, status="reference", reason="not been there yet: no claim")
            for jdx, q in enumerate(ex.places):
                if q.landmark == p.landmark and q.status == "active" and q.end_tok <= j \
                        and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok] \
                        and all(w in lx.FILLERS or w in ("we", "i", "they") or w in lx.NOT_VISITED_WORDS
                                for w in norms[q.end_tok:j]):
                    ex.places[jdx] = replace(q, status="reference", reason="not been there yet: no claim")
        # "and er the church we didn't get to": the place, then that it was not reached
        for idx, p in enumerate(ex.places):
            if p.status != "active" or p.via is not None:
                continue
            k = p.end_tok
            if k < len(norms) and norms[k] in ("we", "i", "they", "crews", "nobody", "noone"):
                tail = norms[k + 1:k + 4]
                if any(tail[:len(t)] == t for t in lx.NOT_REACHED) and (
                        k + 1 + 3 >= len(norms) or any(toks.clause_start[t] for t in range(k + 2, min(len(norms), k + 5)))
                        or "yet" in norms[k + 1:k + 5]):
                    ex.places[idx] = replace(p, status="reference", reason="not been there yet: no claim")
        # "walked past the cafe and the clinic, and at the police station ...": the list passed, every place of it
        for idx, p in enumerate(ex.places):
            if p.status != "active" or p.via is not None or p.start_tok < 2:
                continue
            j = p.start_tok - 1
            while j > 0 and norms[j] in lx.DETERMINERS | lx.FILLERS:
                j -= 1
            if norms[j] != "and" or toks.clause_start[j] or not (
                    p.end_tok >= len(norms) or toks.clause_start[p.end_tok] or norms[p.end_tok] in ("and", "but")
                    or norms[p.end_tok:p.end_tok + 3] in (("on", "the", "way"), ("on", "our", "way"), ("on", "my", "way"))):
                continue  # ("passing the bank and the church on the way")
            prev = next((q for q in ex.places if q.end_tok == j
                         and q.reason.startswith(("in transit ('past", "in transit ('passing", "in transit ('keep",
                                                  "in transit ('stay"))), None)
            if prev is not None:
                ex.places[idx] = replace(p, status="reference", reason=prev.reason)

    def _sighting_after(self, ex: Extraction, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """"just walked past the flats, like half the windows are blown out": the rest of the sentence after a
        place passed says what is there (a cue, and no other place)."""
        toks = ex.tokens
        end = next((t for t in range(p.end_tok, len(norms)) if toks.sentence_start[t]), len(norms))
        if any(q is not p and p.end_tok <= q.start_tok < end for q in ex.places):  # (the sentence's end)
            return False
        after = {h[1][0] for k in range(p.end_tok, end) if (h := self._cues.match_at(norms, k)) is not None}
        if not after:
            return False
        begin = next((t for t in range(p.start_tok, -1, -1) if toks.sentence_start[t]), 0)
        for k in range(begin, p.start_tok):
            h = self._cues.match_at(norms, k)
            if h is None or h[1][0] not in after:
                continue
            j = h[0]
            while j < p.start_tok and norms[j] in lx.FILLERS | {"at", "in", "on", "inside"} | lx.ARTICLES:
                j += 1
            if j > h[0] and j < p.start_tok and "at" in norms[h[0]:j] and norms[j].isalpha() \
                    and not any(q.start_tok <= j < q.end_tok for q in ex.places):
                return False  # "a massive fire at the cinema ..., out past the water tower, like huge flames": the
                # same danger said again, at the place the KB does not name
        return True

    @staticmethod
    def _evacuated_to(toks: Tokens, norms: tuple[str, ...], e: int) -> bool:
        """"Anchor Inn has been evacuated to the car park", "Marlowe Court residents have been moved to ...":
        the place people left is no claim; the place they went to may be."""
        k = e
        if k < len(norms) and norms[k] in lx.EVACUEES:
            k += 1
        while k < len(norms) and norms[k] in {"has", "have", "s", "ve", "been", "is", "are", "were", "was", "all", "now",
                                               "just", "already"} | lx.FILLERS and k - e < 5:
            k += 1
        return k + 1 < len(norms) and norms[k] in lx.EVACUATED_FROM and norms[k + 1] in ("to", "into", "over") \
            and not any(toks.clause_start[i] for i in range(e, k + 1))

    @staticmethod
    def _crew_position(norms: tuple[str, ...], j: int) -> bool:
        """"team two is at the park", "engine 4's outside the bank": where a crew stands claims nothing."""
        while j > 0 and norms[j - 1] in lx.DETERMINERS | lx.FILLERS:
            j -= 1
        if j >= 3 and norms[j - 1] in lx.POSITION_PREPS and norms[j - 2] in ("up", "down", "out", "still", "now") \
                and (norms[j - 3] == "im" or j >= 4 and norms[j - 4:j - 2] in (("i", "m"), ("i", "am"))):
            return True  # "I'm up on the hardware store roof and the place directly behind it ...": where the speaker is
        if j < 3 or norms[j - 1] not in lx.POSITION_PREPS or norms[j - 2] not in ("is", "s", "are", "re"):
            return False
        k = j - 3
        if k > 0 and (norms[k].isdigit() or norms[k] in lx.NUMBER_WORDS or norms[k] == "one"):
            k -= 1
        if norms[k] not in lx.CREW_NOUNS:
            return False
        # ("Staging area for the hazmat team is at the municipal building": the place the crew is given, the subject)
        return not any(norms[i] == "for" and norms[i - 1] in ("area", "point", "post", "base", "centre", "center", "zone")
                       for i in range(max(1, k - 4), k))

    @staticmethod
    def _said_in_a_sentence_before(toks: Tokens, norms: tuple[str, ...], p: PlaceMention, q: PlaceMention) -> bool:
        """"Missing quarryman believed to be inside the compressor house. The compressors are leaking": the first
        place ends a sentence that says something of it, so the next sentence naming it again is no restart."""
        if not any(toks.sentence_start[k] for k in range(p.end_tok, q.start_tok + 1)):
            return False
        s = max(t for t in range(p.start_tok + 1) if toks.sentence_start[t] or t == 0)
        return any(norms[k] not in lx.DETERMINERS | lx.FILLERS for k in range(s, _noun_phrase_start(norms, p)))

    def _apply_dropped(self, ex: Extraction) -> None:
        """"there's a wash-through ... and the top block - never mind, haven't got to the top block yet": a place
        just begun, then dropped with "never mind" before anything is said of it."""
        norms = ex.tokens.norms(0, len(ex.tokens))
        for idx, p in enumerate(ex.places):
            k = p.end_tok
            while k < len(norms) and norms[k] in lx.FILLERS:
                k += 1
            if p.status == "active" and (norms[k:k + 2] == ("never", "mind") or norms[k:k + 1] == ("nevermind",)):
                ex.places[idx] = replace(p, status="retracted", reason="dropped ('never mind')")

    def _apply_restarts(self, ex: Extraction) -> None:
        """"the church is — the church is being used": the first mention is a false start."""
        norms = ex.tokens.norms(0, len(ex.tokens))
        order = sorted((i for i, p in enumerate(ex.places) if p.status == "active"), key=lambda i: ex.places[i].start_tok)
        for i, j in zip(order, order[1:], strict=False):
            p, q = ex.places[i], ex.places[j]
            if p.landmark != q.landmark:
                continue
            between = norms[p.end_tok : q.start_tok]
            toks = ex.tokens
            alone = not between and toks.sentence_start[q.start_tok] and all(
                norms[k] in lx.DETERMINERS | lx.FILLERS for k in range(
                    max(t for t in range(p.start_tok + 1) if toks.sentence_start[t]), p.start_tok))
            if alone and not self._cue_at(norms, p.start_tok):
                # "chemist. chemist's on fire.": a place said alone, then its sentence begun with it
                ex.places[i] = replace(p, status="retracted", reason="restarted: the speaker repeats the place")
                ex.places[j] = replace(q, replaces=p.start_tok)
                continue
            denied = {k for r in ex.places if r.status == "negated" and p.end_tok <= r.start_tok and r.end_tok <= q.start_tok
                      for k in range(r.start_tok, r.end_tok)}
            pre = _noun_phrase_start(norms, p)
            if denied and norms[min(denied) - 1:min(denied)] in (("not",), ("the",)) and p.replaces is None \
                    and not (pre > 0 and norms[pre - 1] in ("s", "is", "its", "was")):
                # (not "it's the town hall, not the library. So, the town hall": the place said, then said again)
                # "the chairlift, not the t-bar, the chairlift's got a chair ripped off": past the place denied
                between = [norms[k] for k in range(p.end_tok, q.start_tok) if k not in denied and norms[k] != "not"]
            if between and len(between) <= 4 and all(w in lx.COPULAS | lx.FILLERS | lx.DETERMINERS | lx.PRONOUNS for w in between) \
                    and any(ex.tokens.clause_start[k] for k in range(p.end_tok, q.start_tok + 1)) \
                    and not any(";" in ex.tokens.gaps[k] for k in range(p.end_tok, q.start_tok + 1)) \
                    and not self._said_in_a_sentence_before(toks, norms, p, q) \
                    and not self._cue_at(norms, p.start_tok):
                # (not "frostbite case at the berghaus; the mountain hut is secure": the first has its own claim)
                ex.places[i] = replace(p, status="retracted", reason="restarted: the speaker repeats the place")
                ex.places[j] = replace(q, replaces=p.start_tok)

        # "not the mess hall, the mess hall's ok": the place denied, said again with why not
        for i, q in enumerate(ex.places):
            if q.status != "active":
                continue
            r = next((r for r in ex.places if r.status == "negated" and r.landmark == q.landmark and r.end_tok < q.start_tok
                      and all(w in lx.DETERMINERS | lx.FILLERS for w in norms[r.end_tok:q.start_tok])), None)
            after = [ex.tokens.tokens[k].text.lower() for k in range(q.end_tok, min(len(norms), q.end_tok + 3))
                     if norms[k] not in {"s", "is", "um", "uh", "er", "erm"}]  # ("ok" is a filler's word elsewhere)
            if r is not None and after[:1] in (["ok"], ["okay"], ["fine"], ["alright"]):
                ex.places[i] = replace(q, status="negated", reason="the place denied, said again ('ok')")

    def _after_clause(self, ex: Extraction, k: int) -> tuple[int, int]:
        """Tokens of the first clause after marker ``k`` (up to a clause break, coordinator or marker)."""
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        a, b, strong = ex.markers[k]
        if not strong and b < len(toks) and toks.sentence_start[b] and k > 0 and norms[a:b] == ("sorry",) \
                and toks.sentence_of[ex.markers[k - 1][0]] == toks.sentence_of[a]:
            return b, b  # "actually no, it's not smoke, it's steam off the compost, sorry. But ...": the apology
            # closes the repair already made; the next sentence is news, not its correction
        nxt_marker = ex.markers[k + 1][0] if k + 1 < len(ex.markers) else len(toks)
        end = b
        ran_on = False
        while end < nxt_marker:
            if end > b and (toks.clause_start[end] or norms[end] in lx.COORDINATORS):
                if not toks.sentence_start[end] and toks.clause_start[end] and end - b <= 6 and (
                        not ran_on or all(w in lx.FILLERS | lx.ARTICLES | lx.PREPOSITIONS for w in norms[b:end])) \
                        and norms[end] not in lx.COORDINATORS \
                        and not any(b <= p.start_tok < end for p in ex.places) \
                        and not any(self._cues.match_at(norms, i) is not None for i in range(b, end)):
                    # an aside or a stutter runs on: "no, sorry, I'm reading this wrong, the fire's at the garage",
                    # "no, in the, the med school" (and on again past hesitations: "no, in the, um, the building")
                    end += 1
                    ran_on = True
                    continue
                # a clause that is only a place ("no wait, the bakery — is on fire") runs on
                if not any(p.start_tok >= b and p.end_tok <= end for p in ex.places) or toks.sentence_start[end]:
                    break
                if not self._has_content(norms, end, nxt_marker):
                    break
                if toks.sentence_start[end] or norms[end] in lx.COORDINATORS:
                    break
            end += 1
        return b, end

    def _cue_starts(self, ex: Extraction) -> list[tuple[int, int]]:
        """Cue spans as the classify stage will see them (used to decide repair kinds)."""
        norms = ex.tokens.norms(0, len(ex.tokens))
        blocked = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        blocked |= {i for a, b, _ in ex.markers for i in range(a, b)}
        return self._claim_cue_spans(norms, blocked)

    def _claim_cue_spans(self, norms: tuple[str, ...], blocked: set[int]) -> list[tuple[int, int]]:
        """Spans of the cue phrases that claim something (neutral phrases such as "fire crew" left out)."""
        return [(a, b) for a, b, (_, src) in self._cues.find_all(norms, blocked) if src != "neutral"
                and not _stranded_relation_cue(norms, a, b)]

    def _claim_cue_tokens(self, norms: tuple[str, ...], blocked: set[int]) -> set[int]:
        return {i for a, b in self._claim_cue_spans(norms, blocked) for i in range(a, b)}

    def _repair_kind(self, ex: Extraction, k: int, cue_spans: list[tuple[int, int]]) -> str | None:
        """What marker ``k`` repairs: ``place``, ``cue``, ``full`` (cue + place restated) or ``None``.

        Decided by what comes first after the marker: "no wait, the bakery" repairs the place,
        "sorry, it's on fire" the category, "correction, fire at the library" restates both.
        """
        norms = ex.tokens.norms(0, len(ex.tokens))
        ma = ex.markers[k][0]
        if norms[ma:ma + 2] == ("i", "mean") and any(
                p.end_tok == ma and p.via is None and any(q.landmark == p.landmark and q.end_tok <= p.start_tok
                                                          and q.status == "active" and q.via is not None
                                                          for q in ex.places)
                for p in ex.places):
            return None  # "the block that marches out onto the square, it's got smoke ..., Kohima I mean": which one it is
        b, end = self._after_clause(ex, k)
        first_place = min((p for p in ex.places if b <= p.start_tok < end and p.status != "reference"),
                          key=lambda p: p.start_tok, default=None)
        first_cue = min(((ca, cb) for ca, cb in cue_spans if b <= ca < end), default=None)
        if first_place is None and first_cue is None:
            return "place" if ex.markers[k][2] and self._cleft_after(ex, norms, b, end) is not None else None
        if first_cue is None or (first_place is not None and first_place.start_tok < first_cue[0]):
            return "place"
        if first_place is not None:
            # "fire at the library", "the smoke's coming from the warehouse": the claim is restated
            between = norms[first_cue[1] : first_place.start_tok]
            glue = lx.PREPOSITIONS | lx.DETERMINERS | lx.FILLERS | lx.COPULAS
            new_clause = {"its", "it", "there", "theres", "thats", "that", "we", "were", "i"}
            raw = [t.text.lower().replace("’", "'") for t in ex.tokens.tokens[first_cue[1]:first_place.start_tok]]
            new_clause -= {"were"} if "we're" not in raw else set()  # ("the survivors were recovered from")
            if len(between) <= 4 and not new_clause & set(between) and (
                    all(w in glue for w in between) or (len([w for w in between if w not in glue]) <= 1
                                                        and any(w in lx.PREPOSITIONS for w in between))):
                return "full"
        return "cue"

    @staticmethod
    def _cleft_after(ex: Extraction, norms: tuple[str, ...], b: int, end: int) -> PlaceMention | None:
        """The place of an "it's the X that ..." later in the sentence of a repair that names none at once."""
        return next((q for q in sorted(ex.places, key=lambda q: q.start_tok)
                     if q.status == "active" and end <= q.start_tok <= b + 25
                     and ex.tokens.sentence_of[q.start_tok] == ex.tokens.sentence_of[b - 1]
                     and norms[max(0, q.start_tok - 2):q.start_tok] == ("its", "the")
                     and norms[q.end_tok:q.end_tok + 1] in (("that",), ("thats",), ("which",))), None)

    def _has_content(self, norms: tuple[str, ...], a: int, b: int) -> bool:
        return any(self._cues.match_at(norms, i) is not None for i in range(a, min(b, a + 6)))

    def _apply_place_repairs(self, ex: Extraction) -> None:
        """A marker followed by a place retracts the last place before the marker."""
        toks = ex.tokens
        cue_spans = self._cue_starts(ex)
        norms = toks.norms(0, len(toks))
        for k, (a, b, _strong) in enumerate(ex.markers):
            kind = self._repair_kind(ex, k, cue_spans)
            if kind not in ("place", "full"):
                continue
            if b < len(norms) and norms[b] in lx.COORDINATORS and any(p.end_tok == a for p in ex.places):
                continue  # "in the coffee shop I mean, and the church ...": the marker closed its own repair
            if a > 0 and b < len(norms) and norms[a - 1] in lx.PREPOSITIONS and norms[b] in lx.PREPOSITIONS \
                    and norms[a - 1] != norms[b] and not any(p.start_tok <= a - 1 < p.end_tok for p in ex.places) \
                    and not any((h := self._relations.match_at(norms, i)) is not None and h[0] == a
                                for i in range(max(0, a - 5), a - 1)) \
                    and not any(p.via is not None and p.status == "active" and a - 3 <= p.end_tok < a
                                and not any(toks.clause_start[t] for t in range(p.end_tok, a)) for p in ex.places):
                # (but not a relation's last word: "in the block the labs' walkway runs to — no, sorry, in the labs")
                continue  # "two casualties outside-- no, inside the supermarket": where, not which place, repaired
                # (not "at the gate the coaches drop off at -- no, sorry, at the coach park": the same word)
            if not _strong and (b >= len(norms) or toks.sentence_start[b]) and any(
                    p.end_tok == a and any(q.status in ("negated", "retracted") and q.landmark != p.landmark
                                           and toks.sentence_of[q.start_tok] == toks.sentence_of[a] and q.end_tok <= p.start_tok
                                           for q in ex.places) for p in ex.places):
                continue  # "no wait, not the bank, it's the hotel, sorry. I did the bank ...": an apology that closes
                # the repair before it
            b, end = self._after_clause(ex, k)
            after = [p for p in ex.places if b <= p.start_tok < end and p.status in ("active", "negated")]
            said_of = next((t for t in range(b, min(end, b + 8)) if norms[t:t + 4] in (
                ("what", "i", "said", "about"), ("what", "we", "said", "about"), ("what", "i", "told", "you"))), None)
            first_q = min((q.start_tok for q in after), default=None)
            if first_q is not None \
                    and any(d in toks.gaps[t] for t in range(b + 1, first_q + 1) for d in ("...", "…")) \
                    and any(w in lx.NUMBER_WORDS or w == "one" for w in norms[b:first_q]):
                continue  # "a scald victim at the boiling vats and, um, another one, no, sorry, just the one... the weigh
                # shed is safe": the count right after the marker is the repair; the place after the pause is news
            if said_of is not None and all(q.start_tok > said_of for q in after):
                continue  # "no, scrap what I said about the cottage, water's just come in": that place's word withdrawn,
                # not the place just before the marker
            if not after and _strong and (cleft := self._cleft_after(ex, norms, b, end)) is not None:
                # "no mum, that's the lanterns on the water behind it, look, it's the wonky house that's burning":
                # what the repair says was meant, said as "it's the X that ..." later in the sentence
                after = [cleft]
            if not after and k + 1 < len(ex.markers):
                # "the mast — no the gen— no wait, the log store": a name cut off after the marker, repaired in its
                # turn; the place said after the next marker is what this one repairs to
                cut = next((p for p in ex.places if p.reason.startswith("false start") and b <= p.start_tok <= b + 2
                            and p.end_tok <= ex.markers[k + 1][0] <= p.end_tok + 1), None)
                if cut is not None:
                    b2, end2 = self._after_clause(ex, k + 1)
                    after = [p for p in ex.places if b2 <= p.start_tok < end2 and p.status == "active"] \
                        or _active_repeats(ex, b2, end2)  # ("... the log store, it's the log store": the repeat stands)
                if cut is None:
                    # "landslip at the pipe, no, at the top d-- the dam, sorry, at the power station": the cut-off
                    # name said again whole, that one repaired in its turn; the place the repairs end on is meant
                    cut = next((p for p in ex.places if p.reason.startswith("false start") and b <= p.start_tok <= b + 3),
                               None)
                    restated = next((p for p in ex.places if cut is not None and p.landmark == cut.landmark
                                     and cut.end_tok <= p.start_tok <= cut.end_tok + 2), None)
                    followed = set()
                    while restated is not None and restated.status == "retracted" and restated.start_tok not in followed:
                        followed.add(restated.start_tok)
                        restated = next((p for p in ex.places if p.replaces == restated.start_tok), None)
                    if restated is not None and restated.status == "active":
                        after = [restated]
            if not after:
                # "belay that, in the mill — the mill": the new place was restarted; its repeat stands in
                restarted = [p for p in ex.places if b <= p.start_tok < end and p.reason.startswith("restarted")]
                if not restarted:
                    continue
                link_to = min(restarted, key=lambda p: p.start_tok)
                after = _active_repeats(ex, b, end)
                if not after:
                    continue
            else:
                link_to = None
            start = self._repair_window_start(ex, k)
            before = [p for p in ex.places if start <= p.start_tok < a and p.status == "active"]
            s_open = max((t for t in range(0, a + 1) if toks.sentence_start[t]), default=0)
            relayed = 0 < a - s_open <= 6 and any(norms[t] in lx.HEARSAY_VERBS or norms[t] == "phone"
                                                  for t in range(s_open, a)) \
                and not any(s_open <= p.start_tok < a for p in ex.places)
            # ("Neighbour, taking the phone: no, it's the one the grain store's joined onto": another voice)
            # ("Smoke coming out of the clinic — what? My husband's saying no, it's the police station")
            if not before and (_strong or relayed):
                # "Man collapsed in the library. ... Okafor again, wrong building, apologies -- he's in the one
                # next door to it": a strong marker whose sentence names no place before it reaches the last
                # sentence that does, up to two back
                prev_end = ex.markers[k - 1][1] if k > 0 else 0
                starts = [t for t in range(0, start) if toks.sentence_start[t] and t >= prev_end][-2:]
                for s0 in reversed(starts):
                    before = [p for p in ex.places if s0 <= p.start_tok < a and p.status == "active"]
                    if before:
                        break
            if not before:
                # "The cafe has been cleared, police say. The ca— sorry, autocorrect — the CLINIC has been
                # cleared.": a name cut off right before the marker says again the one of the sentence before
                cut = next((p for p in ex.places if p.reason.startswith("false start") and a - 2 <= p.end_tok <= a), None)
                if cut is not None:
                    s0 = [t for t in range(0, cut.start_tok + 1) if toks.sentence_start[t]]
                    prev = s0[-2] if len(s0) >= 2 else 0
                    before = [p for p in ex.places if p.status == "active" and p.landmark == cut.landmark
                              and prev <= p.start_tok < cut.start_tok]
                    nxt = min((p for p in ex.places if p.status == "active" and p.landmark != cut.landmark
                               and p.start_tok > a and toks.sentence_of[p.start_tok] == toks.sentence_of[a]),
                              key=lambda p: p.start_tok, default=None)
                    seen = 0
                    while nxt is not None and nxt.replaces is not None and nxt.replaces > a and seen < 5:
                        nxt = next((r for r in ex.places if r.start_tok == nxt.replaces), None)  # (said twice after)
                        seen += 1
                    if not before and nxt is not None and nxt.replaces is None:
                        # "he's in the first aid t- no they've moved him, he's in the marshals' tent now": the name
                        # broken off is repaired by the place said after the marker, which takes up what was said
                        ex.places[ex.places.index(nxt)] = replace(nxt, replaces=cut.start_tok)
                        continue
            if not before:
                continue
            last = max(before, key=lambda p: p.end_tok)
            if a - last.end_tok >= 6 and norms[a - 1] in ("end", "side") and a >= 2 and norms[a - 2] in lx.SIDE_WORDS \
                    and not any(p.start_tok <= a - 1 < p.end_tok for p in ex.places):
                continue  # "the far end's blocked too north end i mean the far mouth": the unnamed end is repaired
            if any(p.reason.startswith("false start") and last.end_tok <= p.start_tok and a - 2 <= p.end_tok <= a
                   and p.landmark != last.landmark and (self._cue_between(norms, last.end_tok, a) or any(
                       norms[t] in ("and", "also", "plus") for t in range(last.end_tok, p.start_tok)))
                   for p in ex.places):
                continue  # "the library has a live wire down and the supermar-- sorry the marketplace": the cut-off
                # name is what the marker repairs (or one added to a list: "the pilhas and also the weighing sh-- no")
            e = a
            while e - 1 > last.end_tok and norms[e - 1] in lx.HESITATIONS:
                e -= 1
            n_cut = next((n for n in (1, 2) if e - n - 1 > last.end_tok and norms[e - n - 1] in lx.ARTICLES), 0)
            if n_cut and e - last.end_tok >= 3 + n_cut and all(norms[t].isalpha() for t in range(e - n_cut, e)) \
                    and norms[e - 1] not in lx.FUNCTION_WORDS and any(d in toks.gaps[e] for d in ("—", "–", "--")) \
                    and not any(p.start_tok <= t < p.end_tok for p in ex.places for t in range(e - n_cut, e)) \
                    and norms[e - n_cut:e] in self._name_prefix_owners \
                    and self._cue_between(norms, last.end_tok, e - n_cut - 1) and not toks.sentence_start[e - n_cut - 1] \
                    and any(toks.clause_start[t] or norms[t] == "and" for t in range(last.end_tok, e - n_cut - 1)):
                continue  # "The place behind the changing huts is our recovery area, and there's a near drowning at
                # the deep— er, sorry, the paddling pool": a name broken off ("the deep end"; "the staff car -- no,
                # the drop trailers") is what the marker repairs
            if a - last.end_tok >= 4 and a >= 2 and norms[a - 1] in ("the", "a", "an") and norms[a - 2] in lx.PREPOSITIONS \
                    and any(d in toks.gaps[a] for d in ("...", "…", "—", "–", "--")) \
                    and any(toks.clause_start[t] for t in range(last.end_tok, a - 2)):
                continue  # "the rope is broken, very dangerous, and my friend she is on the... no, she is in the
                # playground": where she is, begun and not named, is what the marker repairs
            if a - last.end_tok >= 6 and norms[a - 2] in lx.ARTICLES and norms[a - 1].isalpha() \
                    and norms[a - 1] not in lx.FUNCTION_WORDS and toks.tokens[a - 1].text.lower().endswith(("'s", "’s")) \
                    and any(d in toks.gaps[a] for d in ("...", "…", "—", "–", "--")) \
                    and not any(p.start_tok <= a - 1 < p.end_tok for p in ex.places) \
                    and any(toks.clause_start[t] for t in range(last.end_tok, a - 2)):
                continue  # "school's dry, we've got sixty-odd in there and, um, the manager's... no, the er, the
                # chapel": a thing named by no place, broken off, is what the marker repairs
            if min(after, key=lambda p: p.start_tok).status == "negated":
                # "hold that, not the school": the negation already retracted it; the place said after the
                # negated one takes over what was said of it ("the gym is where we're putting everyone — sorry,
                # not the gym, the library")
                neg = min(after, key=lambda p: p.start_tok)
                nxt = min((p for p in after if p.status == "active" and p.start_tok > neg.start_tok),
                          key=lambda p: p.start_tok, default=None)
                if nxt is not None and nxt.replaces is None and neg.landmark == last.landmark \
                        and last.status != "active" and nxt.landmark != last.landmark:
                    ex.places[ex.places.index(nxt)] = replace(nxt, replaces=last.start_tok)
                continue
            first_after = min((p for p in after if p.status == "active"), key=lambda p: p.start_tok, default=None)
            if first_after is not None and first_after.landmark == last.landmark:
                prev = max((p for p in ex.places if p.end_tok <= last.start_tok), key=lambda p: p.end_tok, default=None)
                if prev is not None and prev.status == "active" and prev.via is None and prev.landmark != last.landmark \
                        and _noun_phrase_start(norms, last) - prev.end_tok <= 1 \
                        and all(norms[i] in lx.FILLERS for i in range(prev.end_tok, _noun_phrase_start(norms, last))) \
                        and any(d in toks.gaps[t] for t in range(prev.end_tok, _noun_phrase_start(norms, last) + 1)
                                for d in ("...", "…", "—", "–", "--", " - ")) \
                        and not self._cue_between(norms, prev.end_tok, a):
                    # "the spillway... the gates, sorry, the radial gates": the place the speaker broke off from
                    # before the one said again more exactly is repaired too
                    ex.places[ex.places.index(prev)] = replace(
                        prev, status="retracted", reason=f"self-repair: '{toks.span_text(a, b)}' then '{first_after.text}'")
                    if first_after.replaces is None:
                        ex.places[ex.places.index(first_after)] = replace(first_after, replaces=prev.start_tok)
                continue  # "I mean the chapel, st mary's, same place": a restatement, not a repair
            if first_after is not None and not _strong and first_after.landmark in self._replaced_chain(ex, last) \
                    and [w for w in norms[first_after.end_tok:first_after.end_tok + 2] if w not in ("s", "is")][:1] \
                    in (["empty"], ["fine"], ["ok"], ["okay"], ["alright"]):
                continue  # "at the pub -- no, the towpath cafe, sorry, the pub's empty": why not the pub, no repair
            if first_after is not None and any(
                    (q.landmark == first_after.landmark and q.status in ("negated", "retracted")
                     or q.reason.startswith("then 'not")) and last.end_tok <= q.start_tok < a for q in ex.places):
                # a place denied between the last place and the marker is what the repair is about: "the corner shop
                # is safe, and the rec - not the rec, hold on, the rec hasn't been checked", "a man down at the bank
                # — no, the man down's at the fire station, not the bank"
                continue
            if any(q.landmark == last.landmark and q.status == "active" and b <= q.start_tok
                   and toks.sentence_of[q.start_tok] == toks.sentence_of[a]
                   and any(norms[i] in ("and", "plus") for i in range(b, q.start_tok))
                   and (q.end_tok >= len(norms) or toks.clause_start[q.end_tok]) for q in ex.places):
                continue  # "... — not the gym, sorry, just the park and the square": the list said again, the square kept
            if first_after is not None and not _strong and any(
                    q.landmark == first_after.landmark and q.status == "active" and q.end_tok <= last.start_tok
                    for q in ex.places) and (any(self._cancel.match_at(norms, i) is not None for i in range(b, end))
                                             or "out" in norms[b:end]):
                # "fire at the hay barn and the cattle sheds, smoke, and, um, actually the fire at the barn's out
                # now": news of a place said before the last one, which it does not replace
                continue
            withdraw = _withdraws(norms[a:ex.markers[k][1]])
            if first_after is not None and any(
                    (h := self._cancel.match_at(norms, i)) is not None
                    and (withdraw or h[1] in lx.CANCEL_MISSING_ONLY) for i in range(b, first_after.start_tok)):
                # ("The verger's missing — no, no, he's been found, he was at the post office")
                continue  # "child missing from the beach ... cancel that, mum's found her, she was in the toilet block"
            if first_after is not None and norms[a:ex.markers[k][1]] in (("wait",), ("hang", "on"), ("hold", "on")) \
                    and self._adds_to(toks, norms, first_after):
                continue  # "wait... crew three says the bank's alight as well": more news, not a repair
            if first_after is not None and last.via is not None \
                    and norms[first_after.end_tok:first_after.end_tok + 2] in (("same", "thing"), ("same", "place")) \
                    and any(q.status == "reference" and q.landmark == first_after.landmark and q.end_tok == last.end_tok
                            for q in ex.places):
                continue  # "the club that tows its skiers round pit two -- er, sorry, the ski pit, same thing": the
                # description's anchor named again, the description stands
            i = ex.places.index(last)
            ex.places[i] = replace(last, status="retracted",
                                   reason=f"self-repair: '{toks.span_text(a, b)}' then '{after[0].text}'")
            successor = link_to or next((p for p in sorted(after, key=lambda p: p.start_tok) if p.status == "active"), None)
            if successor is not None and successor.replaces is None:
                ex.places[ex.places.index(successor)] = replace(successor, replaces=last.start_tok)
            # every earlier mention of the retracted place in the window goes too ("I said the bank"); after
            # "I said", every earlier one in the report ("A man collapsed in the library. ... Sorry, I said the
            # library, I meant the school."), its claims going to the place that replaces it
            quoted = any(norms[i] in ("said", "say") for i in range(max(0, last.start_tok - 3), last.start_tok))
            if k > 0 and (0 <= last.start_tok - ex.markers[k - 1][1] <= 2 or 0 <= last.start_tok - ex.markers[k - 1][1] <= 5
                          and all(norms[t] in lx.PRONOUNS | lx.COPULAS | lx.PREPOSITIONS | lx.ARTICLES | lx.FILLERS
                                  | {"hes", "shes", "theyre", "s", "he", "she", "they"}
                                  for t in range(ex.markers[k - 1][1], _noun_phrase_start(norms, last)))):
                # ("woman stuck on the avenue ... er no she's on the yew walk no wait the meadow": said again in a
                # clause of its own, then repaired)
                # "one at the church — sorry, the chapel — I mean the hardware store": the name it restated goes too
                pa = ex.markers[k - 1][0]
                for j, q in enumerate(ex.places):
                    if q.status == "active" and q.landmark == last.landmark and pa - 3 <= q.end_tok <= pa \
                            and name_words(q.text) != name_words(last.text):
                        ex.places[j] = replace(q, status="retracted", reason=f"self-repair of '{last.text}'")
            for j, q in enumerate(ex.places):
                if q.status == "active" and q.landmark == last.landmark and start <= q.start_tok < a:
                    ex.places[j] = replace(q, status="retracted", reason=f"self-repair of '{last.text}'")
                elif quoted and q.status == "active" and q.landmark == last.landmark and q.start_tok < start:
                    ex.places[j] = replace(q, status="retracted", reason=f"said again later, then repaired: '{last.text}'")
            # its reference points ("the cafe across from the church") go with it
            for j, q in enumerate(ex.places):
                if q.status == "reference" and last.start_tok <= q.start_tok < a:
                    ex.places[j] = replace(q, status="retracted", reason="reference point of a retracted place")

    @staticmethod
    def _says_who_and_where(toks: Tokens, norms: tuple[str, ...], p: PlaceMention) -> bool:
        """A clause that is only a caller and a position: "Scaffolder on the roof of the hotel, over",
        "Postman at the bakery here"."""
        start = p.start_tok
        while start > 0 and not toks.sentence_start[start]:
            start -= 1
        before = [w for w in norms[start:p.start_tok] if w not in lx.FILLERS and w not in lx.DETERMINERS]
        # the caller: one word ("Scaffolder at ...") or a head with its modifiers ("Security guard at ...")
        k = next((i for i, w in enumerate(before[:4]) if w in lx.POSITION_PREPS), None)
        if k is None or k == 0 or before[0] in lx.PRONOUNS | lx.LAY_PERSONS or before[0] in lx.MOVED_PEOPLE:
            return False
        head = before[k - 1]
        if k > 1 and head not in lx.WORKER_PERSONS | lx.CREW_NOUNS | lx.CALLER_ROLES:
            return False
        if not set(before[k + 1:]) <= lx.PREPOSITIONS | lx.LOCATIVE_PARTS | {"roof", "of", "top", "up", "here"}:
            return False
        end = p.end_tok
        while end < len(norms) and not toks.sentence_start[end] and norms[end] not in lx.COORDINATORS:
            end += 1
        tail = [w for w in norms[p.end_tok:end] if w not in lx.FILLERS or w in ("over", "here")]
        if not set(tail) <= {"over", "here", "now"}:
            return False
        # ("Water in the compartment." claims; "Scaffolder on the roof of the hotel, over." calls in)
        return bool(tail) or head in lx.WORKER_PERSONS | lx.CREW_NOUNS | lx.CALLER_ROLES

    @staticmethod
    def _this_is_who_at(toks: Tokens, norms: tuple[str, ...], p: PlaceMention,
                        places: Sequence[PlaceMention] = ()) -> bool:
        """"Reception, this is Dan down at the jetty.": the caller's name and where they are, the place ending the
        sentence (or its clause, where the sentence goes on to another place: "this is Ahmed at the front desk, a
        lady fainted in the restaurant")."""
        start = p.start_tok
        while start > 0 and not toks.sentence_start[start]:
            start -= 1
        before = [w for w in norms[start:p.start_tok] if w not in lx.FILLERS]
        while before and before[-1] in lx.ARTICLES:
            before.pop()
        k = next((i for i in range(len(before) - 1) if before[i:i + 2] == ["this", "is"]), None)
        if k is None:
            return False
        rest = before[k + 2:]
        if len(rest) < 2 or rest[-1] not in lx.POSITION_PREPS:
            return False
        rest = rest[:-1]
        while len(rest) >= 2 and rest[-1] in lx.ARTICLES and rest[-2] in lx.POSITION_PREPS:
            rest = rest[:-2]  # ("Ahmed at the, at the front desk")
        if rest and rest[-1] in ("up", "down", "over", "out", "back", "here"):
            rest = rest[:-1]
        if not 1 <= len(rest) <= 2 or any(not w.isalpha() or w in lx.FUNCTION_WORDS for w in rest):
            return False
        end = p.end_tok
        while end < len(norms) and not toks.sentence_start[end]:
            end += 1
        if places:  # (only where the sentence goes on, past a pause, to another place)
            return end > p.end_tok and toks.clause_start[p.end_tok] and any(
                q.status == "active" and q.landmark != p.landmark and q.via is None and p.end_tok < q.start_tok < end
                for q in places)
        return set(norms[p.end_tok:end]) <= lx.FILLERS | {"over", "here", "now"}

    def _sheltered_people(self, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"twenty patients sheltering in there": people said with the shelter they have are no casualty claim."""
        starts = {c.start_tok: c for c in cues}
        out = []
        for c in cues:
            nxt = starts.get(c.end_tok)
            if c.end_tok - c.start_tok == 1 and norms[c.start_tok] in lx.MOVED_PEOPLE | {"patient", "survivor", "evacuee"} \
                    and self.kb.category_by_name[c.category].role == Role.CRITICAL and nxt is not None \
                    and self.kb.category_by_name[nxt.category].role == Role.DESIRABLE:
                continue
            if c.end_tok - c.start_tok == 1 and norms[c.start_tok] == "contaminated" and c.end_tok < len(norms) \
                    and norms[c.end_tok] in lx.CREW_NOUNS | _PEOPLE_WORDS:
                continue  # "bring the contaminated crews down": people to wash down, no spill there
            out.append(c)
        return out

    @staticmethod
    def _apply_confirmations(ex: Extraction, norms: tuple[str, ...]) -> None:
        """"so that's ... and the police station flooded, yeah? -- no, no, the hurt one's at the grocer's ...
        Police station's right.": a place said to be right, later, takes back the repair that retracted it."""
        toks = ex.tokens
        for p in list(ex.places):
            if p.status != "active":
                continue
            i = p.end_tok
            while i < len(norms) and i - p.end_tok < 2 and norms[i] in ("s", "is", "was"):
                i += 1
            if i >= len(norms) or norms[i] not in ("right", "correct") or i > p.end_tok and toks.clause_start[i] \
                    or not (i + 1 >= len(norms) or toks.clause_start[i + 1]):
                continue
            earlier = [q for q in ex.places if q.landmark == p.landmark and q.start_tok < p.start_tok
                       and q.status == "retracted" and q.reason.startswith("self-repair")]
            for q in earlier:
                ex.places[ex.places.index(q)] = replace(q, status="active", reason=f"confirmed by '{p.text} right'")

    @staticmethod
    def _replaced_chain(ex: Extraction, p: PlaceMention) -> set[str]:
        """The landmarks a place was repaired from, back along its chain of repairs."""
        at = {q.start_tok: q for q in ex.places}
        out: set[str] = set()
        seen = 0
        while seen < 10:
            # ("the cafe, at the towpath cafe": a name said again in full took over from the shorter one)
            prev = at.get(p.replaces) if p.replaces is not None else max(
                (q for q in ex.places if q.end_tok <= p.start_tok and q.landmark == p.landmark and q.replaces is not None),
                key=lambda q: q.start_tok, default=None)
            if prev is None:
                break
            p = prev
            out.add(p.landmark)
            seen += 1
        return out

    def _apply_trailing_repairs(self, ex: Extraction) -> None:
        """"the mortuary -- er, the chapel I mean -- is safe": "I mean" said after the new place retracts
        the one before it, when nothing was claimed in between."""
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        cue_tokens = {i for a, b in self._cue_starts(ex) for i in range(a, b)}
        for a, b, _ in ex.markers:
            sorry = norms[a:b] == ("sorry",)
            if norms[a:b] not in (("i", "mean"), ("i", "meant")) and not sorry:
                continue
            new = next((p for p in ex.places if p.end_tok == a and p.status == "active"), None)
            if new is None or toks.clause_start[a]:
                continue
            if sorry:
                # "the water tower— the tower block sorry, the tower block has cracks": "sorry" after the new
                # place; a place said next that is another one is a repair of its own
                then = next((p for p in ex.places if b <= p.start_tok <= b + 3), None)
                if then is not None and then.landmark != new.landmark:
                    continue
            sent = toks.sentence_of[a]
            old = max((p for p in ex.places if p.status == "active" and p.end_tok <= new.start_tok
                       and toks.sentence_of[p.start_tok] == sent), key=lambda p: p.end_tok, default=None)
            if old is None or old.landmark == new.landmark or cue_tokens & set(range(old.end_tok, new.start_tok)):
                continue
            if not any(toks.clause_start[i] for i in range(old.end_tok, new.start_tok + 1)):
                continue  # ("the bakery and the school I mean": a list, no pause)
            if any(norms[i] in lx.COORDINATORS for i in range(old.end_tok, new.start_tok)):
                continue
            ex.places[ex.places.index(old)] = replace(old, status="retracted",
                                                      reason=f"self-repair: '{new.text}' then '{toks.span_text(a, b)}'")

    @staticmethod
    def _adds_to(toks: Tokens, norms: tuple[str, ...], place: PlaceMention) -> bool:
        """The place after a "wait" is said as more news, not instead: "wait... crew three says the
        bank's alight as well", "... the school too"."""
        end = place.end_tok
        while end < len(norms) and not toks.clause_start[end] and end - place.end_tok < 6:
            end += 1
        tail = norms[place.end_tok:end]
        if "too" in tail:
            return True
        return any(tail[i:i + 2] == ("as", "well") and tail[i + 2:i + 3] != ("as",) for i in range(len(tail) - 1))

    @staticmethod
    def _repair_window_start(ex: Extraction, k: int) -> int:
        """First token a repair marker can reach back to: its sentence (a strong marker that opens
        a sentence reaches into the previous one), never past the previous marker."""
        toks = ex.tokens
        a, b, strong = ex.markers[k]
        prev_marker_end = ex.markers[k - 1][1] if k > 0 else 0
        sent_starts = [t for t in range(0, a + 1) if toks.sentence_start[t]]
        start = sent_starts[-1] if sent_starts else 0
        # "Fire at the hotel. No. Fire at the warehouse.": a marker set off by a pause at the start of
        # a sentence reaches into the previous one, as a strong marker always does
        alone = b >= len(toks) or toks.clause_start[b]
        # (past a speaker's label: "Supervisor, cutting in: negative, the boathouse is dry")
        # (not an answer to a question read back: "..., yeah? Milkman: no, no, ...")
        label = next((t for t in range(start + 1, min(a, start + 5) + 1) if ":" in toks.gaps[t]), start) \
            if strong and "?" not in toks.gaps[start] else start
        opens = all(toks.tokens[t].norm in lx.FILLERS | {"actually", "wait", "sorry", "oh", "no"} for t in range(label, a))
        if (strong or alone) and opens and len(sent_starts) >= 2:
            start = sent_starts[-2]  # (words before the marker are only fillers: "Actually no, ...")
        return max(start, prev_marker_end)

    # ------------------------------------------------------------------ classify
    def classify(self, ex: Extraction) -> Classification:
        """Cues, their attachment to places, claims and denials (thread-safe)."""
        with self._call_lock:
            return self._classify(ex)

    def _contracted_is_cues(self, ex: Extraction, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"the whole fair's a lake": a cue phrase the vocabulary writes after a split "'s" ("s a lake"), read
        after a place's contracted "'s" (whose key drops it)."""
        toks = ex.tokens
        out: list[CueMention] = []
        for p in ex.places:
            i = p.end_tok - 1
            if p.status != "active" or not toks.tokens[i].text.lower().endswith(("'s", "’s")) or p.end_tok >= len(norms) \
                    or p.end_tok in blocked or toks.clause_start[p.end_tok]:
                continue
            if self._cues.match_at(norms, p.end_tok) is not None:
                continue  # (a cue of its own follows: "the barn's on fire")
            spliced = norms[:p.end_tok] + ("s",) + norms[p.end_tok:]
            hit = self._cues.match_at(spliced, p.end_tok)
            if hit is None or hit[0] - p.end_tok < 3 or hit[1][1] == "neutral" \
                    or any(j in blocked for j in range(p.end_tok, hit[0] - 1)):
                continue
            end = hit[0] - 1
            a, b = toks.tokens[p.end_tok].start, toks.tokens[end - 1].end
            out.append(CueMention(p.end_tok, end, a, b, toks.text[a:b], hit[1][0], hit[1][1], reason="after a contracted 's"))
        return out

    def _stove_in_cues(self, toks: Tokens, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"the whole front wall's stove in": smashed in, after a verb or a contracted "'s" (the vocabulary has no
        bare "stove in": "the stove in the refuge" is a stove)."""
        out: list[CueMention] = []
        und = self._category_for_role(lx.UNDESIRABLE, "smashed in, collapsed")
        if und is None:
            return out
        for i in range(1, len(norms) - 1):
            if norms[i:i + 2] == ("stove", "in") and not blocked & {i, i + 1} and _stove_in(toks, norms, i):
                a, b = toks.tokens[i].start, toks.tokens[i + 1].end
                out.append(CueMention(i, i + 2, a, b, toks.text[a:b], und, "lexicon", reason="stove in"))
        return out

    def _structure_gone(self, ex: Extraction, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"Jenny's arch has gone.": a bridge, an arch or a wall said to have gone (or the roof of a place said to be
        down), closing its clause, has collapsed (a fire "has gone" out is the cancellation's business; a place named so is no cue word)."""
        toks = ex.tokens
        out: list[CueMention] = []
        for p in ex.places:
            k = p.end_tok
            if p.status != "active" or p.via is not None or k >= len(norms) or k in blocked:
                continue
            last = norm(p.text.split()[-1])
            np0 = _noun_phrase_start(norms, p)
            part_of = np0 >= 2 and norms[np0 - 1] == "of" and norms[np0 - 2] in _FALLING_PARTS | _HOLDING_PARTS
            if norms[k] in _HOLDING_PARTS and k + 1 < len(norms) and p.via is None:
                part_of, k = True, k + 1  # "the lagoon banks are going", "the slurry pond wall has gone"
            if last not in lx.STRUCTURE_WORDS | _SPANS and not part_of:
                continue
            if norms[k:k + 2] in (("has", "gone"), ("s", "gone"), ("have", "gone")) or part_of and norms[k:k + 2] in (
                    ("is", "down"), ("s", "down"), ("was", "down")):
                end = k + 2
            elif (norms[k] == "gone" or part_of and norms[k] == "down") \
                    and toks.tokens[k - 1].text.lower().endswith(("'s", "’s")):
                end = k + 1
            elif part_of and norms[k:k + 3] in (("has", "come", "in"), ("s", "come", "in"), ("have", "come", "in")):
                end = k + 3  # "Roof of the dressing mill has come in"
            elif part_of and norms[k:k + 2] == ("come", "in") and toks.tokens[k - 1].text.lower().endswith(("'s", "’s")):
                end = k + 2
            elif part_of and norms[k - 1] in _HOLDING_PARTS and norms[k:k + 2] in (("are", "going"), ("is", "going")):
                end = k + 2  # a wall or bank "going" gives way as it is said
            elif part_of and norms[k - 1] in _HOLDING_PARTS and norms[k] == "going" and norms[k - 1].endswith("s"):
                end = k + 1  # "lagoon banks going"
            else:
                continue
            if norms[end:end + 1] == ("flat",):
                end += 1  # "the roof of the hangar is down flat"
            if end + 3 < len(norms) and norms[end:end + 2] == ("on", "the") and norms[end + 3] in ("side", "end") \
                    and (end + 4 == len(norms) or toks.clause_start[end + 4]):
                end += 4  # "... has gone on the south side": where along it, the same claim
            if end < len(norms) and not toks.clause_start[end]:
                continue  # ("the bridge has gone under", "has gone to ...": more words, another meaning)
            c0 = next((i for i in range(p.start_tok, -1, -1) if toks.clause_start[i]), 0)
            if any((h := self._cues.match_at(norms, i)) is not None and h[1][1] != "neutral" for i in range(c0, p.start_tok)):
                continue  # "the fire at the pack bridge has gone.": the fire is what has gone
            und = self._category_for_role(lx.UNDESIRABLE, "collapsed, fallen down")
            if und is not None:
                out.append(CueMention(k, end, toks.tokens[k].start, toks.tokens[end - 1].end,
                                      toks.text[toks.tokens[k].start:toks.tokens[end - 1].end], und, "lexicon",
                                      reason="a structure gone"))
        return out

    @functools.cached_property
    def _dry_described(self) -> bool:
        """Does any category's description call its places dry ("a dry, safe place to shelter")?"""
        return any(re.search(r"\bdry\b", c.description.lower()) for c in self.kb.categories)

    @functools.cached_property
    def _flooded_category(self) -> str | None:
        """The undesirable category a place "flooded, under water" reads as in this KB (fixed by the KB)."""
        return self._category_for_role(lx.UNDESIRABLE, "flooded, under water")

    @functools.cached_property
    def _under_water_category(self) -> str | None:
        """The category the vocabulary gives "under water" in this KB (None where it reads as no claim)."""
        hit = self._cues.match_at(("under", "water"), 0)
        return None if hit is None or hit[1][1] == "neutral" else hit[1][0]

    def _water_over_cues(self, ex: Extraction, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"The ditch the little pump lifts into is over the road at the south end": water said to be over the road
        (the lane, the track, the fields) has left its bed, flooded (not "the pub is over the road": no water)."""
        toks = ex.tokens
        out: list[CueMention] = []
        if self._flooded_category is None:
            return out
        for p in ex.places:
            if p.status != "active" or norm(p.text.split()[-1]) not in WATERCOURSE_WORDS:
                continue
            for k in range(p.end_tok, min(len(norms) - 3, p.end_tok + 8)):
                if k > p.end_tok and toks.sentence_start[k] or any(q.start_tok == k and q.status == "active"
                                                                   for q in ex.places):
                    break
                if norms[k] in ("is", "s", "come", "gone", "right") and norms[k + 1:k + 3] == ("over", "the") \
                        and norms[k + 3] in _OVERRUN_GROUND and not blocked & {k + 1, k + 2, k + 3}:
                    a, b = toks.tokens[k + 1].start, toks.tokens[k + 3].end
                    out.append(CueMention(k + 1, k + 4, a, b, toks.text[a:b], self._flooded_category, "lexicon",
                                          reason="water over the road"))
                    break
        return out

    def _under_final(self, ex: Extraction, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"it's the slipway that's under.": a place said to be "under", closing its clause, is under water (the
        category the vocabulary gives "under water"); "under control", "under the bridge" say more."""
        cat = self._under_water_category
        if cat is None:
            return []
        toks = ex.tokens
        out: list[CueMention] = []
        # ("the row backing onto whatever ..., the whole row's under": the head of a description said again)
        said_again = []
        for p in ex.places:
            if p.status == "active" and p.via is not None:
                head = norms[p.start_tok + 1] if p.end_tok - p.start_tok > 1 and norms[p.start_tok] in lx.ARTICLES else ""
                said_again.extend(
                    replace(p, start_tok=k - 1, end_tok=k) for k in range(p.end_tok + 1, len(norms))
                    if norms[k] == "under" and norms[k - 1] == head and head.isalpha() and head not in lx.FUNCTION_WORDS
                    and toks.tokens[k - 1].text.lower().endswith(("'s", "’s")) and norms[k - 2] in ("whole", "the"))
        for p in [*ex.places, *said_again]:
            k = p.end_tok
            if p.status != "active" or k >= len(norms) or k in blocked:
                continue
            if norms[k] in ("that", "which") and not toks.clause_start[k]:
                k += 1
            if k + 1 < len(norms) and norms[k] in ("is", "s", "are", "was") and norms[k + 1] == "under":
                a, end = k, k + 2
            elif k < len(norms) and norms[k] == "under" and toks.tokens[k - 1].text.lower().endswith(("'s", "’s")):
                a, end = k, k + 1
            else:
                continue
            if end < len(norms) and not toks.clause_start[end] or any(j in blocked for j in range(a, end)):
                continue
            out.append(CueMention(a, end, toks.tokens[a].start, toks.tokens[end - 1].end,
                                  toks.text[toks.tokens[a].start:toks.tokens[end - 1].end], cat, "lexicon",
                                  reason="said to be under"))
        return out

    def _dry_water(self, ex: Extraction, norms: tuple[str, ...], a: int) -> bool:
        """Is the subject of "(bone) dry" at token ``a`` a water body (a pond, a pool, a ditch): water not there,
        no dry place to shelter in?"""
        j = a - 1
        while j >= 0 and norms[j] in ("is", "s", "was", "are", "were", "still", "completely", "totally", "all", "now",
                                      "gone", "run", "looks"):
            j -= 1
        subject = next((p for p in ex.places if p.end_tok == j + 1), None)
        return subject is not None and norm(subject.text.split()[-1]) in lx.WATER_BODIES | _STILL_WATERS

    def _safe_for(self, toks: Tokens, norms: tuple[str, ...], a: int) -> bool:
        """Is the word at ``a`` whom a safe place is said to be for ("safe for the walking patients", "open for
        residents")? "for", at most two words before it (an article, a modifier), ends a desirable cue."""
        f = next((j for j in range(a - 1, max(-1, a - 4), -1) if norms[j] == "for"), None)
        if f is None or any(norms[j] in lx.FUNCTION_WORDS and norms[j] not in lx.ARTICLES for j in range(f + 1, a)) \
                or any(toks.clause_start[j] for j in range(f + 1, a + 1)):
            return False  # (not "it's clear for landing, the casualty is on the switch": a clause of its own)
        for m in range(max(0, f - 3), f):
            hit = self._cues.match_at(norms, m)
            if hit is not None and hit[0] == f and hit[1][0] is not None \
                    and self.kb.category_by_name[hit[1][0]].role == Role.DESIRABLE:
                return True
        return False

    def _classify(self, ex: Extraction) -> Classification:
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        all_place_tokens = {i for p in ex.places for i in range(p.start_tok, p.end_tok)
                            if p.via is None or p.status != "active"}
        # tokens inside a resolved relational description (e.g. "shop attached to") are not cues,
        # but the words of named places are never cues either
        blocked = set(all_place_tokens)
        for p in ex.places:
            if p.via is not None:
                blocked.update(range(p.start_tok, p.end_tok))
                h = p.start_tok + (norms[p.start_tok] in lx.ARTICLES)
                m = self._cues.match_at(norms, h) if p.status == "active" and h < p.end_tok else None
                if m is not None and m[1][0] in self.kb.category_by_name and m[0] < p.end_tok \
                        and self.kb.category_by_name[m[1][0]].role == Role.DESIRABLE \
                        and (m[1][1] in ("glossary", "category")
                             or norms[m[0] - 1] in ("point", "area", "station", "zone", "centre", "center", "post")) \
                        and self._relations.match_at(norms, m[0]) is not None:
                    # "we've set the muster point across from the site office": the description's head is what the
                    # place is said to be
                    blocked.difference_update(range(h, m[0]))
        marker_tokens = {i for a, b, _ in ex.markers for i in range(a, b)}
        blocked |= marker_tokens
        blocked |= self._struck_tokens(toks)  # what a log line strikes through says nothing
        blocked |= ex.relation_tokens
        self._place_tokens = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        self._places_now = ex.places
        self._relation_tokens_now = frozenset(ex.relation_tokens)
        self._marker_tokens = marker_tokens
        cues: list[CueMention] = []
        shut: set[int] = set()
        self._shut_tokens = shut
        neutral: set[int] = set()
        self._neutral_tokens = neutral
        cues.extend(self._structure_gone(ex, norms, blocked))
        cues.extend(self._contracted_is_cues(ex, norms, blocked))
        cues.extend(self._under_final(ex, norms, blocked))
        cues.extend(self._water_over_cues(ex, norms, blocked))
        cues.extend(self._stove_in_cues(toks, norms, blocked))
        for a, b, (cat, source) in self._cues.find_all(norms, blocked):
            if source == "neutral":
                neutral.update(range(a, b))  # ("people sitting in here out of the smoke": no person, no smoke)
                continue
            if norms[b - 1] == "swamped" and norms[b:b + 1] == ("with",):
                continue  # "swamped with injured guests": overwhelmed, no water
            if norms[a:b] == ("block", "the") and toks.tokens[a].text.lower() == "block":
                continue  # "in the block the labs' walkway runs to": the noun, not "blocks the" way
            if norms[a:b] == ("medic", "to", "the") and toks.tokens[a].text.lower() == "medic":
                continue  # "Medic to the sick bay, man down at the crusher": a call, not medics sent there
            if cat == self._person_category and self._safe_for(toks, norms, a):
                continue  # "confirmed safe for the walking patients and visitors": whom a safe place is for
            if norms[a:b] == ("clear",) and toks.sentence_start[a] and b < len(norms) \
                    and norms[b] in ("everyone", "everybody", "people", "all", "out", "the", "them"):
                continue  # "Clear everyone out of the building": an order, not a place said to be clear
            k = a - 1
            while k >= 0 and norms[k] in lx.ARTICLES:
                k -= 1
            if k >= 3 and norms[k] == "as" and norms[k - 1] == "it" and norms[k - 2] in ("marked", "had", "flagged", "logged") \
                    and (norms[k - 2] == "had" or norms[k - 3] in ("wed", "had", "d", "theyd", "id")):
                continue  # "we'd marked it as a hot zone, but ... it's stable": what it was taken for before
            if self.kb.category_by_name[cat].role == Role.DESIRABLE and k >= 0 and norms[k] == "as" and any(
                    norms[v] in ("opening", "open", "using", "use", "setting", "set", "designating", "keeping")
                    and any(norms[m] in ("not", "nt", "never", "arent", "wont", "isnt", "dont") for m in range(max(0, v - 2), v))
                    for v in range(max(0, k - 8), k)):
                continue  # "we're not opening the food bank as a rest centre after all": what it will not be
            o = b + 1 if b + 1 < len(norms) and norms[b] not in ("in", "on", "to") and norms[b + 1] in ("in", "on") \
                and norms[b].isalpha() and self._cues.match_at(norms, b) is None else b  # ("chemical splashes in his eyes")
            if self._person_category and norms[o:o + 1] in (("in",), ("on",), ("to",)) \
                    and norms[o + 1:o + 2] in (("her",), ("his",), ("their",), ("my",)) \
                    and (norms[o + 2:o + 3] in (("lung",), ("lungs",)) or norms[o + 2] in lx.BODY_PARTS if o + 2 < len(norms) else False) \
                    and (o + 3 >= len(norms) or toks.clause_start[o + 3] or norms[o + 3] in lx.FUNCTION_WORDS):
                # (not "a leak in their back room")
                start, end = toks.tokens[a].start, toks.tokens[o + 2].end
                cues.append(CueMention(a, o + 3, start, end, toks.text[start:end], self._person_category, source,
                                       reason="what harmed a person"))
                continue  # "a woman with smoke in her lungs": the person's harm, no danger there
            if b - a == 1 and norms[a] in _SUBSTANCE_MODIFIERS and b < len(norms) and not toks.clause_start[b] \
                    and norms[b].isalpha() and norms[b] not in lx.FUNCTION_WORDS | _SUBSTANCE_EVENTS | lx.RELATION_ENDINGS \
                    and norms[b] not in ("away", "round") \
                    and not norms[b].endswith(("ing", "ed")) and self._cues.match_at(norms, b) is None \
                    and toks.gaps[b].strip() == "":
                continue  # "the diesel day tank's shifted on its mounts", "the petrol station": what a thing holds
            if b - a == 1 and norms[a] in _SUBSTANCE_MODIFIERS and a > 0 and norms[a - 1] == "for" \
                    and (b >= len(norms) or toks.clause_start[b]):
                continue  # "heading to the bowser for diesel": what someone goes there for, nothing spilt
            if norms[b:b + 1] == ("out",) and norms[b + 1:b + 2] != ("of",) \
                    and any(norms[m] in ("put", "putting", "got", "getting") for m in range(max(0, a - 3), a)) \
                    and self.kb.category_by_name[cat].role == Role.UNDESIRABLE:
                continue  # "they've put the fire out": over
            if norms[a:b] in (("stuck",), ("attached",)) and norms[b:b + 1] in (("to",), ("onto",)) and not any(
                    norms[m] in _PERSON_WORDS or norms[m] in lx.PERSON_SUBJECTS for m in range(max(0, a - 3), a)):
                continue  # "the shop stuck to the side of the bread shop": joined on, no one stuck
            if norms[b - 1] == "clear" and norms[b:b + 2] == ("on", "the") and b + 2 < len(norms) and any(
                    self._role_cue_at(norms, m, Role.UNDESIRABLE) for m in range(b + 2, min(len(norms), b + 5))):
                continue  # "all clear on the tyre fire at Doyle's": the danger is over, no place said safe
            if norms[a:b] == ("clear",) and a >= 3 and norms[a - 1] == "to" and any(
                    norms[m] in ("waiting", "wait", "waited", "for") for m in range(max(0, a - 6), a - 1)):
                continue  # "waiting for the road to clear": not clear yet
            if norms[a] == "clear" and self.kb.category_by_name[cat].role == Role.DESIRABLE and any(
                    (h := self._cancel.match_at(norms, k)) is not None and toks.sentence_of[k] == toks.sentence_of[a]
                    and any(w in h[1].split() for w in ("down", "receded", "subsided", "dropped", "drained"))
                    for k in range(b, min(len(norms), b + 8))):
                continue  # "the causeway is clear now, water's gone down": the danger over, no safe place said
            if norms[b - 1] == "full" and norms[b:b + 1] == ("of",) and self.kb.category_by_name[cat].role == Role.DESIRABLE:
                continue  # "the shower block is still full of people": what fills it, no water supply
            if self._kept_clear_for(toks, norms, a):
                continue  # "keep the road clear for the aerial ladder coming down from the fire station": who it is for
            if norms[b - 1] == "dry" and self.kb.category_by_name[cat].role == Role.DESIRABLE and self._dry_water(ex, norms, a):
                neutral.update(range(a, b))
                continue  # "it's the duck pond that's overflowing, not the dew pond. The dew pond's bone dry": no water
            undesirable = self.kb.category_by_name[cat].role == Role.UNDESIRABLE
            if self._person_category and undesirable and self._injury_cause_at(norms, a):
                # "a man hit by falling slates", "two hurt by the blast": what hurt them, the person the claim
                start, end = toks.tokens[a].start, toks.tokens[b - 1].end
                cues.append(CueMention(a, b, start, end, toks.text[start:end], self._person_category, source,
                                       reason="the cause of an injury"))
                continue
            if undesirable and self._danger_not_here(norms, a, b):
                continue
            if _stranded_relation_cue(norms, a, b):
                continue  # "the tank the pumps push water up to has split": a relation's words, its object before it
            if undesirable and self._danger_kept_off(norms, a, b):
                continue
            if norms[a:b] == ("flooded", "out") and (norms[b:b + 1] == ("of",) or a > 0 and norms[a - 1] in lx.ORIGIN_PEOPLE
                                                      | {"anyone", "anybody", "those", "families", "the"}):
                continue  # "families flooded out of their homes": who they are, no place flooded
            if norms[a:b] == ("stuck",) and any(norms[k:k + n] in lx.HELD_UP for k in range(b, min(len(norms), b + 8))
                                                 for n in (2, 3)
                                                 if not any(toks.clause_start[m] for m in range(b, k + 1))):
                continue  # "we've been stuck in traffic outside the town hall": held up, in no danger
            if norms[a:b] == ("use",) and toks.tokens[a].text.lower() in ("uses", "used") and any(
                    norms[k:k + 2] in (("as", "its"), ("as", "their"), ("as", "his"), ("as", "her"))
                    for k in range(b, min(len(norms), b + 7))):
                continue  # "the school that uses the hall as its gym": what one place uses another for, no refuge
            if norms[a:b] in (("collapsed",), ("collapsing",), ("fallen",)) and b < len(norms) \
                    and not toks.clause_start[b] and norms[b].isalpha() and norms[b] != "in" \
                    and not {"roof", "building", "ceiling"} & set(norms[b:b + 3]) \
                    and next((w for w in reversed(norms[max(0, a - 3):a]) if w not in lx.ARTICLES | {"some", "big"}), "") \
                    in ("under", "beneath", "underneath"):
                continue  # "a postman under a collapsed shelving unit": what pins the person, no danger of the place
            if norms[a:b] in (("have", "slid"), ("has", "slid")) and (
                    self._person_before(norms, a) or a > 0 and norms[a - 1] in lx.PRONOUNS):
                continue  # "a lorry driver has slid into the mud ponds": a person, no heap or slope that slid
            if norms[a:b] in (("leaning",), ("leaning", "on")) and self._person_before(norms, a):
                continue  # "that was Mrs Patel leaning on it": a person leaning, nothing giving way
            if norms[b - 1] == "fall" and norms[b:b + 1] == ("of",):
                continue  # "the top bench has had a fall of ground": a fall of rock, no person's fall
            if norms[a:b] == ("halfway", "up") and norms[b:b + 1] in (("by",), ("at",), ("near",), ("next",)):
                continue  # "collapsed spectator on the hill, halfway up by the practice nets": where on it
            if norms[a:b] == ("spark",) and norms[max(0, a - 3):a] == ("one", "of", "the") \
                    and norms[b:b + 1] in (("has",), ("is",), ("s",), ("was",), ("got",)):
                continue  # "one of the sparks has gashed his arm open": an electrician, no sparks
            if norms[a:b] in (("everyone", "out"), ("everybody", "out")) and norms[b:b + 2] == ("of", "the") \
                    and norms[b + 2:b + 3] and norms[b + 2] in lx.ESCAPED_THINGS:
                continue  # "moved everyone out of the smoke into the school": out of the danger, no order about a place
            if norms[a:b] in (("everyone", "out"), ("everybody", "out")) and a > 0 \
                    and norms[a - 1] in ("moved", "got", "taken", "took", "brought", "led", "walked", "ushered", "helped") \
                    and (norms[b:b + 1] == ("of",) or b == len(norms) or toks.clause_start[b]) and a > 1 \
                    and norms[a - 2] in ("weve", "we", "ive", "i", "theyve", "they", "have", "has", "s", "had", "all"):
                continue  # "We've moved everyone out of the cafe and into the sports hall": done, where they left
            if b == a + 1 and norms[max(0, a - 3):a] == ("out", "of", "the") and norms[a] in lx.ESCAPED_THINGS:
                continue  # "we've moved everyone out of the smoke into the school": what they left, not where they are
            if b == a + 1 and b < len(norms) and norms[b] in lx.VICTIM_NOUNS and norms[a] in lx.ESCAPED_THINGS | {
                    "quake", "earthquake", "storm", "blast", "explosion", "crash"}:
                continue  # "use it for the flood victims": who they are, no danger there
            if b == a + 1 and a > 0 and norms[a] in self._kb_nouns and norms[a - 1] in lx.ARTICLES \
                    and source != "glossary" and not undesirable:
                continue  # "the burn's burst its banks": a thing of the KB's own ("beside the burn"), no burns
            if norms[a:b] == ("clear",) and any(norms[k] in ("keep", "stay") or norms[k] in lx.MOVED_CLEAR_VERBS
                                                and all(w in ("well", "right", "away") for w in norms[k + 1:a])
                                                for k in range(max(0, a - 4), a)) \
                    and not any(toks.clause_start[k] for k in range(max(1, a - 3), a + 1)):
                continue  # "keep all boats clear of the lock", "stay well clear": an instruction, like "keep clear"; "crew
                # have stepped well clear": people who moved away, nothing said of the place
            if norms[a:b] == ("clear",) and a > 0 and (norms[a - 1] in ("through", "jumped", "jumping", "jumps", "went")
                                                       or norms[b:b + 1] == ("round",)):
                continue  # "rider forty-two through clear, no penalties": a clear round, nothing said of a place
            if norms[a:b] == ("cleared",) and a >= 2 and (norms[a - 1] in ("it", "them", "everyone", "everybody")
                                                          and norms[a - 2] in ("get", "getting") or norms[a - 1] == "being"):
                continue  # "the grandstand is cracking, get it cleared now": an order to empty it, no safety said
            if norms[a:b] in (("cleared",), ("lifted",)) and a >= 2 and norms[a - 1] in ("has", "have", "s") \
                    and any(self._cues.match_at(norms, k) is not None for k in range(max(0, a - 4), a - 1)):
                continue  # "the smoke has cleared": the danger has gone, the place is not said to be cleared
            if norms[a:b] == ("clear",) and b < len(norms) and norms[b] == "of" and a > 0 \
                    and toks.tokens[a - 1].text.lower().replace("’", "'") in ("we're", "were", "i'm", "im", "they're",
                                                                               "we", "they", "everyone's"):
                continue  # "we're clear of the slipway and heading out": the crew has left it
            if norms[a:b] == ("clear",) and norms[b:b + 2] in (("of", "it"), ("of", "that"), ("of", "them")) \
                    and a > 0 and norms[a - 1] in ("is", "s", "are", "re"):
                continue  # "bad air in the building behind it, the bunkhouse is clear of it": the danger just said is
                # not there, no safety claimed
            nb = b + 1  # ("Fire Two-One en route": a number of two words)
            if nb < len(norms) and (norms[nb] in lx.NUMBER_WORDS | {"one"} or norms[nb].isdigit()) \
                    and toks.gaps[nb] in ("-", "–"):
                nb += 1
            if b == a + 1 and b < len(norms) and (toks.tokens[a].text[:1].isupper() or _after_station(norms, a)) \
                    and (norms[b] in lx.NUMBER_WORDS | {"one"} or norms[b].isdigit()) and toks.gaps[b] == " " \
                    and (nb == len(norms) or toks.clause_start[nb] or norms[nb] in lx.COPULAS | {"to", "here"}
                         or toks.tokens[nb].text.lower().replace("’", "'") in ("we're", "we've", "i'm", "we")
                         or (a == 0 or toks.sentence_start[a]) and norms[nb] in (
                             "moving", "heading", "going", "proceeding", "arriving", "attending", "returning", "leaving",
                             "approaching", "now", "en", "mobile", "mobilising", "mobilizing",
                             "up", "down", "at", "on", "in", "out", "over", "inside", "outside", "by")):
                # ("Fire Two moving from the lodge up to the weighbridge", "Fire 3 up on the wall walk.")
                continue  # "Control, Hazmat One, we're ...", "uh yeah control er fire two we're ...": a call sign
            if b == a + 1 and a > 0 and norms[a - 1] in lx.ARTICLES and norms[a] in lx.NEGATABLE_STATES \
                    and toks.tokens[a].text.lower() == norms[a] + "s":
                continue  # "the stables that back onto it": a plural noun, not the state ("stable")
            if norms[a:b] == ("shelter",) and (b < len(norms) and norms[b] in ("roof", "glass", "wall", "panel")
                                               or a > 0 and norms[a - 1] == "bus"):
                continue  # "under the shelter roof", "the bus shelter": the structure, no place of safety
            start, end = toks.tokens[a].start, toks.tokens[b - 1].end
            if (norms[a:b] in lx.LOCK_CUES or norms[a] == "jammed" and norms[a:b] != ("jammed", "open")
                    and "door" in norms[max(0, a - 3):a]) and (not self._access_category() or norms[a:b] in lx.LOCK_CUES
                                                                and not self._lock_category()):
                # "The church is locked, nobody's using it": shut, no danger, where no category is about access
                # (nor a shelter: the MiniLM fallback does not guess at it)
                shut.update(range(a, b))
                continue
            if norms[a:b] in (("coming", "down"), ("comes", "down"), ("running", "down"), ("runs", "down")) \
                    and norms[b:b + 1] == ("from",) and a > 0 \
                    and norms[a - 1] in ("ramp", "slip", "slipway", "path", "track", "road", "lane", "steps", "stairs"):
                continue  # "the concrete ramp coming down from Kingfisher": a way that runs down from it, nothing falling
            if norms[a:b] in (("everyone", "out"), ("everybody", "out")) \
                    and toks.tokens[a].text.lower().endswith(("'s", "’s")) and self._person_category:
                # "everyone's out of the lift shaft": they have left (nobody in need there), no order to get out
                cues.append(CueMention(a, b, start, end, toks.text[start:end], self._person_category, source,
                                       polarity="denied", reason="everyone has left"))
                continue
            cue = CueMention(a, b, start, end, toks.text[start:end], cat, source)
            if norms[a:a + 2] == ("cut", "off") and b > a + 2 and self._person_category \
                    and self.kb.category_by_name[cat].role == Role.UNDESIRABLE and self._person_before(norms, a):
                # "two people cut off by the water at the allotments": the water there, and people to rescue
                cues.append(replace(cue, category=self._person_category, reason="people cut off"))
            if (source == "lexicon" or source == "category" and self.kb.category_by_name[cat].role != Role.CRITICAL) \
                    and norms[a:b] in lx.PERSON_STATE_CUES and self._person_category and (
                        self._person_before(norms, a) or self._person_at_place_before(norms, a)
                        or self._person_inside_before(norms, a)) \
                    and not (norms[a + 1:a + 2] == ("fall",) and not any(
                        norms[m] in lx.LAY_PERSONS or norms[m] in lx.PERSON_NOUNS for m in range(max(0, a - 4), a - 1))):
                # (a learner's "he is fall down" of a person just named, "my friend he is fall down"; not "the boom,
                # the big arm for the ship, he is fall down", a thing called "he")
                # (the undesirable category's description may list "collapsed" too: "one of the riggers has collapsed")
                cue = replace(cue, category=self._person_category, reason=f"a person {norms[a]}")
            elif (source == "lexicon" or source == "category" and self.kb.category_by_name[cat].role != Role.CRITICAL) \
                    and norms[a:b] in (("burned",), ("burnt",), ("collapsed",)) and self._person_category and a > 0 \
                    and norms[a - 1] in ("a", "an", "one", "two", "three", "badly", "the") and b < len(norms) \
                    and (norms[b] in _PEOPLE_WORDS | lx.CREW_NOUNS or norms[a] == "collapsed" and norms[b] in lx.WORKER_PERSONS):
                cue = replace(cue, category=self._person_category, reason=f"a {norms[a]} person")  # "a burned worker"
            if norms[a:b] == ("slumped",) and cue.category == self._person_category and not self._person_before(norms, a) \
                    and (self._thing_before(norms, a, self._place_tokens) or next(
                        (w for w in reversed(norms[max(0, a - 3):a]) if w not in lx.FILLERS | {"s", "has", "have", "is"}),
                        "") in lx.EARTHWORKS | {"side", "end", "edge", "half"}):
                und = self._category_for_role(lx.UNDESIRABLE, "the ground has slumped and given way")
                if und is not None:  # "the whole south side's slumped": ground, no person
                    cue = replace(cue, category=und, reason="ground slumped")
            if norms[a] in ("jammed", "stuck", "trapped", "caught", "wedged") and self._person_category and a >= 2 \
                    and norms[a - 1] in lx.BODY_PARTS and norms[a - 2] in ("his", "her", "their", "my", "your") \
                    and cue.category != self._person_category:
                cue = replace(cue, category=self._person_category, reason="a person's limb caught")  # "Kid's got his
                # foot jammed in the grate"
            if norms[a:b] == ("crushed", "against") and self._person_category and next(
                    (w for w in reversed(norms[max(0, a - 3):a]) if w not in lx.FILLERS), "") in (
                    "man", "woman", "lad", "kid", "child", "boy", "girl", "he", "she", "hes", "shes", "bloke"):
                cue = replace(cue, category=self._person_category, reason="one person crushed")  # ("a young lad, crushed
                # against the rails"; a crowd pressed against a barrier stays a crush)
            if source == "category" and norms[a:b] in lx.PERSON_STATE_CUES \
                    and self.kb.category_by_name[cat].role == Role.CRITICAL and self._thing_before(norms, a, self._place_tokens):
                # the critical category's description lists "collapsed" (a person who has): the wall that has
                # collapsed is the danger the vocabulary reads it as
                und = self._category_for_role(lx.UNDESIRABLE, " ".join(norms[a:b]))
                if und is not None:
                    cue = replace(cue, category=und, source="lexicon", reason=f"a thing {norms[a]}")
            if source == "lexicon" and norms[a:b] in (("slumped",), ("slumping",)) and cue.category == self._person_category \
                    and (self._thing_before(norms, a, self._place_tokens) or next(
                        (w for w in reversed(norms[max(0, a - 5):a]) if w not in ("has", "have", "s", "is", "just", "partly",
                                                                                  "that", "thats", "which", "itself")
                         and w not in lx.FILLERS), "") in lx.EARTHWORKS | {"stockpile", "pile"}
                         or any(i in self._place_tokens for i in range(max(0, a - 4), a - 2))
                         and norms[a - 3:a] in (("itself", "that", "s"), ("itself", "thats", "s"), ("itself", "that", "has"))):
                # ("it's the lump stockpile itself that's slumped")
                und = self._category_for_role(lx.UNDESIRABLE, "slumped, collapsed ground")
                if und is not None:
                    cue = replace(cue, category=und, reason="ground slumped")  # "part of the face has slumped"
            if source == "lexicon" and norms[a:b] in (("been", "hit", "by"), ("was", "hit", "by"),
                                                      ("got", "hit", "by")) \
                    and cue.category == self._person_category and not self._person_before(norms, a) \
                    and not any(w in _PEOPLE_WORDS for w in norms[max(0, a - 8):a]) \
                    and (self._thing_before(norms, a, self._place_tokens) or a > 1 and norms[a - 1] == "that"
                         and a - 2 in self._place_tokens):
                und = self._category_for_role(lx.UNDESIRABLE, "struck and damaged")
                if und is not None:
                    cue = replace(cue, category=und, reason="a thing hit")  # "the seismo hut that's been hit by a bomb"
            if source == "lexicon" and norms[a:b] == ("swept", "away") and cue.category == self._person_category \
                    and self._thing_before(norms, a, self._place_tokens) and not self._person_before(norms, a):
                und = self._category_for_role(lx.UNDESIRABLE, "washed away by the flood")
                if und is not None:
                    cue = replace(cue, category=und, reason="a thing swept away")  # "the bridge ... has been swept away"
            if source in ("lexicon", "category") and norms[a:b] == ("buried",) and a > 0 and (
                    norms[a - 1] in lx.THING_SUBJECTS or self._thing_before(norms, a, self._place_tokens)
                    or next((w for w in reversed(norms[max(0, a - 4):a]) if w not in lx.FILLERS and w != "all"), "")
                    in ("its", "it")) \
                    and self.kb.category_by_name[cat].role == Role.CRITICAL:
                und = self._category_for_role(lx.UNDESIRABLE, "buried under snow and debris")
                if und is not None:
                    cue = replace(cue, category=und, reason="a thing buried")  # "cars buried": no person
            if cue.category == self._person_category and self._person_category is not None:
                j = a - 1
                while j >= 0 and norms[j] in lx.DETERMINERS | lx.FILLERS | {"all", "any", "your"}:
                    j -= 1
                if j >= 0 and norms[j] in lx.SEND_VERBS and not toks.clause_start[j + 1]:
                    continue  # "bring the walking wounded there": where to take people, not people there
            if norms[a] in ("come", "came", "coming") and a > 0 and (norms[a - 1] in ("we", "i", "you", "weve", "ive")
                                                                  or norms[a - 1] in ("re", "m") and a > 1
                                                                  and norms[a - 2] in ("we", "i", "you")):
                continue  # "we come down past the fish market": the speaker moving, nothing fallen
            if norms[a] in ("come", "came", "coming") and cue.category != self._person_category and (subj := next(
                    (i for i in range(a - 1, max(-1, a - 5), -1) if norms[i] not in lx.FILLERS | {
                        "have", "ve", "has", "had", "all", "just", "now", "re"}), None)) is not None \
                    and subj not in self._place_tokens and not toks.clause_start[subj + 1] \
                    and (norms[subj] in _PEOPLE_OR_GROUPS or norms[subj] in ("everyone", "everybody")):
                continue  # "quite a few people have come down off the trail": people moving, nothing fallen
                # (but "he came off the ladder" is a person hurt)
                # (not "the ceiling of the chemist's has come down")
            if b - a == 1 and a >= 3 and norms[a - 1] == "the" and norms[a - 2] == "of" and norms[a - 3] in _COMPASS \
                    and b < len(norms) and norms[b].isalpha() and not toks.clause_start[b] \
                    and (norms[b] not in lx.COPULAS | lx.FUNCTION_WORDS or norms[b] == "well") \
                    and self._cues.match_at(norms, b) is None:
                continue  # "east of the gas wells": a bearing from things the word only names, no gas there
            if norms[a] == "come" and a > 0 and norms[a - 1] in ("can", "could", "should", "will", "ll", "to") \
                    and norms[b:b + 1] in (("off",), ("from",), ("to",), ("into",), ("onto",)):
                continue  # "ambulances can come down off the top lot": a way to go, nothing fallen
            if norms[a] in ("come", "came", "coming") and norms[b:b + 1] == ("from",) and any(
                    norms[j] in lx.MOVING_PEOPLE for j in range(max(0, a - 4), a)):
                continue  # "forty of us who came down from the campsite": people moving, nothing fallen
            if norms[a:b] in (("gone", "under"), ("going", "under"), ("went", "under")) \
                    and norms[b:b + 1] in (("a",), ("an",)) and not toks.clause_start[b] \
                    and b + 1 < len(norms) and norms[b + 1] not in _UNDER_WATER:
                # (not "the yard's gone under a foot of water", "went under a wave", "went under a lake")
                continue  # "foot went under a lorry wheel": how someone was hurt, not a place's claim
            if norms[a:b] in (("gone", "under"), ("going", "under"), ("went", "under")) \
                    and self.kb.category_by_name[cue.category].role == Role.CRITICAL \
                    and not (norms[b:b + 1] in (("a",), ("an",), ("the",), ("his",), ("her",), ("their",))
                             and not toks.clause_start[b] and b + 1 < len(norms)
                             and norms[b + 1] not in _UNDER_WATER):
                # (not "his foot went under a lorry wheel": under a thing, caught, no water)
                near = range(max(0, a - 3), a)
                # a place (or a place's own thing said as a noun: "the yard's gone under") before it, and no person
                thing_near = cue.category == self._person_category and any(
                    i in self._place_tokens or norms[i] in lx.PREMISES_PARTS | lx.STRUCTURE_WORDS
                    or norms[i] in lx.DESCRIPTION_HEADS - {"one"} for i in near) \
                    and not any(norms[i] in lx.PERSON_SUBJECTS or norms[i] in _PERSON_WORDS for i in near)
                # or its subject is no person ("wherever the bridge comes down on the south bank has gone under")
                j = _subject_before(norms, a, ("has", "have", "s", "is", "was", "just", "now", "completely", "all",
                                               "totally"))
                thing_subject = j >= 0 and norms[j] not in _PERSON_WORDS | lx.LAY_PERSONS | lx.WORKER_PERSONS \
                    | lx.PERSON_SUBJECTS | {"someone", "somebody", "he", "she", "they", "who", "i", "we", "hes", "shes",
                                            "theyve", "whos"}
                if (thing_near or thing_subject) and self._flooded_category is not None:
                    # "whatever the Fleece looks out over has gone under": the place, flooded
                    cue = replace(cue, category=self._flooded_category, reason="a place gone under")
            if cue.category == self._person_category and norms[a] == "in" and any(
                    norms[j] in ("it", "its") for j in range(max(0, a - 3), a)) \
                    and not any(norms[j] in lx.PERSON_SUBJECTS for j in range(max(0, a - 3), a)):
                continue  # "it's got a span down, it's hanging in the water": a thing in the water, no person
            if cue.category == self._person_category and norms[a] == "in" and any(
                    norms[j] in lx.SUNK_THINGS for j in range(max(0, a - 3), a)) \
                    and not any(norms[j] in lx.PERSON_SUBJECTS or norms[j] in _PERSON_WORDS for j in range(max(0, a - 4), a)):
                und = self._category_for_role(lx.UNDESIRABLE, "debris in the flood water")
                if und is None:
                    continue
                cue = replace(cue, category=und, reason="things in the water, no person")  # "logs everywhere in the water"
            if self._person_category and norms[b - 1] in ("burnt", "burned", "scalded", "scorched") and b < len(norms) \
                    and norms[b] in lx.BODY_PARTS and cue.category != self._person_category:
                cue = replace(cue, category=self._person_category, reason="a person's burn")  # "a lad with a burnt forearm"
            if norms[b:b + 1] in (("burns",), ("burn",), ("inhalation",)) and cue.category != self._person_category \
                    and self.kb.category_by_name[cue.category].role == Role.UNDESIRABLE:
                continue  # "chemical burns to the face", "acid burns": the injury, the person's claim
            if "knocked" in norms[a:b] and any(norms[j] in ("that", "it", "its", "thats", "fire", "flames")
                                               for j in range(max(0, a - 3), a)):
                continue  # "the station had a fire earlier but that's been knocked down": the fire put out
            if norms[a:b] in (("spreading",), ("spread",)) and any(
                    c.end_tok in (a, a - 1) and c.polarity == "affirmed" for c in cues) and (
                    cues and cues[-1].end_tok == a or a >= 1 and norms[a - 1] in ("is", "s", "now", "still")):
                continue  # "Tanker leak spreading in the park": the leak's own verb, no other danger
            if norms[a:b] == ("missing",) and cue.category == self._person_category:
                j = _subject_before(norms, a, ("are", "is", "s", "were", "was", "all", "now", "just"))
                if j >= 0 and norms[j] in lx.MISSING_PARTS:
                    und = self._category_for_role(lx.UNDESIRABLE, "damaged, broken, torn off")
                    if und is None:
                        continue
                    cue = replace(cue, category=und, reason="parts of it missing: damage, no person")
                    # ("two deck panels are missing": torn away, nobody lost)
            if norms[a:b] == ("stuck",) and cue.category == self._person_category:
                j = _subject_before(norms, a, ("is", "s", "was", "got", "gets", "has", "been", "just", "now", "completely"))
                if j >= 0 and norms[j] in lx.THING_SUBJECTS - {"lift"}:
                    continue  # "my bus is stuck in a flash flood": a vehicle stuck, no person said to be
            if a >= 4 and norms[a - 1] == "in" and norms[a - 4:a - 2] in (("to", "his"), ("to", "her"), ("to", "their")) \
                    and norms[a - 5:a - 4] == ("up",) and self.kb.category_by_name[cat].role == Role.UNDESIRABLE:
                continue  # "he's up to his chest in silt": what the person is stuck in, said of him
            if norms[a:b] == ("clear",) and any(norms[j] in ("keep", "keeping") and not any(
                    toks.clause_start[t] for t in range(j + 1, a + 1)) for j in range(max(0, a - 8), a)):
                continue  # "keep the road in front of the supermarket clear": an order, not a safe place
            checked = self._apply_cue_negation(toks, norms, cue)
            cues.append(checked)
            if checked.category != cue.category:  # "no longer safe": unsafe now, and no longer safe
                cues.append(replace(cue, polarity="denied", reason=checked.reason))
        cues = self._contradiction_words_dropped(toks, norms, cues)
        cues = self._read_cue_pairs(toks, norms, cues)
        cues = self._damage_by_cause(norms, cues)
        cues = self._spread_of_what(toks, norms, cues)
        cues = self._sheltered_people(norms, cues)
        cues = self._animals_in_trouble(toks, norms, cues)
        cues = self._things_in_the_water(norms, cues)
        cues.extend(self._animal_states(toks, norms, blocked | neutral | {i for c in cues for i in range(c.start_tok, c.end_tok)}))
        cues.extend(self._cues_into_description(ex, norms, {i for c in cues for i in range(c.start_tok, c.end_tok)}))
        cues.extend(self._predicative_cues(ex, norms, blocked | {i for c in cues for i in range(c.start_tok, c.end_tok)}))
        cues.extend(self._person_cues(ex, norms, blocked | neutral | {i for c in cues for i in range(c.start_tok, c.end_tok)}))
        cues.extend(self._another_one_cues(toks, norms, cues, blocked))
        cues.extend(self._people_down(toks, norms, blocked | {i for c in cues for i in range(c.start_tok, c.end_tok)}))
        cues = self._evacuation_destinations(ex, norms, cues)
        cues.sort(key=lambda c: c.start_tok)
        cues = self._apply_cue_repairs(ex, cues)
        cues = self._drop_restarted_cues(toks, norms, cues)
        cues = self._apply_false_alarms(toks, norms, cues)
        cues = self._mistaken_beliefs(toks, norms, cues)
        self._markers_now = ex.markers
        cues = self._apply_non_reports(toks, norms, cues)
        cues = self._unknown_source(ex, norms, cues)
        cues, moved = self._relocations(ex, norms, cues)
        claims, denied = self._associate(ex, cues)
        claims.extend(self._cleft_claims(ex, norms, cues, claims))
        claims.extend(moved)
        claims.extend(self._answered_locations(ex, norms, cues, claims))
        spread = self._spread_claims(ex, norms, cues, claims, denied)
        claims.extend(spread)
        cues.extend(c.cue for c in spread)
        if self.embedder is not None and self.semantic_fallback and not _exercise_frame(norms):
            # (an exercise or training message claims nothing, by word or by meaning)
            self._all_cues_now = cues
            denied_keys = {c.key for c in denied}
            extra = [c for c in self._semantic_claims(ex, claims, denied) if c.key not in denied_keys]
            claims.extend(extra)
            cues.extend(c.cue for c in extra)
        claims = self._the_actual_one(ex, norms, claims)
        claims = self._motion_of_named_danger(ex, cues, claims)
        claims = self._all_clear_after_revocation(ex, claims, denied)
        return Classification(cues, self._not_from_us(ex, norms, self._drop_unspecific_dangers(claims)), denied)

    def _all_clear_after_revocation(self, ex: Extraction, claims: list[Claim], denied: list[Claim]) -> list[Claim]:
        """"the chlorine leak in the shed beside the pump room is sealed, all clear there": an all-clear said right
        after the danger at the same place is said to be over ends that danger; it makes no place of safety."""
        toks = ex.tokens
        out = []
        for c in claims:
            all_clear = c.cue.text.lower().replace("-", " ") == "all clear" and c.cue.source == "lexicon"
            if all_clear and any(
                    d.place.landmark == c.place.landmark and (d.cue.end_tok <= c.cue.start_tok <= d.cue.end_tok + 12
                                                              or c.cue.end_tok <= d.cue.start_tok <= c.cue.end_tok + 8)
                    and toks.sentence_of[d.cue.start_tok] == toks.sentence_of[c.cue.start_tok]
                    and self.kb.category_by_name[d.cue.category].role == Role.UNDESIRABLE for d in denied):
                continue
            a, b = c.cue.start_tok, c.cue.end_tok
            if all_clear and toks.clause_start[a] \
                    and c.place.end_tok <= a and all(toks.sentence_of[t] != toks.sentence_of[a] or toks.norms(t, t + 1)[0]
                                                     in lx.FILLERS for t in range(b, len(toks))) \
                    and any(d.cue.end_tok <= a and toks.sentence_of[d.cue.start_tok] == toks.sentence_of[a] for d in denied):
                continue  # "the fire round the back of the cable station is out, and the nurse says nobody on the pitch
                # needs her, all clear": an all-clear closing what was called off sums it up; no place said safe
            out.append(c)
        return out

    def _motion_of_named_danger(self, ex: Extraction, cues: list[CueMention], claims: list[Claim]) -> list[Claim]:
        """"Avalanche has come down onto the 4k loop", "avalanche, it came down the black gully": a verb of
        motion says the kind of the danger named just before it (three words at most, no place between), not a
        collapse of its own."""
        undesirable = {c.name for c in self.kb.categories_with_role(Role.UNDESIRABLE)}
        sentence = ex.tokens.sentence_of
        named = [c for c in cues if c.category in undesirable and c.polarity == "affirmed" and c.status == "active"
                 and norm_phrase(c.text) not in lx.MOTION_DANGERS]
        out: list[Claim] = []
        for c in claims:
            if norm_phrase(c.cue.text) in lx.MOTION_DANGERS and c.cue.category in undesirable:
                before = [d for d in named if d.end_tok <= c.cue.start_tok <= d.end_tok + 3
                          and sentence[d.start_tok] == sentence[c.cue.start_tok]
                          and not any(d.end_tok <= p.start_tok < c.cue.start_tok for p in ex.places)]
                last = max(before, key=lambda d: d.end_tok, default=None)
                if last is not None and last.category != c.cue.category:
                    c = Claim(c.place, replace(c.cue, category=last.category, reason=f"the motion of '{last.text}'"))
                    if any(o.place.landmark == c.place.landmark and o.cue.category == c.cue.category for o in out):
                        continue
            out.append(c)
        return out

    @staticmethod
    def _cleft_claims(ex: Extraction, norms: tuple[str, ...], cues: list[CueMention], claims: list[Claim]) -> list[Claim]:
        """"it's the bakery not the bank that's burning": the cue of the cleft is the first place's, not the one
        it is set against."""
        bound = {id(c.cue) for c in claims}
        out = []
        for c in cues:
            if id(c) in bound or c.status != "active" or c.polarity != "affirmed":
                continue
            j = c.start_tok
            for rel in (("that", "s"), ("thats",), ("that", "is"), ("whats",), ("which", "is"), ("that",)):
                if norms[max(0, j - len(rel)):j] == rel:
                    j -= len(rel)
                    break
            else:
                continue
            neg = next((p for p in ex.places if p.end_tok == j and p.status == "negated"), None)
            if neg is None:
                continue
            k = neg.start_tok
            while k > 0 and norms[k - 1] in lx.DETERMINERS:
                k -= 1
            if k < 1 or norms[k - 1] != "not":
                continue
            head = next((p for p in ex.places if p.end_tok == k - 1 and p.status == "active"), None)
            if head is not None:
                out.append(Claim(head, c))
        return out

    @staticmethod
    def _the_actual_one(ex: Extraction, norms: tuple[str, ...], claims: list[Claim]) -> list[Claim]:
        """"the fire's at the fire station -- no I mean, our crew's at the fire station, the actual fire is at the
        supermarket": after a repair, "the actual fire" is the one meant, and the same danger said of another place
        before the repair is taken back."""
        out = claims
        for c in claims:
            a = c.cue.start_tok
            if c.cue.polarity != "affirmed" or a < 2 or norms[a - 1] not in ("actual", "real") or norms[a - 2] != "the":
                continue
            marks = [m for m, _, _ in ex.markers if m < a]
            if marks:
                m = max(marks)
                out = [d for d in out if not (d.cue.category == c.cue.category and d.place.landmark != c.place.landmark
                                              and d.cue.end_tok <= m)]
        return out

    @staticmethod
    def _not_from_us(ex: Extraction, norms: tuple[str, ...], claims: list[Claim]) -> list[Claim]:
        """"we've got smoke, but the smoke's coming from the bakery, not from us": the place named is where it
        is; what the speaker's place was said to have of it, before, is taken back."""
        toks = ex.tokens
        for i in range(1, len(norms) - 1):
            if not (norms[i:i + 3] in (("not", "from", "us"), ("not", "from", "here")) or norms[i:i + 2] == ("not", "us")):
                continue
            n = toks.sentence_of[i]
            named = [p for p in ex.places if p.status == "active" and p.end_tok <= i and toks.sentence_of[p.start_tok] == n]
            if not named:
                continue
            there = max(named, key=lambda p: p.end_tok)
            cats = {c.cue.category for c in claims if c.place.landmark == there.landmark}
            claims = [c for c in claims if not (c.place.landmark != there.landmark and c.cue.category in cats
                                                and c.place.end_tok <= there.start_tok)]
        return claims

    NOT_DESIRABLE = "desirable cue means undesirable"

    def _drop_unspecific_dangers(self, claims: list[Claim]) -> list[Claim]:
        """"the bridge is NOT safe, water over the deck": where a KB has several undesirable categories, "not
        safe" names none of them; a place that another cue gives an undesirable category keeps only that."""
        undesirable = {c.name for c in self.kb.categories_with_role(Role.UNDESIRABLE)}
        if len(undesirable) < 2:
            return claims
        def unspecific(c: Claim) -> bool:
            # (nor does an order to keep out or get out: "it's scalding, keep everyone out of it")
            return c.cue.reason.endswith(self.NOT_DESIRABLE) or norm_phrase(c.cue.text) in _UNSPECIFIC_DANGERS

        specific = {(c.place.landmark, c.cue.category) for c in claims
                    if c.cue.category in undesirable and not unspecific(c)}
        return [c for c in claims if not (unspecific(c) and c.cue.category in undesirable
                                          and any(lm == c.place.landmark and cat != c.cue.category
                                                  for lm, cat in specific))]

    def _answered_locations(self, ex: Extraction, norms: tuple[str, ...], cues: list[CueMention],
                            claims: list[Claim]) -> list[Claim]:
        """"say again location of your casualty? — pharmacy, I say again, the pharmacy": a question that asks
        where something is, answered by naming a place, says the thing is there."""
        toks = ex.tokens
        out: list[Claim] = []
        asking = self._question_sentences(toks)
        for c in cues:
            if c.polarity != "affirmed" or toks.sentence_of[c.start_tok] not in asking \
                    or c.status != "active" and c.reason != "a question, not a report" \
                    or any(cl.cue is c for cl in claims):
                continue
            n = toks.sentence_of[c.start_tok]
            asked_of = {p.landmark for p in ex.places if p.status in ("active", "retracted")
                        and toks.sentence_of[p.start_tok] == n}
            denied = [p for p in ex.places if p.status == "negated" and p.landmark in asked_of
                      and n < toks.sentence_of[p.start_tok] <= n + 2]
            if denied:
                # "are we still using the red lion as the rendezvous point? ... so it's the green now, not the pub":
                # the answer puts another place in the asked one's stead
                d = denied[0]
                instead = max((p for p in ex.places if p.status == "active" and p.landmark not in asked_of
                               and toks.sentence_of[p.start_tok] == toks.sentence_of[d.start_tok]
                               and p.end_tok <= d.start_tok), key=lambda p: p.end_tok, default=None)
                if instead is not None and not any(cl.place.landmark == instead.landmark and cl.cue.category == c.category
                                                   for cl in claims):
                    out.append(Claim(instead, replace(c, status="active", reason=f"the answer: '{instead.text}', "
                                                                                 f"not '{d.text}'")))
                continue
            sent = [i for i in range(len(norms)) if toks.sentence_of[i] == n]
            words = [norms[i] for i in sent]
            if not any(words[k:k + 2] == ["location", "of"] for k in range(len(words))) and "where" not in words:
                continue
            if any(p.status == "active" and toks.sentence_of[p.start_tok] == n for p in ex.places):
                continue  # ("where's the casualty at the bank?": the place is in the question)
            nxt = [i for i in range(len(norms)) if toks.sentence_of[i] == n + 1]
            if not nxt:
                continue
            k = next((j + 1 for j in nxt[:4] if j + 1 < len(norms) and toks.gaps[j + 1].strip().startswith(":")),
                     nxt[0])  # past a speaker label, "Engine 3:"
            while k < nxt[-1] and (norms[k] in lx.FILLERS or norms[k] in lx.DETERMINERS):
                k += 1
            answer = next((p for p in ex.places if p.status == "active" and p.start_tok == k), None)
            if answer is not None and not any(cl.place.landmark == answer.landmark and cl.cue.category == c.category
                                              for cl in claims):
                out.append(Claim(answer, replace(c, status="active", reason="the place given in answer to where")))
        return out

    @staticmethod
    def _unknown_source(ex: Extraction, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"I can see smoke from the top of the road but I don't know where it's coming from": the speaker says
        they do not know where it is; what they saw since the last place they named is claimed of no place."""
        toks = ex.tokens
        for i, _, _ in _UNKNOWN_SOURCE.find_all(norms):
            n = toks.sentence_of[i]
            named = [p.end_tok for p in ex.places if p.status == "active" and p.end_tok <= i
                     and toks.sentence_of[p.start_tok] == n]
            lo = max(named, default=min(t for t in range(i + 1) if toks.sentence_of[t] == n))
            cues = [replace(c, status="retracted", reason="where it is, the speaker does not know")
                    if c.status == "active" and lo <= c.start_tok < i and c.polarity == "affirmed" else c
                    for c in cues]
        # "theres smoke everywhere on our road": where it is, said, and no place of the KB
        place_tokens = {t for p in ex.places for t in range(p.start_tok, p.end_tok)}
        for idx, c in enumerate(cues):
            if c.status != "active" or c.polarity != "affirmed":
                continue
            for k in range(c.end_tok, min(len(norms) - 2, c.end_tok + 3)):
                if norms[k] in ("on", "in", "at", "down", "along", "up") and norms[k + 1] in ("our", "my") \
                        and norms[k + 2] in lx.OWN_PLACES and not (place_tokens & set(range(k, k + 6))):
                    cues[idx] = replace(c, status="retracted", reason=f"said of '{toks.span_text(k + 1, k + 3)}'")
                    break
        return cues

    @staticmethod
    def _restated_list_mate(ex: Extraction, norms: tuple[str, ...], p: PlaceMention, active: list[PlaceMention],
                            pairs: list[Claim]) -> list[CueMention]:
        """The cues of a place coordinated with ``p`` ("the library and the post office") that says again a place
        claimed earlier in the sentence, after a place of that list was taken back."""
        toks = ex.tokens
        n = toks.sentence_of[p.start_tok]
        glue = lx.DETERMINERS | lx.FILLERS | {"and", "just", "only"}
        for q in active:
            if q is p or q.landmark == p.landmark or toks.sentence_of[q.start_tok] != n:
                continue
            lo, hi = (q.end_tok, p.start_tok) if q.end_tok <= p.start_tok else (p.end_tok, q.start_tok)
            if hi - lo > 4 or "and" not in norms[lo:hi] or not all(w in glue for w in norms[lo:hi]):
                continue
            own = [c for c in pairs if c.place is q]
            earlier = own or [c for c in pairs if c.place.landmark == q.landmark
                              and c.place.end_tok <= min(p.start_tok, q.start_tok) and toks.sentence_of[c.place.start_tok] == n]
            dropped = any(r.status in ("retracted", "negated") and r.landmark not in (p.landmark, q.landmark)
                          and toks.sentence_of[r.start_tok] == n and r.start_tok < min(p.start_tok, q.start_tok)
                          for r in ex.places)
            if earlier and dropped:
                return [c.cue for c in earlier]
        return []

    def _relocations(self, ex: Extraction, norms: tuple[str, ...],
                     cues: list[CueMention]) -> tuple[list[CueMention], list[Claim]]:
        """"police station is the staging area... er, was, they've moved it to the clinic"; "we're putting it at
        the park instead": a facility said to be at one place is moved to another; the new place has it, the old
        one no longer does. People moved ("we've moved her to the bank") are at the new place too."""
        toks = ex.tokens
        moved: list[Claim] = []
        active = [p for p in ex.places if p.status == "active"]

        def undesirable(c: CueMention) -> bool:
            return self.kb.category_by_name[c.category].role == Role.UNDESIRABLE

        def move(last: CueMention, target: PlaceMention, why: str, left: str | None) -> None:
            """``target`` has ``last`` now (``why``); the place it was said of no longer does, for ``left``."""
            nonlocal cues
            if left is not None:
                cues = [replace(c, status="retracted", reason=left) if c is last else c for c in cues]
            moved.append(Claim(target, replace(last, reason=why)))

        for i, j, _ in _SOURCE_IS.find_all(norms):  # "smoke over the square. Source identified as the bus depot."
            target = next((p for p in active if j <= p.start_tok <= j + 2
                           and all(norms[t] in lx.DETERMINERS for t in range(j, p.start_tok))), None)
            last = self._last_cue_before(toks, cues, i, 1, undesirable)
            if target is not None and last is not None:
                move(last, target, f"its source is {target.text}", f"its source is {target.text}")

        def said_after(p: PlaceMention, words: tuple[tuple[str, ...], ...]) -> int | None:
            """The token of the preposition before ``p`` (articles and fillers skipped) if the words end there."""
            k = p.start_tok - 1
            while k >= 0 and norms[k] in lx.ARTICLES | lx.FILLERS and p.start_tok - k <= 3:
                k -= 1
            return k if k >= 1 and any(norms[k - len(w) + 1:k + 1] == w for w in words) else None

        # "the triage tent, they've moved it, it was in the square, now it's in the park"
        for y in [p for p in ex.places if p.status == "active" or p.reason.startswith("restarted")]:
            k = said_after(y, (("in",), ("at",), ("on",), ("to",)))
            if k is None or "now" not in norms[max(0, k - 4):k]:
                continue
            x = max((p for p in active if p.end_tok < k and p.landmark != y.landmark and y.start_tok - p.end_tok <= 14
                     and said_after(p, (("was", "in"), ("was", "at"), ("was", "on"))) is not None),
                    key=lambda p: p.start_tok, default=None)
            target = y if y.status == "active" else next(
                (p for p in active if p.landmark == y.landmark and p.start_tok > y.start_tok), None)
            last = self._last_cue_before(toks, cues, x.start_tok, 1, lambda c: True) if x is not None else None
            if x is not None and target is not None and last is not None:
                move(last, target, f"was at {x.text}, now at {target.text}", f"moved to {target.text}")
        for i, w in enumerate(norms):  # "fire's jumped from the tank farm to the station it feeds": both burn
            if w not in lx.SPREAD_VERBS or norms[i + 1:i + 2] != ("from",):
                continue
            src = next((p for p in active if i + 1 < p.start_tok <= i + 3), None)
            if src is None or src.end_tok >= len(norms) or norms[src.end_tok] not in ("to", "into", "onto"):
                continue
            dst = next((p for p in active if src.end_tok < p.start_tok <= src.end_tok + 3), None)
            last = self._last_cue_before(toks, cues, i, 0, undesirable)
            if dst is not None and last is not None:
                move(last, dst, f"spread to {dst.text}", None)  # (the source still burns)
        for i, w in enumerate(norms):
            if w not in lx.RELOCATE_VERBS:
                continue
            j = i + 1
            obj = norms[j] if j < len(norms) else ""
            if obj in lx.RELOCATED_OBJECTS:
                j += 1
            elif not (w in ("going", "gone") and i >= 1 and norms[i - 1] in ("its", "s", "is") and i >= 2
                      and norms[i - 2] in ("it", "its", "that", "thats") or norms[i - 1] in ("its", "thats")):
                continue  # ("it's going in the bus station instead")
            while j < len(norms) and norms[j] in ("over", "across", "up", "down", "back"):
                j += 1
            if j >= len(norms) or norms[j] not in ("to", "at", "in", "into", "inside", "over"):
                continue
            target = next((p for p in active if j < p.start_tok <= j + 3
                           and all(norms[t] in lx.DETERMINERS for t in range(j + 1, p.start_tok))), None)
            if target is None:
                continue
            instead = "instead" in norms[target.end_tok:target.end_tok + 4]
            if _still_to_come(norms, target.end_tok):
                continue  # "Moving them to the first aid post shortly": not there yet
            person = obj in ("her", "him", "them") and self._person_category is not None
            if not (instead or w in lx.RELOCATE_EXPLICIT):
                continue
            last = self._last_cue_before(toks, cues, i, 1, (lambda c: c.category == self._person_category) if person
                                         else (lambda c: self.kb.category_by_name[c.category].role == Role.DESIRABLE))
            if last is not None:
                move(last, target, f"moved to {target.text}", None if person else f"moved to {target.text}")
        return cues, moved

    @staticmethod
    def _last_cue_before(toks: Tokens, cues: list[CueMention], i: int, back: int,
                         keep: Callable[[CueMention], bool]) -> CueMention | None:
        """The last active, affirmed cue ``keep`` accepts that ends by token ``i``, in its sentence or up to
        ``back`` sentences before it."""
        n = toks.sentence_of[i]
        return max((c for c in cues if c.status == "active" and c.polarity == "affirmed" and c.end_tok <= i
                    and n - back <= toks.sentence_of[c.start_tok] <= n and keep(c)),
                   key=lambda c: c.start_tok, default=None)

    RESTART_WORDS = frozenset({"there", "theres", "s", "is", "a", "an", "the", "its", "it", "some"})

    @staticmethod
    def _drop_restarted_cues(toks: Tokens, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"there's a fire, there's a fire at the jute sheds": a cue the speaker says again at once, in the
        same sentence, is one cue, the second; the first would bind to the places said before it."""
        out = sorted(cues, key=lambda c: c.start_tok)
        for x in range(len(out) - 1):
            c1, c2 = out[x], out[x + 1]
            if c1.status != "active" or c2.status != "active":
                continue
            if norms[c1.start_tok:c1.end_tok] == norms[c2.start_tok:c2.end_tok] and c1.polarity == c2.polarity \
                    and 0 < c2.start_tok - c1.end_tok <= 4 and toks.sentence_of[c1.start_tok] == toks.sentence_of[c2.start_tok] \
                    and all(norms[i] in ReportAnalyzer.RESTART_WORDS or norms[i] in lx.FILLERS
                            for i in range(c1.end_tok, c2.start_tok)):
                out[x] = replace(c1, status="retracted", reason=f"said again: '{c2.text}'")
                if c2.replaces is None and c1.replaces is not None:
                    out[x + 1] = replace(c2, replaces=c1.replaces)  # (the repair it made is the second one's)
        return out

    @staticmethod
    def _thing_before(norms: tuple[str, ...], a: int, place_tokens: set[int]) -> bool:
        """Is the subject before token ``a`` a structure ("the north boundary wall has collapsed", "its roof
        has collapsed", "the stairs collapsed")? A place named there, or a word for part of a building."""
        j = a - 1
        while j >= 0 and (norms[j] in ("have", "has", "had", "s", "is", "are", "was", "were", "been", "just", "partly",
                                       "partially", "completely", "totally", "now", "all", "also", "then")
                          or norms[j] in lx.FILLERS):
            j -= 1
        if j < 0:
            return False
        if j >= 2 and norms[j] in ("it", "them") and norms[j - 1] == "of":
            j -= 2  # "the bottom end of it is buried": a part of the place
            if norms[j] in ("end", "side", "half", "part", "section", "rest"):
                return True
        return j in place_tokens or norms[j] in lx.DANGER_KIND_PARTS or norms[j] in lx.STRUCTURE_WORDS \
            or norms[j] in lx.LOCATIVE_PARTS

    @staticmethod
    def _person_inside_before(norms: tuple[str, ...], a: int) -> bool:
        """"the building's on fire and the engineer inside is badly burned": a person, "inside", then the word."""
        j = a - 1
        while j >= 0 and norms[j] in ("is", "s", "was", "has", "been", "badly", "very", "bad", "got"):
            j -= 1
        return j >= 2 and norms[j] == "inside" and norms[j - 2] in ("the", "a", "an") and (
            norms[j - 1] in lx.WORKER_PERSONS or norms[j - 1] in lx.PERSON_NOUNS or norms[j - 1] in lx.LAY_PERSONS)

    def _person_at_place_before(self, norms: tuple[str, ...], a: int) -> bool:
        """"The guard in the hut that guards the entrance to the truck park has collapsed": a person, then where they
        are (a preposition and a place the report names, however long its description), then the word at ``a``."""
        j = a - 1
        while j >= 0 and norms[j] in ("have", "has", "had", "s", "is", "was", "just", "now"):
            j -= 1
        if j < 0 or j not in self._place_tokens:
            return False
        while j >= 0 and j in self._place_tokens:
            j -= 1
        while j >= 0 and norms[j] in lx.ARTICLES:
            j -= 1
        if j < 1 or norms[j] not in ("in", "at", "on", "inside", "from"):
            return False
        w = norms[j - 1]
        return w in lx.LAY_PERSONS or w in lx.WORKER_PERSONS or w in lx.PERSON_NOUNS

    @staticmethod
    def _person_before(norms: tuple[str, ...], a: int) -> bool:
        """Is the subject before token ``a`` a person ("two residents have collapsed", "the gardeners all
        collapsed")? A person word, or a counted noun of a doer ("two gardeners", "3 climbers")."""
        j = a - 1
        while j >= 0 and norms[j] in ("have", "has", "had", "s", "is", "are", "was", "were", "been", "got", "just",
                                      "both", "all", "also", "then", "suddenly", "badly", "very", "bad", "like"):
            j -= 1  # ("he's, like, burned both hands")
        if j >= 1 and norms[j] == "else" and norms[j - 1] in ("somebody", "someone", "anyone", "anybody"):
            j -= 1  # "somebody else has collapsed"
        who = next((m for m in range(j, max(0, j - 7), -1) if norms[m] in ("who", "whos")), None)
        if who is not None and who >= 1 and (norms[who - 1] in lx.LAY_PERSONS or norms[who - 1] in lx.WORKER_PERSONS
                                             or norms[who - 1] in lx.PERSON_NOUNS):
            return True  # "the bloke who went to check it has collapsed": the person a relative clause describes
        if j >= 1 and norms[j] in ("there", "here") and norms[j - 1] in ("up", "down", "in", "over", "out", "back"):
            j -= 2  # "one of the riggers up there has collapsed": where they are, between
        elif j >= 1 and norms[j] in ("there", "here") and norms[j - 1] not in lx.FUNCTION_WORDS:
            j -= 1  # "one of the medics there has collapsed"
        k = next((k for k in range(j - 1, max(-1, j - 4), -1) if norms[k] in ("in", "wearing")), None)
        if k is not None and k >= 1 and (norms[k - 1] in lx.LAY_PERSONS or norms[k - 1] in lx.WORKER_PERSONS) \
                and all(norms[m].isalpha() or "-" in norms[m] for m in range(k + 1, j + 1)):
            return True  # "Bloke in hi-vis collapsed": what the person wears, between
        d = next((m for m in range(j - 1, max(-1, j - 8), -1) if norms[m:m + 2] == ("of", "the")), None)
        if d is not None and d >= 1 and (norms[d - 1] in lx.LAY_PERSONS or norms[d - 1] in lx.WORKER_PERSONS) \
                and not any(norms[m] in ("and", "but", "who", "which", "that", "where") for m in range(d + 2, j + 1)):
            return True  # "the driver of the crane straddling quay one has collapsed": whose the person is, between
        if j < 0:
            return False
        if any(norms[m].endswith("ing") and norms[m - 1] in _DOERS for m in range(max(1, j - 3), j)) \
                and norms[j] not in lx.STRUCTURE_WORDS:
            return True  # "a woman visiting a grave has collapsed": what the person was doing, between
        w = norms[j]
        if j >= 3 and norms[j - 2:j] == ("of", "the") and (norms[j - 3] in lx.NUMBER_WORDS or norms[j - 3] in (
                "one", "some", "both", "all", "two")) and w in ("men", "women"):
            return True  # "one of the men has collapsed" (a worker, "one of the riggers", is read below)
        if w == "after" and any(norms[m] in _PEOPLE_WORDS for m in range(max(0, j - 10), j)):
            return True  # "woman with hypothermia at the ferry landing after falling in"
        if w in lx.STRUCTURE_WORDS:
            return False  # "the access ladder's collapsed": a ladder, not a ladder crew
        if w in lx.LAY_PERSONS or w in lx.WORKER_PERSONS or w in lx.PERSON_NOUNS or w in lx.CREW_NOUNS \
                or w in ("we", "they", "i", "he", "she", "hes", "shes", "him", "her", "who", "whos"):
            return True  # ("one at the cafe who's collapsed")
        if w in lx.BODY_PARTS and j > 0 and norms[j - 1] in ("his", "her", "their", "my", "your"):
            return True  # "his arm is burned": a person's
        if w in ("neighbour", "neighbor", "neighbours", "neighbors") and j > 0 \
                and norms[j - 1] in ("his", "her", "their", "my", "your", "our"):
            return True  # "his neighbour's collapsed" (not the post office's neighbour: the place next to it)
        if j > 0 and norms[j - 1] in ("mr", "mrs", "ms", "miss", "dr", "keeper", "nurse", "officer", "sister"):
            return True  # "keeper Mills has collapsed": a name after a title
        if (w in lx.NUMBER_WORDS or w.isdigit()) and any(norms[m] in _PEOPLE_WORDS for m in range(max(0, j - 10), j)):
            return True  # "the men in there are choking, two have collapsed": two of the people just said
        if w in ("them", "us") and j > 1 and norms[j - 1] == "of" and (
                norms[j - 2] in lx.NUMBER_WORDS or norms[j - 2] in ("one", "some", "both", "all")) and any(
                norms[m] in _PEOPLE_WORDS or norms[m] == "staff" for m in range(max(0, j - 15), j - 2)):
            return True  # "staff got out but one of them is badly burned": one of the people just said
        counted = j > 0 and (norms[j - 1] in lx.NUMBER_WORDS or norms[j - 1].isdigit())
        if counted and w.endswith(("er", "ent", "ist", "or", "ian")):
            return True
        if j > 0 and norms[j - 1] == "one" and w.endswith(("ist", "ian")):
            return True  # "one electrician burned"
        if j >= 3 and norms[j - 2:j] == ("of", "the") and norms[j - 3] in ("one", "two", "three", "some", "both") \
                and (w.endswith(("ist", "ian")) or w.endswith("er") and any(
                    norms[m] in ("he", "she", "hes", "shes", "him", "her") for m in range(a, min(len(norms), a + 10)))) \
                and w not in lx.VEHICLE_WORDS and len(w) >= 5:
            return True  # "one of the feeders is burned, he's in the yard": one of a crew, named by what they do
            # (not "one of the containers has collapsed": a thing, no "he" or "she" after it)
        # "the organist up in the loft has collapsed", "a boy from the kitchen burned both hands": the person, then
        # where they are (a preposition, its article and one or two plain words)
        at = next((m for m in range(j - 1, max(-1, j - 4), -1) if norms[m] in ("in", "at", "on", "from")), None)
        if at is not None and at + 2 <= j and norms[at + 1] in lx.ARTICLES and all(
                norms[m].isalpha() and norms[m] not in lx.FUNCTION_WORDS and norms[m] not in lx.STRUCTURE_WORDS
                for m in range(at + 2, j + 1)):
            p = at - 1 - (at >= 2 and norms[at - 1] in ("up", "down", "over", "out", "back"))
            if p >= 0 and (norms[p] in lx.LAY_PERSONS or norms[p] in lx.WORKER_PERSONS or norms[p] in lx.PERSON_NOUNS):
                return True
        # "old Mr Reid at the end cottage has collapsed": the person before where they are
        at = next((m for m in range(j - 1, max(-1, j - 5), -1) if norms[m] in ("at", "in", "inside")), None)
        return at is not None and at > 1 and norms[at - 2] in ("mr", "mrs", "ms", "miss", "dr") and not any(
            norms[m] in lx.STRUCTURE_WORDS for m in range(at, j + 1))  # (a named person only)

    PAIR_LINKS = {"is", "are", "s", "re", "was", "were", "has", "have", "been", "still", "now", "all", "badly"}

    def _damage_by_cause(self, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"damaged by the blast", "cracked in the quake": a word of harm done, said with what did it, takes the
        category of its cause where the KB splits the undesirable role ("blast" a gas explosion, not the flood)."""
        out = list(cues)
        for i, c in enumerate(out):
            if c.polarity != "affirmed" or self.kb.category_by_name[c.category].role != Role.UNDESIRABLE \
                    or norms[c.end_tok - 1] not in lx.HARM_WORDS:
                continue  # (not "blocked by a burnt-out moped", "cut off by the landslip": no harm of that kind)
            j = c.end_tok
            if norms[j:j + 1] not in (("by",), ("in",), ("from",)):
                continue
            j += 1
            while j < len(norms) and norms[j] in lx.ARTICLES and j - c.end_tok < 3:
                j += 1
            cause = next((d for d in out if d.start_tok == j and d is not c and d.polarity == "affirmed"
                          and self.kb.category_by_name[d.category].role == Role.UNDESIRABLE), None)
            if cause is not None and cause.category != c.category:
                out[i] = replace(c, category=cause.category)
        return out

    def _spread_of_what(self, toks: Tokens, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"Fire in the plating shed, and it's spreading to the paint shop": a word that says a danger spreads
        names no kind of its own; where the KB splits the undesirable role it takes the kind of the danger said
        before it in its sentence (or the one before), not the category its word lies nearest to."""
        if len(self.kb.categories_with_role(Role.UNDESIRABLE)) < 2:
            return cues
        out = list(cues)
        for i, c in enumerate(out):
            if c.polarity != "affirmed" or c.source != "lexicon" or norms[c.start_tok:c.end_tok] not in lx.SPREAD_WORDS:
                continue
            before = [d for d in out if d.end_tok <= c.start_tok and d.polarity == "affirmed" and d.status == "active"
                      and 0 <= toks.sentence_of[c.start_tok] - toks.sentence_of[d.start_tok] <= 1
                      and self.kb.category_by_name[d.category].role == Role.UNDESIRABLE]
            last = max(before, key=lambda d: d.start_tok, default=None)
            if last is not None and last.category != c.category:
                out[i] = replace(c, category=last.category, reason="spreads the danger said before it")
        return out

    @functools.cached_property
    def _glossary_keys(self) -> frozenset[tuple[str, ...]]:
        """The KB's glossary terms as word keys."""
        return frozenset(norm_phrase(t.term) for t in self.kb.glossary)

    @functools.cached_property
    def _compass_relations(self) -> bool:
        """Does the KB name any relation by a compass point ("north_of")?"""
        return any(set(norm_phrase(r.relation)) & _COMPASS for r in self.kb.relations)

    @functools.cached_property
    def _animal_category(self) -> str | None:
        """Where the KB splits the critical role into people and animals: the category its description gives to
        livestock or animals (one only), else None."""
        crit = self.kb.categories_with_role(Role.CRITICAL)
        if len(crit) < 2:
            # (or an undesirable one: "The show's animals at a place that are loose, bolting, panicking ...", beside
            # the people's critical category)
            und = [c.name for c in self.kb.categories_with_role(Role.UNDESIRABLE)
                   if self._affirmed_words(c.description) & lx.ANIMAL_WORDS]
            return und[0] if len(und) == 1 and len(crit) == 1 else None
        found = [c.name for c in crit if self._affirmed_words(c.description) & lx.ANIMAL_WORDS]
        return found[0] if len(found) == 1 else None

    def _cues_into_description(self, ex: Extraction, norms: tuple[str, ...], taken: set[int]) -> list[CueMention]:
        """"one of the grooms has gone into the water downhill of the lion shed": a cue phrase that runs on into a
        description's head ("gone into the water") is said of the place described."""
        toks = ex.tokens
        out: list[CueMention] = []
        for p in ex.places:
            a = p.start_tok
            if p.via is None or p.status != "active" or norms[a:a + 2] != ("the", "water") or a < 2:
                continue
            for k in range(max(0, a - 4), a):
                if taken & set(range(k, a)) or any(toks.clause_start[m] for m in range(k + 1, a + 1)):
                    continue
                hit = self._cues.match_at(norms[:a + 2], k)
                if hit is not None and hit[0] == a + 2 and hit[1][1] != "neutral":
                    s_, e_ = toks.tokens[k].start, toks.tokens[a - 1].end
                    out.append(CueMention(k, a, s_, e_, toks.text[s_:e_], hit[1][0], hit[1][1],
                                          reason="runs on into the description's head"))
                    break
        return out

    def _animal_subject(self, toks: Tokens, norms: tuple[str, ...], a: int) -> bool:
        """An animal word before token ``a`` in its clause, with no person word between: "the bulls are chained in
        there screaming", "The lions in the barn across the yard from the horse lines are panicking"."""
        they = False
        # (a word that only qualifies a place's name, "the poultry tent", "the cattle shed"; not "the goats" said of a
        # place named so)
        places = {i for p in getattr(self, "_places_now", []) for i in range(p.start_tok, p.end_tok - 1)}
        for j in range(a - 1, max(-1, a - 25), -1):
            if j in places or j >= 2 and norms[j - 1] in lx.ARTICLES and norms[j - 2] in ("by", "after"):
                continue  # (or an animal that did it, "kicked by a cow"; or gone after: "gone in after a dog and is
                # in trouble")
            if norms[j] in ("they", "theyre", "theyve", "them"):
                they = True  # (whoever "they" are: the sentence before says)
                continue
            if norms[j] in _PEOPLE_WORDS or norms[j] in lx.PERSON_SUBJECTS or norms[j] in lx.CALLER_ROLES:
                return False  # ("one of the keepers is trapped in the night den": a person)
            if norms[j] in lx.ANIMAL_WORDS:
                return True
            if toks.clause_start[j] and not (j > 0 and norms[j - 1] in lx.ANIMAL_WORDS) and not (
                    they and j > 0 and toks.sentence_of[j - 1] == toks.sentence_of[a]):
                # (but "the goats are in the goat yard and some of them fell down": "them", the animals said before)
                return False
            if j < a - 12 and not they:
                return False
        return False

    def _animal_states(self, toks: Tokens, norms: tuple[str, ...], taken: set[int]) -> list[CueMention]:
        """"the bulls in the barn it's built against are going frantic": a state only animals in trouble are said
        to be in, its animal the subject of the clause, where the KB has a category for animals."""
        animal = self._animal_category
        out: list[CueMention] = []
        if animal is None:
            return out
        for i in range(1, len(norms)):
            n = 2 if norms[i:i + 2] in _ANIMAL_STATE_KEYS else 1
            if n == 1 and norms[i:i + 1] not in _ANIMAL_STATE_KEYS:
                continue
            if taken & set(range(i, i + n)) or not self._animal_subject(toks, norms, i):
                continue
            a_, b_ = toks.tokens[i].start, toks.tokens[i + n - 1].end
            out.append(CueMention(i, i + n, a_, b_, toks.text[a_:b_], animal, "lexicon", reason="said of animals"))
            taken = taken | set(range(i, i + n))
        for i in range(2, len(norms)):
            # "the nannies are down in the kid pens": animals down (a person down is read apart)
            if norms[i] == "down" and i not in taken and (norms[i - 1] in ("is", "are", "s", "re") and (
                    norms[i - 2] in lx.ANIMAL_WORDS or norms[i - 2] in ("they", "them")) or norms[i - 1] == "theyre") \
                    and (i + 1 == len(norms) or toks.clause_start[i + 1] or norms[i + 1] in ("in", "at", "inside", "and"))\
                    and self._animal_subject(toks, norms, i - 1):
                a_, b_ = toks.tokens[i].start, toks.tokens[i].end
                out.append(CueMention(i, i + 1, a_, b_, toks.text[a_:b_], animal, "lexicon", reason="said of animals"))
        return out

    def _animals_in_trouble(self, toks: Tokens, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"bullocks stuck in the cattle lines", "a bullock loose", "ewes swimming in there": a critical cue said of
        animals takes the KB's category for animals, where it has one apart from the people's."""
        animal = self._animal_category
        if animal is None:
            return cues
        people = [c.name for c in self.kb.categories_with_role(Role.CRITICAL) if c.name != animal]
        out = []
        for c in cues:
            if c.source == "lexicon" and self.kb.category_by_name[c.category].role == Role.UNDESIRABLE \
                    and norms[c.start_tok:c.end_tok] in lx.PERSON_STATE_CUES and self._animal_subject(toks, norms, c.start_tok):
                c = replace(c, category=animal, reason="said of animals")  # "some of the goats fell down"
            elif c.source == "lexicon" and self.kb.category_by_name[c.category].role == Role.CRITICAL \
                    and c.category != animal and self._animal_subject(toks, norms, c.start_tok):
                c = replace(c, category=animal, reason="said of animals")  # "and they're coughing and coughing"
            elif self.kb.category_by_name[c.category].role == Role.CRITICAL and c.category != animal:
                j = c.start_tok - 1
                while j >= 0 and c.start_tok - j <= 4 and (norms[j] in ("are", "is", "s", "re", "been", "got", "all", "still",
                                                                         "now", "just", "a", "an", "the", "two", "three")
                                                           or norms[j] in lx.FILLERS or is_number(norms[j])):
                    j -= 1
                said = set(norms[c.start_tok:c.end_tok])
                if said & lx.ANIMAL_WORDS or j >= 0 and norms[j] in lx.ANIMAL_WORDS \
                        or c.end_tok - c.start_tok == 1 and norms[c.start_tok] in (
                            "screaming", "panicking", "trapped", "stuck", "hurt", "injured") \
                        and self._animal_subject(toks, norms, c.start_tok):
                    c = replace(c, category=animal, reason="said of animals")
            elif c.source == "lexicon" and c.category == animal and len(people) == 1 \
                    and self.kb.category_by_name[animal].role == Role.CRITICAL \
                    and not set(norms[c.start_tok:c.end_tok]) & lx.ANIMAL_WORDS \
                    and self._person_before(norms, c.start_tok) and not self._animal_subject(toks, norms, c.start_tok):
                # "a groom's been kicked in the bays", "a lady's been knocked over at the food vans": what the
                # vocabulary reads as the animals' is said of a person
                c = replace(c, category=people[0], reason="said of a person")
            out.append(c)
        return out

    def _things_in_the_water(self, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"the truck's in the water", "the front end's in the water": a vehicle (or its end) in the water is a
        danger at the place, no person in it."""
        und = None
        out = []
        for c in cues:
            j = c.start_tok - 1
            while j >= 0 and norms[j] in ("s", "is", "are", "re", "was", "now", "right", "half", "all", "just", "still"):
                j -= 1
            if c.source == "lexicon" and norms[c.start_tok:c.end_tok] == ("in", "the", "water") and j >= 0 \
                    and self.kb.category_by_name[c.category].role == Role.CRITICAL \
                    and (norms[j] in lx.VEHICLE_WORDS or norms[j] in ("pickup", "cab", "bonnet")
                         or norms[j] == "end" and j > 0 and norms[j - 1] in ("front", "back", "rear")):
                und = und or self._category_for_role(lx.UNDESIRABLE, "a vehicle gone through into the water")
                if und is None:
                    continue
                c = replace(c, category=und, reason="a vehicle in the water")
            out.append(c)
        return out

    def _read_cue_pairs(self, toks: Tokens, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """Two vocabulary cues of one role that the KB splits into several categories, said as one
        predicate ("the ammonia is leaking", "fuel leaking"), take the category of what they say
        together: "leaking" alone reads as flood water, "ammonia is leaking" as a chemical danger."""
        out = list(cues)
        order = sorted(range(len(out)), key=lambda k: out[k].start_tok)
        for x, y in zip(order, order[1:], strict=False):
            c1, c2 = out[x], out[y]
            if c1.source != "lexicon" or c2.source != "lexicon" or c1.category == c2.category \
                    or c1.polarity != "affirmed" or c2.polarity != "affirmed":
                continue
            role = self.kb.category_by_name[c1.category].role
            if self.kb.category_by_name[c2.category].role != role or c2.start_tok - c1.end_tok > 2 \
                    or any(norms[i] not in self.PAIR_LINKS for i in range(c1.end_tok, c2.start_tok)) \
                    or any(toks.clause_start[i] for i in range(c1.end_tok, c2.end_tok)):
                continue
            cat = self._category_for_role(role.value, toks.text[c1.start:c2.end])
            if cat is not None:
                out[x], out[y] = replace(c1, category=cat), replace(c2, category=cat)
        return out

    # ------------------------------------------------------------------ semantic fallback
    semantic_fallback: bool = True
    FALLBACK_MIN_SIM = 0.35
    FALLBACK_MARGIN = 0.07

    def _exemplars(self) -> tuple[np.ndarray, list[str]]:
        if getattr(self, "_ex_cache", None) is None:
            texts: list[str] = []
            labels: list[str] = []
            for role, phrases in lx.EXEMPLARS.items():
                for phrase in phrases:
                    # each exemplar to its own category: a KB with two undesirable categories
                    # ("peril", "submerged") gets "flooded" as the one and "on fire" as the other
                    label = role if role == "none" else self._category_for_role(role, phrase)
                    if label is not None:
                        texts.append(phrase)
                        labels.append(label)
            for term in self.kb.glossary:
                texts.append(term.term)
                labels.append(term.category)
            assert self.embedder is not None
            self._ex_cache = (self.embedder.embed_fixed(texts), labels)
        return self._ex_cache

    def _predicate_region(self, ex: Extraction, p: PlaceMention, norms: tuple[str, ...]) -> tuple[int, int]:
        toks = ex.tokens
        marker_starts = {a for a, _, _ in ex.markers}
        others = [q.start_tok for q in ex.places if q.start_tok > p.start_tok and q.status == "active"]
        stop = min(others + [len(toks)])
        end = p.end_tok
        while end < stop and end - p.end_tok < 14 and not toks.sentence_start[end] and end not in marker_starts:
            end += 1
        start = p.start_tok
        while start > 0 and p.start_tok - start < 6 and not toks.clause_start[start]:
            if any(q.end_tok == start for q in ex.places):
                break
            start -= 1
        if self._speaker_at(norms, p):
            # "she's crying and I'm in the park": what is said before the speaker says where they are is not
            # said of that place
            start = max(start, max((i for i in range(start, p.start_tok) if norms[i] in ("i", "im", "we", "were")),
                                   default=start))
        return start, end

    def _semantic_claims(self, ex: Extraction, claims: list[Claim], denied: list[Claim]) -> list[Claim]:
        """Places the vocabulary left without a category: classify their predicate with MiniLM."""
        todo = self._silent_places(ex, claims, denied)
        if not todo:
            return []
        assert self.embedder is not None
        vecs = self.embedder.embed([text for _, _, _, text in todo])
        toks = ex.tokens
        out = []
        for (p, a, b, _), v in zip(todo, vecs, strict=True):
            label, score, runner = self._rank_meaning(v)
            if label == "none" or score < self.FALLBACK_MIN_SIM or score - runner < self.FALLBACK_MARGIN:
                continue
            start, end = toks.tokens[a].start, toks.tokens[b - 1].end
            cue = CueMention(a, b, start, end, toks.text[start:end], label, "embedding",
                             reason=f"MiniLM predicate match {score:.2f} (runner-up {runner:.2f})")
            out.append(Claim(p, cue))
        return out

    def _predicate_words(self, ex: Extraction, p: PlaceMention, a: int, b: int) -> str:
        """What is said of ``p`` in its predicate region, without fillers and the place's own words."""
        toks = ex.tokens
        words = [t.text for t in toks.tokens[a : p.start_tok] if t.norm not in lx.FILLERS and t.norm not in lx.DETERMINERS]
        words += [t.text for t in toks.tokens[p.end_tok : b] if t.norm not in lx.FILLERS]
        return " ".join(words)

    def _silent_places(self, ex: Extraction, claims: list[Claim],
                       denied: list[Claim]) -> list[tuple[PlaceMention, int, int, str]]:
        """Active places nothing in the vocabulary spoke of, where a guess is allowed: (place, region
        start, region end, what is said of it)."""
        done = {id(c.place) for c in claims} | {id(c.place) for c in denied}
        done_keys = {(c.place.start_tok) for c in claims} | {c.place.start_tok for c in denied}
        silent = getattr(self, "_non_report_tokens", set())
        claimed = {c.place.landmark for c in claims}
        # (nor a head word that takes up a place already claimed: "the fields ... are burning now, the wind's driving
        # it straight across the terraces")
        todo = [p for p in ex.places if p.status == "active" and id(p) not in done and p.start_tok not in done_keys
                and p.start_tok not in silent and not (p.landmark in claimed and "' named last, " in p.reason)]
        if not todo:
            return []
        toks = ex.tokens
        all_cues = getattr(self, "_all_cues_now", [])
        kept = []
        norms = toks.norms(0, len(toks))
        negated = {i for i, w in enumerate(norms) if w in lx.NEGATORS or w in ("couldnt", "wouldnt", "wont", "shouldnt", "stopped")
                   or w in ("evacuated", "evacuating")}  # ("the water treatment works has been evacuated": no guess)
        for a, b, _ in self._negators.find_all(norms):
            negated.update(range(a, b))
        # "the kids from the school are all out": got out, nobody left to guess a claim for
        negated.update(i for i in range(len(norms) - 1) if norms[i + 1] == "out" and norms[i] in lx.GOT_OUT_BEFORE)
        # ("the hotel is being cleared": emptied, no safe place to guess)
        negated.update(i for i in range(1, len(norms)) if norms[i] == "cleared" and norms[i - 1] == "being")
        asking = self._question_sentences(toks)
        # ("team three at the tank the pumps feed, moving on to the hangar next, no problems seen": all well there)
        well = {toks.sentence_of[i] for i in range(len(norms)) if norms[i:i + 2] in _ALL_WELL}
        for p in todo:
            if toks.sentence_of[p.start_tok] in asking:
                continue  # "is the health centre still taking walk-ins?": a question is no claim to guess at
            if toks.sentence_of[p.start_tok] in well:
                continue  # (said to be well)
            if p.start_tok == 0 and p.via is None and p.end_tok < len(toks) and toks.gaps[p.end_tok].strip().startswith(","):
                nxt = next((w for w in norms[p.end_tok:] if w not in lx.FILLERS), "")
                if nxt in lx.RADIO_CALL_WORDS:
                    continue  # "Port Control, uh, all stations, ...": the station called, no claim to guess at
                e = p.end_tok + 2
                if e <= len(norms) and (is_number(norms[e - 1]) or norms[e - 1] in lx.NUMBER_WORDS) \
                        and toks.tokens[p.end_tok].text[:1].isupper() and (e == len(norms) or toks.sentence_start[e]):
                    continue  # "Rally office, Fire Two.": the station called and who calls, no claim to guess at
            if _call_sign_at(toks, norms, p):
                continue  # "Rescue Two at the gorge.": who calls and where they are, no claim to guess at
            a, b = self._predicate_region(ex, p, norms)
            if any(a <= c.start_tok < b or c.start_tok < a < c.end_tok for c in all_cues) \
                    or any(a <= ma < b for ma, _, _ in ex.markers) \
                    or any(a <= i < b for i in getattr(self, "_shut_tokens", ())) \
                    or any(a <= i < b for i in getattr(self, "_neutral_tokens", ())):
                continue  # the vocabulary (or a repair) already spoke here; the fallback stays silent
            if any(a <= i < b for i in negated):
                continue  # "nobody home at the flats": a negated predicate is no claim to guess at
            if any(b <= ma <= b + 2 for ma, _, _ in ex.markers):
                continue  # "we were told it had blown, but that's wrong": taken back at once, no claim to guess at
            if any(norms[i:i + len(key)] == key for _, key in _FALSE_ALARM_KEYS for i in range(a, b)):
                continue  # "it's just fog round the bell tower": a dismissal is no claim to guess at
            if any(norms[i] in ("just", "only") and (norms[i - 1] in ("s", "is", "its", "are", "thats") or toks.tokens[
                    i - 1].text.lower().endswith(("'s", "’s"))) for i in range(a + 1, b)):
                continue  # "The green's just puddles": what it only is, no claim to guess at
            if any(norms[i] in lx.HARMLESS_SIGHTS and norms[i - 1] == "was" and norms[i - 2] in ("it", "that")
                   for i in range(max(a, 2), b)):
                continue  # "cancel that, it was fog off the chiller doors": what it was, harmless, no claim to guess at
            sent = [i for i in range(len(norms)) if toks.sentence_of[i] == toks.sentence_of[p.start_tok]]
            if {norms[i] for i in sent} & {"scared", "worried", "afraid", "fear", "frightened"} \
                    and {norms[i] for i in range(a, b)} & {"might", "could", "may", "will", "ll"}:
                continue  # "I'm scared the cladding might come off onto the playground": feared, no claim to guess at
            if self._says_who_and_where(toks, norms, p) or self._this_is_who_at(toks, norms, p):
                continue  # "Scaffolder on the roof of the hotel, over.": who is calling and from where
            if any(norms[i] in _MOVING_CREWS and any(
                    norms[m] in _CREW_MOVES for m in range(i + 1, min(i + 4, p.start_tok)))
                   for i in sent if i < p.start_tok):
                continue  # "the crew's moving across to the winery to help with the pumps": where responders go
            if any((h := self._transit.match_at(norms, k)) is not None and h[0] == _noun_phrase_start(norms, p)
                   for k in range(max(0, p.start_tok - 8), p.start_tok)):
                continue  # "keep the public back from the crossing below the old bridge": passed or kept from
            if any(q.landmark == p.landmark and q.status == "retracted" and q.reason.startswith("restarted")
                   and q.end_tok <= p.start_tok and any(
                       norms[k] in ("im", "were") and norms[k + 1] in ("at", "on", "in", "by", "up")
                       and not any(toks.clause_start[m] for m in range(k + 1, q.start_tok + 1))
                       for k in range(max(0, q.start_tok - 9), q.start_tok - 1)) for q in ex.places):
                continue  # "I'm on the quad at the top of the pit, the gravel pit, and ...": where the speaker is
            if self._kept_clear_for(toks, norms, p.start_tok):
                continue  # "keep the road clear for the ladder coming down from the fire station": no claim to guess
            if ("from" in norms[max(0, p.start_tok - 3):p.start_tok] or "off" in norms[max(0, p.start_tok - 2):p.start_tok]) \
                    and any(norms[i] in lx.MOVE_VERBS | lx.EVACUATE_VERBS | {"launching", "launched", "launch"}
                            or norms[i] in ("come", "drive")
                            and norms[i - 1] in ("can", "could", "will", "ll", "should") for i in sent if i < p.start_tok - 1):
                continue  # "we've walked about forty people up there from the caravan park", "walking the evacuees
                # off the boardwalk": where they came from
            after = [w for w in norms[p.end_tok:p.end_tok + 5] if w not in lx.FILLERS]
            if after[:2] in (["and", "i"], ["and", "we"]) and after[2:3] and after[2] in lx.PERCEPTION_VERBS:
                continue  # "up on the scaffold at the town hall and i seen the roof of the sports hall fold in": where
                # the one who saw it stood
            if any((h := self._cancel.match_at(norms, i)) is not None and ("out" in h[1].split() or h[1] in (
                    "extinguished", "under control") or ({"gone", "down"} <= set(h[1].split())
                                                        or {"receded", "subsided"} & set(h[1].split()))
                    and (h[0] >= len(norms) or toks.clause_start[h[0]] or norms[h[0]] in ("now", "again", "already")))
                   for i in range(p.end_tok, b)):
                # ("the water at the boat landing has gone back down": the water over, no claim to guess)
                continue  # "it was someone's bonfire on the allotments, and that's out now": ended, no claim to guess
            if all(norms[i] in lx.FILLERS or norms[i] in lx.DETERMINERS or norms[i] in ("all", "whole", "every", "both", "of")
                   for i in range(a, b) if not p.start_tok <= i < p.end_tok):
                continue  # "All the flats.": a place said alone, nothing said of it to guess at
            if {"saying", "says", "said"} & set(norms[a:b]):
                continue  # "people keep saying garage": what others say, no claim to guess at
            if [w for w in norms[p.end_tok:b] if w not in lx.FILLERS | lx.COPULAS | {"s", "bone", "quite", "all"}][:1] \
                    == ["dry"] and not self._dry_described:
                continue  # "the front row is flooded and the back row's dry": not flooded, no claim to guess at (where
                # no category is described as dry: in a KB whose shelter is "a dry, safe place", it is the guess's)
            if any(norms[i] in ("full", "capacity") and norms[i + 1:i + 2] != ("of",) for i in range(p.end_tok, b)):
                continue  # "moved to the rec because the welfare hall is full": how many it holds, no claim
            said = [w for w in norms[p.end_tok:b] if w not in lx.FILLERS]
            if toks.tokens[p.end_tok - 1].text.lower().replace("’", "'").endswith("'s"):
                said = ["s", *said]
            if said[:2] in (["s", "the"], ["is", "the"]) and "one" in said[2:6]:
                continue  # "the bank's the brick one": which building it is, nothing said of it
            after = norms[p.end_tok:min(len(norms), p.end_tok + 6)]
            if any((h := self._cancel.match_at(norms, i)) is not None and h[1] in lx.CANCEL_MISSING_ONLY
                   for i in range(max(0, p.start_tok - 10), p.start_tok)) \
                    and any(after[n:n + 2] in (("whole", "time"), ("all", "along")) for n in range(len(after))):
                continue  # "mum's found her, she was in the toilet block the whole time": never lost there
            kept.append(p)
        out = []
        for p in kept:
            a, b = self._predicate_region(ex, p, norms)
            out.append((p, a, b, self._predicate_words(ex, p, a, b)))
        if all(b - a <= (p.end_tok - p.start_tok) + 1 for p, a, b, _ in out):
            return []  # nothing but the places' own words around them
        return out

    @staticmethod
    def _answered(toks: Tokens, norms: tuple[str, ...], sentence: tuple[int, int], words: frozenset[str]) -> bool:
        """Does the sentence open with one of ``words`` ("Caller: no, no", "Yes."), past a speaker's label?"""
        a, b = sentence
        i = a
        label = next((k for k in range(a + 1, min(b, a + 4)) if toks.gaps[k].strip() == ":"), None)
        if label is not None:
            i = label  # "Caller:", "Heron Four:"
        while i < b and norms[i] in lx.FILLERS:
            i += 1
        return i < b and norms[i] in words and (i + 1 >= b or toks.clause_start[i + 1])

    @staticmethod
    def _question_sentences(toks: Tokens) -> set[int]:
        """Sentences that end in a question mark."""
        out = set()
        for i in range(len(toks)):
            last = i + 1 >= len(toks) or toks.sentence_start[i + 1]
            tail = toks.gaps[i + 1] if i + 1 < len(toks) else toks.text[toks.tokens[i].end:]
            if last and "?" in tail:
                out.add(toks.sentence_of[i])
        return out

    def _rank_meaning(self, v: np.ndarray, exclude: str | None = None) -> tuple[str, float, float]:
        """(label, score, runner-up score) of an embedded predicate against the exemplars: a category
        name or "none"; each label scores the mean of its two closest exemplars."""
        mat, labels = self._exemplars()
        sims = mat @ v
        best: dict[str, float] = {}
        for lab in set(labels) - {exclude}:
            vals = np.sort(sims[[i for i, x in enumerate(labels) if x == lab]])[-2:]
            best[lab] = float(vals.mean())
        ranked = sorted(best.items(), key=lambda kv: (-kv[1], kv[0]))
        if not ranked:
            return "none", 0.0, 0.0
        return ranked[0][0], ranked[0][1], ranked[1][1] if len(ranked) > 1 else -1.0

    def _repaired_by_meaning(self, ex: Extraction, b: int, end: int, old: CueMention) -> CueMention | None:
        """"the garage is clear— strike that— there's fuel all over the floor": a repair whose new
        claim the vocabulary misses; MiniLM reads it, any category but the one withdrawn."""
        if self.embedder is None:
            return None
        toks = ex.tokens
        place_toks = {i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        end = next((i for i in range(b + 1, end) if toks.clause_start[i]), end)  # its first clause
        words = [toks.tokens[i].text for i in range(b, end)
                 if i not in place_toks and toks.tokens[i].norm not in lx.FILLERS | lx.DETERMINERS]
        if len(words) < 3 or any(toks.tokens[i].norm in lx.NEGATORS | lx.DISMISSALS for i in range(b, end)):
            return None
        label, score, runner = self._rank_meaning(self.embedder.embed_one(" ".join(words)), exclude=old.category)
        if label == "none" or score < self.FALLBACK_MIN_SIM or score - runner < self.FALLBACK_MARGIN:
            return None
        start, stop = toks.tokens[b].start, toks.tokens[end - 1].end
        return CueMention(b, end, start, stop, toks.text[start:stop], label, "embedding", replaces=old.start_tok,
                          reason=f"MiniLM reading of the repair {score:.2f} (runner-up {runner:.2f})")

    @staticmethod
    def _mistaken_beliefs(toks: Tokens, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"we thought the school was on fire but it's fine", "we thought Mr Hale was missing ... but he's -- no
        he's fine": what was believed, then found all right, is denied."""
        out = list(cues)
        for idx, c in enumerate(out):
            if c.status != "active" or c.polarity != "affirmed":
                continue
            n = toks.sentence_of[c.start_tok]
            thought = next((k for k in range(c.start_tok - 1, max(-1, c.start_tok - 9), -1)
                            if norms[k] == "thought" and k > 0 and norms[k - 1] in ("we", "i", "they", "wed", "id", "had")
                            and toks.sentence_of[k] == n), None)
            if thought is None:
                continue
            but = next((k for k in range(c.end_tok, min(len(norms), c.end_tok + 10))
                        if norms[k] == "but" and toks.sentence_of[k] == n), None)
            if but is None or not any(norms[m] in lx.FINE_WORDS for m in range(but + 1, min(len(norms), but + 8))
                                      if toks.sentence_of[m] == n):
                continue
            out[idx] = replace(c, polarity="denied", reason="believed, then found all right")
        return out

    def _people_down(self, toks: Tokens, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"two of my crew are down", "firefighter down, need assistance": a person down, hurt or out cold; and
        "Mr Bowen in the flats has fallen on the stairs": a person fallen."""
        cat = self._person_category
        if cat is None:
            return []
        out = []
        for i in range(2, len(norms)):
            if norms[i] in ("fallen", "fell") and i not in blocked and norms[i - 1] in ("has", "have", "s", "just") \
                    and self._person_before(norms, i) and (i + 1 == len(norms) or toks.clause_start[i + 1] or norms[
                        i + 1] in ("on", "down", "over", "in", "at", "and", "badly", "again", "off")):
                # "Mr Bowen in the flats has fallen on the stairs": a person fallen
                start, end = toks.tokens[i].start, toks.tokens[i].end
                out.append(CueMention(i, i + 1, start, end, toks.text[start:end], cat, "lexicon", reason="a person fallen"))
        for i in range(1, len(norms)):
            if norms[i] != "down" or i in blocked or not (
                    i + 1 == len(norms) or toks.clause_start[i + 1]
                    or norms[i + 1] in ("need", "needs", "and", "in", "at", "inside", "here", "there")):
                continue
            if not self._person_before(norms, i) or norms[i - 1] not in ("is", "are", "s", "re") \
                    and norms[i - 1] not in lx.CREW_NOUNS | lx.WORKER_PERSONS | {"man", "men", "woman", "person"}:
                continue
            if any(norms[k] in lx.BRING_VERBS | {"send", "sent", "sending", "get", "move"} for k in range(max(0, i - 5), i - 1)):
                continue  # "bring the contaminated crews down": people moved down, no one fallen
            start, end = toks.tokens[i].start, toks.tokens[i].end
            out.append(CueMention(i, i + 1, start, end, toks.text[start:end], cat, "lexicon", reason="a person down"))
        for i in range(2, len(norms) - 3):
            # "the roof has come in and there are still three slate splitters inside": people counted as still inside
            # (whatever their trade), in a report that says a danger
            if norms[i] != "still" or norms[i - 2:i] not in (("there", "are"), ("there", "re"), ("there", "s"),
                                                              ("there", "is")) or i in blocked:
                continue
            n = i + 1
            if not (norms[n].isdigit() or norms[n] in lx.NUMBER_WORDS | {"some", "people", "folk"}):
                continue
            inside = next((m for m in range(n + 1, min(len(norms), n + 4)) if norms[m] in ("inside", "in")), None)
            if inside is None or any(toks.clause_start[m] for m in range(i, inside + 1)) \
                    or any(norms[m] in lx.ANIMAL_WORDS for m in range(n, inside)) \
                    or norms[inside] == "in" and norms[inside + 1:inside + 2] not in (("there",), ("it",), ("the",)) \
                    or any(norms[m] in lx.FINE_WORDS | {"working", "sheltering", "safe"} for m in range(len(norms))
                           if toks.sentence_of[m] == toks.sentence_of[i]):
                continue
            start, end = toks.tokens[i].start, toks.tokens[inside].end
            out.append(CueMention(i, inside + 1, start, end, toks.text[start:end], cat, "lexicon",
                                  reason="people still inside"))
        return out

    def _person_cues(self, ex: Extraction, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"a person at the window", "there's someone under it", "a woman clinging to a fence post":
        a member of the public placed somewhere in a report is someone to rescue."""
        cat = self._person_category
        if cat is None:
            return []
        toks = ex.tokens
        out = []
        for i, w in enumerate(norms):
            worker = w in lx.WORKER_PERSONS
            if not (w in lx.LAY_PERSONS or worker) or i in blocked:
                continue
            j = i - 1
            while j >= 0 and norms[j] in lx.PERSON_MODIFIERS:
                j -= 1
            if worker and j >= 1 and norms[j].isalpha() and norms[j] not in lx.FUNCTION_WORDS \
                    and norms[j - 1] in lx.PERSON_INTRODUCERS:
                j -= 1  # "a forklift driver", "one delivery driver"
            introduced = j >= 0 and (norms[j] in lx.PERSON_INTRODUCERS or norms[j].isdigit() or norms[j] in lx.NUMBER_WORDS)
            k = i + 1
            held_in = j >= 1 and norms[j - 1] == "with" and norms[k:k + 1] in (("inside",), ("aboard",), ("onboard",)) \
                and (k + 1 >= len(norms) or toks.clause_start[k + 1]) \
                and any(norms[m] in ("stuck", "stranded", "trapped", "jammed", "hanging", "dangling")
                        for m in range(max(0, j - 5), j - 1))
            if held_in:  # "one car stuck with the driver inside": someone held in the thing that is stuck
                t0, t1 = toks.tokens[i], toks.tokens[k]
                out.append(CueMention(i, k + 1, t0.start, t1.end, toks.text[t0.start:t1.end], cat, "lexicon",
                                      reason="a person held inside"))
                continue
            if not introduced and i > 0 and norms[i - 1] == "the" and w in norms[:i - 1] \
                    and toks.tokens[i].text.lower().endswith(("'s", "’s")):
                # "an injured man at the water tower? -- no, ... the man's at the water tower": the one spoken of,
                # placed again
                introduced = True
            if not introduced and j >= 0 and norms[j] in ("hear", "heard", "hearing", "see", "seen", "saw") \
                    and k < len(norms) and norms[k] in lx.DISTRESS_VERBS:
                introduced = True  # "I can hear kids crying in there"
            if not introduced and w not in ("someone", "somebody") and not (
                    toks.clause_start[j + 1] and any(norms[m] in lx.DISTRESS_VERBS and not toks.clause_start[m]
                                                     for m in range(k + 1, min(len(norms), k + 7)))):
                continue  # ("..., people on the balconies shouting": a clause of people in distress)
            if norms[k : k + 1] == ("of",) and k + 1 < len(norms) and (norms[k + 1].isdigit() or norms[k + 1] in lx.NUMBER_WORDS):
                k += 2  # "a family of five up on the gantry"
            if norms[k : k + 1] == ("and",) and k + 3 < len(norms) and norms[k + 1] in lx.PERSON_INTRODUCERS | lx.NUMBER_WORDS \
                    and norms[k + 3] in lx.PERSON_SITUATIONS and not toks.clause_start[k + 3]:
                k += 3  # "two adults and a dog on the roof"
            while k < len(norms) and norms[k] in lx.FILLERS | {"still", "definitely", "probably", "possibly", "maybe",
                                                                "apparently", "certainly", "stuck"}:
                k += 1
            pinned = False
            if k + 1 < len(norms) and norms[k] in ("were", "was", "are", "is") and introduced:
                m = k + 1
                while m < len(norms) and norms[m] in lx.FILLERS and not toks.sentence_start[m]:
                    m += 1
                if m < len(norms) and norms[m] in ("under", "underneath", "beneath", "pinned", "trapped"):
                    k, pinned = m, True  # "two kids were, like, under it": pinned there
            still = "still" in norms[i + 1:k] and k < len(norms) and norms[k] in ("in", "inside", "up") \
                and j >= 1 and norms[j] in ("a", "an", "one") and norms[j - 1] in ("theres", "there", "s", "is")
            # ("there's a lifeguard still up in it": someone left in the place the danger is at)
            if k >= len(norms) or norms[k] not in lx.PERSON_SITUATIONS or toks.clause_start[k] and not pinned \
                    or worker and not still and norms[k] not in lx.PINNED_SITUATIONS and not any(
                        norms[m] in ("waving", "stranded", "screaming", "shouting", "clinging") for m in range(k, min(
                            len(norms), k + 7)) if not any(toks.clause_start[t] for t in range(k, m + 1))):
                continue  # ("a lad on the roof of one waving at me": in distress there, whatever his work)
            if toks.tokens[i].text.lower().replace("’", "'").endswith("'s") and i >= 2 \
                    and norms[i - 1] in ("his", "her", "their", "my", "our", "your") and norms[i - 2] in ("at", "to", "from"):
                continue  # "the keeper's been stopping at his daughter's in town": her home, no person in need
            if norms[k] == "left" and k + 1 < len(norms) and norms[k + 1] in lx.ARTICLES | {"his", "her", "their", "it", "them"}:
                continue  # "somebody's left a van right across the entrance": left something, not left behind
            if w in ("someone", "somebody") and i > 0 and norms[i - 1] in ("get", "send", "put", "need", "needs") \
                    and norms[k] == "on" and norms[k + 1:k + 2] in (("it",), ("that",), ("this",)):
                continue  # "that's a fire, get someone on it": someone to deal with it, nobody in need
            if j >= 2 and norms[j - 1] == "from" and norms[j - 2] in _CALL_NOUNS:
                continue  # "relaying a 999 call from a lady up the terrace": who called, not someone in need
            if w in ("someone", "somebody") and i > 0 and norms[i - 1] in ("can", "could", "will", "would"):
                continue  # "can someone at the fire shed pick up": a call to whoever is there, nobody in need
            if any(norms[m] in lx.NEGATORS and not toks.clause_start[m + 1] for m in range(max(0, j - 2), i)):
                continue  # "no one at the window" is handled as a negation elsewhere (not "no, the man's at ...")
            if self._speaks_next(toks, norms, k + 1):
                continue  # "a man in the coffee house says the building across from it ...": who tells, not who is hurt
            if j >= 1 and norms[j] in ("a", "an") and (norms[j - 1] in ("were", "im") or norms[max(0, j - 2):j] in (
                    ("we", "are"), ("i", "am"), ("we", "re"))):
                continue  # "We're a family in a car, parked in visitor parking": who is calling
            if norms[k] in ("up", "down", "over", "across", "out") and norms[k + 1:k + 2] in (("to",), ("into",)) \
                    and any(norms[m] in lx.MOVING_VERBS for m in range(max(0, j - 2), j + 1)):
                continue  # "We've moved our old people up to the tin tabernacle": taken somewhere, no one in need
            if w in _KIN and any(norms[m] in _LOST_WORDS or norms[m:m + 2] == ("cant", "find")
                                 for m in range(0, i) if toks.sentence_of[m] == toks.sentence_of[i]):
                continue  # "lost child at the dodgems, her mum's at the first aid tent": who waits for the child
            t0, t1 = toks.tokens[i], toks.tokens[k]
            out.append(CueMention(i, k + 1, t0.start, t1.end, toks.text[t0.start:t1.end], cat, "lexicon",
                                  reason="a person placed at the scene"))
        return out

    @staticmethod
    def _speaks_next(toks: Tokens, norms: tuple[str, ...], k: int) -> bool:
        """A verb of telling within the next few words of the clause ("somebody in the queue said ...")."""
        for m in range(k, min(len(norms), k + 7)):
            if toks.clause_start[m]:
                return False
            if norms[m] in lx.TELLING_VERBS:
                return True
        return False

    def _evacuation_destinations(self, ex: Extraction, norms: tuple[str, ...],
                                 cues: list[CueMention]) -> list[CueMention]:
        """"we've evacuated everyone to the church", "moving residents into the town hall": the place
        people were taken to is a place of safety (the evacuation is no hazard of that place)."""
        cat = self._role_category.get("desirable")
        if cat is None:
            return cues
        toks = ex.tokens
        # (a place taken back by a repair leads to the one put in its stead: "put the others in the ambulance
        # station -- I mean the doctors', the surgery")
        starts = {p.start_tok for p in ex.places if p.status == "active"
                  or p.status == "retracted" and p.reason.startswith("self-repair")}
        starts |= {s + 1 for s in starts if s + 1 < len(norms) and norms[s] in lx.ARTICLES}  # ("the field it plays ...")
        for i, w in enumerate(norms):
            evac = w in lx.EVACUATE_VERBS
            # ("We've put the others in the surgery till it stops": people put somewhere to wait)
            put = w in ("put", "putting") and i > 0 and norms[i - 1] in ("weve", "ive", "theyve", "have", "were", "been")
            # ("so take the kids to the leisure centre"; not "we were told to take the children to ...": a plan)
            order = w in ("take", "bring") and not (i > 0 and norms[i - 1] in lx.PLAN_WORDS)
            if not (evac or w in lx.MOVE_VERBS or put or order):
                continue
            if any(norms[m] in lx.NAVIGATION_AIDS for m in range(max(0, i - 3), i)):
                continue  # "the satnav sent us to the lodge gate": a way found, nobody taken anywhere
            into = ("to", "into", "in", "inside") if put else ("to", "into", "onto")
            k, people = i + 1, evac or any(norms[m] in lx.MOVED_PEOPLE for m in range(max(0, i - 3), i))
            origins = {p.start_tok: p.end_tok for p in ex.places if p.status == "active"}
            past_origin = None
            while k < len(norms) and k - i <= 10 and norms[k] not in into and not toks.clause_start[k]:
                if k in starts:
                    if k in origins and k - i <= 8 and (("out", "of") in (norms[k - 2:k], norms[k - 3:k - 1])
                                                        or "from" in norms[k - 2:k]):
                        k = past_origin = origins[k]  # "moved everyone out of the cafe and into the sports hall": from
                        continue
                    break
                if k - i > (6 if past_origin is None else past_origin - i + 3):
                    break
                people = people or norms[k] in lx.MOVED_PEOPLE or norms[k] in ("them", "other", "others", "rest", "us")
                k += 1
            if not people or k >= len(norms) or norms[k] not in into or toks.clause_start[k]:
                continue
            j = k + 1
            while j < len(norms) and (norms[j] in lx.DETERMINERS or norms[j] in lx.FILLERS) and j - k <= 3:
                j += 1
            again = next((m for m in range(k + 1, min(len(norms), k + 5)) if norms[m] == norms[k]), None)
            first = i if past_origin is None else past_origin  # (the cue does not span the place left)
            if j not in starts and again is not None and any(
                    d in toks.gaps[m] for m in range(k + 1, again + 1) for d in ("-", "—", "–", "...", "…")):
                k = j = again  # "moved everyone across into the vic— into the, the Red Lion": the name said again
                j += 1
                first = k
                while j < len(norms) and (norms[j] in lx.DETERMINERS or norms[j] in lx.FILLERS) and j - k <= 3:
                    j += 1
            if j not in starts:
                continue
            if _still_to_come(norms, next((p.end_tok for p in ex.places if p.start_tok == j), j + 1)):
                continue  # "Moving them to the first aid post shortly": where they will go, not where they are
            if any(c.start_tok < i < c.end_tok or i < c.start_tok < k for c in cues if c.source != "glossary"):
                continue  # a cue of its own inside ("moved the injured to ...") speaks for itself
            t0, t1 = toks.tokens[first], toks.tokens[k]
            cues = [c for c in cues if c.start_tok != i]  # "evacuating ... to": no hazard of the destination
            cues.append(CueMention(first, k + 1, t0.start, t1.end, toks.text[t0.start:t1.end], cat, "lexicon",
                                   reason="people were taken there"))
        return cues

    def _another_one_cues(self, toks: Tokens, norms: tuple[str, ...], cues: list[CueMention],
                          blocked: set[int]) -> list[CueMention]:
        """"the leak at the bakery is fixed, but we found a new one at the cafe": "a new one" or
        "another one" takes up the category of the cue spoken just before it."""
        out = []
        taken = blocked | {i for c in cues for i in range(c.start_tok, c.end_tok)}
        for i in range(len(norms)):
            n = 3 if norms[i : i + 3] in (("a", "new", "one"), ("a", "second", "one"), ("one", "more", "one")) else \
                2 if norms[i : i + 2] in (("another", "one"), ("new", "one")) else 0
            # ("heat exhaustion, two of them, in the grandstand, and one more at the trade stands": one more person)
            more = not n and norms[i:i + 2] == ("one", "more") and norms[i + 2:i + 3] in (("at",), ("in",), ("on",), ("inside",))
            n = 2 if more else n
            if not n or taken.intersection(range(i, i + n)):
                continue
            before = [c for c in cues if c.end_tok <= i and i - c.end_tok <= (24 if more else 12)
                      and (not more or self.kb.category_by_name[c.category].role == Role.CRITICAL)]
            if not before:
                continue
            src = max(before, key=lambda c: c.end_tok)
            t0, t1 = toks.tokens[i], toks.tokens[i + n - 1]
            out.append(CueMention(i, i + n, t0.start, t1.end, toks.text[t0.start:t1.end], src.category, src.source,
                                  reason=f"takes up the earlier '{src.text}'"))
        return out

    def _predicative_cues(self, ex: Extraction, norms: tuple[str, ...], blocked: set[int]) -> list[CueMention]:
        """"the library is sound", "bank is red": adjectives that are cues only after a copula."""
        toks = ex.tokens
        ends = {p.end_tok for p in ex.places}
        out = []
        if getattr(self, "_predicatives", None) is None:
            self._predicatives = dict(lx.PREDICATIVE_CUES)
            for word, role in lx.DESCRIBED_PREDICATIVE_CUES.items():
                if any(word in norm_phrase(c.description) or word in norm_phrase(c.name.replace("_", " "))
                       for c in self.kb.categories_with_role(role)):  # (or its name: "high_and_dry")
                    self._predicatives[word] = role
        for i, w in enumerate(norms):
            role = self._predicatives.get(w)
            if role is None or i in blocked or i == 0:
                continue
            after = norms[i + 1] if i + 1 < len(norms) else ""
            if after in lx.GENERIC_HEADS or after in ("light", "zone", "tag", "line", "team", "of"):
                continue
            if not (norms[i - 1] in ("is", "s", "are", "was", "now", "still", "as", "looks", "look", "seems", "seem", "be", "completely",
                                     "structurally", "totally", "all", "thats", "its", "theyre", "whos", "both",
                                     "confirmed", "declared", "reported")  # ("the market hall is confirmed sound")
                    or toks.tokens[i - 1].text.lower().replace("’", "'") in ("that's", "which's")  # ("tank seven that's split")
                    or i in ends and (i + 1 >= len(norms) or toks.clause_start[i + 1] or after in lx.COORDINATORS)):
                continue  # ("in the HGV park, green liquid running": an adjective of what follows)
            if w in ("broken", "snapped") and (norms[i - 1] not in ("is", "s", "are", "was", "were")
                                               or any(norms[k] in lx.BODY_PARTS | _PERSON_WORDS | lx.PRONOUNS
                                                      for k in range(max(0, i - 5), i))):
                continue  # "the brine pipe is broken", not "holding his arm, looks broken" (a person's)
            if w == "under" and not (i + 1 >= len(norms) or toks.clause_start[i + 1]) or w == "under" and i not in ends:
                continue  # "the towpath's under.": flooded; not "the fire is under control"
            cat = self._category_for_role(role, "flooded, under water" if w == "under" else w)
            if cat:
                t = toks.tokens[i]
                out.append(CueMention(i, i + 1, t.start, t.end, t.text, cat, "lexicon"))
        starts = {p.start_tok for p in ex.places}
        last_words = {p.end_tok - 1 for p in ex.places}
        for i in range(1, len(norms) - 1):
            # "the bakery's going up", "the building opposite that's going up": burning, said of a place;
            # not "a tent going up at the school"
            if norms[i : i + 2] not in (("going", "up"), ("gone", "up")) or i in blocked or i + 1 in blocked \
                    or toks.sentence_start[i + 1]:  # ("legs are gone. Up top now.": two sentences)
                continue
            prev = toks.tokens[i - 1].text.lower().replace("’", "'")
            if not (norms[i - 1] in ("is", "s", "are") or prev.endswith("'s") and (i - 1) in last_words
                    or prev in ("that's", "it's", "its")):
                continue
            nxt = i + 2
            if nxt < len(norms) and not toks.clause_start[nxt] and (norms[nxt] in lx.PREPOSITIONS or nxt in starts
                                                                    or norms[nxt] in ("there", "here")):
                continue
            if i >= 2 and norms[i - 1] in ("are", "is") and norms[i - 2] in lx.LAY_PERSONS | {"we", "everyone", "everybody"}:
                continue  # "people are going up there": people move, nothing burns
            cat = self._category_for_role(lx.UNDESIRABLE, "going up in flames")
            if cat:
                t0, t1 = toks.tokens[i], toks.tokens[i + 1]
                out.append(CueMention(i, i + 2, t0.start, t1.end, toks.text[t0.start:t1.end], cat, "lexicon",
                                      reason="'going up' said of a place"))
        return out

    def _apply_non_reports(self, toks: Tokens, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """Questions and instructions to the system claim nothing."""
        sentences: list[tuple[int, int]] = []
        for i in range(len(toks)):
            if toks.sentence_start[i]:
                sentences.append((i, i + 1))
            else:
                sentences[-1] = (sentences[-1][0], i + 1)
        dropped: dict[int, str] = {}
        forgot: list[tuple[int, int, set[str]]] = []  # ("Forget safe --": where, and the categories taken back)
        asked: set[int] = set()
        marker_starts = {ma for ma, _, _ in getattr(self, "_markers_now", [])}
        questions = self._question_sentences(toks)
        for n, (a, b) in enumerate(sentences):
            if n in questions:
                # only the clause that asks: "Control, is the church still open?"; "or is it the flats?" repairs;
                # a sentence that opens with the question word asks all through ("Which is the rest centre, ...?")
                # ("wait was it the bank or the library that had the gas?": a word that only opens the turn)
                opener = next((i for i in range(a, b) if norms[i] not in lx.FILLERS and norms[i] not in lx.TURN_OPENERS), a)
                start = a if norms[opener] in lx.WH_OPENERS and not any(a <= m < b and m != a for m in marker_starts) \
                    else max((i for i in range(a, b) if toks.clause_start[i] and toks.gaps[i] != "-"), default=a)
                # (a hyphen inside a word, "walk-in", does not open the asking clause)
                back = start
                while back > a:
                    # "did you say the fire's in the kitchens or the, um, the laundry?": a noun phrase begun again
                    # after a pause goes on the clause that asks (where that clause opens with a question word)
                    prev = max((i for i in range(a, back) if toks.clause_start[i] and toks.gaps[i] != "-"), default=a)
                    lead = next((w for w in norms[back:b] if w not in lx.FILLERS), "")
                    tail = [w for w in norms[prev:back] if w not in lx.FILLERS]
                    if tail and not (lead in lx.ARTICLES and tail[-1] in lx.ARTICLES | {"or", "and"}):
                        break
                    back = prev
                if next((w for w in norms[back:b] if w not in lx.FILLERS), "") in lx.QUESTION_OPENERS:
                    start = back
                first = opener if start == a and opener > a \
                    else next((i for i in range(start, b) if norms[i] not in lx.FILLERS), start)
                if norms[first] == "or" and first + 1 < b and norms[first + 1] in lx.QUESTION_OPENERS:
                    # "is the chapel still open for visits, or is everything shut?": the question asked first goes on
                    earlier = max((i for i in range(a, start) if toks.clause_start[i] or i == opener
                                   if norms[i] in lx.QUESTION_OPENERS and i not in marker_starts), default=None)
                    if earlier is not None:
                        start, first = earlier, earlier
                words = [w for w in norms[a:b] if w not in lx.FILLERS]
                nxt = sentences[n + 1] if n + 1 < len(sentences) and n + 1 in questions else None
                if words[-2:] in (["or", "no"], ["or", "not"], ["or", "what"]) \
                        or _asks_if_true(norms[a:b]) or nxt is not None and _asks_if_true(norms[nxt[0]:nxt[1]], alone=True) \
                        or any(
                        words[i:i + 3] in (["want", "to", "ask"], ["wanted", "to", "ask"], ["can", "i", "ask"])
                        for i in range(len(words))):
                    reply = set(norms[sentences[n + 1][0]:sentences[n + 1][1]]) if n + 1 < len(sentences) else set()
                    if _asks_if_true(norms[a:b]) and reply & {"confirms", "confirmed", "confirm"} \
                            and reply & (lx.YES_WORDS | {"correct", "affirmative"}) and not reply & lx.NO_WORDS:
                        continue  # "... is that correct? Caller confirms, yes.": a readback confirmed
                    asked.update(range(a, b))  # "the fire, it is at the garage or no?": the whole sentence asks
                    continue
                if norms[first] in lx.QUESTION_OPENERS and first not in marker_starts:
                    if not (n + 1 < len(sentences) and self._answered(toks, norms, sentences[n + 1], lx.YES_WORDS)):
                        asked.update(range(start, b))  # (answered "Yes.", the question says what is so)
                elif n + 1 < len(sentences) and self._answered(toks, norms, sentences[n + 1], lx.NO_WORDS):
                    asked.update(range(start, b))  # "the church is flooded? -- no, no, the school": an echo denied
                continue
            opener = next((i for i in range(a, b) if norms[i] not in lx.FILLERS
                           and not (n == 0 and i <= a + 1 and norms[i] in lx.STATIONS_CALLED)), a)
            # ("control er is the is the tunnel still closed or have they reopened it": the station called first)
            if norms[opener] in lx.YES_NO_OPENERS and opener + 1 < b and norms[opener + 1] in lx.YES_NO_SUBJECTS \
                    and opener not in marker_starts:
                # "is the is the square safe can anyone confirm": speech without a question mark still asks
                end = next((i for i in range(opener + 1, b) if toks.clause_start[i]), b)
                while end < b:  # "is the, uh, is the marketplace free ...": the question started again
                    again = next((i for i in range(end, b) if norms[i] not in lx.FILLERS), b)
                    if again >= b or norms[again] != norms[opener]:
                        break
                    end = next((i for i in range(again + 1, b) if toks.clause_start[i]), b)
                asked.update(range(a, end))
                continue
            first = norms[opener] if opener < b else ""
            said = next((i for i in range(opener + 1, b) if norms[i] not in lx.FILLERS), b)
            hit = self._cues.match_at(norms, said) if first in ("forget", "scratch") and said < b else None
            if hit is not None and (hit[0] >= b or toks.clause_start[hit[0]]):
                # "Forget safe -- the plate racks have toppled": that word taken back, then the report goes on
                forgot.append((a, hit[0], {c.category for c in cues if c.start_tok == said}))
            elif first in lx.INSTRUCTION_VERBS and set(norms[a:b]) & lx.INSTRUCTION_WORDS:
                dropped[n] = "an instruction to the system, not a report"
            elif any(norms[k].isdigit() and len(norms[k]) == 4 and 1900 <= int(norms[k]) <= 2025
                     and norms[k - 1] in ("in", "of", "back") for k in range(max(a, 1), b)) \
                    and set(norms[a:b]) & {"was", "were", "used"}:
                dropped[n] = "said of another year, not a report"  # "In the big snow of 2009 the hall was the warm room"
        asked |= _indirect_questions(toks, norms)
        if asked:
            # "is there anything going on at the bone cave? ... I can't get hold of him": a worried caller asking,
            # not someone known to need help
            asked |= {c.start_tok for c in cues if c.polarity == "affirmed" and any(
                norms[c.start_tok:c.end_tok][:len(k)] == k for k in _UNREACHABLE)}
        for a, e, cats in forgot:
            cues = [replace(c, status="retracted", reason=f"taken back by '{toks.span_text(a, e)}'")
                    if c.category in cats and c.start_tok < e and c.polarity == "affirmed" else c for c in cues]
        supposed = self._conditional_tokens(toks, norms)
        self._non_report_tokens = ({i for n, (a, b) in enumerate(sentences) if n in dropped for i in range(a, b)}
                                   | asked | supposed)
        cues = [replace(c, status="retracted", reason="a question, not a report") if c.start_tok in asked
                else replace(c, status="retracted", reason="a condition, not a report") if c.start_tok in supposed
                # "I've heard on the radio there's flooding somewhere in the village": nowhere it names
                else replace(c, status="retracted", reason="said of somewhere unnamed")
                if c.end_tok < len(norms) and norms[c.end_tok] == "somewhere" and c.source != "embedding"
                and norms[c.end_tok + 2:c.end_tok + 3] not in (("it",), ("there",), ("them",))
                else c for c in cues]  # (but "buried somewhere on it": on the place just said)
        if not dropped:
            return cues
        sent_of = {}
        for n, (a, b) in enumerate(sentences):
            for i in range(a, b):
                sent_of[i] = n
        return [replace(c, status="retracted", reason=dropped[sent_of[c.start_tok]]) if sent_of.get(c.start_tok) in dropped
                else c for c in cues]

    @staticmethod
    def _conditional_tokens(toks: Tokens, norms: tuple[str, ...]) -> set[int]:
        """Tokens of a condition ("if the tip starts moving", "in case the bridge floods", "check if anyone's
        trapped"): what it supposes is no report. It runs to the next clause, a "then", or a new subject
        pronoun ("if the tip starts moving we fall back"); "as if" compares, it supposes nothing."""
        out: set[int] = set()
        n = len(norms)
        for i, w in enumerate(norms):
            opens = (w in lx.CONDITIONAL_OPENERS and not (i > 0 and norms[i - 1] in ("as", "even"))) \
                or (w == "case" and i > 0 and norms[i - 1] == "in")
            if not opens:
                continue
            j = i + 1
            while j < n and not toks.clause_start[j] and norms[j] not in ("then", "but") \
                    and not (j - i > 2 and norms[j] in lx.CONDITION_END_SUBJECTS):
                j += 1  # ("i dunno if this counts but there's smoke coming out of the gym": the news after "but")
            out.update(range(i, j))
        return out

    def _restated_category(self, ex: Extraction, k: int, out: list[CueMention], b: int, end: int, a: int,
                           withdraw: bool = False) -> None:
        """"the hotel's sound — hold that — hotel's got a cracked stairwell": same place, new category;
        the cues said about the earlier mention are retracted. After a withdrawal ("collapse at the tower —
        disregard, the tower is standing") they are retracted even when nothing new is said of it."""
        first = min((p for p in ex.places if b <= p.start_tok < end and p.status not in ("reference", "negated")),
                    key=lambda p: p.start_tok, default=None)
        if first is None:
            return  # ("sorry, not the gym, the library": a place denied is no place said again)
        lo = self._repair_window_start(ex, k)
        same = [p for p in ex.places if lo <= p.start_tok < a and p.landmark == first.landmark]
        if not same:
            return
        last = max((p for p in ex.places if lo <= p.start_tok < a), key=lambda p: p.start_tok)
        if withdraw and (max(same, key=lambda p: p.start_tok).status != "active" or last.landmark != first.landmark):
            # ("casualties at the place next to the school, scratch that, at the school itself"; "the casualty is at
            # the bank -- strike that, she's at the hotel": a place repaired, not a claim withdrawn)
            withdraw = False
        since = max(p.start_tok for p in same)
        if not any(b <= c.start_tok < end and c.status == "active" for c in out):
            # "the apron is clear, correction, the apron's got fuel all over it": no listed word says the
            # new category; MiniLM reads the restated predicate
            earlier = [c for c in out if since < c.start_tok < a and c.status == "active"]
            if not earlier and not withdraw:
                return
            new = self._repaired_by_meaning(ex, first.end_tok, end, earlier[-1]) if earlier else None
            if new is None and not withdraw:
                return
            if new is not None:
                out.append(new)
        if withdraw and not any(since < c.start_tok < a and c.status == "active" for c in out):
            # the cue said of it may stand before it ("collapse at the tower"): back to the last other place
            since = max([p.end_tok - 1 for p in ex.places if lo <= p.end_tok <= since and p.landmark != first.landmark
                         and p.status != "reference"], default=lo - 1)
        new_roles = {self.kb.category_by_name[c.category].role for c in out
                     if b <= c.start_tok < end and c.status == "active" and c.polarity == "affirmed"}
        for i, c in enumerate(out):
            if since < c.start_tok < a and c.status == "active":
                if not withdraw and new_roles == {Role.CRITICAL} \
                        and self.kb.category_by_name[c.category].role == Role.UNDESIRABLE:
                    continue  # "the gantry's half collapsed, someone under it, I mean under the gantry, pinned": the
                    # person said again; the danger stands beside them
                said = ex.tokens.span_text(a, ex.markers[k][1])
                out[i] = replace(c, status="retracted",
                                 reason=f"withdrawn by '{said}'" if withdraw else f"category restated after '{said}'")

    def _apply_false_alarms(self, toks: Tokens, norms: tuple[str, ...], cues: list[CueMention]) -> list[CueMention]:
        """"... the smoke was a false alarm": every claim of that sentence is denied."""
        sentence_of = toks.sentence_of
        if _exercise_frame(norms):
            return [replace(c, polarity="denied", reason="exercise or training message") for c in cues]
        alarms: dict[int, int] = {}  # sentence -> the token before which its claims are denied
        danger_only: dict[int, bool] = {}  # sentences whose alarm only says what a danger was
        withdrawn: set[int] = set()  # sentences a withdrawal takes back whole, safe places with the rest
        places_now = getattr(self, "_places_now", [])
        positions: dict[str, list[int]] = {}
        for i, w in enumerate(norms):
            positions.setdefault(w, []).append(i)
        for phrase, key in _FALSE_ALARM_KEYS:
            if key[0] in ("just", "only") and key[-1] in self._danger_words:
                continue  # "it's not chlorine, it's just steam, live steam blasting out": the KB says steam is a danger
            for i in positions.get(key[0], ()):
                if i > len(norms) - len(key):
                    break
                stutter = norms[i + 1 : i + 1 + len(key)] == key  # "are, are false"
                if norms[i : i + len(key)] == key and norms[i + len(key):i + len(key) + 1] \
                        and norms[i + len(key)] in lx.FALSE_ALARM_NOT_BEFORE and "nothing" in key \
                        and not toks.clause_start[i + len(key)]:
                    continue  # "there's nothing left of the bakery": what is gone, not a false alarm
                if (norms[i : i + len(key)] == key or stutter) and any(
                        p.status == "negated" and 0 <= i - p.end_tok <= 3
                        and p.reason.removeprefix("negated by '").rstrip("'").lower() in lx.RETRACT_VERBS
                        and all(w in ("thats", "that", "s", "its", "it", "was", "is") for w in norms[p.end_tok:i])
                        and any(q.status == "active" and q.start_tok >= i + len(key) and sentence_of[q.start_tok] == sentence_of[i]
                                and any(o.landmark == q.landmark and o.status == "active" and o.end_tok <= p.start_tok
                                        for o in places_now) for q in places_now)
                        for p in places_now):
                    # "the copper house is burning, ... scratch the pagoda, that's just steam, just the copper house":
                    # said of the place taken back; the place said before it is said again and keeps its claim
                    continue
                if phrase in ("never mind", "nevermind") and any(
                        0 <= i - p.end_tok <= 2 and all(norms[m] in lx.FILLERS for m in range(p.end_tok, i))
                        and any(c.start_tok < p.start_tok and sentence_of[c.start_tok] == sentence_of[i]
                                and c.polarity == "affirmed" for c in cues)
                        and not any(p.end_tok <= c.start_tok < i for c in cues) for p in places_now):
                    continue  # "there's a wash-through ... and the top block - never mind, haven't got to the top
                    # block yet": the speaker drops the place just begun, not what was said before it
                if phrase == "ignore me" and any(
                        p.status == "negated" and 0 <= i - p.end_tok <= 3 and sentence_of[p.start_tok] == sentence_of[i]
                        for p in places_now):
                    continue  # "the loos are overflowing ... and the hedge is — no, nothing on the hedge, ignore me":
                    # the place just begun and denied is what the speaker takes back
                if norms[i : i + len(key)] == key or stutter:
                    # "disregard my last, the spill is at the store": an earlier report is withdrawn and
                    # what follows replaces it
                    until = i if phrase in lx.PREVIOUS_REPORT_WITHDRAWN else len(norms)
                    if until == i and norms[i + len(key):i + len(key) + 1] in (("about",), ("regarding",), ("re",)):
                        # "disregard my last about water in the sheds": what it was about (up to a semicolon: "...;
                        # rest point is now the chapel" is the new report)
                        until = next((j for j in range(i + len(key), len(norms)) if ";" in toks.gaps[j]
                                      # (or a clause of its own after the place it was about: "disregard my last
                                      # about the medical centre being out of action, the medical centre is open")
                                      or toks.clause_start[j] and any(i + len(key) < p.start_tok < j for p in places_now)
                                      and any(j <= c.start_tok < j + 8 and sentence_of[c.start_tok] == sentence_of[j]
                                              and norms[c.start_tok - 1] not in ("its", "the", "their")
                                              and not any(toks.clause_start[m] for m in range(j + 1, c.start_tok + 1))
                                              for c in cues)),
                                     len(norms))
                    if phrase in lx.DISMISSED_BEFORE:
                        until = i + len(key)  # ("'supermarket smoke was a barbecue' ...; 'water tower leaking'")
                    # "no fire at the chip shop, it's just steam, but the hotel's got a proper fire going": a
                    # contrast that names another place afterwards is not part of the false alarm
                    places = {p.start_tok for p in places_now}
                    but = next((j for j in range(i + len(key), len(norms)) if sentence_of[j] == sentence_of[i]
                                and norms[j] in ("but", "however", "whereas")
                                and (any(t in places for t in range(j + 1, min(len(norms), j + 12)))
                                     or norms[j + 1:j + 2] in (("theres",), ("there",)))), None)
                    # ("it was just the alarm going, but there's a dude in there who's cut his hand": news after it)
                    if but is None:  # "there's nothing wrong with the roof, it's the floor, there's beer ...": the
                        # contrast said as "it's the"
                        but = next((j for j in range(i + len(key), len(norms)) if sentence_of[j] == sentence_of[i]
                                    and toks.clause_start[j] and norms[j:j + 2] in (("its", "the"), ("it", "is"))
                                    and norms[j + 1:j + 3] != ("is", "a")), None)
                    if but is not None and until == len(norms):
                        until = but
                    # "someone trapped in the supermarket but no, false alarm — it's the gym, someone's trapped
                    # in the gym": the place the repair puts in the retracted one's stead keeps its claims
                    repaired = [p.start_tok for p in places_now if p.replaces is not None
                                and p.replaces < i < p.start_tok and sentence_of[p.start_tok] == sentence_of[i]
                                and p.status == "active"]
                    if repaired and until == len(norms):
                        until = min(repaired)
                    alarms[sentence_of[i]] = max(alarms.get(sentence_of[i], 0), until)
                    n = sentence_of[i]
                    explained = phrase in lx.DANGER_EXPLAINED  # ("just steam" says what the smoke was, not the hurt)
                    danger_only[n] = danger_only.get(n, True) and explained
                    if phrase in lx.PREVIOUS_REPORT_WITHDRAWN:
                        withdrawn.add(n)
                    if phrase in lx.WHOLE_REPORT_WITHDRAWN:
                        for m in range(n):  # "... Please disregard all of it, nobody is hurt."
                            alarms[m] = len(norms)
                            withdrawn.add(m)
                    if n > 0 and phrase not in lx.PREVIOUS_REPORT_WITHDRAWN and not any(
                            sentence_of[p.start_tok] == n and p.start_tok < i for p in places_now) \
                            and not any(c.start_tok < i and sentence_of[c.start_tok] == n and c.polarity == "affirmed"
                                        for c in cues) \
                            and (any(norms[j] in ("no", "sorry", "oh", "actually", "wait", "its", "just")
                                     for j in range(i) if sentence_of[j] == n)
                                 # ("... nothing showing. False alarm, it was a barbecue on the terrace.")
                                 or all(norms[j] in lx.FILLERS for j in range(i) if sentence_of[j] == n)
                                 and not any(sentence_of[p.start_tok] == n for p in places_now)):
                        # "Fire at the bakery! ... oh, no, sorry, it's just steam off their ovens, false alarm."
                        alarms[n - 1] = len(norms)
                        danger_only[n - 1] = danger_only.get(n - 1, True) and explained
                        opens = [norms[j] for j in range(i) if sentence_of[j] == n - 1 and norms[j] not in lx.FILLERS][:2]
                        if n > 1 and opens in (["it", "was"], ["that", "was"], ["turned", "out"], ["it", "turned"]):
                            # "... someone in the water at the weir? It was a log with a coat snagged on it. There's
                            # no one, it's a false alarm": what it was, then the alarm, for the sentence before both
                            alarms[n - 2] = len(norms)
        # "... child stuck up a tree in the park. Update - child now down and unhurt, job closed.": a later
        # update that closes the job closes what was reported before it
        closed = [sentence_of[i] for i in range(len(norms) - 1) if norms[i + 1] == "closed"
                  and norms[i] in ("job", "incident", "report", "case", "call")
                  and "update" in {norms[j] for j in range(len(norms)) if sentence_of[j] == sentence_of[i]}]
        if closed:
            for n in range(max(closed)):
                alarms[n] = len(norms)
        if not alarms:
            return cues
        # (a false alarm says a danger was none; a place said to be safe stays so: "searched, nothing found, safe")
        safe_said = {sentence_of[c.start_tok] for c in cues if self.kb.category_by_name[c.category].role == Role.DESIRABLE
                     and {"safe", "clear", "secure", "secured"} & set(norms[c.start_tok:c.end_tok])}
        return [replace(c, polarity="denied", reason="false alarm")
                if c.start_tok < alarms.get(sentence_of[c.start_tok], -1) and not (
                    danger_only.get(sentence_of[c.start_tok]) and self.kb.category_by_name[c.category].role == Role.CRITICAL
                    and sentence_of[c.start_tok] not in withdrawn) and (
                    sentence_of[c.start_tok] in withdrawn or sentence_of[c.start_tok] not in safe_said
                    or self.kb.category_by_name[c.category].role != Role.DESIRABLE) else c for c in cues]

    def _undesirable(self) -> str | None:
        return self._role_category.get("undesirable") or next(
            (c.name for c in self.kb.categories_with_role(Role.UNDESIRABLE)), None)

    def _cleared_of_danger_before(self, toks: Tokens, norms: tuple[str, ...], k: int) -> str | None:
        """"the chlorine smell at the filters, that's cleared now": "cleared" at ``k`` opens its clause with only words
        that take up what was said before, and the clause before has a danger in it: the danger has gone. The reason to
        deny the cue with (:data:`_CLEARED_AFTER_BUT` where "but" opens the clause), or None."""
        a = k
        while a > 0 and not toks.clause_start[a] and norms[a - 1] in lx.BACK_REFERENCE_WORDS | lx.FILLERS:
            a -= 1
        but = a < k and a > 1 and not toks.clause_start[a] and norms[a - 1] == "but"  # ("had smoke earlier but
        a -= but  # that's cleared now": the clause "but" opens)
        if a == k or not (toks.clause_start[a] or but) or a == 0 or set(norms[a:k]) & _CLEARING_SUBJECTS:
            return None  # (not "we've cleared it": the crew has emptied the place)
        b = a - 1
        while b > 0 and not toks.clause_start[b]:
            b -= 1
        while b > 0 and all(w in lx.BACK_REFERENCE_WORDS | lx.FILLERS for w in norms[b:a]):
            a = b  # ("that's, er, that's cleared now": past the restart)
            b -= 1
            while b > 0 and not toks.clause_start[b]:
                b -= 1
        if not any(self.kb.category_by_name[c].role == Role.UNDESIRABLE and b <= s < a
                   for s, _, (c, _src) in self._cues.find_all(norms) if c in self.kb.category_by_name):
            return None
        return _CLEARED_AFTER_BUT if but else "the danger before it was cleared"

    def _apply_cue_negation(self, toks: Tokens, norms: tuple[str, ...], cue: CueMention) -> CueMention:
        # negator shortly before, inside the clause: "no fire", "not safe", "no one trapped"
        negated_by = None
        j = cue.start_tok - 1
        steps = 0
        place_toks = self._place_tokens | self._marker_tokens
        if norms[cue.end_tok - 1] in ("cordon", "cordons", "closure", "warning", "alert"):
            # "cordon lifted", "the cordon's been lifted": the warning withdrawn, the danger with it
            w = cue.end_tok
            while w < len(norms) and w - cue.end_tok < 3 and norms[w] in ("has", "have", "s", "is", "been", "now", "just"):
                w += 1
            if norms[w:w + 1] in (("lifted",), ("removed",)) or norms[w:w + 2] == ("stood", "down"):
                return replace(cue, polarity="denied", reason=f"negated by '{norms[w]}'")
        if norms[cue.start_tok:cue.end_tok] == ("clear",) and (toks.clause_start[cue.start_tok] or cue.start_tok == 0) \
                and norms[cue.end_tok:cue.end_tok + 1] in (("the",), ("everyone",), ("everybody",), ("all",)) \
                and self.kb.category_by_name[cue.category].role == Role.DESIRABLE:
            # "the headgear's leaning ..., clear the yard round number one shaft": an order to empty it, no safe place
            return replace(cue, polarity="denied", reason="an order to clear it, not a safe place")
        if norms[cue.start_tok] in ("hasnt", "havent") and norms[cue.start_tok + 1:cue.end_tok] == ("caught",):
            # "the old trees haven't caught": the danger word said with its own negation
            return replace(cue, polarity="denied", reason=f"negated by '{toks.tokens[cue.start_tok].text}'")
        if norms[cue.start_tok] in lx.NEGATORS:
            j = -1  # "he's not, he's not breathing": a cue that is itself a negation is not negated again
        if cue.start_tok > 0 and norms[cue.start_tok - 1] == "negative" and cue.category == self._person_category:
            return replace(cue, polarity="denied", reason="negated by 'negative'")  # "negative casualties here"
        if cue.category == self._person_category and norms[cue.start_tok] == "still" \
                and norms[cue.end_tok:cue.end_tok + 1] in (("unhurt",), ("uninjured",), ("unharmed",), ("fine",), ("ok",)) \
                and not toks.sentence_start[min(cue.end_tok, len(norms) - 1)]:
            return replace(cue, polarity="denied", reason="said unhurt")  # "I'm still in the cab, unhurt."
        saw_or = False  # "haven't seen any damage or anyone hurt": the negation runs on over "or"
        while j >= 0 and steps < (8 if saw_or else 4) and j not in place_toks:
            if norms[j] in ("or", "nor") and not toks.clause_start[j + 1]:
                saw_or = True
            if j + 1 < cue.start_tok and toks.clause_start[j + 1]:
                break  # "the place across from it isn't — there's a fire": another clause's negation
            if norms[j] in ("there", "theres") and (toks.tokens[j].text.lower().replace("’", "'") in ("theres", "there's")
                                                    or j + 1 < cue.start_tok and norms[j + 1] in ("s", "is", "are")):
                break  # "wait no its not theres a gas smell": a new "there's" clause, past the negation
            if norms[j] in lx.NEGATORS and (h := self._cues.match_at(norms, j)) is not None and h[0] <= cue.start_tok \
                    and h[0] > j + 1:
                break  # "a man lying in the doorway not moving please come": "not" is part of the cue before
            if norms[j] in lx.NEGATORS or norms[j].endswith("nt") and norms[j] in ("isnt", "arent", "wasnt", "werent", "dont", "doesnt", "didnt", "hasnt", "havent", "cant"):
                if j + 1 == cue.start_tok and toks.clause_start[cue.start_tok] and "," in toks.gaps[cue.start_tok] \
                        and j > 0 and norms[j - 1] in ("theyre", "its", "re", "s", "is", "are", "was", "were"):
                    break  # "they were safe, now they're not, embers are landing": that clause ends; a new one opens
                if norms[j + 1 : j + 3] != ("the", "one") and not (
                        norms[j] == "no" and j + 1 < cue.start_tok
                        and (norms[j + 1] in lx.NUMBER_WORDS or norms[j + 1].isdigit())):
                    # ("the pharmacy isn't the one on fire": which place, not whether; "two, no three
                    # patients": a repaired count)
                    negated_by = toks.tokens[j].text
                break
            hit = None
            for k in range(max(0, j - 3), j + 1):
                h = self._negators.match_at(norms, k)
                if h is not None and h[0] == j + 1:
                    hit = h
            if hit is not None:
                negated_by = hit[1]
                break
            if toks.clause_start[j + 1] and j + 1 <= cue.start_tok:
                if j + 1 != cue.start_tok or toks.clause_start[cue.start_tok]:
                    break
            if self._cues.match_at(norms, j) is not None and not (saw_or and norms[j] not in lx.NEGATORS):
                break
            j -= 1
            steps += 1
        cancelled_by = None
        said = set(norms[cue.start_tok:cue.end_tok])
        missing = " ".join(norms[cue.start_tok:cue.end_tok]) in lx.MISSING_CUES \
            or bool(_LOST_WORDS & said) and not said & (lx.BODY_PARTS | _LOST_NOT_MISSING)
        # ("found him" ends only this; a glossary's "separated child" too, not "lost a finger")
        # cancellation after: "the fire is out", "gas leak fixed", "fire under control"
        k = cue.end_tok
        steps = 0
        ends = {p.start_tok: p.end_tok for p in getattr(self, "_places_now", [])}
        but, steps_ = None, 0
        for i in range(k, len(norms)):  # (a place, or a whole relational description, counts as one word)
            if norms[i] == "but":
                but = i
                break
            steps_ += i not in self._place_tokens
            if steps_ >= 6:
                break
        if but is not None and toks.sentence_of[but] == toks.sentence_of[cue.start_tok] \
                and self._hearsay_before(toks, norms, cue.start_tok) and self._contradicted_after(toks, norms, but + 1):
            # "my wife says the coffee shop's collapsed but I can see it from here, it's still standing"
            cancelled_by = "but it isn't"
            k = len(norms)
        elif k < len(norms) and toks.clause_start[k] and any(norms[k:k + len(w)] == w for w in lx.NO_LONGER_SO) \
                and toks.sentence_of[k] == toks.sentence_of[cue.start_tok]:
            # "they were safe, now they're not, embers are landing on the thatch": said, then taken back
            cancelled_by = "now it's not"
            k = len(norms)
        elif but is None and self._hearsay_before(toks, norms, cue.start_tok) \
                and self._contradicted_after(toks, norms, cue.end_tok):
            # "bloke in my cab swears the fire station's on fire, which, er, yeah no, I'm parked right outside it and
            # it's not"
            cancelled_by = "said, and it isn't"
            k = len(norms)
        undesirable = self.kb.category_by_name[cue.category].role == Role.UNDESIRABLE
        contracted = toks.tokens[cue.end_tok - 1].text.lower().endswith(("'s", "’s"))  # (the cue's own "'s")
        articles = 0
        while k < len(norms) and steps < 7 and not toks.clause_start[k]:  # "the fire on the roof at the bakery is out"
            if norms[k] in lx.UNTIL_WORDS:
                break  # "no entry till it's shored up": what will end it, not that it has
            if k in ends and ends[k] > k:
                k = ends[k]  # a place (or a whole relational description) counts as one word
                while k < len(norms) and k in getattr(self, "_relation_tokens_now", ()) and not toks.clause_start[k]:
                    k += 1  # (with the words that relate it: "the gas over the vents the lookout looks down on")
                steps += 1
                continue
            if norms[k] in ("the", "a", "an") and k + 1 < len(norms) and not toks.clause_start[k + 1]:
                k += 1  # ("the flue fire on the boat moored at the far mouth is out": an article is no word of its own)
                articles += 1
                continue
            if norms[k] in ("that", "which") and (k - 1) in self._place_tokens and any(
                    p.status == "reference" and p.reason.startswith("reference point") and k < p.start_tok <= k + 2
                    for p in self._places_now):
                cop = next((m for m in range(k + 2, min(len(norms), k + 9)) if norms[m] in ("is", "s", "was", "has")
                            and not any(toks.clause_start[t] for t in range(k, m + 1))), None)
                if cop is not None:
                    k = cop  # "the fuel fire in the yard that the barrage road runs down to is out now": the clause
                    steps += 1  # that only says which yard counts as one word
                    continue
            if norms[k:k + 3] in (("but", "it", "isnt"), ("but", "its", "not"), ("but", "it", "wasnt"),
                                  ("but", "thats", "not"), ("but", "they", "arent")) \
                    and (k + 3 >= len(norms) or toks.clause_start[k + 3]):
                cancelled_by = "but it isn't"  # "keeps saying the water tower's on fire but it isn't, it's the ..."
                break
            h = self._cancel.match_at(norms, k)
            if h is None and k == cue.end_tok and norms[k] == "cleared" and undesirable and contracted:
                h = (k + 1, "s cleared")  # "the bad air's cleared": the cue took the "'s"
            if h is not None and h[1].endswith("out") and h[0] < len(norms) and norms[h[0]] in lx.ROUTE_PREPOSITIONS \
                    and not (h[1] == "confirmed out" and norms[h[0]] == "by"):
                h = None  # "evacuation route is out through the park": the way out, nothing put out
            if h is not None and (_out_and_still_ill(h[1], norms[cue.start_tok:cue.end_tok]) or _walked_out_to(norms, h)):
                h = None
            if h is not None and h[1].endswith("out") and norms[h[0]:h[0] + 1] in (("at",), ("by",), ("on",), ("near",)) \
                    and self.kb.category_by_name[cue.category].role == Role.DESIRABLE:
                h = None  # "the assembly point is out at the gate": where it is, no safe place put out
            if h is not None and h[1] == "drained" and norms[h[0]:h[0] + 2] in (("out", "into"), ("out", "onto"),
                                                                               ("away", "into"), ("into", "the")):
                h = None  # "the wall's split open and all the water's drained out into the rocks": where it went
            if h is not None and steps + articles >= 7 and not h[1].endswith("out"):
                break  # ("the boathouse is smashed to bits the big doors are just gone": only "is out" reaches so far)
            if h is not None:
                nxt = h[0]
                while nxt < len(norms) and norms[nxt] in lx.DETERMINERS:
                    nxt += 1
                if h[1] == "no longer" and nxt in ends:
                    break  # "the evacuation point is no longer the town hall": the place is negated, not the cue
                if h[1] in lx.CANCEL_PEOPLE_ONLY and self.kb.category_by_name[cue.category].role != Role.CRITICAL \
                        and not (h[1] in ("they're out", "theyre out") and norms[cue.end_tok - 1] in lx.PLURAL_FIRES):
                    break  # "gas leak at the police post, they evacuated": people left, the leak stays
                    # (but "flames at the bakery earlier but they're out now": the flames are out)
                if h[1] in lx.CANCEL_MISSING_ONLY and not missing:
                    break  # "casualty at the bank, we found him under the desk": found, not safe
                if k > 0 and (norms[k - 1] in ("not", "nt", "isnt", "hasnt", "wasnt", "never")
                              or norms[k - 1] == "been" and k > 1 and norms[k - 2] in ("not", "hasnt", "havent")
                              or _nobody_said(norms, k - 3, k)):
                    break  # "fire at the bakery is NOT knocked down", "nobody has brought him out yet": denied
                if k > 1 and norms[k - 1] == "to" and norms[k - 2] in ("trying", "try", "tried", "tries", "attempting"):
                    break  # "a lad's burnt his hands trying to put it out": tried, not done
                if h[1].startswith("out") and k > 0 and norms[k - 1] in ("carried", "stretchered", "brought", "helped") \
                        and norms[cue.start_tok].startswith(("casualt", "injured", "wounded")):
                    break  # "two casualties being carried out now": hurt people being got out are still hurt
                if h[1].endswith("out") and any(norms[i] in lx.ANIMAL_WORDS and i not in self._place_tokens
                                                for i in range(max(cue.end_tok, k - 2), k)):
                    break  # "the fence is down and a tiger is out": the animal got out, the fence stays down
                if h[1] == "gone" and norms[h[0]:h[0] + 2] in (("out", "to"), ("over", "to"), ("to",), ("in", "to")):
                    break  # "our doctor's gone out to him": gone to help, nothing over
                if h[1] in ("gone", "has gone", "is gone") and "and" in norms[cue.end_tok:k] and k > 0 \
                        and norms[k - 1] not in lx.PRONOUNS \
                        and norms[k - 1] not in lx.ESCAPED_THINGS | {"s"} and self._cues.match_at(norms, k - 1) is None:
                    break  # "the sea's smashed its doors in and the slip's gone": another thing gone, more damage
                if h[1] in ("gone", "has gone", "have gone") and (h[0] >= len(norms) or toks.clause_start[h[0]]) \
                        and any(w in ("bottle", "cylinder", "canister", "cylinders", "bottles", "canisters")
                                for w in norms[cue.start_tok:cue.end_tok]):
                    break  # "one of the gas bottles has gone": gone off, burst
                if h[1] == "gone" and norms[h[0]:h[0] + 1] == ("up",) \
                        and self.kb.category_by_name[cue.category].role == Role.DESIRABLE:
                    break  # "that's where the welfare tent's gone up": put up, not gone
                if h[1].startswith(("off", "s off", "is off")) and k >= 2 and norms[k - 1] in ("it", "that", "them", "this") \
                        and norms[k - 2] in ("cordon", "tape", "rope", "fence", "block") and k - 2 == cue.end_tok - 1:
                    break  # "the canopy is tearing loose, cordon it off now": an order to keep out, nothing over
                if h[1] == "contained" and norms[h[0]:h[0] + 1] in (("to",), ("within",), ("in",), ("inside",)):
                    break  # "fire's contained to the bakery": still burning, there
                cancelled_by = h[1]
                break
            right_after = k == cue.end_tok and undesirable and (contracted or k + 1 < len(norms)) \
                and not toks.tokens[cue.end_tok - 1].text.lower().endswith("ing")  # "wall bowing out" goes on
            copula = norms[k - 1] in ("is", "s", "are", "was", "been", "now", "all") \
                or k > cue.end_tok and toks.tokens[k - 1].text.lower().endswith(("'s", "’s"))  # "the cafe's out"
            if norms[k] == "out" and undesirable and (right_after or copula) \
                    and not (norms[k + 1:k + 2] == ("there",) and norms[cue.end_tok - 1].endswith("out")) \
                    and not (norms[k + 1:k + 2] == ("there",) and not copula and not contracted) \
                    and not (norms[k + 1:k + 2] == ("there",) and norms[k + 2:k + 3] in (
                        ("is",), ("s",), ("are",), ("was",), ("has",), ("getting",), ("still",))) \
                    and (k + 1 >= len(norms) or toks.clause_start[k + 1] or norms[k + 1] in ("now", "completely", "over", "there")
                         or (contracted or copula) and norms[k + 1] in ("at", "in", "on")):  # "fire's out at the bakery"
                cancelled_by = "out"
                break
            if self._cues.match_at(norms, k) is not None:
                break
            k += 1
            steps += 1
        # ("the fire at the bakery is, er, out now": the predicate goes on past the pause)
        predicate_cut = 0 < k < len(norms) and (norms[k - 1] in ("is", "are", "was", "s", "its")
                                                or k == cue.end_tok and contracted)  # ("the leak's, uh, capped")
        if cancelled_by is None and k < len(norms) and toks.clause_start[k] and k >= cue.end_tok \
                and self.kb.category_by_name[cue.category].role != Role.DESIRABLE:
            # "the flooding at the cafe, it's, it's drained now": the next clause says it of the same thing
            # (past a clause that only names the place again: "the fire at the church, the chapel, it's out")
            j = k
            while j < len(norms) and norms[j] in lx.DETERMINERS:
                j += 1
            if j in ends and ends[j] < len(norms) and toks.clause_start[ends[j]]:
                k = ends[j]
            elif norms[j:j + 2] == ("one", "from") or norms[j:j + 2] == ("one", "that"):
                # "the fire at the store, the one from earlier? it's out now": past an aside that only
                # says which one
                e = next((i for i in range(j + 1, min(len(norms), j + 8)) if toks.clause_start[i]), None)
                if e is not None and not any(self._cues.match_at(norms, i) is not None for i in range(j, e)):
                    k = e
            for _ in range(2):
                # "the fire in the, er, the paint shed, it's out": past the rest of a noun phrase cut by pauses
                e = next((i for i in range(k + 1, min(len(norms), k + 6)) if toks.clause_start[i]), None)
                if e is None or norms[k] not in lx.DETERMINERS | lx.FILLERS | {"from", "in", "on", "at"} or any(
                        norms[i] in lx.COPULAS or norms[i] in lx.PRONOUNS - {"that", "this"}
                        or self._cues.match_at(norms, i) is not None for i in range(k, e)):
                    break
                k = e
            j = k
            if norms[k] == "but" and not self._cue_between(norms, cue.end_tok, k):
                j += 1  # "we did have smoke, er, from the kitchen, but it's out now"
            said_by = next((m for m in range(j, min(len(norms), j + 4)) if norms[m] in (
                "confirm", "confirms", "confirmed", "say", "says", "report", "reports")), None)
            if said_by is not None and said_by + 1 < len(norms) and norms[said_by + 1] in ("its", "it", "thats", "that") \
                    and not any(toks.clause_start[m] for m in range(j + 1, said_by + 1)) \
                    and not any(j <= q.start_tok < said_by for q in self._places_now):
                j = said_by + 1  # "ref the fire in the building adjoining the granary, fire service confirm it's out"
            while j < len(norms) and j - k < 6 and (norms[j] in lx.BACK_REFERENCE_WORDS | lx.FILLERS
                                                    or norms[j] in ("no", "hang", "on", "wait") and "its" in norms[j + 1:j + 4]):
                j += 1  # ("swinging load on the goliath... no hang on it's, it's landed")
            if missing and j + 1 < len(norms) and norms[j] in ("her", "his", "their", "the") and norms[j + 1] in _KIN:
                j += 1  # ("her mum's turned up")
            if missing and j < len(norms) and norms[j] in _KIN and not toks.clause_start[j + 1:j + 2] == (True,):
                j += 1  # "the separated child at the toffee apples, mum's turned up": the one looked for, found
            h = self._cancel.match_at(norms, j) if j < len(norms) else None
            if h is not None and h[1] in ("gone", "is gone", "has gone") and norms[cue.end_tok - 1] == "gone":
                h = None  # "the roof's gone, just gone": the cue's own word said again
            if h is not None and j == k and h[1] not in lx.CANCEL_CLAUSES and not predicate_cut:
                h = None  # (a clause of its own, "no sign of him", needs no "it's" before it)
            if h is None and j > k and j < len(norms) and norms[j] == "out":
                h = (j + 1, "out")
            if h is None and j > k and j < len(norms) and norms[j] == "cleared" and undesirable \
                    and not set(norms[k:j]) & _CLEARING_SUBJECTS:
                h = (j + 1, "cleared")  # "the chlorine smell at the filters, that's cleared now": the danger gone
            if h is None and j > k and j < len(norms) and norms[j] in ("not", "isnt", "wasnt", "arent", "werent") \
                    and (j + 1 >= len(norms) or toks.clause_start[j + 1]):
                h = (j + 1, norms[j])  # "I said the archway was coming down — it's not, ...": said of it, denied
            if h is not None and h[1] in lx.CANCEL_PEOPLE_ONLY \
                    and self.kb.category_by_name[cue.category].role != Role.CRITICAL:
                h = None  # "gas in the winding house, we've pulled everyone out, all accounted for": the gas stays
            if h is not None and h[1] in lx.CANCEL_MISSING_ONLY and not missing:
                h = None
            if h is not None and _out_and_still_ill(h[1], norms[cue.start_tok:cue.end_tok]):
                h = None
            if h is not None and h[0] < len(norms) and norms[h[0]] in ("it", "them") \
                    and (h[0] + 1 >= len(norms) or toks.clause_start[h[0] + 1]):
                h = (h[0] + 1, h[1])  # "the gas leak at the hardware store, they've capped it, ..."
            if h is not None and (h[0] >= len(norms) or toks.clause_start[h[0]] or norms[h[0]] in ("now", "completely")
                                  or h[1] in lx.CANCEL_CLAUSES
                                  or norms[h[0]] == "and" and norms[h[0] + 1:h[0] + 2] in (
                                      ("theyre",), ("they",), ("were",), ("we",), ("crews",), ("everyone",))):
                cancelled_by = h[1]  # ("fire service confirm it's out and they're leaving": a new clause after it)
        if negated_by is None and cue.start_tok >= 4 and self.kb.category_by_name[cue.category].role == Role.CRITICAL:
            # "nobody at the tombola's hurt": "nobody", where, then what is not so
            nb = _nobody_at(norms, cue.start_tok - 8, cue.start_tok)
            if nb is not None and norms[nb + 1 + (norms[nb] == "no"):][:1] in (("at",), ("in",), ("on",), ("inside",), ("from",)) \
                    and not any(toks.clause_start[m] for m in range(nb + 1, cue.start_tok)) \
                    and (norms[cue.start_tok - 1] in ("is", "was", "s", "got", "been", "hurt")
                         or toks.tokens[cue.start_tok - 1].text.lower().endswith(("'s", "’s"))):
                negated_by = norms[nb]
        if negated_by is None:
            j = cue.start_tok - 1
            while j >= 0 and norms[j] in lx.DETERMINERS | lx.FILLERS:
                j -= 1
            if j >= 1 and norms[j] == "on" and norms[j - 1] == "negative":
                negated_by = "negative on"  # "negative on the fire at the ice house"
        cleared = negated_by is None and cancelled_by is None and cue.start_tok > 0 \
            and self.kb.category_by_name[cue.category].role == Role.DESIRABLE \
            and norms[cue.start_tok:cue.end_tok] == ("cleared",)
        if cleared and norms[cue.start_tok - 1] in ("has", "have") and norms[cue.end_tok:cue.end_tok + 1] == ("it",) \
                and any(norms[m] in _CLEARING_THINGS for m in range(max(0, cue.start_tok - 4), cue.start_tok - 1)) \
                and any(self.kb.category_by_name[c].role == Role.UNDESIRABLE and s_ < cue.start_tok
                        and toks.sentence_of[s_] == toks.sentence_of[cue.start_tok]
                        for s_, _, (c, _src) in self._cues.find_all(norms) if c in self.kb.category_by_name):
            # "the ammonia leak in the engine room, the extraction fans have cleared it": the danger has gone
            return replace(cue, polarity="denied", reason="the danger before it was cleared")
        if cleared and (why := self._cleared_of_danger_before(toks, norms, cue.start_tok)) is not None:
            # "the chlorine smell at the filters, that's cleared now": the danger the clause before spoke of
            return replace(cue, polarity="denied", reason=why)
        if cleared and (norms[cue.start_tok - 1] in ("been", "has", "have")
                        or toks.tokens[cue.start_tok - 1].text.lower().endswith(("'s", "’s")) and any(
                            b == cue.start_tok and self.kb.category_by_name[c].role == Role.UNDESIRABLE
                            for _, b, (c, src) in self._cues.find_all(norms) if c in self.kb.category_by_name)):
            # "the rockfall at the elbow has been cleared", "the bad air's cleared" (the danger's own "'s"), "the smoke
            # at the filters has cleared": the danger is gone, the place is not said to be safe
            for i in range(cue.start_tok - 1, -1, -1):
                if toks.clause_start[i + 1]:
                    break
                h = self._cues.match_at(norms, i)
                if h is not None and self.kb.category_by_name[h[1][0]].role == Role.UNDESIRABLE:
                    return replace(cue, polarity="denied", reason="the danger before it was cleared")
        if negated_by is None and cancelled_by is None and self.kb.category_by_name[cue.category].role == Role.DESIRABLE:
            j = cue.start_tok - 1
            while j >= 0 and norms[j] in lx.FILLERS | {"be", "been", "all"}:
                j -= 1
            offered = j >= 3 and norms[j] == "to" and norms[j - 1] in ("need", "needs") and norms[j - 2] in ("who", "that") \
                and "for" in norms[max(0, j - 5):j - 2]  # ("opened up the net sheds for anyone who needs to shelter")
            if j >= 0 and not offered and (norms[j] in lx.INTENT_WORDS
                                           or norms[j] == "to" and j > 0 and norms[j - 1] in lx.INTENT_TO):
                # "crews will clear shortly": a plan, not yet a fact (and not "unsafe" either)
                return replace(cue, polarity="denied", reason=f"a plan ('{norms[j]}'), not a report")
        if negated_by in ("clear of", "free of") and self.kb.category_by_name[cue.category].role == Role.DESIRABLE:
            negated_by = None  # "clear of stalls now and safe": what it is clear of is the danger, not the safety
        if negated_by is None and cancelled_by is None:
            return cue
        why = negated_by or cancelled_by
        role = self.kb.category_by_name[cue.category].role
        said = norms[cue.start_tok:cue.end_tok]
        # "not safe" / "no longer safe" means unsafe: the place is undesirable now (but "the block is clear --
        # no, sorry, it's not clear, there's people on the top floor" says the word again to take it back)
        if role == Role.DESIRABLE and negated_by is not None and " ".join(said) in lx.NEGATABLE_STATES and not any(
                norms[i:i + len(said)] == said for i in range(max(0, cue.start_tok - 10), cue.start_tok - len(said))):
            und = self._undesirable()
            if self._role_category.get("undesirable") is None:
                # (where the KB splits the undesirable role, the danger said before it in the sentence: "the ceiling's
                # come down in the back and it's not safe to go in")
                sent = toks.sentence_of[cue.start_tok]
                dangers = [(a, c) for a, _, (c, src) in self._cues.find_all(norms)
                           if toks.sentence_of[a] == sent and src != "neutral" and c in self.kb.category_by_name
                           and self.kb.category_by_name[c].role == Role.UNDESIRABLE]
                before = [c for a, c in dangers if a < cue.start_tok]
                # (or, none before, the one said right after it to say why: "they're not safe, the ceiling's coming
                # down in the offices")
                after = [c for a, c in dangers if a >= cue.end_tok]
                if before:
                    und = before[-1]
                elif after:
                    und = after[0]
            if und is not None:
                return replace(cue, category=und, source=cue.source, reason=f"'{negated_by}' + {self.NOT_DESIRABLE}")
        return replace(cue, polarity="denied", reason=f"negated by '{why}'")

    @staticmethod
    def _injury_cause_at(norms: tuple[str, ...], a: int) -> bool:
        """Token ``a`` opens what hurt someone: "hit by falling slates", "hurt by the blast", "injured in the
        collapse"."""
        j = a - 1
        while j >= 0 and a - j <= 3 and norms[j] in lx.ARTICLES | {"falling", "flying", "some", "loose"}:
            j -= 1
        if not (j >= 1 and (norms[j] == "by" and norms[j - 1] in lx.INJURY_VERBS
                            or norms[j] == "in" and norms[j - 1] in ("hurt", "injured") and norms[j + 1:j + 2] == ("the",)
                            or norms[j] in ("on", "over") and norms[j - 1] in ("tripped", "slipped", "stumbled", "fell")
                            or norms[j] == "by" and norms[j - 1] in ("on", "caused", "triggered", "worsened"))):
            return False  # ("tripped on the rubble outside the church", "an asthma attack brought on by the smoke")
        reach = 10 if norms[j - 1] in ("on", "caused", "triggered", "worsened") else 6
        return any(norms[m] in _PERSON_WORDS or norms[m].isdigit() or norms[m] in lx.NUMBER_WORDS
                   for m in range(max(0, j - reach), j - 1))  # (a person hurt: "the bakery was hit by fire" is no one)

    @staticmethod
    def _danger_not_here(norms: tuple[str, ...], a: int, b: int) -> bool:
        """A danger word at ``a:b`` said of no place: "the fire crews have checked it for gas" (what was looked for),
        "everyone from the gas leak area is at the town hall" (where they came from), "the town hall's been cleared
        of smoke" (gone from it)."""
        return (a >= 2 and norms[a - 1] == "for" and any(norms[m] in lx.CHECK_VERBS for m in range(max(0, a - 4), a - 1))
                or norms[max(0, a - 2):a] == ("from", "the") and norms[b:b + 1] in (("area",), ("zone",), ("site",))
                or a >= 2 and ("cleared", "of") in (norms[a - 2:a], norms[a - 3:a - 1]))

    def _danger_kept_off(self, norms: tuple[str, ...], a: int, b: int) -> bool:
        """A danger word at ``a:b`` that a place is kept from: "untouched by the flood", "a safe distance from the
        fire", "upstream of the flooding" (no place named right after it: "away from the fire at the bakery" says
        where the fire is), "the fire's well away from the library", "smoke blowing over from somewhere else"; or
        where people came from ("people from the fire are at the library")."""
        j = a - 1
        while j >= 0 and norms[j] in lx.ARTICLES:
            j -= 1
        word, link = (norms[j - 1], norms[j]) if j >= 1 and a - j <= 3 else ("", "")
        if link == "from" and word in lx.ORIGIN_PEOPLE:
            return True
        after = norms[b:b + 6]
        if after[:3] in (("well", "away", "from"), ("away", "from", "the")) or after[:4] == ("s", "well", "away", "from"):
            return True
        if word in lx.DANGER_KEPT_OFF.get(link, ()):
            return not any(i in self._place_tokens for i in range(b, min(len(norms), b + 4)))
        return any(after[i:i + 3] == ("from", "somewhere", "else") or after[i:i + 2] == ("from", "elsewhere")
                   for i in range(len(after)))

    @staticmethod
    def _kept_clear_for(toks: Tokens, norms: tuple[str, ...], a: int) -> bool:
        """Token ``a`` says whom an order to keep a way clear is for ("keep the road clear for the ladder ...")."""
        return any(norms[k:k + 2] == ("clear", "for") and any(norms[m] in ("keep", "keeping") for m in range(max(0, k - 8), k))
                   and not any(toks.clause_start[t] for t in range(k + 1, a + 1)) for k in range(max(0, a - 12), a))

    def _contradiction_words_dropped(self, toks: Tokens, norms: tuple[str, ...],
                                     cues: list[CueMention]) -> list[CueMention]:
        """"said the library had been flooded, but ... it's bone dry": the words that deny what was said are
        no claim of their own (no safe place), unless another place is named between."""
        denied = [c for c in cues if c.polarity == "denied" and c.reason.endswith(("'but it isn't'", "'said, and it isn't'"))]
        if not denied:
            return cues
        starts = {p.start_tok for p in getattr(self, "_places_now", [])}
        out = []
        for c in cues:
            if c.polarity == "affirmed" and self.kb.category_by_name[c.category].role == Role.DESIRABLE and any(
                    d.end_tok <= c.start_tok <= d.end_tok + 16 and toks.sentence_of[d.start_tok] == toks.sentence_of[c.start_tok]
                    and not starts & set(range(d.end_tok, c.start_tok)) for d in denied):
                continue
            out.append(c)
        return out

    @staticmethod
    def _hearsay_before(toks: Tokens, norms: tuple[str, ...], a: int) -> bool:
        """Someone else's word opens the cue's sentence: "a woman here says the bakery's flooded"."""
        j = a - 1
        while j >= 0 and toks.sentence_of[j] == toks.sentence_of[a] and a - j <= 14:
            if norms[j] == "tell" and (j == 0 or toks.sentence_start[j] or norms[j - 1] in ("please", "just", "so")):
                return False  # "tell 'em the mill's safe": an order to pass it on, the speaker's own word
            if norms[j] in lx.HEARSAY_VERBS and not (j > 0 and norms[j - 1] in ("i", "we") and norms[j] not in ("heard", "hear")):
                return True
            j -= 1
        return False

    @staticmethod
    def _contradicted_after(toks: Tokens, norms: tuple[str, ...], k: int) -> bool:
        """The speaker's own word against it, later in the sentence: "but I'm stood right outside it and it
        isn't", "but I can see it from here, it's still standing"."""
        n = toks.sentence_of[k - 1]
        for j in range(k, min(len(norms), k + 16)):
            if toks.sentence_of[j] != n:
                return False
            for form in lx.CONTRADICTIONS:
                e = j + len(form)
                if norms[j:e] == form and (e >= len(norms) or toks.clause_start[e] or norms[e] in ("its", "thats")):
                    return True
        return False

    @staticmethod
    def _same_place_dismissed(ex: Extraction, norms: tuple[str, ...], a: int, b_after: int, e_after: int) -> bool:
        """"bank is on fire -- no wait, it's not, it's just the alarm going off at the bank": the place after the
        marker is the one before it, said again with a dismissal, so the claim is withdrawn, not moved."""
        toks = ex.tokens
        before = max((p for p in ex.places if p.end_tok <= a and toks.sentence_of[p.start_tok] == toks.sentence_of[a]),
                     key=lambda p: p.end_tok, default=None)
        after = [p for p in ex.places if b_after <= p.start_tok < e_after]
        words = [w for w in norms[b_after:e_after] if w not in lx.FILLERS]
        # ("smoke in the store attached to the import shed — cancel that, it was fog off the chiller doors": what was
        # seen, said harmless, where it came from the same place)
        harmless = words[:2] in (["it", "was"], ["that", "was"]) and words[2:3] != [] and (
            words[2] in lx.HARMLESS_SIGHTS or words[2] in ("just", "only") and words[3:4] != [] and words[3] in lx.HARMLESS_SIGHTS)
        # ("fire at the silo, no wait, the silo's ok, it's the chute that's burning": the place said again first, and
        # said to be all right)
        first = min(after, key=lambda p: p.start_tok) if after else None
        all_right = first is not None and (
            toks.tokens[first.end_tok - 1].text.lower().replace("’", "'").endswith("'s")
            and norms[first.end_tok:first.end_tok + 1] in (("ok",), ("okay",), ("fine",))
            or norms[first.end_tok:first.end_tok + 2] in (("is", "ok"), ("is", "okay"), ("is", "fine"))) \
            and (first.end_tok + 2 >= len(norms) or toks.clause_start[first.end_tok + 1 + (norms[first.end_tok] == "is")])
        if before is not None and all_right and first.landmark == before.landmark:
            return True
        return before is not None and bool(after) and all(p.landmark == before.landmark for p in after) \
            and (words[:2] in (["its", "not"], ["it", "isnt"], ["thats", "not"]) and bool(set(norms[b_after:e_after]) & lx.DISMISSALS)
                 or harmless)

    @staticmethod
    def _repairs_uncued_statement(ex: Extraction, cues: list[CueMention], since: int, a: int, b: int,
                                  first_cue: int) -> bool:
        """"an old lady with a broken hip, and the heating's out... no wait the heating's back on, they're sheltering
        people there": the repair begins by naming again the thing of a statement said after the last cue ("the
        heating"), so it corrects that statement, and the cue before it stands."""
        norms = ex.tokens.norms(0, len(ex.tokens))
        words = [(i, w) for i, w in enumerate(norms[b:first_cue], start=b) if w not in lx.FUNCTION_WORDS]
        if not words or any(p.start_tok <= words[0][0] < p.end_tok for p in ex.places):
            return False
        taken = {i for c in cues for i in range(c.start_tok, c.end_tok)} | {
            i for p in ex.places for i in range(p.start_tok, p.end_tok)}
        return any(norms[i] == words[0][1] and i not in taken for i in range(since, a))

    def _apply_cue_repairs(self, ex: Extraction, cues: list[CueMention]) -> list[CueMention]:
        """A marker followed by a cue (and no new place) retracts the last cue before it."""
        toks = ex.tokens
        out = list(cues)
        cue_spans = [(c.start_tok, c.end_tok) for c in out]
        norms_all = toks.norms(0, len(toks))
        for k, (a, _b, strong) in enumerate(ex.markers):
            kind = self._repair_kind(ex, k, cue_spans)
            b_after, e_after = self._after_clause(ex, k)
            withdraw = _withdraws(norms_all[a:_b])
            if kind == "place" and strong and self._same_place_dismissed(ex, norms_all, a, b_after, e_after):
                kind = None  # the place said again with a dismissal: a withdrawal of the cue, not a place repair
            just_said = [c for c in out if c.status == "active" and c.end_tok <= a
                         and all(w in lx.FILLERS for w in norms_all[c.end_tok:a])]
            said_after = [w for w in norms_all[b_after:min(len(norms_all), b_after + 12)] if w not in lx.FILLERS]
            # "Smoke — no — it's steam, sorry, steam off the ice plant": what was seen, said again as harmless
            explained = not strong and bool(just_said) and bool(
                said_after[:1] and said_after[0] in lx.HARMLESS_SIGHTS
                or said_after[:1] in (["its"], ["thats"]) and said_after[1:2]
                and said_after[1] in lx.HARMLESS_SIGHTS | {"just", "only"})
            if kind == "place" and explained and not any(
                    self._repair_window_start(ex, k) <= p.start_tok < a for p in ex.places):
                kind = None  # (no place before the marker to repair: the place after is where the steam comes from)
            if kind == "place":
                self._restated_category(ex, k, out, b_after, e_after, a, withdraw)
                continue
            taken_back = kind is None and strong and bool(just_said) and e_after > b_after \
                and not any(b_after <= c.start_tok < e_after for c in out) \
                and not any(b_after <= p.start_tok < e_after for p in ex.places)
            # "the hard's flooded - well, no, it's not, it's gone back down, it's just wet": the cue just said, denied
            # and explained away after a plain "no"
            denied_after = not strong and kind is None and bool(just_said) and said_after[:2] in (
                ["its", "not"], ["it", "isnt"], ["it", "not"]) \
                and bool(set(norms_all[b_after + 3:min(len(norms_all), b_after + 12)]) & lx.DISMISSALS) \
                and not any(b_after <= p.start_tok < b_after + 12 for p in ex.places)
            denied_after = denied_after or explained and kind is None
            if kind is None and (strong or denied_after) and (set(norms_all[b_after:e_after]) & lx.DISMISSALS or withdraw
                                                              or taken_back or denied_after):
                # ("I'm trapped — no, no, sorry, the door's opened": the cue just said is taken back)
                # "smoke at the cafe, correction, that's just steam": the claim is withdrawn
                lo = self._repair_window_start(ex, k)
                before = [c for c in out if lo <= c.start_tok < a and c.status == "active"]
                if not before and withdraw and k > 0 and not any(lo <= p.start_tok < a for p in ex.places) \
                        and toks.sentence_of[ex.markers[k - 1][0]] == toks.sentence_of[a] \
                        and [w for w in norms_all[ex.markers[k - 1][1]:a] if w not in lx.FILLERS][:1] in (
                            ["that"], ["thats"], ["it"], ["its"]):
                    # "flames at the hardware store — no, sorry, that's the low sun on the glass, ignore that": what
                    # the marker before it took up, when only an explanation stands between
                    lo = self._repair_window_start(ex, k - 1)
                    before = [c for c in out if lo <= c.start_tok < a and c.status == "active"]
                if before:
                    last = max(before, key=lambda c: c.start_tok)
                    out[out.index(last)] = replace(last, status="retracted", reason="withdrawn by a correction")
                    if not set(norms_all[b_after:e_after]) & lx.DISMISSALS:
                        new = self._repaired_by_meaning(ex, b_after, e_after, last)
                        if new is not None:
                            out.append(new)
                continue
            if kind not in ("cue", "full"):
                continue
            b, end = self._after_clause(ex, k)
            after_cues = [c for c in out if b <= c.start_tok < end and c.status == "active"]
            if not after_cues:
                continue
            first_cue = min(after_cues, key=lambda c: c.start_tok)
            lo = self._repair_window_start(ex, k)
            before = [c for c in out if lo <= c.start_tok < a and c.status == "active"]
            if not before:
                continue
            last = max(before, key=lambda c: c.start_tok)
            if not strong and kind == "cue" and norms_all[a:_b] in (("hang", "on"), ("hold", "on"), ("wait",)) \
                    and self.kb.category_by_name[first_cue.category].role == Role.CRITICAL \
                    and self.kb.category_by_name[last.category].role != Role.CRITICAL:
                continue  # "the meeting point, everyone's there, but hang on, someone's just collapsed": news
            if not strong and first_cue.polarity == "denied":
                continue  # "smoke, and, um, actually the fire at the barn's out now": news that ends a claim, said so
            if not strong and kind == "cue" and any(p.status == "active" and last.end_tok <= p.start_tok < a
                                                    for p in ex.places):
                # "it's the rest centre, and the cloisters, they're shut, actually there's a gas smell in
                # there": what the new place was said to be is corrected, not the claim before it
                continue
            if self._repairs_uncued_statement(ex, out, last.end_tok, a, b, first_cue.start_tok):
                continue
            i = out.index(last)
            out[i] = replace(last, status="retracted", reason=f"self-repair: '{toks.span_text(a, b)}' then '{first_cue.text}'")
            # ... with the cues of the same category said of the same place just before it ("it's dry
            # inside, safe to come -- no, scratch that, the floor's cracking")
            since = max((p.end_tok for p in ex.places if p.end_tok <= last.start_tok), default=lo)
            for c in before:
                if c is not last and c.category == last.category and c.start_tok >= max(lo, since) \
                        and c.category != first_cue.category:
                    out[out.index(c)] = replace(c, status="retracted", reason=out[i].reason)
            if kind == "cue":  # a restated claim ("full") keeps its own binding
                j = out.index(first_cue)
                out[j] = replace(first_cue, replaces=last.start_tok)
        return out

    def _segments(self, ex: Extraction) -> list[tuple[int, int]]:
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        marker_tokens = {i for a, b, _ in ex.markers for i in range(a, b)}
        coord = {i for key in _COORDINATOR_KEYS for i in range(len(norms)) if norms[i : i + len(key)] == key}
        cuts = [0]
        aux = ("is", "are", "was", "were", "s", "has", "have", "had", "re")

        def held(i: int) -> bool:
            """A hesitation between a verb's auxiliary and the rest, or a subject and its verb, cuts no clause
            ("the viaduct has, um, lost a parapet", "the viaduct, um, has lost a parapet")."""
            h = i if norms[i] in lx.HESITATIONS else i - 1 if norms[i - 1] in lx.HESITATIONS else None
            return h is not None and 0 < h < len(norms) - 1 and not toks.sentence_start[i] \
                and (norms[h - 1] in aux or norms[h + 1] in aux and not any(
                    q in toks.tokens[h + 1].text for q in ("'", "’"))) and h - 1 not in marker_tokens \
                and h + 1 not in marker_tokens  # ("gas, um, we're up at the platform": "we're" opens a clause)
        for i in range(1, len(toks)):
            if toks.clause_start[i] and not (held(i) and norms[i] not in lx.COORDINATORS and i not in coord) \
                    or norms[i] in lx.COORDINATORS or i in coord or i in marker_tokens and (i - 1) not in marker_tokens:
                cuts.append(i)
        cuts.append(len(toks))
        segs = [(cuts[k], cuts[k + 1]) for k in range(len(cuts) - 1) if cuts[k] < cuts[k + 1]]
        # relational descriptions span their own words; never cut inside a mention
        merged: list[tuple[int, int]] = []
        for s in segs:
            if merged and any(p.start_tok < s[0] < p.end_tok for p in ex.places):
                merged[-1] = (merged[-1][0], s[1])
            else:
                merged.append(s)
        return merged

    def _counted_ones(self, ex: Extraction, norms: tuple[str, ...], pairs: list[Claim]) -> list[Claim]:
        """"two hurt — one in the parking lot, one in the ticket hall, and the souvenir shop is safe": each "one at X"
        of a count is one of the people counted, as the first was; what the next place is said to be is its own."""
        toks = ex.tokens

        def one_at(p: PlaceMention) -> bool:
            k = _noun_phrase_start(norms, p)
            first = next((r for r in ex.places if p.replaces is not None and r.start_tok == p.replaces
                          and r.status == "retracted"), None)
            if first is not None:
                k = _noun_phrase_start(norms, first)  # ("one in the car p-- the parking lot")
            return k >= 2 and norms[k - 1] in ("in", "at", "on", "by", "inside") and norms[k - 2] == "one" \
                and toks.clause_start[k - 2]

        def critical(c: Claim) -> bool:
            return c.cue.polarity == "affirmed" and self.kb.category_by_name[c.cue.category].role == Role.CRITICAL

        ones = sorted((p for p in ex.places if p.status == "active" and one_at(p)), key=lambda p: p.start_tok)
        add: list[Claim] = []
        drop: set[int] = set()
        for i, p in enumerate(ones):
            prev = [q for q in ones[:i] if toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok]]
            if not prev or any(c.place.start_tok == p.start_tok and critical(c) for c in pairs):
                continue
            counted = [c for c in pairs if c.place.start_tok == prev[-1].start_tok and critical(c)]
            if not counted:
                continue
            add.extend(Claim(p, c.cue) for c in counted)
            drop.update(id(c) for c in pairs if c.place.start_tok == p.start_tok and c.cue.start_tok > p.end_tok
                        and any(r.status == "active" and p.end_tok <= r.start_tok < c.cue.start_tok for r in ex.places))
        return [c for c in pairs if id(c) not in drop] + add

    def _associate(self, ex: Extraction, cues: list[CueMention]) -> tuple[list[Claim], list[Claim]]:
        """Attach cues to places.

        1. Natural binding: inside a segment every cue (live or retracted) binds to its nearest
           place (active, retracted or negated), prepositional and copular binding first.
        2. Repairs carry bindings over: a replacement place inherits the cues of the place it
           replaced ("fire at the bank, sorry, the bakery"), a replacement cue binds to the place
           of the cue it replaced ("the school is safe, sorry, it's on fire").
        3. Cues in a segment without places attach to the place they talk about.
        4. Places still without a cue borrow from the list they belong to.
        """
        toks = ex.tokens
        norms = toks.norms(0, len(toks))
        usable = [p for p in ex.places if p.status in ("active", "retracted", "negated")]
        active = [p for p in usable if p.status == "active"]
        segs = self._segments(ex)
        seg_index = [0] * len(toks)
        for k, (a, b) in enumerate(segs):
            for i in range(a, b):
                seg_index[i] = k
        cue_at = {c.start_tok: c for c in cues}

        # 1. natural binding
        seg_usable: dict[int, list[PlaceMention]] = {}
        for p in usable:
            seg_usable.setdefault(seg_index[p.start_tok], []).append(p)
        bound: dict[int, PlaceMention] = {}  # cue start -> place
        for c in cues:
            ps = seg_usable.get(seg_index[c.start_tok], [])
            if ps:
                near = ps[0] if len(ps) == 1 else min(ps, key=lambda p: self._bind_cost(norms, c, p))
                before = [p for p in ps if p.status == "active" and p.end_tok <= c.start_tok]
                if near.status == "negated" and before and near.start_tok >= c.end_tok \
                        and [w for w in norms[c.end_tok:near.start_tok]
                             if w not in lx.DETERMINERS and w not in lx.FILLERS] == ["not"]:
                    # "the bothy both open as warm rooms not the office": the place put against the one said
                    # before the cue, not the cue's own
                    near = min(before, key=lambda p: self._bind_cost(norms, c, p))
                bound[c.start_tok] = near
        own: dict[int, list[CueMention]] = {}  # place start -> live cues bound naturally
        for c in cues:
            if c.status == "active" and c.start_tok in bound and c.replaces is None:
                own.setdefault(bound[c.start_tok].start_tok, []).append(c)

        successor: dict[int, PlaceMention] = {}
        for p in usable:
            if p.replaces is not None:
                successor[p.replaces] = p

        def forward(p: PlaceMention | None) -> PlaceMention | None:
            seen = 0
            while p is not None and p.status != "active" and seen < 10:
                nxt = successor.get(p.start_tok)
                if nxt is None and p.reason.startswith("said again later"):
                    nxt = next((q for q in ex.places if q.landmark == p.landmark and q.start_tok > p.start_tok), None)
                elif nxt is None and p.reason.startswith("then '"):
                    # "injured kid at the gardens, the park -- no, ... the sports hall, not the park": every
                    # mention the negation took back goes where the last one went
                    nxt = next((q for q in ex.places if q.landmark == p.landmark and q.start_tok > p.start_tok
                                and q.reason == p.reason), None)
                    if nxt is None:
                        # "the hotel's on fire, well, not the hotel, it's the ware— no, hotel, it is the hotel": the
                        # place the speaker comes back to, past the one put in its stead and taken back
                        nxt = next((q for q in ex.places if q.landmark == p.landmark and q.start_tok > p.start_tok
                                    and q.status == "active" and (any(
                                        r.landmark != p.landmark and p.start_tok < r.start_tok < q.start_tok
                                        and r.status == "retracted" for r in ex.places)
                                        # "no not the bank, the credit— oh it's the same thing, yes, the bank"
                                        or any(norms[i] == "same" and norms[i + 1:i + 2] in (("thing",), ("place",),
                                                                                              ("one",), ("building",))
                                               for i in range(p.end_tok, q.start_tok)))), None)
                    neg = next((q for q in ex.places if nxt is None and q.landmark == p.landmark
                                and q.start_tok > p.start_tok and q.status == "negated"), None)
                    if neg is not None:
                        # "a guy hurt at the depot— at the d- the scale house, not the depot": the place said before
                        # the negation is the one put in its stead
                        nxt = max((q for q in usable if q.landmark != p.landmark and p.end_tok <= q.start_tok
                                   and q.end_tok <= neg.start_tok and q.status != "negated"
                                   and toks.sentence_of[q.start_tok] == toks.sentence_of[neg.start_tok]),
                                  key=lambda q: q.start_tok, default=None)
                elif nxt is None and p.status == "negated" and p.reason.startswith("negated by 'not"):
                    # "it's not the library that's flooding it's the town hall basement": the place the cleft names
                    nxt = next((q for q in ex.places if q.status == "active" and q.landmark != p.landmark
                                and q.start_tok > p.end_tok and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok]
                                and [w for w in norms[max(0, q.start_tok - 3):q.start_tok] if w not in lx.ARTICLES][-1:]
                                in (["its"], ["is"])), None)
                elif nxt is None and p.reason.startswith(("false start", "restarted", "self-repair of '")):
                    # "fire at the hot-- / ... / hotel": a name cut off or said again is the same place, named
                    # in full later
                    nxt = next((q for q in usable if q.landmark == p.landmark and q.start_tok > p.start_tok), None)
                    mark = next((mb for ma, mb, _ in ex.markers if p.end_tok <= ma <= p.end_tok + 1), None) \
                        if nxt is None and p.reason.startswith("false start") else None
                    if mark is not None:
                        # "people trapped in the tourist off-- no, sorry, in the place in front of the bus
                        # terminal": a name cut off and repaired at once is the place the repair names
                        nxt = min((q for q in usable if q.status == "active" and mark <= q.start_tok <= mark + 3
                                   and toks.sentence_of[q.start_tok] == toks.sentence_of[p.start_tok]),
                                  key=lambda q: q.start_tok, default=None)
                p = nxt
                seen += 1
            return p if p is not None and p.status == "active" else None

        def owner(c: CueMention) -> PlaceMention | None:
            seen = 0
            while c.replaces is not None and c.replaces in cue_at and seen < 10:
                c = cue_at[c.replaces]
                seen += 1
            return bound.get(c.start_tok)

        pairs: list[Claim] = []
        claimed_places: set[int] = set()
        broken_off: set[int] = set()  # cue segments whose place broke off and was repaired after them
        handled: set[int] = set()
        for c in cues:
            if c.status != "active":
                continue
            if c.replaces is not None:
                tgt = forward(owner(c))
                if tgt is not None:
                    pairs.append(Claim(tgt, c))
                    claimed_places.add(tgt.start_tok)
                    handled.add(c.start_tok)
                    continue
            p = bound.get(c.start_tok)
            if p is None:
                continue
            handled.add(c.start_tok)
            if p.status == "active":
                pairs.append(Claim(p, c))
                claimed_places.add(p.start_tok)
                continue
            tgt = forward(p)
            if tgt is not None and not own.get(tgt.start_tok):
                pairs.append(Claim(tgt, c))
                claimed_places.add(tgt.start_tok)

        seg_places: dict[int, list[PlaceMention]] = {}
        for p in active:
            seg_places.setdefault(seg_index[p.start_tok], []).append(p)
        seg_cues: dict[int, list[CueMention]] = {}
        for c in cues:
            if c.status == "active":
                seg_cues.setdefault(seg_index[c.start_tok], []).append(c)
        sentence_of = toks.sentence_of
        marker_tokens = {i for a, b, _ in ex.markers for i in range(a, b)}
        inactive_tokens = {i for p in ex.places if p.status != "active" for i in range(p.start_tok, p.end_tok)}
        cue_tokens = {i for c in cues for i in range(c.start_tok, c.end_tok)}
        hollow = {k for k, (a, b) in enumerate(segs)
                  if all((i in marker_tokens or i in inactive_tokens or norms[i] in lx.FILLERS or norms[i] in lx.COORDINATORS
                          or norms[i] in lx.DETERMINERS or norms[i] in lx.PREPOSITIONS or norms[i] in ("just", "only", "its", "it"))
                         and i not in cue_tokens for i in range(a, b))
                  or norms[a:b] in (("but", "it", "isnt"), ("but", "its", "not"), ("but", "it", "wasnt"),
                                    ("but", "it", "is", "not"))}  # "says the bakery's on fire but it isn't, it's ..."

        # ("two at the bakery and one at the, uh, the chemist's": a count that leads on to its place)
        counts = lx.NUMBER_WORDS | {"one", "another"}
        counting = {k for k, (a, b) in enumerate(segs) if k not in hollow and any(norms[i] in counts for i in range(a, b))
                    and all(norms[i] in counts or norms[i] in lx.FILLERS or norms[i] in lx.COORDINATORS
                            or norms[i] in lx.DETERMINERS or norms[i] in lx.PREPOSITIONS for i in range(a, b))}

        # sentences a cue-only sentence may look back across to the place it talks about: the
        # dispatcher's questions, one-word answers ("Yes.", "Eight o'clock."), and sentences that go
        # on about the same place ("Fire at the bakery. The roof is sagging. Two people trapped inside.")
        questions = self._question_sentences(toks)
        sent_words: dict[int, int] = {}
        for i in range(len(toks)):
            sent_words[sentence_of[i]] = sent_words.get(sentence_of[i], 0) + (norms[i] not in lx.FILLERS)
        placed = {sentence_of[p.start_tok] for p in usable}
        cued = {sentence_of[c.start_tok] for c in cues if c.status == "active"}
        # (a short sentence that names no place goes on about it too: "That's the one.", "Windows all blown out.")
        transparent = {n for n in sent_words if n not in placed and (n in questions or n in cued or sent_words[n] <= 5)}
        # (and an aside about where the speaker is: "I've lived here thirty years and never seen it like this.")
        transparent |= {sentence_of[i] for i in range(len(toks)) if norms[i] == "here" and sentence_of[i] not in placed
                        and sent_words[sentence_of[i]] <= 14
                        and {"i", "ive", "weve", "id"} & {norms[j] for j in range(max(0, i - 3), i)}}

        floated: set[int] = set()  # places given only the cues of a later segment with no place of its own
        # 3. cue-only segments attach to the places they talk about; a segment whose place was
        #    repaired away keeps its cues for the replacement (step 2), they do not float
        for k, cs in seg_cues.items():
            cs = [c for c in cs if c.start_tok not in handled]
            if not cs or seg_usable.get(k):
                continue
            a, b = segs[k]
            lead3 = [w for w in norms[a:b] if w not in lx.FILLERS][:3]
            if all(c.polarity == "denied" for c in cs) and lead3[:1] == ["the"] and (
                    lead3[2:3] in (["ones"], ["one"]) or lead3[1:2] in (["others"], ["rest"])):
                continue  # "fire in the B cabins. The A ones haven't caught.": other things denied, not the place before
            # "two people are unconscious inside. The coffee house ...": a preposition that ends a
            # sentence is an adverb, not a broken-off "at the" (which a dash or ellipsis marks)
            closed = b < len(toks) and (toks.sentence_start[b] or ";" in toks.gaps[b]) \
                and norms[b - 1] not in lx.DETERMINERS \
                and not any(m in toks.gaps[b] for m in ("-", "—", "–", "...", "…"))
            if (norms[b - 1] in lx.PREPOSITIONS or norms[b - 1] in lx.DETERMINERS) and not closed \
                    and not self._particle_end(toks, norms, segs, seg_places, k, cs) \
                    and not (norms[b - 1] in ("out", "off", "up", "over", "in") and any(c.end_tok == b for c in cs)) \
                    and not (norms[b - 1] in ("down", "away") and any(c.end_tok == b for c in cs)
                             and not seg_places.get(k + 1)):
                # ("but it's flooded out, so ...", "rocks rolling down, we've got everyone off the site": the cue's own
                # word; "man down, warehouse" still leads on to its place)
                nxt = k + 1
                skipped = 0
                taken_back = None
                while nxt < len(segs) and (nxt in hollow or (not seg_places.get(nxt) and not seg_cues.get(nxt) and skipped < 2)):
                    taken_back = next((went for q in ex.places if q.status == "retracted" and q.reason.startswith("then '")
                                       and segs[nxt][0] <= q.start_tok < segs[nxt][1]
                                       and (went := forward(q)) is not None), None)
                    if taken_back is not None:
                        break  # "flooding in the basement of the, of the bank ... it's not the bank, it's the hotel"
                    skipped += nxt not in hollow
                    nxt += 1
                if taken_back is not None:
                    pairs.extend(Claim(taken_back, c) for c in cs)
                    claimed_places.add(taken_back.start_tok)
                    continue
                if seg_places.get(nxt):
                    pairs.extend(Claim(p, c) for p in seg_places[nxt] for c in cs)
                    claimed_places.update(p.start_tok for p in seg_places[nxt])
                    continue
            fix = k + 1  # (the repair may stand as a segment of its own: "no wait, in the generator shed")
            if fix < len(segs) and not seg_places.get(fix) and not seg_cues.get(fix) and segs[fix][1] - segs[fix][0] <= 3:
                fix += 1
            w0 = b - 2 if b - a >= 3 and norms[b - 2] in lx.ARTICLES else b - 3 if (
                b - a >= 4 and norms[b - 3] in lx.ARTICLES and norms[b - 2].isalpha()
                and norms[b - 2] not in lx.FUNCTION_WORDS) else -1  # (or two words cut: "is the staff car --")
            if w0 > a and (norms[w0 - 1] in lx.PREPOSITIONS or w0 == b - 3 and norms[w0 - 1] in ("is", "s")) \
                    and norms[b - 1].isalpha() \
                    and (norms[b - 1] not in lx.FUNCTION_WORDS or w0 == b - 3 and any(  # ("the tourist off--" office)
                        ws[:1] == norms[b - 2:b - 1] and len(ws) >= 2 and ws[1].startswith(norms[b - 1])
                        for ws in (name_words(f) for lm in self.kb.landmarks for f in lm.surface_forms))) \
                    and not seg_places.get(k) and fix < len(segs) \
                    and any(d in toks.gaps[b] for d in ("-", "—", "–")) and seg_places.get(fix) \
                    and any(segs[k + 1][0] <= ma <= segs[k + 1][0] + 1 for ma, _, _ in ex.markers) \
                    and sentence_of[segs[fix][0]] == sentence_of[a]:
                # "we got a, like, a fire in the box-- no wait, in the generator shed": a place broken off and
                # repaired; the place said in the repair has the claim
                pairs.extend(Claim(p, c) for p in seg_places[fix][:1] for c in cs)
                claimed_places.add(seg_places[fix][0].start_tok)
                broken_off.add(k)
                continue
            nxt, steps, opened = k + 1, 0, False
            cats = {c.category for c in cs}
            while nxt < len(segs) and steps < 4 and not seg_places.get(nxt) \
                    and (not seg_cues.get(nxt) or {c.category for c in seg_cues[nxt]} <= cats) \
                    and segs[nxt][1] - segs[nxt][0] <= 4 and sentence_of[segs[nxt][0]] == sentence_of[a]:
                # ("there's, er, smoke, loads of smoke, coming from the building next door to it": the same said again)
                a2, b2 = segs[nxt]
                opened = opened or (norms[b2 - 1] in lx.PREPOSITIONS | lx.DETERMINERS
                                    and any(norms[i] in lx.POSITION_PREPS for i in range(a2, b2))) \
                    or norms[b2 - 2:b2] in (("coming", "from"), ("pouring", "from"), ("pouring", "out"),
                                            ("coming", "out"))  # ("smoke, lots of it, coming from, er, the ...")
                nxt, steps = nxt + 1, steps + 1
            lead = tuple(w for w in norms[segs[nxt][0]:segs[nxt][1]] if w not in lx.FILLERS or w == "over")[:2] \
                if nxt < len(segs) else ()
            if seg_places.get(nxt) and sentence_of[segs[nxt][0]] == sentence_of[a] and (lead in (
                    ("coming", "from"), ("pouring", "from"), ("billowing", "from"), ("pouring", "out"), ("coming", "out"))
                    or lead[:1] in (("over",), ("at",), ("inside",)) and lead[1:] in (("the",), ("their",))
                    and all(c.polarity == "affirmed" for c in cs)):
                opened = True  # ("smoke, loads of smoke, coming from the building next door to it"; "a vapour cloud,
                # just vapour, over the jetty")
            if opened and seg_places.get(nxt) and sentence_of[segs[nxt][0]] == sentence_of[a]:
                # "there's this gas smell, like really strong, at the, you know, the bread shop": past the
                # asides, the place the broken-off "at the" was leading to
                pairs.extend(Claim(p, c) for p in seg_places[nxt][:1] for c in cs)
                claimed_places.add(seg_places[nxt][0].start_tok)
                continue
            first_at = next((i for i in range(a, b) if norms[i] not in lx.FILLERS and norms[i] not in ("and", "so")), b)
            first = norms[first_at] if first_at < b else ""
            if norms[a] == "and" and k > 0 and not seg_usable.get(k - 1) and not seg_cues.get(k - 1) \
                    and sentence_of[segs[k - 1][0]] == sentence_of[a] \
                    and norms[segs[k - 1][0]] in ("it", "its") and segs[k - 1][1] - segs[k - 1][0] <= 3:
                first = norms[segs[k - 1][0]]  # ("bringing him to the sick bay, it's heated and set up as our warm room")
            storey = first not in ("it", "its", "there", "thats", "theres") and any(
                (norms[i] in lx.STOREY_WORDS and ("on", "the") in (norms[i - 2:i], norms[i - 3:i - 1])
                 or norms[i] in ("first", "second", "third", "fourth", "fifth", "top") and norms[i - 2:i] == ("on", "the"))
                for i in range(max(a, 3), b))  # ("we're at the guest house, two casualties on the second floor")
            that_one = first == "that" and norms[first_at + 1:first_at + 2] in (("one",), ("ones",))
            thats = first == "that" and toks.tokens[first_at].text.lower().replace("’", "'").endswith("'s") \
                and all(c.polarity == "affirmed" for c in cs)  # ("bring her to the gatehouse, that's safe and warm")
            if (first in ("it", "its", "there", "thats", "theres") or storey or that_one or thats) and k > 0:
                # ("Moving on to the garage, yeah, that one's got actual flames": the place the speaker came to)
                # "standing by at the garage, it is safe": a position names the place the pronoun claims
                # ("we're at the bank and it's on fire"; "We're at the bank. It's on fire.")
                opens = toks.sentence_start[first_at] if first_at < b else False
                back = k - 1
                while back > 0 and k - back < 3 and not seg_places.get(back) and not seg_cues.get(back) \
                        and not any(segs[back][0] <= ma < segs[back][1] for ma, _, _ in ex.markers):
                    back -= 1  # ("we're at the health centre, and the doctors say it's safe": past who says so)
                lower = segs[back][0]
                if opens and storey:  # ("We're at the guest house, ... . Fire's on the third floor.")
                    lower = min(lower, next((i for i in range(a) if sentence_of[i] == sentence_of[a] - 1), lower))
                here = [p for p in ex.places if p.reason.startswith("in transit") and lower <= p.start_tok < a
                        and not (first in ("there", "theres")
                                 and p.reason.endswith((" to'): no claim", " towards'): no claim")))  # (where one goes)
                        and not (p.reason.startswith(("in transit ('past'", "in transit ('passing'"))
                                 and "from" in [norms[i] for i in range(a, len(norms)) if sentence_of[i] == sentence_of[a]])
                        # ("past the caravan park and there's smoke, loads of smoke, from the -": from somewhere else)
                        and (sentence_of[p.start_tok] == sentence_of[a]
                             or opens and sentence_of[p.start_tok] == sentence_of[a] - 1)]
                prev = k - 1
                while prev > 0 and all(norms[i] in lx.FILLERS or norms[i] in ("and", "then") for i in range(*segs[prev])):
                    prev -= 1  # ("heading up the tracks and um, there's a derailment": the tracks, past the "um")
                cut_to_next = b < len(norms) and b - a >= 3 and norms[b - 2] in lx.ARTICLES \
                    and re.search(r"[—–-]", toks.gaps[b]) is not None and bool(seg_usable.get(k + 1))
                # (not "there's a hazchem leak coming out of the impound— the prohibition bay": the place the
                # speaker began to name, given after the break)
                if here and not seg_usable.get(prev) and not cut_to_next:
                    pairs.extend(Claim(replace(here[-1], status="active"), c) for c in cs)
                    continue
            if k > 0 and all(c.polarity == "denied" for c in cs) and "there" in norms[a:b] \
                    and sentence_of[segs[k - 1][0]] == sentence_of[a] and seg_usable.get(k - 1) \
                    and all(q.status == "negated" for q in seg_usable[k - 1]):
                continue  # "..., the fuel farm's not affected, no fire there": said of the place just set apart
            if all(c.category == self._person_category for c in cs) and self._person_category is not None:
                # "we're at the hotel, and the -- the groom's uncle has collapsed": a person said to need help, in
                # the sentence that says where the speaker is and names no other place, is there
                sent = sentence_of[a]
                at = {q.landmark: q for q in ex.places if sentence_of[q.start_tok] == sent and (
                    q.reason.startswith(("in transit ('we're at'", "in transit ('we are at'")) and q.start_tok < a
                    # ("my friend is cut very bad from the glass, we are in the cucumber cathedral": said after)
                    or q.reason == _CREW_POSITION and q.start_tok >= b
                    and "we" in norms[max(0, _noun_phrase_start(norms, q) - 4):q.start_tok])}
                others = [q for q in ex.places if sentence_of[q.start_tok] == sent and q.landmark not in at]
                if len(at) == 1 and not others:
                    q = next(iter(at.values()))
                    pairs.extend(Claim(replace(q, status="active"), c) for c in cs)
                    continue
            if "here" in norms[a:b]:
                # "we're at the east portal, RVP established here": where the speaker said they are
                sent = sentence_of[a]
                at = {q.landmark: q for q in ex.places if (q.reason.startswith("in transit") and (
                    "at'" in q.reason or "in'" in q.reason) or (
                    q.status == "active" and self._speaker_here(norms, q))) and sent - 1 <= sentence_of[q.start_tok] <= sent
                    and q.start_tok < a}
                if len(at) == 1 and not ({"it", "its"} & set(norms[a:b]) and any(
                        r.status == "active" and r.landmark not in at and next(iter(at.values())).end_tok <= r.start_tok < a
                        for r in ex.places)):
                    # (not where "it" takes up a place said between: "We're at the bike wash, and the stream it
                    # drains into is coming up fast, it's burst its banks right along here")
                    q = next(iter(at.values()))
                    pairs.extend(Claim(replace(q, status="active"), c) for c in cs)
                    continue
            start = a
            while start > 0 and sentence_of[start - 1] == sentence_of[a]:
                start -= 1
            opening = next((w for w in norms[start:b] if w not in lx.FILLERS), "")
            target = self._target_for_cues(k, segs, seg_usable, seg_cues, sentence_of, transparent, opening, norms)
            if target is None and not any(seg_usable.get(j) for j in range(k)):
                person = all(self.kb.category_by_name[c.category].role == Role.CRITICAL for c in cs)
                target = self._named_after(k, segs, seg_usable, seg_cues, sentence_of, norms, sent_words, person)
            if target is None and len({q.landmark for q in ex.places if q.status != "retracted"}) == 1:
                # "I'm at the pond in the, the park, and ... But the big trees by the pond are down across the path":
                # where the speaker said they are, in a report that names no other place
                at = [j for j in range(k) if any(q.status == "active" and (self._speaker_here(norms, q) or any(
                    norms[t] in ("im", "were") and sentence_of[t] == sentence_of[q.start_tok]
                    for t in range(max(0, q.start_tok - 9), q.start_tok))) for q in seg_usable.get(j, []))]
                if at:
                    target = at[-1]
            if target is not None and all(q.status == "negated" for q in seg_usable[target]):
                # "the harbour master's office, not the ice house, has got a gas leak": past the negated aside
                # to the place it was contrasted with, in the same sentence
                back = target - 1
                while back >= 0 and (back in hollow or not seg_usable.get(back) and not seg_cues.get(back)) \
                        and target - back <= 3:
                    back -= 1
                if back >= 0 and sentence_of[segs[back][0]] == sentence_of[segs[target][0]] \
                        and any(q.status == "active" for q in seg_usable.get(back, [])) and not seg_cues.get(back):
                    target = back
            if target is not None and sentence_of[segs[target][0]] < sentence_of[a] \
                    and all(self._says_who_and_where(toks, norms, q) for q in seg_usable[target]) \
                    and not {"here", "us", "we", "our", "it", "its", "there", "inside"} & set(norms[a:b]) \
                    and any(sentence_of[q.start_tok] == sentence_of[a] for q in active):
                target = None  # "Mechanic at the car workshop. A flash flood has come down the south road: ...": who
                # is calling from where, not what the next sentence's news is about
            silent = getattr(self, "_non_report_tokens", set())
            if target is not None and all(q.start_tok in silent and sentence_of[q.start_tok] != sentence_of[a]
                                          for q in seg_usable[target]) \
                    and not {"there", "it", "its", "inside", "theres"} & set(norms[a:b]) \
                    and {"we", "weve", "i", "ive", "us", "our", "my", "me"} & set(norms[max(0, a - 3):b]):
                target = None  # "is anyone at the cottage hospital? we've got walking wounded": asked about, not told of
            if target is not None:
                denied_at = {bound[c.start_tok].start_tok for c in cues if c.polarity == "denied" and c.start_tok in bound}
                told = seg_usable[target]
                inside = any(norms[i:i + 2] in (("in", "there"), ("in", "it")) for i in range(a, b))
                if inside and len(told) > 1 and not any(
                        norms[i] in lx.COORDINATORS or norms[i] == "or" or toks.clause_start[i]
                        for i in range(min(q.end_tok for q in told), max(q.start_tok for q in told))):
                    # "The steeple has collapsed into the minster ... a verger is trapped under the rubble in there":
                    # the place the first one fell into
                    told = [max(told, key=lambda q: q.start_tok)]
                first_word = next((w for w in norms[a:b] if w not in lx.FILLERS), "")
                if target > k and len(told) > 1 and norms[segs[target][0]] in ("in", "at", "inside"):
                    told = [min(told, key=lambda q: q.start_tok)]  # ("... In the stream that's fed by the overflow off
                    # the top water": the place the fragment opens on)
                told = told + self._list_opening(toks, norms, segs, target, seg_usable, seg_cues, told)
                if first_word in ("which", "where") and len(told) > 1 and target == k - 1:
                    # "the caravan park's been evacuated up to the quarry car park, which is safe ground": the
                    # relative clause is said of the place right before it
                    told = [max(told, key=lambda q: q.start_tok)]
                for q in told:
                    if len(seg_usable[target]) > 1 and self._origin(norms, q):
                        continue
                    if len(told) > 1 and _moved_from(norms, q, told):
                        continue  # "walked all sixty of us from the hotel over to the town park and told us that's
                        # the assembly point": said of where they were taken, not where they came from
                    if q.start_tok in denied_at and any(r.start_tok not in denied_at and r.status == "active"
                                                        for r in seg_usable[target]):
                        continue  # "the tool shop's not on fire it's the mechanics ... and there's a guy under a car in
                        # there": the place just denied is not the one talked about
                    fq = forward(q)
                    if fq is not None:
                        pairs.extend(Claim(fq, c) for c in cs)
                        if fq.start_tok not in claimed_places and target < k:
                            floated.add(fq.start_tok)
                        claimed_places.add(fq.start_tok)

        # 2b/4. places without a cue: inherit from the place they replaced, else borrow from a list
        for p in sorted(active, key=lambda p: p.start_tok):
            n = sentence_of[p.start_tok]
            lead = [w for i, w in enumerate(norms[:p.start_tok]) if sentence_of[i] == n
                    and w not in lx.FILLERS and w not in lx.DETERMINERS]
            if n > 0 and lead in (["same", "for"], ["same", "with"], ["same", "goes", "for"], ["and", "same", "for"]):
                # "Ma Baxter's is taking in families, ... Same for St Bartholomew's": what the sentence before says
                said = {c.cue.category: c.cue for c in pairs if sentence_of[c.place.start_tok] == n - 1
                        and c.cue.polarity == "affirmed" and c.place.landmark != p.landmark}
                pairs.extend(Claim(p, c) for c in said.values())
                claimed_places.add(p.start_tok)
                continue
            if p.start_tok in floated:
                # "water coming in at the school and at the terrace across the lane from it, and the old lady at the
                # far end of that terrace needs lifting out": a later sentence's word, and the list's as well
                np0 = _noun_phrase_start(norms, p)
                prior = next((r for r in active if np0 >= 3 and r.end_tok == np0 - 2 and norms[np0 - 2] == "and"
                              and norms[np0 - 1] in lx.PREPOSITIONS
                              and norms[_noun_phrase_start(norms, r) - 1:_noun_phrase_start(norms, r)] == (norms[np0 - 1],)),
                             None)
                if prior is not None:
                    pairs.extend(Claim(p, c.cue) for c in list(pairs) if c.place is prior and c.cue.polarity == "affirmed")
            if p.start_tok in claimed_places:
                continue
            if _moved_from(norms, p, [r for r in active if seg_index[r.start_tok] == seg_index[p.start_tok]]):
                continue  # "walked all sixty of us from the hotel over to the town park": where they came from
            n = sentence_of[p.start_tok]
            if any(c.status == "retracted" and c.reason.startswith("withdrawn")
                   and p.end_tok <= c.start_tok <= p.end_tok + 3 and sentence_of[c.start_tok] == n for c in cues):
                continue  # "... and the helipad's usable... Scratch that last bit": its own word was taken back
            rest = [w for i, w in enumerate(norms) if sentence_of[i] == n and not p.start_tok <= i < p.end_tok
                    and (w not in lx.FILLERS or w == "well") and w not in lx.DETERMINERS]
            if rest in (["too"], ["also"], ["as", "well"], ["aswell"], ["and", "all"], ["all"]) and n > 0:
                # "Caravan park evacuated and checked, it's safe. Chapel too.": the sentence before, said of it
                said = {c.cue.category: c.cue for c in pairs if sentence_of[c.place.start_tok] == n - 1
                        and c.cue.polarity == "affirmed"}
                pairs.extend(Claim(p, c) for c in said.values())
                claimed_places.add(p.start_tok)
                continue
            first = next((q for q in ex.places if q.landmark == p.landmark and q.reason.startswith("restarted")
                          and 0 <= p.start_tok - q.end_tok <= 4), p)  # ("the grocer's too, the grocery store")
            before = [w for w in norms[max(0, first.start_tok - 4):first.start_tok] if w not in lx.DETERMINERS | lx.FILLERS]
            after = [w for w in norms[first.end_tok:first.end_tok + 3] if w not in lx.FILLERS]
            also = before[-2:] in (["as", "can"], ["as", "is"], ["as", "does"], ["as", "has"], ["as", "are"],
                                   ["as", "will"]) or before[-1:] == ["and"] and (
                after[:1] == ["too"] or after[:2] == ["as", "well"])
            if not also and before[-1:] == ["and"]:
                # "... is full of smoke, and the place that kitchen sends the feeds over to is starting to fill up as
                # well": a clause that says only that the same goes for it
                e = p.end_tok
                while e < len(norms) and not toks.clause_start[e] and e - p.end_tok < 8:
                    e += 1
                told = [w for w in norms[p.end_tok:e] if w not in lx.FILLERS or w == "well"]
                also = 2 <= len(told) <= 7 and told[0] in ("is", "s", "are", "has", "was") \
                    and (told[-2:] == ["as", "well"] or told[-1:] == ["too"]) \
                    and not any(c.start_tok in range(p.end_tok, e) for c in cues)
            if also:
                # "City hall has been secured and can take evacuees, as can the post office"; "the police post is
                # being used for shelter and um the grocer's too": what the place before it in the sentence has
                prior = [c for c in pairs if c.place.end_tok <= p.start_tok and sentence_of[c.place.start_tok] == n
                         and c.cue.polarity == "affirmed" and c.place.landmark != p.landmark]
                if prior:
                    last = max(c.place.end_tok for c in prior)
                    pairs.extend(Claim(p, c.cue) for c in prior if c.place.end_tok == last)
                    claimed_places.add(p.start_tok)
                    continue
            k = seg_index[p.start_tok]
            if seg_cues.get(k) and len(seg_places.get(k, [])) == 1 and not any(
                    q.status != "active" for q in seg_usable.get(k, [])):
                pairs.extend(Claim(p, c) for c in seg_cues[k])
                continue
            if any(q.landmark == p.landmark and q.status == "retracted" and q.start_tok < p.start_tok
                   and not q.reason.startswith(("restarted", "false start")) for q in ex.places) and p.replaces is None:
                continue  # "that should be the town hall, the library's shut": no claim revives the library
            # "the lodge and the car park, the first one's got smoke": a list member borrows nothing said
            # after an ordinal names one of the list
            beside = next((q for q in active if p.replaces is None and q.anaphor is None and p.anaphor is None
                           and not q.also and q.landmark == p.landmark and q is not p and q.start_tok in claimed_places
                           and (seg_index[q.start_tok] == k
                                or 0 <= q.start_tok - p.end_tok <= 3 and not any(
                                    norms[i] in lx.COORDINATORS for i in range(p.end_tok, q.start_tok)))), None)
            if beside is not None:
                # "across from there, the block of flats, ... it's clear", "two of the mechanics are hurt in the
                # garage": the place is said again beside it, with its own word, which is this one's too
                got = [c.cue for c in pairs if c.place is beside]
                if seg_index[beside.start_tok] == k:
                    got += [c for c in seg_cues.get(k, []) if all(c is not g for g in got)]
                pairs.extend(Claim(p, c) for c in got)
                claimed_places.add(p.start_tok)
                continue
            mate = self._restated_list_mate(ex, norms, p, active, pairs)
            if mate:
                # "people hurt at the library, the school, and, hold that, not the school, just the library and the
                # post office": a list said again after a repair; the new member has what the old one has
                pairs.extend(Claim(p, c) for c in mate)
                claimed_places.add(p.start_tok)
                continue
            counted = len(norms) if p.counted_by is None else p.counted_by
            listed = self._list_share(ex, norms, p, pairs)
            if listed:
                # "casualties at the school, the church and the bank — no, not the bank, the town hall":
                # the replacement takes the retracted list item's share of the list's claims
                pairs.extend(Claim(p, c) for c in listed if c.start_tok < counted)
                claimed_places.add(p.start_tok)
                continue
            if self._origin(norms, p):
                continue
            if _nobody_said(norms, p.start_tok - 4, p.start_tok):
                continue  # "there's nobody in the queue line": said of its people, and none there
            if any(q.landmark == p.landmark and q.start_tok > p.start_tok and q.status == "active"
                   and sentence_of[q.start_tok] == sentence_of[p.start_tok]
                   and _nobody_said(norms, q.start_tok - 4, q.start_tok) for q in ex.places):
                continue  # "the rookery isn't— there's nobody at the rookery": broken off, then said of its people
            if self._speaker_at(norms, p) and any(q.landmark == p.landmark and q.start_tok > p.start_tok
                                                  and q.status == "active" for q in ex.places):
                continue  # "im outside the school the school yard is the assembly point ...": where the caller stands
            tail = [w for w in norms[p.end_tok:segs[k][1]] if w not in lx.FILLERS]
            if tail in (["is"], ["s"], ["was"], ["are"]):  # ("the lifeguard hut is... standing": past the pause)
                tail = [w for w in norms[p.end_tok:min(len(norms), segs[k][1] + 1)] if w not in lx.FILLERS]
            own = tail[1:] if tail[:1] in (["itself"], ["themselve"]) else tail  # ("the weir itself is holding")
            if (own[:1] in (["dry"], ["untouched"], ["unaffected"], ["solid"], ["holding"], ["standing"]) or own[:2] in (
                    ["is", "dry"], ["s", "dry"], ["still", "dry"], ["is", "solid"], ["s", "solid"], ["still", "solid"],
                    ["is", "standing"], ["s", "standing"], ["still", "standing"], ["is", "holding"], ["s", "holding"],
                    ["still", "holding"], ["are", "holding"])) \
                    and len(seg_places.get(k, [])) == 1:
                continue  # "the gift shop, that's where the water's coming in... the tea room's dry": its own word
            if tail[:1] and tail[0] in ("evacuated", "evacuating", "closed", "shut", "locked") and len(tail) <= 2 \
                    and len(seg_places.get(k, [])) == 1:
                continue  # "hotel evacuated, they're all at the town hall now which is safe": a word of its own
            if tail[:1] == ["empty"] and len(seg_places.get(k, [])) == 1:
                continue  # "the gas cage is on fire, reception's empty, we checked it": said of it, its own
            nxt_words = [w for w in norms[segs[k][1]:min(len(norms), segs[k][1] + 8)] if w not in lx.FILLERS]
            if not tail and nxt_words[:1] in (["i"], ["we"]) and nxt_words[1:2] and nxt_words[1] in (
                    "walked", "drove", "went", "passed", "cycled", "checked", "looked", "saw", "been"):
                continue  # "and er zion, I walked past zion, it's all locked up": a clause of the speaker's own
            unsure = tail[-4:] + nxt_words[:4]
            if "dunno" in unsure or any(unsure[m:m + 2] in (["dont", "know"], ["not", "sure"], ["havent", "been"],
                                                             ["no", "idea"], ["cant", "say"])
                                        for m in range(len(unsure) - 1)):
                continue  # "and er the market outside it, uh, I dunno, I haven't been out there": nothing said of it
            if tail in ([], ["itself"], ["themselve"]) and (nxt_words[:2] in (["no", "problem"], ["nothing", "wrong"])
                                                            or nxt_words[:1] in (["fine"], ["unaffected"], ["untouched"])):
                continue  # "the huts themselves, no problem there, they're dry": a word of its own, no danger
            if [w for w in tail if w not in ("itself", "themselve")][:2] in (["isnt", "touched"], ["not", "touched"],
                                                                              ["untouched"], ["unaffected"]):
                continue  # "the siding itself isn't touched": said to be spared, no danger borrowed
            np0 = _noun_phrase_start(norms, p)
            if np0 >= 1 and norms[np0 - 1] == "with" and len(tail) >= 3 and tail[0].endswith("ing") and len(tail[0]) >= 5:
                continue  # "the splash is impassable with the beck running a metre over the stepping stones, and the
                # bethel is safe": an absolute clause, the beck's own predicate
            if "still" in tail[:3] and len(seg_places.get(k, [])) == 1 \
                    and {"running", "working", "chugging", "pumping", "operating", "turning"} & set(tail + nxt_words[:5]):
                continue  # "the crowtree pumps have tripped out ... and old thumper's still chugging away": working
            if set(tail[:2]) & lx.FINE_WORDS and len(seg_places.get(k, [])) == 1 \
                    and nxt_words[:2] in (["its", "the"], ["it", "is"]):
                continue  # "the bridge is fine, it's the acoustic barn where the water's coming in": the contrast
            if len(tail) >= 3 and set(tail[:3]) & {"got", "has", "have", "is", "was", "are", "had"} \
                    and len(seg_places.get(k, [])) == 1 and not {"too", "also", "well", "same"} & set(tail):
                continue  # "the hotel's got the gas leak, the bank's just got its alarm ringing": a predicate of its own
            if tail[1 if tail[:1] in (["is"], ["s"], ["was"], ["are"], ["re"]) else 0:] in (
                    ["full"], ["packed"], ["rammed"], ["closed"], ["shut"], ["full", "up"], ["locked"]) \
                    and len(seg_places.get(k, [])) == 1:
                continue  # "The clinic's full, uh, so the building next to the clinic is now our second aid station":
                # a state of its own, the reason for the other place
            if len(tail) >= 3 and set(tail[:4]) & {"went", "stopped", "tripped", "failed", "died", "cut"} \
                    and tail[0] in ("lights", "light", "power", "electric", "electrics", "alarm", "alarms", "radio", "phone",
                                    "phones", "pump", "pumps", "engine", "generator") \
                    and len(seg_places.get(k, [])) == 1 and not {"too", "also", "well", "same"} & set(tail):
                continue  # "smoke coming off the genny ... and the tower lights just went out": what failed there
            if self._addressed_list(norms, segs, k, seg_places):
                self._non_report_tokens.add(p.start_tok)  # (nor a claim guessed for it)
                continue  # "Passengers in the waiting cabin, the cafe and the car park, please make your way to the
                # pilots' lodge": where the people told to move are, nothing said of them
            done_to = [w for w in norms[max(0, np0 - 4):np0] if w not in lx.FILLERS]
            if len(done_to) >= 2 and done_to[-1] in lx.CREW_ACTION_VERBS \
                    and done_to[-2] in ("we", "weve", "ive", "i", "theyve", "they", "have", "ve"):
                continue  # "the engine's on fire and we've shut the gallopers down": what the crew did to it, no claim
            donor = self._donor_for_places(k, segs, seg_places, seg_cues, sentence_of, hollow | counting,
                                           [self._opening(norms, a, b) for a, b in segs],
                                           [norms[a:b] for a, b in segs])
            if donor is not None and any(q.landmark == p.landmark and q.start_tok >= p.start_tok
                                         and sentence_of[q.start_tok] == sentence_of[p.start_tok]
                                         and (set(norms[q.end_tok:q.end_tok + 2]) & lx.FINE_WORDS
                                              and {"its", "thats"} & set(norms[q.end_tok + 1:q.end_tok + 5])
                                              or any(norms[m] in ("fine", "okay", "ok", "alright") and norms[m - 1] in (
                                                  "its", "thats") and "no" in norms[q.end_tok:m - 1]
                                                  for m in range(q.end_tok + 1, min(len(norms), q.end_tok + 5))))
                                         for q in ex.places):
                continue  # "the snake is -- nah nah the snake's ok -- its the adventure thats flooded"
            if donor is not None and donor != k and any(
                    _anchored_at(q, p.landmark) and not any(r.landmark == p.landmark and q.start_tok <= r.start_tok < q.end_tok
                                                            for r in ex.places) for q in seg_places.get(donor, [])):
                continue  # "following the brook down from the ford - the field it runs along the bottom of has gone
                # under": the brook is the "it" of the place described there, not said to be under
            np0 = _noun_phrase_start(norms, p)
            if donor is not None and donor != k and np0 >= 2 and norms[np0 - 1] in ("onto", "into", "over", "across") \
                    and any(c.end_tok == np0 - 1 and c.category != self._person_category for c in cues):
                continue  # "..., and the pool its gate opens into is overflowing onto the path": where the danger
                # spills, not a place the sentence before says anything of
            if donor is not None and tail[:1] and tail[0] in (lx.COPULAS | {"looks", "seems", "has", "got"}) - _ADDING \
                    and any(_anchored_at(q, p.landmark) for q in seg_places.get(donor, [])):
                continue  # "the library is quiet but the hall next to it is burning": its own word, then the anchor
            if donor is not None and next((w for w in norms[segs[donor][0]:segs[donor][1]] if w not in lx.FILLERS), "") \
                    in ("which", "where") and any(p.end_tok <= q.start_tok < segs[donor][0] for q in active):
                continue  # "..., evacuated up to the quarry car park, which is safe ground": said of the place before it
            left_open = [w for w in norms[segs[donor][0]:segs[donor][1]] if w not in lx.FILLERS][-1:] \
                if donor is not None else []
            if donor is not None and donor > k and left_open and left_open[0] in lx.PREPOSITIONS | lx.DETERMINERS and any(
                    q.status == "retracted" and q.reason.startswith("self-repair") and q.start_tok >= segs[donor][1]
                    and q.start_tok - segs[donor][1] <= 4 and "and" not in norms[segs[donor][1]:q.start_tok]
                    and sentence_of[q.start_tok] == sentence_of[segs[donor][0]] for q in ex.places):
                continue  # "this is Jean at the co-op, we've got ammonia in the, in the cave two — no, sorry, cave
                # one": the cue's clause breaks off before its own place, then repaired; the place before lends nothing
            if donor is not None and donor in broken_off:
                continue  # (nor the cue whose own place broke off and was repaired: "this is Ana at the packing shed,
                # we got a fire in the box-- no wait, in the generator shed")
            if donor is not None and donor > k and self._speaker_here(norms, p) and any(
                    q.status == "active" and q.landmark != p.landmark and p.end_tok <= q.start_tok < segs[donor][0]
                    for q in ex.places):
                continue  # "this is Maria from the mill houses my son he fell off the water tank, he's hurt bad":
                # where the caller is; another place is named before the cue
            if donor is not None:
                for c in seg_cues[donor]:
                    if c.start_tok >= counted:
                        continue
                    if c.polarity == "affirmed" and any(
                            q.place.landmark == p.landmark and q.cue.category == c.category and q.cue.polarity == "denied"
                           and q.cue.start_tok < p.start_tok for q in pairs):
                        continue  # "says the chippy is on fire but i can see the chippy and it's not": denied, not lent
                    if c.polarity == "denied" and any(q.landmark == p.landmark for q in seg_places.get(donor, [])):
                        pass  # "the warehouse is secure and the — strike that, the warehouse isn't secure": the same
                        # place said again, denied, lends its denial, no contrast
                    elif c.polarity == "denied" and c.reason.lower().startswith((
                            "negated by 'not'", "negated by 'n't'", "negated by 'isn't'", "negated by 's not'",
                            "negated by 'nt'", "negated by 'but it isn't'")):
                        # "the station is not flooded, the clinic is": the contrast takes the claim
                        c = replace(c, polarity="affirmed", reason="contrast with a negated claim")
                    pairs.append(Claim(p, c))
        pairs.extend(self._speaker_claims(ex, norms, cues, pairs))
        pairs.extend(self._last_seen_claims(ex, norms, cues, pairs))
        pairs.extend(self._so_is_claims(ex, norms, pairs))
        pairs.extend(self._shared_by_list(ex, norms, pairs))
        pairs = self._counted_ones(ex, norms, pairs)
        # (a list member denied after "both of them" was read is no member: "at the bull ring sorry not the bull ring
        # the bus station both of them at the bus station"; but "no wait, both are" takes a repair back)
        gone = {p.landmark for p in ex.places if p.status == "negated"} \
            - {p.landmark for p in ex.places if p.status == "active" and not p.anaphor}
        pairs = self._distribute(pairs, gone)
        # "Two possible shelters: the church and the cafe. The former's roof is unsafe": what the list was
        # introduced as gives way to what its members are then said to be, one by one, where the two disagree
        # (a safe place against a danger); "Smoke at the bank and the hotel. The first one also has a man
        # trapped" adds to the list's claim
        desirable = {c.place.landmark: self.kb.category_by_name[c.cue.category].role == Role.DESIRABLE
                     for c in pairs if c.place.anaphor and c.cue.polarity == "affirmed"}
        pairs = [c for c in pairs if not (c.place.counted_by is not None and c.place.landmark in desirable
                                          and desirable[c.place.landmark]
                                          != (self.kb.category_by_name[c.cue.category].role == Role.DESIRABLE))]
        claims = [c for c in pairs if c.cue.polarity == "affirmed"]
        held = {c.key for c in claims}
        denied = [c for c in pairs if c.cue.polarity == "denied"
                  and not (c.cue.reason == NEITHER and c.key in held)]
        # the last word on a place and category stands: "the gas at the wash house ... the gas men
        # capped the pipe" revokes the first mention, "no fire at the bank -- wait, there is" restores it
        last: dict[tuple[str, str], tuple[int, bool]] = {}
        for c in sorted(pairs, key=lambda c: c.cue.start_tok):
            if c.cue.polarity == "denied" and (c.cue.reason.lower().startswith(lx.ABILITY_NEGATIONS)
                                               or c.cue.reason == NEITHER):
                continue  # "she can't get past the smoke on the stairs" revokes nothing, nor does "the first has a
                # chemical spill ... neither of them has a fire"
            if c.cue.polarity == "denied" and any(
                    q.key == c.key and q.cue.polarity == "affirmed" and 0 <= c.cue.start_tok - q.cue.end_tok <= 1
                    and norms[q.cue.start_tok:q.cue.end_tok] != norms[c.cue.start_tok:c.cue.end_tok] for q in pairs):
                continue  # "well, smoke, no flames really": a kind denied right after the kind there is
            if c.cue.polarity == "denied" and c.cue.reason == "negated by 'no'" \
                    and _not_seen_yet(norms, c.cue.end_tok) and any(
                    q.key == c.key and q.cue.polarity == "affirmed" and q.cue.end_tok <= c.cue.start_tok
                    and toks.sentence_of[q.cue.start_tok] == toks.sentence_of[c.cue.start_tok]
                    and norms[q.cue.start_tok:q.cue.end_tok] != norms[c.cue.start_tok:c.cue.end_tok] for q in pairs):
                continue  # "a hot spot on the roof of the valve hut, no flames visible yet": the worse kind not seen yet
            if c.cue.polarity == "denied" and c.cue.reason == _CLEARED_AFTER_BUT:
                continue  # "the school is the rest centre, it had a bit of smoke earlier but that's cleared now": the
                # word says the danger has gone; it takes no safety back
            if c.cue.polarity == "denied" and c.cue.reason in _MADE_SAFE and (
                    kind := self._danger_kind_by_words.get(norm_phrase(c.cue.text))) is not None and any(
                    q.key == c.key and q.cue.polarity == "affirmed" and q.cue.start_tok < c.cue.start_tok
                    and self._danger_kind_by_words.get(norm_phrase(q.cue.text)) not in (None, kind) for q in pairs):
                continue  # "Fat fire in the kitchen of the cafe, gas is isolated": the gas made safe, the fire stands
            last[c.key] = (c.cue.start_tok, c.cue.polarity == "affirmed")
        for landmark, at in self._people_revoked(ex, norms, cues):
            # "1012 STILT VLG - 3 stranded on rf. 1014 UPD STILT VLG - all 3 lifted off": no cue is said
            # again, but the people at the place are out
            for key, (pos, _) in list(last.items()):
                if key[0] == landmark and pos < at \
                        and self.kb.category_by_name[key[1]].role == Role.CRITICAL:
                    last[key] = (at, False)
        for landmark, at in self._places_put_out(ex, norms):
            # "Item two, fire at the bakery. Er, update just in: the bakery one's out": the place's danger is over
            for key, (pos, _) in list(last.items()):
                if key[0] == landmark and pos < at \
                        and self.kb.category_by_name[key[1]].role == Role.UNDESIRABLE:
                    last[key] = (at, False)
        for landmark, at, cats in self._places_negated_later(ex, cues):
            # "Fire at the school. ... No, that's not the school, that's the library": a place negated in a
            # later sentence takes back what was said of it before, in the negating sentence's categories
            for key, (pos, _) in list(last.items()):
                if key[0] == landmark and pos < at and (not cats or key[1] in cats):
                    last[key] = (at, False)
        revoked = {k for k, (_, affirmed) in last.items() if not affirmed}
        denied.extend(c for c in claims if c.key in revoked)
        claims = [c for c in claims if c.key not in revoked]
        return claims, denied

    @staticmethod
    def _distribute(pairs: list[Claim], gone: Collection[str] = frozenset()) -> list[Claim]:
        """"the gym and the park ... both of them are flooded": a claim on "both of them" is a claim on every
        place of the list; "Neither of them has anyone hurt" denies it of every one."""
        out: list[Claim] = []
        for c in pairs:
            if c.place.anaphor == "neither" and c.cue.polarity == "affirmed":
                c = Claim(c.place, replace(c.cue, polarity="denied", reason=NEITHER))
            out.append(c)
            out.extend(Claim(replace(c.place, landmark=other, also=()), c.cue) for other in c.place.also
                       if other not in gone)
        return out

    @staticmethod
    def _places_negated_later(ex: Extraction, cues: list[CueMention]) -> list[tuple[str, int, set[str]]]:
        """(landmark, token, categories) for each place negated after an earlier sentence named it: "Scratch my
        last, wasn't the bank", "Correction: casualty is in the bank, not the hotel". The categories are
        those the negating sentence affirms (the hotel loses its casualty, not a fire said of it), or
        every category where it affirms none."""
        sentence_of = ex.tokens.sentence_of
        out: list[tuple[str, int, set[str]]] = []
        for p in ex.places:
            if p.status != "negated" or not p.reason.startswith("negated by"):
                continue
            n = sentence_of[p.start_tok]
            if not any(q.landmark == p.landmark and sentence_of[q.start_tok] < n and q.status == "active"
                       for q in ex.places):
                continue
            cats = {c.category for c in cues if sentence_of[c.start_tok] == n and c.polarity == "affirmed"
                    and c.status == "active"}
            out.append((p.landmark, p.start_tok, cats))
        return out

    @staticmethod
    def _shared_by_list(ex: Extraction, norms: tuple[str, ...], pairs: list[Claim]) -> list[Claim]:
        """"the medical centre and the welfare tent are both dry, powered and open for shelter": what is said of
        the last place of a list after "are both" / "are all" is said of every place of the list."""
        toks = ex.tokens
        places = sorted((p for p in ex.places if p.status == "active"), key=lambda p: p.start_tok)
        claimed = {id(c.place) for c in pairs}
        have = {(id(c.place), id(c.cue)) for c in pairs}
        out: list[Claim] = []
        def past_part(j: int) -> int:  # ("the Navvy's function room": a room of the place, said after its name)
            start = j
            while j < len(norms) and norms[j] in lx.ROOM_WORDS and j - start < 2 and not toks.clause_start[j]:
                j += 1
            return j
        for idx, last in enumerate(places):
            e = past_part(last.end_tok)
            if norms[e:e + 2] not in (("are", "both"), ("are", "all"), ("were", "both"), ("were", "all"),
                                      ("re", "both"), ("re", "all")) \
                    and not (norms[e:e + 1] == ("both",) and not toks.clause_start[e]):
                continue  # (and "we checked the post office and the fire hall both clear")
            listed = [last]
            k = idx - 1
            while k >= 0:
                gap = norms[past_part(places[k].end_tok):listed[0].start_tok]
                if not set(gap) <= {"and", "the", "a", "an"} or not gap and toks.gaps[listed[0].start_tok].strip() != "," \
                        or id(places[k]) in claimed or any(";" in toks.gaps[i] or toks.sentence_start[i]
                                                           for i in range(places[k].end_tok, listed[0].start_tok + 1)):
                    break  # (not "heavy smoke at the coffee house, the hotel and the square are all clear")
                listed.insert(0, places[k])
                k -= 1
            if len(listed) < 2 or "and" not in norms[listed[-2].end_tok:last.start_tok]:
                continue
            said = [c for c in pairs if c.place is last and c.cue.start_tok >= e
                    and toks.sentence_of[c.cue.start_tok] == toks.sentence_of[e]
                    and not any(";" in toks.gaps[i] for i in range(e, c.cue.start_tok + 1))]
            out.extend(Claim(p, c.cue) for p in listed[:-1] for c in said if (id(p), id(c.cue)) not in have)
        return out

    @staticmethod
    def _so_is_claims(ex: Extraction, norms: tuple[str, ...], pairs: list[Claim]) -> list[Claim]:
        """"the building ... is open as a muster point, and so is — um — the hall itself", "... and the dripstone
        one too": what was said of the place before is said of this one too."""
        toks = ex.tokens
        out: list[Claim] = []
        for p in ex.places:
            if p.status != "active":
                continue
            j = p.start_tok
            while j > 0 and (norms[j - 1] in lx.FILLERS or norms[j - 1] in lx.ARTICLES) and p.start_tok - j < 5:
                j -= 1
            so_is = j >= 3 and norms[j - 2] == "so" and norms[j - 1] in ("is", "are", "was", "were") and norms[j - 3] == "and"
            # "... water's backing up in there. Oh — and the dripstone one too": the same news of another place
            too = j >= 1 and norms[j - 1] == "and" and norms[p.end_tok:p.end_tok + 1] == ("too",) \
                and not any(c.place.landmark == p.landmark for c in pairs)
            # "Chapel's open as an assembly point, ... . The school is the same": the same news of another place
            e = p.end_tok + (norms[p.end_tok:p.end_tok + 1] in (("is",), ("s",), ("was",)))
            same = (e > p.end_tok or toks.tokens[p.end_tok - 1].text.lower().endswith(("'s", "’s"))) \
                and norms[e:e + 2] == ("the", "same") and toks.sentence_start[j] \
                and (e + 2 >= len(norms) or toks.clause_start[e + 2]) \
                and not any(c.place.landmark == p.landmark for c in pairs)
            # "the deck's smoke logged, ... and the slope it looks out over is just as bad": the same danger again
            e2 = p.end_tok + (norms[p.end_tok:p.end_tok + 1] in (("is",), ("s",), ("was",), ("are",), ("were",)))
            m = e2 + (norms[e2:e2 + 1] in (("just",), ("about",), ("nearly",), ("almost",)))
            every_bit = norms[m:m + 4] == ("every", "bit", "as", "bad")  # (said out, no end to wait for)
            as_bad = e2 > p.end_tok and (every_bit or norms[m:m + 2] in (("as", "bad"), ("no", "better")) and (
                m + 2 >= len(norms) or norms[m + 2] == "too" or toks.clause_start[m + 2])) \
                and (toks.clause_start[j] or norms[j - 1:j] == ("and",)) \
                and not any(c.place.landmark == p.landmark for c in pairs)
            too = too or same or as_bad
            if not (so_is or too):
                continue
            n = toks.sentence_of[p.start_tok]
            k = j - 3 if so_is else j if same or as_bad else j - 1
            said_in = (n,) if so_is else (n, n - 1)  # ("too" reaches the sentence before)
            before = [c for c in pairs if c.place.end_tok <= k and c.place.landmark != p.landmark
                      and toks.sentence_of[c.place.start_tok] in said_in and c.cue.start_tok < k]
            if not before:
                continue
            last = max(c.place.start_tok for c in before)
            out.extend(Claim(p, c.cue) for c in before if c.place.start_tok == last
                       and not any(q.place.landmark == p.landmark and q.cue.category == c.cue.category for q in pairs))
        return out

    def _last_seen_claims(self, ex: Extraction, norms: tuple[str, ...], cues: list[CueMention],
                          pairs: list[Claim]) -> list[Claim]:
        """"Lost camper: little girl, ... last seen playing on the marram hills": a person cue bound to no place,
        and the one place where the missing were last seen."""
        bound = {id(c.cue) for c in pairs}
        toks = ex.tokens
        loose = [c for c in cues if id(c) not in bound and c.status == "active" and c.polarity == "affirmed"
                 and self.kb.category_by_name[c.category].role == Role.CRITICAL]
        seen = [p for p in ex.places if p.status == "active" and any(
            norms[k:k + 2] == ("last", "seen") and toks.sentence_of[k] == toks.sentence_of[p.start_tok]
            for k in range(max(0, p.start_tok - 6), p.start_tok))]
        if not loose or len({p.landmark for p in seen}) != 1:
            return []
        return [Claim(seen[0], loose[0])]

    def _speaker_claims(self, ex: Extraction, norms: tuple[str, ...], cues: list[CueMention],
                        pairs: list[Claim]) -> list[Claim]:
        """"I can't get down, the cab's filling with smoke, I'm in crane, the STS cranes": a person cue the
        speaker says of themselves, bound to no place, is claimed of the one place the speaker says they are."""
        bound = {id(c.cue) for c in pairs}
        toks = ex.tokens
        mine = [c for c in cues if id(c) not in bound and c.status == "active" and c.polarity == "affirmed"
                and (self.kb.category_by_name[c.category].role == Role.CRITICAL
                     and any(norms[i] in ("i", "im", "we", "were", "me") for i in range(max(0, c.start_tok - 3), c.start_tok)
                             if toks.sentence_of[i] == toks.sentence_of[c.start_tok])
                     or self.kb.category_by_name[c.category].role == Role.DESIRABLE
                     and any(norms[i] in ("we", "were", "weve", "us", "our") for i in range(max(0, c.start_tok - 8), c.start_tok)
                             if toks.sentence_of[i] == toks.sentence_of[c.start_tok]))]
        # ("This is the caretaker at Fenside School. ... We're running it as a warm room": the speaker's own place)
        if not mine:
            return []
        def said_at(p: PlaceMention) -> bool:  # "I'm in crane, the, the STS cranes": a few words after "I'm in"
            if self._speaker_at(norms, p) or self._speaker_here(norms, p):
                return True
            for j in range(max(1, p.start_tok - 6), p.start_tok):
                if norms[j] in ("in", "at", "on", "inside") and norms[j - 1] in ("im", "were") \
                        and toks.sentence_of[j] == toks.sentence_of[p.start_tok] \
                        and not any(q.start_tok in range(j, p.start_tok) for q in ex.places):
                    return True
            return False
        at = {p.landmark: p for p in ex.places if p.status == "active" and said_at(p)}
        if len(at) != 1:
            return []
        place = next(iter(at.values()))
        return [Claim(place, c) for c in mine]

    def _undesirable_says(self, pattern: str) -> bool:
        """Does an undesirable category's description match ``pattern`` (a regular expression, lower case)? Cached."""
        cache = self.__dict__.setdefault("_undesirable_says_cache", {})
        if pattern not in cache:
            cache[pattern] = any(re.search(pattern, c.description.lower())
                                 for c in self.kb.categories_with_role(Role.UNDESIRABLE))
        return cache[pattern]

    def _lock_category(self) -> bool:
        """Does an undesirable category's description speak of places locked or jammed shut?"""
        return self._undesirable_says(r"\b(lock|locks|locked|lockdown|jammed)\b")  # (not "blocked")

    def _access_category(self) -> bool:
        """Does an undesirable category's description speak of places that cannot be entered or got through?"""
        # (not "closed": "bridges the flood has damaged or closed")
        return self._undesirable_says(
            "lock|blocked|access|impassable|cannot be entered|got through|cannot be passed|jammed")

    def _places_put_out(self, ex: Extraction, norms: tuple[str, ...]) -> list[tuple[str, int]]:
        """(landmark, token) for each "<place> (one)'s out" clause ("the bakery one's out", "garage is out now") and
        each place a danger has "not reached yet"."""
        toks = ex.tokens
        out = []
        for p in ex.places:
            if p.status != "active":
                continue
            j = p.end_tok
            while j < len(norms) and j - p.end_tok < 4 and not toks.clause_start[j] \
                    and norms[j] in ("one", "s", "is", "are", "was", "been", "put", "now", "all", "fire"):
                j += 1
            if j < len(norms) and norms[j] == "out" and j > p.end_tok and not toks.clause_start[j] \
                    and (j + 1 >= len(norms) or toks.clause_start[j + 1] or norms[j + 1] in ("now", "completely")):
                out.append((p.landmark, j))
                continue
            # "fires at the garage, the warehouse and the supermarket, er, the warehouse, oh, they've put that out
            # now": the place said again, then its danger put out
            # ("they said the hotel's on fire as well but that was an hour ago and the brigade have put it out":
            # further on in the sentence, once the put-out is done, not planned)
            k = p.end_tok
            while k < len(norms) and (k - p.end_tok < 8 or k - p.end_tok < 18 and toks.sentence_of[k] == toks.sentence_of[p.start_tok]) \
                    and not any(q.start_tok == k for q in ex.places if q is not p):
                h = self._cancel.match_at(norms, k)
                if h is not None and h[1] in lx.CANCEL_SAID_AGAIN and norms[k - 1] not in lx.PLAN_WORDS and (
                        k - p.end_tok < 8 or norms[k - 1] in ("have", "ve", "has", "had", "already", "now", "just")):
                    out.append((p.landmark, k))
                    break
                k += 1
            # "it's drifting off toward the tug pen but, but it's not there yet": heading there, not there
            ahead = norms[p.end_tok:min(len(norms), p.end_tok + 10)]
            for n in range(len(ahead) - 2):
                if ahead[n:n + 3] == ("not", "there", "yet") or ahead[n:n + 2] in (("hasnt", "reached"),
                                                                                   ("not", "reached")):
                    r = p.end_tok + n + 2
                    while r < len(norms) and norms[r] in lx.DETERMINERS:
                        r += 1
                    if ahead[n + 1] == "reached" and any(q.start_tok == r for q in ex.places):
                        break  # "fire on the embankment, it hasn't reached the allotments yet": those not reached
                    out.append((p.landmark, p.end_tok + n))
                    break
        return out

    def _people_revoked(self, ex: Extraction, norms: tuple[str, ...], cues: list[CueMention]) -> list[tuple[str, int]]:
        """(landmark, token) for each phrase that says the people of a place are out ("all 3 lifted off",
        "everyone rescued") with no cue of its own: the place named last before it in its sentence."""
        toks = ex.tokens
        cue_ends = {c.end_tok for c in cues}
        out = []
        for i in range(len(norms)):
            h = self._cancel.match_at(norms, i)
            if h is None or h[1] not in lx.CANCEL_PEOPLE_ONLY or i in cue_ends:
                continue
            if _walked_out_to(norms, h) or any(
                    _out_and_still_ill(h[1], norms[c.start_tok:c.end_tok]) and c.end_tok <= i
                    and toks.sentence_of[c.start_tok] == toks.sentence_of[i] for c in cues):
                continue
            if i > 0 and norms[i - 1] in lx.NEGATORS | {"be", "being", "to", "will", "need", "needs"}:
                continue  # "not rescued yet", "to be lifted off": not done
            if _nobody_said(norms, i - 3, i):
                continue  # "nobody has brought him out yet": not done
            before = [p for p in ex.places if p.status == "active" and p.end_tok <= i
                      and toks.sentence_of[p.start_tok] == toks.sentence_of[i]]
            after = [p for p in ex.places if p.status == "active" and h[0] <= p.start_tok <= h[0] + 2
                     and ("of" in norms[h[0]:p.start_tok] or norms[h[0] - 1] in ("in", "inside"))]
            if after:  # "the paramedics have taken everybody out of the cafe"
                out.append((after[0].landmark, i))
                continue
            if not before and any(w in ("there", "inside") for w in norms[i:i + 6]):
                # "Caller B said the gym was empty. Turns out nobody was in there": the place of the sentence before
                before = [p for p in ex.places if p.status == "active" and p.end_tok <= i
                          and toks.sentence_of[p.start_tok] == toks.sentence_of[i] - 1]
            if not before:
                # "We had a gentleman fall in the chapel, he's hurt ... the gentleman's fine now, he's up and walking":
                # the person spoken of before, at the place of the sentence that spoke of him
                sent = toks.sentence_of[i]
                who = next((j for j in range(i - 1, -1, -1) if toks.sentence_of[j] == sent and j > 0
                            and norms[j - 1] == "the" and (norms[j] in lx.LAY_PERSONS or norms[j] in lx.PERSON_NOUNS)
                            and norms[j] in norms[:j - 1]), None)
                if who is not None:
                    first = norms.index(norms[who])
                    before = [p for p in ex.places if p.status == "active" and p.start_tok > first
                              and toks.sentence_of[p.start_tok] == toks.sentence_of[first]][:1]
            said = [p for p in ex.places if p.end_tok <= i and toks.sentence_of[p.start_tok] == toks.sentence_of[i]]
            last_said = max(said, key=lambda p: p.end_tok, default=None)
            if before and last_said is not None and last_said.status in ("negated", "retracted") \
                    and last_said.end_tok > max(before, key=lambda p: p.end_tok).end_tok:
                continue  # "scrap the library, they've all walked out of there unhurt": of the place taken back
            if before:
                out.append((max(before, key=lambda p: p.end_tok).landmark, i))
        return out

    @staticmethod
    def _list_share(ex: Extraction, norms: tuple[str, ...], p: PlaceMention, pairs: list[Claim]) -> list[CueMention]:
        """The cues of the list item just before the place ``p`` replaced, when that place ended a list."""
        if p.replaces is None:
            return []
        q = next((x for x in ex.places if x.start_tok == p.replaces and x.status == "retracted"), None)
        if q is None:
            return []
        # ("two casualties at the fire station, one at the bank — no, ... the hotel": a count said again)
        counts = {"one", "another"} | lx.NUMBER_WORDS
        glue = lx.DETERMINERS | lx.FILLERS | {"and", "or", "plus", "at", "in", "on", "inside"} | counts
        prev = [c for c in pairs if c.place.end_tok <= q.start_tok and c.cue.polarity == "affirmed"
                and ex.tokens.sentence_of[c.place.start_tok] == ex.tokens.sentence_of[q.start_tok]]
        if not prev:
            return []
        last = max(c.place.end_tok for c in prev)
        between = norms[last : q.start_tok]
        if not between or any(w not in glue for w in between) \
                or not any(w in ("and", "or", "plus") or w in counts for w in between):
            return []
        return [c.cue for c in prev if c.place.end_tok == last]

    @staticmethod
    def _bind_cost(norms: tuple[str, ...], c: CueMention, p: PlaceMention) -> float:
        if c.reason == "people were taken there":  # "the caravan park's been evacuated up to the quarry": where to
            return -10.0 if c.end_tok <= p.start_tok <= c.end_tok + 4 else 10.0
        if c.end_tok <= p.start_tok and c.reason != "what harmed a person" and "from" in norms[c.end_tok:p.start_tok] \
                and set(norms[c.end_tok:p.start_tok]) <= {
                "coming", "pouring", "billowing", "from", "out", "of", "the", "a", "rising", "blowing"}:
            return -5.0  # "a man at the bakery reported smoke coming from the bank": where it comes from
        if c.end_tok <= p.start_tok:  # cue before place: "fire at the bakery" ("he fell off the uh the water tank")
            between = norms[c.end_tok : p.start_tok]
            glue = all(w in _BINDING_PREPOSITIONS or w in lx.DETERMINERS or w in lx.FILLERS or w in lx.COPULAS
                       for w in between)
            return len(between) - (2.5 if glue and any(w in _BINDING_PREPOSITIONS for w in between) else 0)
        # place before cue: "the bakery is on fire" (a hesitation is no distance: "the viaduct has, um, lost a parapet
        # into the marina")
        between = tuple(w for w in norms[p.end_tok : c.start_tok] if w not in lx.HESITATIONS)
        glue = all(w in lx.COPULAS or w in lx.FILLERS or w in lx.PREPOSITIONS or w in lx.DETERMINERS or w in lx.PRONOUNS for w in between)
        # ("rockfall on the coast path live ground at the top car park": a cue that goes on "at the" names its
        # own place after it)
        onward = 2.0 if norms[c.end_tok:c.end_tok + 1] and norms[c.end_tok] in lx.POSITION_PREPS and not between \
            and norms[c.end_tok + 1:c.end_tok + 2] in (("the",), ("a",)) else 0.0
        return len(between) - (2.0 if glue else 0) + 0.25 + onward

    @staticmethod
    def _donor_for_places(k: int, segs: list[tuple[int, int]], seg_places: dict[int, list[PlaceMention]],
                          seg_cues: dict[int, list[CueMention]], sentence_of: list[int], hollow: set[int],
                          first_norm: list[str], seg_words: list[tuple[str, ...]] | None = None) -> int | None:
        sent = sentence_of[segs[k][0]]
        if first_norm[k] in ("we", "i", "im", "were", "you", "youre", "because", "cos", "coz"):
            return None  # "...full of smoke; we are shifting to emergency steering in the tiller flat": no list item
            # ("moved to the rec because the welfare hall is full": a reason, no list item either)

        def own(j: int) -> bool:
            """The donor's place is one said before it ("I can see the park, the sports hall and the water tower,
            and the water tower's leaning"), or it opens a new event ("..., and then when I got to the
            warehouse ..."): its predicate is that place's own."""
            first = min(seg_places[j], key=lambda p: p.start_tok)
            said = any(q.landmark == first.landmark for i in range(0, j) for q in seg_places.get(i, [])
                       if sentence_of[q.start_tok] == sent)
            return said or any(w in ("then", "when") for w in first_norm[j].split())
        # a list closed by "and": "the hotel and the market square are all clear"
        j = k + 1
        while j < len(segs) and sentence_of[segs[j][0]] == sent and (j in hollow or (seg_places.get(j) and not seg_cues.get(j))):
            j += 1
        if j < len(segs) and sentence_of[segs[j][0]] == sent and seg_cues.get(j) and seg_places.get(j) \
                and first_norm[j] in ("and", "or", "plus") \
                and min(p.start_tok for p in seg_places[j]) < min(c.start_tok for c in seg_cues[j]) \
                and not min(seg_places[j], key=lambda p: p.start_tok).text.lower().endswith(("'s", "’s")) \
                and not own(j):
            return j  # ("..., and the fire hall's secure": a singular predicate is that place's own)
        if j < len(segs) and j - 1 > k and sentence_of[segs[j][0]] == sent and seg_cues.get(j) and not seg_places.get(j) \
                and seg_places.get(j - 1) and not seg_cues.get(j - 1) and first_norm[j - 1] == "and" \
                and first_norm[j] in ("and", "are", "have", "were", "both", "all"):
            return j  # "the town hall and the library have both been checked and are clear": the list's own predicate
        # backward: "fire at the bakery and the school", "people trapped in the, um, school, no, the library"
        j = k - 1
        while j >= 0 and sentence_of[segs[j][0]] == sent:
            if seg_cues.get(j):
                return j
            if not seg_places.get(j) and j not in hollow:
                break
            j -= 1
        # forward through a list: "the bakery, the school and the library are on fire"
        j = k + 1
        while j < len(segs) and sentence_of[segs[j][0]] == sent:
            if " " in first_norm[j]:
                break  # "the hotel — and I can see a bloke trapped in ...": a new clause with its own subject
            if seg_cues.get(j):
                ps = seg_places.get(j, [])
                if ps and min(ps, key=lambda p: p.start_tok).text.lower().endswith(("'s", "’s")) \
                        and not any(seg_places.get(i) for i in range(k + 1, j)):
                    break  # "not the gym, the library — the gym's got exposed wiring": that place's own predicate
                if ps and own(j):
                    break
                if not ps or min(p.start_tok for p in ps) <= min(c.start_tok for c in seg_cues[j]):
                    return j
                break
            if not seg_places.get(j) and j not in hollow:
                break
            if seg_places.get(j) and seg_words is not None and {"is", "are", "was", "were", "where"} & set(seg_words[j]):
                break  # "the butts, and er, the lodge is where we've put the beaters, it's safe up there": a clause
                # of its own stands between, no list
            j += 1
        return None

    def _spread_claims(self, ex: Extraction, norms: tuple[str, ...], cues: list[CueMention], claims: list[Claim],
                       denied: list[Claim]) -> list[Claim]:
        """"the leak from the drum store has reached the fuel island", "smoke ... is now covering the battery plant",
        "it's into the pit as well, the effluent pit": a danger said to reach another place is that danger there too."""
        toks = ex.tokens
        cue_tokens = {i for c in cues for i in range(c.start_tok, c.end_tok)}
        starts = {p.start_tok: p for p in ex.places if p.status == "active"}
        out = []
        for i in range(len(norms)):
            for key in lx.SPREAD_PHRASES:
                b = i + len(key)
                if norms[i:b] != key or any(j in cue_tokens for j in range(i, b)) or b >= len(norms):
                    continue
                if any(norms[m] in lx.NEGATORS | {"hasnt", "havent", "hadnt", "isnt", "not", "nt", "never", "wont"}
                       for m in range(max(0, i - 3), i) if not any(toks.clause_start[t] for t in range(m + 1, i + 1))):
                    continue  # "it hasn't reached the plots yet": not spread there
                k = b
                while k < len(norms) and norms[k] in lx.DETERMINERS and k - b < 2:
                    k += 1
                place = starts.get(k) or starts.get(b)
                if place is None and k < len(norms):
                    # "it's into the pit as well, the effluent pit": the place said again after a pause
                    e = k
                    while e < len(norms) and not toks.clause_start[e] and e - k < 5:
                        e += 1
                    later = [p for p in ex.places if p.status == "active" and e <= p.start_tok <= e + 2]
                    place = later[0] if later and any(norms[j] in name_words(later[0].landmark) for j in range(k, e)) \
                        else None
                if place is None:
                    continue
                if any(norms[m] in ("fine", "ok", "okay", "alright", "untouched", "unaffected") and norms[m - 1] in (
                        "is", "s", "its", "are", "still") for m in range(place.end_tok, min(len(norms), place.end_tok + 3))):
                    continue  # "the bakery's smoke blowing over, the hardware store is fine": not reached
                prior = [c for c in cues if c.end_tok <= i and c.polarity == "affirmed" and c.status == "active"
                         and toks.sentence_of[c.start_tok] == toks.sentence_of[i]
                         and self.kb.category_by_name[c.category].role == Role.UNDESIRABLE]
                if not prior or any(c.place.landmark == place.landmark and c.place.start_tok != place.start_tok
                                    for c in claims + denied):
                    continue
                # what the place borrowed from a later clause ("..., and the staff car park is our welfare point")
                # gives way to the danger that reached it
                # (people there are no claim against it: "it's reaching the lorry park now three drivers collapsed")
                owned = [c for c in claims if c.place is place
                         and self.kb.category_by_name[c.cue.category].role != Role.CRITICAL]
                later_clause = [c for c in owned if c.cue.start_tok > place.end_tok and any(
                    toks.clause_start[j] for j in range(place.end_tok, c.cue.start_tok + 1))]
                if len(later_clause) < len(owned):
                    continue  # it has a claim of its own
                for c in later_clause:
                    claims.remove(c)
                src = max(prior, key=lambda c: c.start_tok)
                start, end = toks.tokens[i].start, toks.tokens[b - 1].end
                out.append(Claim(place, CueMention(i, b, start, end, toks.text[start:end], src.category, "lexicon",
                                                   reason=f"the {src.text} has spread there")))
                break
        return out

    @staticmethod
    def _origin(norms: tuple[str, ...], p: PlaceMention) -> bool:
        """Where the speaker or the people come from: "Mrs Kay from the village shop here, ...", "Residents
        from the caravan field are walking up to the village hall, which is our dry refuge"."""
        j = p.start_tok - 1
        while j >= 0 and norms[j] in lx.DETERMINERS:
            j -= 1
        after = [w for w in norms[p.end_tok:min(len(norms), p.end_tok + 4)] if w not in lx.FILLERS]
        if j >= 1 and norms[j] == "from" and (norms[j - 1] in lx.CALLER_ROLES | lx.WORKER_PERSONS
                                              or norms[j - 1] in _PERSON_WORDS) \
                and (not after or after[0] in ("again", "here", "speaking", "calling") or after[0] in lx.PRONOUNS
                     or after[0] in ("we", "were", "i", "im")):
            return True  # "pensioner from the flats again, we're all out now standing in the park"
        if j >= 1 and norms[j] == "of" and norms[j - 1] == "out" and any(
                norms[t] in lx.SEND_VERBS or norms[t] in lx.OUT_OF_VERBS for t in range(max(0, j - 6), j - 1)):
            return True  # "use it to bring the residents out of the flats": where they leave
        return j >= 0 and norms[j] == "from" and bool(after) and (
            after[0] in ("here", "calling", "speaking")
            or bool(set(after) & {"walking", "coming", "heading", "moving", "going", "making"})
            # ("the kids from the primary school have all been walked over to the police post")
            or bool(set(after) & (lx.MOVE_VERBS | {"walked", "evacuated", "led", "ferried"})))

    @staticmethod
    def _opening(norms: tuple[str, ...], a: int, b: int) -> str:
        """First word of a segment; "and i", "but we": a coordinator that opens a clause with its own subject."""
        if a + 1 < b and norms[a] in lx.COORDINATORS and norms[a + 1] in ("i", "we", "im", "you", "they", "he", "she",
                                                                         "there", "theres"):
            return f"{norms[a]} {norms[a + 1]}"
        return norms[a]

    @staticmethod
    def _particle_end(toks: Tokens, norms: tuple[str, ...], segs: list[tuple[int, int]],
                      seg_places: dict[int, list[PlaceMention]], k: int, cs: list[CueMention]) -> bool:
        """Is the preposition that ends cue-only segment ``k`` a verb's particle, not a broken-off "at the"?
        Before ", and" ("it's safe to stay in, and the high gate's flooded"), or as a cue's own last word before
        a place with a word of its own ("that's where the water's coming in... the tea room's dry")."""
        b = segs[k][1]
        if b < len(norms) and norms[b] in lx.COORDINATORS and "," in toks.gaps[b] and norms[b - 1] not in lx.DETERMINERS:
            return True
        nq = min(seg_places.get(k + 1, []), key=lambda q: q.start_tok, default=None)
        said_of_next = nq is not None and any(norms[i] not in lx.FILLERS for i in range(nq.end_tok, segs[k + 1][1]))
        return any(c.end_tok == b and c.end_tok - c.start_tok >= 2 for c in cs) and said_of_next \
            and b < len(norms) and not any(m in toks.gaps[b] for m in ("-", "—", "–"))

    @staticmethod
    def _named_after(k: int, segs: list[tuple[int, int]], seg_places: dict[int, list[PlaceMention]],
                     seg_cues: dict[int, list[CueMention]], sentence_of: list[int], norms: tuple[str, ...],
                     sent_words: dict[int, int], person: bool = False) -> int | None:
        """A report that opens with the danger and names the place after it: "There is fire! Big fire.
        It is the... the shop for medicine. The pharmacy." Up to two sentences on, none with a cue of
        its own, the first place said alone or as "it's the X" is the one meant; for people hurt, so is
        the place the person is then said to be ("Someone's trapped under a shelf. She's in the back
        of the hardware store.")."""
        here = sentence_of[segs[k][0]]
        for j in range(k + 1, len(segs)):
            n = sentence_of[segs[j][0]]
            if n > here + 2:
                return None
            if n == here:
                continue
            if seg_cues.get(j):
                return None
            if seg_places.get(j) and all(q.status == "retracted" for q in seg_places[j]):
                continue  # ("I keep saying bus depot, it's the bus station": past the name taken back)
            if seg_places.get(j):
                start = next(i for i in range(segs[j][0], -1, -1) if i == 0 or sentence_of[i - 1] != n)
                words = [w for w in norms[start:segs[j][1]] if w not in lx.FILLERS]
                said_alone = sent_words.get(n, 99) <= 3 or _place_fragment(
                    n, [q for qs in seg_places.values() for q in qs if sentence_of[q.start_tok] == n], sentence_of, norms)
                own = [w for w in norms[segs[j][0]:segs[j][1]] if w not in lx.FILLERS]
                named = words[:2] in (["it", "is"], ["this", "is"]) or words[:1] in (["its"], ["thats"]) \
                    or own[:2] == ["its", "the"] \
                    or words[:2] in (["that", "at"], ["that", "in"], ["thats", "at"], ["thats", "in"]) \
                    or words[:2] in (["in", "the"], ["at", "the"], ["inside", "the"]) and start == segs[j][0] \
                    and min(q.start_tok for q in seg_places[j]) <= start + 3
                # ("Person in the water! In the beck, clinging onto a branch.": a sentence that opens on where)
                # ("sorry, I keep saying guest house, it's the hotel"; "That's at the guest house.")
                who = next((i for i, w in enumerate(words[:6]) if w in lx.PERSON_SUBJECTS or w in ("we", "i")), None)
                # ("my husband ... his leg is broken. We are inside the guest house": where the caller is with him)
                placed = person and who is not None and any(
                    w in lx.POSITION_PREPS or w in ("inside", "lying", "sitting", "lies") for w in words[who + 1:who + 5])
                return j if said_alone or named or placed else None
        return None

    @staticmethod
    def _list_opening(toks: Tokens, norms: tuple[str, ...], segs: list[tuple[int, int]], target: int,
                      seg_places: dict[int, list[PlaceMention]], seg_cues: dict[int, list[CueMention]],
                      told: list[PlaceMention]) -> list[PlaceMention]:
        """The items before the last one of a list that makes a whole sentence and says nothing of its own
        ("Hotel, cafe and bank all checked. All clear, all usable for shelter."): a later sentence about the
        list is about all of them."""
        sentence_of = toks.sentence_of
        sent = sentence_of[segs[target][0]]
        a, b = segs[target]
        if len(told) != 1 or seg_cues.get(target) or next((w for w in norms[a:b] if w not in lx.FILLERS), "") != "and":
            return []
        if any(not told[0].start_tok <= i < told[0].end_tok and norms[i] not in lx.DETERMINERS | lx.FILLERS | {
                "and", "all", "both", "checked", "searched", "done", "visited", "walked"} for i in range(a, b)):
            return []  # ("were at the gardens yeah and like the fire station is flooded": no list, a clause)
        mates: list[PlaceMention] = []
        j = target - 1
        while j >= 0 and sentence_of[segs[j][0]] == sent:
            ps = seg_places.get(j, [])
            a2, b2 = segs[j]
            opens = j == 0 or sentence_of[segs[j - 1][0]] != sent  # ("I checked the hotel, the cafe and ...")
            if len(ps) != 1 or seg_cues.get(j) or any(
                    not ps[0].start_tok <= i < ps[0].end_tok and norms[i] not in lx.DETERMINERS | lx.FILLERS
                    and not (opens and i < ps[0].start_tok) for i in range(a2, b2)):
                return []
            mates.append(ps[0])
            j -= 1
        return mates[::-1] if mates and all(q.status == "active" for q in mates) else []

    @staticmethod
    def _target_for_cues(k: int, segs: list[tuple[int, int]], seg_places: dict[int, list[PlaceMention]],
                         seg_cues: dict[int, list[CueMention]], sentence_of: list[int],
                         transparent: set[int], opening: str, norms: tuple[str, ...]) -> int | None:
        nxt = k + 1
        if nxt < len(segs) and sentence_of[segs[nxt][0]] == sentence_of[segs[k][0]] \
                and seg_places.get(nxt) and not seg_cues.get(nxt):
            words = [w for w in norms[segs[nxt][0]:segs[nxt][1]] if w not in lx.FILLERS]
            if words[:1] and words[0] in lx.PERSON_SUBJECTS and any(
                    w in lx.POSITION_PREPS or w == "inside" for w in words[1:4]):
                return nxt  # "the injured porter, he's in the tea warehouse": where the person is said to be
            if words[:1] == ["and"] and words[1:2] and words[1] in lx.POSITION_VERBS | {"lying", "standing", "waiting"} \
                    and any(w in lx.POSITION_PREPS for w in words[2:5]):
                return nxt  # "the driver's burnt and sitting up on the bank that looks down on the off-slip"
        # the nearest earlier segment with places ("the bakery — it's on fire", "Checked the school. All clear."),
        # over sentences that are transparent (questions, one-word answers, more about the same place)
        lo = segs[k - 1][0] if k > 0 and not seg_places.get(k - 1) and not seg_cues.get(k - 1) \
            and sentence_of[segs[k - 1][0]] == sentence_of[segs[k][0]] else segs[k][0]  # ("there's a — a fire")
        said = [w for w in norms[lo:segs[k][1]] if w not in lx.FILLERS]
        if "theres" in said or any(said[i] == "there" and said[i + 1:i + 2] in (["is"], ["a"], ["an"], ["some"])
                                   and (i == 0 or said[i - 1] not in ("in", "over", "out", "up", "down"))
                                   for i in range(len(said))):
            # "..., but now there's a fire, small one, in the spray store": a danger brought in anew, and where,
            # said after a short aside
            for j in (k + 1, k + 2):
                if j >= len(segs) or sentence_of[segs[j][0]] != sentence_of[segs[k][0]] or seg_cues.get(j):
                    break
                if seg_places.get(j):
                    first = next((w for w in norms[segs[j][0]:segs[j][1]] if w not in lx.FILLERS), "")
                    if j == k + 2 and first in ("in", "at", "inside", "on"):
                        return j
                    break
        for j in range(k - 1, -1, -1):
            if seg_places.get(j):
                between = range(sentence_of[segs[j][0]] + 1, sentence_of[segs[k][0]])
                if len(between) > 3 or any(n not in transparent for n in between):
                    return None
                here = sentence_of[segs[k][0]]
                if sentence_of[segs[j][0]] != here:
                    # "The smoke -- it's coming from the kitchen, the hotel kitchen": a sentence that names its
                    # place after the danger talks about that place, not the one before it; so does one that
                    # turns to a new matter with "but" ("But the organist, she's trapped ..., the stairs have
                    # given way in the church"), though that place has a danger of its own
                    later = next((i for i in range(k + 1, len(segs)) if sentence_of[segs[i][0]] == here
                                  and seg_places.get(i)), None)
                    if later is not None and all(q.status == "negated" for q in seg_places[later]):
                        return j  # ("the lawn? that's where everyone's gathering, not the car park": a place put
                        # against the one talked about, not the one the danger is said of)
                    if later is not None and (not seg_cues.get(later) or opening == "but"):
                        return later
                    if later == k + 1 and _cue_list_into(k, later, segs, seg_cues, norms):
                        return later  # "And there's sparks and smoke coming off the water tower."
                return j
        # else the next one in the same sentence ("on fire, the bakery"), over a short aside
        j, steps = k + 1, 1
        while j < len(segs) and steps <= 3 and sentence_of[segs[j][0]] == sentence_of[segs[k][0]]:
            if seg_places.get(j):
                # ("Smoke and sparks from the box the food stalls back onto": a list of dangers said of its place)
                return j if not seg_cues.get(j) or j == k + 1 and _cue_list_into(k, j, segs, seg_cues, norms) else None
            if seg_cues.get(j):
                return None
            # (a segment of hesitations only is no aside: "heat exhaustion, uh, two of them, in the stand — the
            # terraces, the grandstand")
            steps += any(w not in lx.FILLERS for w in norms[segs[j][0]:segs[j][1]])
            j += 1
        return None


def _active_repeats(ex: Extraction, lo: int, hi: int) -> list[PlaceMention]:
    """For each place restarted between tokens ``lo`` and ``hi`` ("in the mill — the mill"), the active place that in
    the end repeats it (following each place's ``replaces`` link)."""
    by_replaced = {q.replaces: q for q in ex.places if q.replaces is not None}
    out = []
    for r in ex.places:
        if not (lo <= r.start_tok < hi and r.reason.startswith("restarted")):
            continue
        q = by_replaced.get(r.start_tok)
        while q is not None and q.status != "active":
            q = by_replaced.get(q.start_tok)
        if q is not None:
            out.append(q)
    return out


_FRAGMENT_WORDS = frozenset(lx.STOREY_WORDS | lx.PART_NOUNS | lx.LOCATIVE_PARTS) | {
    "ground", "first", "second", "third", "top", "upper", "lower", "back", "inside", "outside", "upstairs",
    "downstairs", "room", "number", "flat", "one", "two", "three", "four", "five", "six", "corner"}


def _place_fragment(n: int, places: list[PlaceMention], sentence_of: list[int], norms: tuple[str, ...]) -> bool:
    """Sentence ``n`` is a place said as a fragment, with nothing but where in it ("Casualty found. Ground
    floor, town hall."): the place the sentence before was about."""
    inside = {i for q in places for i in range(q.start_tok, q.end_tok)}
    words = [w for i, w in enumerate(norms) if sentence_of[i] == n and i not in inside]
    return bool(inside) and all(w in _FRAGMENT_WORDS or w in lx.FILLERS or w in lx.DETERMINERS
                                or w in lx.PREPOSITIONS for w in words)


# "I had it right the first time", "the first one was right": the speaker goes back to the first place said
_FIRST_WAS_RIGHT = [norm_phrase(p) for p in ("right first time", "right the first time", "first one was right",
                                             "first one was correct", "first was right", "right to begin with",
                                             "as i said first", "like i said at first", "what i said first")]


_FIRST_WAS_RIGHT_STARTS = frozenset(key[0] for key in _FIRST_WAS_RIGHT)


def _first_was_right_at(norms: tuple[str, ...], i: int) -> bool:
    """Does one of ``_FIRST_WAS_RIGHT`` begin at token ``i``?"""
    return norms[i] in _FIRST_WAS_RIGHT_STARTS and any(norms[i:i + len(key)] == key for key in _FIRST_WAS_RIGHT)


# The relation names the phrase tables read ("behind", "backs onto"), as ``Relation.phrase`` writes them.
_TABLE_RELATIONS = frozenset(lx.RELATION_SYNONYMS) | frozenset(s for v in lx.RELATION_SYNONYMS.values() for s in v)

# Words between a place and another that only says which one it is ("the lobby at the bottom of the lift").
_WHICH_ONE_PREPS = frozenset({"from", "at", "of", "on", "by", "in", "out", "beside", "behind", "under", "below", "above"})
_END_PARTS = frozenset({"bottom", "top", "end", "foot", "head", "side", "back", "front", "far", "near", "other"})


def _says_which_after(toks: Tokens, norms: tuple[str, ...], end: int, q: PlaceMention) -> bool:
    """``q`` stands in a phrase right after ``end`` that only says which place ends there ("the tunnel | from
    reception", "the huts | at the bottom of the top garden"): a preposition, then articles, prepositions and words
    for a part's end, in one clause."""
    return end < q.start_tok <= end + 5 and norms[end] in _WHICH_ONE_PREPS \
        and all(norms[t] in lx.DETERMINERS | _WHICH_ONE_PREPS | _END_PARTS for t in range(end, q.start_tok)) \
        and not any(toks.clause_start[t] for t in range(end, q.end_tok))


# Heads of names that say what a building holds ("evaporator house", "boiler room"): the thing said alone names it.
_HOUSING_HEADS = frozenset({"house", "shed", "room", "hall", "hut", "building"})


def _ends_on_own_words(between: list[str], phrase: str) -> bool:
    """Do the words between a head and its anchor end on the last three words of the relation's name, a noun of
    its among them ("... tied up at the end of" for ``is moored off the end of``)?"""
    tail = norm_phrase(phrase.replace("_", " "))[-3:]
    return len(tail) == 3 and tuple(between[-3:]) == tail and any(w not in lx.FUNCTION_WORDS for w in tail)


def _sole_antecedent(ex: Extraction, toks: Tokens, limit: int, k: int) -> PlaceMention | None:
    """The place a pronoun at ``k`` takes up: the active one named last before ``limit``, in an earlier clause, where
    no other place is said between it and the pronoun; else None."""
    # (a coordinator opens a clause too: "the bale store's on fire and the shed it sends its bales to")
    before = [p for p in ex.places if p.status == "active" and p.end_tok < limit
              and any(toks.clause_start[i] or toks.tokens[i].norm in ("and", "but", "then") for i in range(p.end_tok, limit))]
    if not before:
        return None
    last = max(before, key=lambda p: p.end_tok)
    # (a place said in the antecedent's own clause only to say which it is counts as no other: "the pond the log yard
    # rolls its logs into, and ... whatever drags the logs back out of it")
    if any(q.end_tok > last.end_tok and q.start_tok < k for q in ex.places if q is not last
           and not (q.status == "reference" and q.reason.startswith("reference point")
                    and not any(toks.clause_start[i] for i in range(last.end_tok, q.start_tok + 1)))):
        return None
    return last


def _spoken_number_forms(kb: KnowledgeBase, taken: Collection[tuple[str, ...]]) -> list[tuple[tuple[str, ...], str]]:
    """A name with a number in digits said as radio says it: "runway 26" -> "runway two six", "runway twenty
    six"; "hut 7" -> "hut seven". Not where the form is another landmark's already."""
    out: list[tuple[tuple[str, ...], str]] = []
    seen = set(taken)
    for lm in kb.landmarks:
        for f in lm.surface_forms:
            words = name_words(f)
            at = [i for i, w in enumerate(words) if w.isdigit() and len(w) <= 2 and not w.startswith("0")]
            if len(at) != 1 or len(words) < 2:
                continue
            i = at[0]
            for spoken in spoken_forms(words[i]):
                key = tuple(words[:i]) + spoken + tuple(words[i + 1:])
                if key not in seen:
                    seen.add(key)
                    out.append((key, lm.name))
    return out


def _synonym_forms(kb: KnowledgeBase) -> list[tuple[tuple[str, ...], str]]:
    """Another word for a one-word form of a landmark ("church" for the chapel, "tavern" for the inn), from
    ``lexicon.PLACE_SYNONYMS``: only where exactly one landmark has a one-word form in the group and no
    landmark's name or alias uses the other word at all."""
    used = {w for lm in kb.landmarks for f in lm.surface_forms for w in name_words(f)}
    out = []
    for group in lx.PLACE_SYNONYMS:
        keys = {norm(w) for w in group}
        owners = {lm.name for lm in kb.landmarks for f in lm.surface_forms if len(name_words(f)) == 1
                  and name_words(f)[0] in keys}
        if len(owners) != 1:
            continue
        name = next(iter(owners))
        out.extend(((k,), name) for k in sorted(keys - used))
    return out


def _particle_verb_forms(term: str) -> list[str]:
    """A glossary term that names a verb and its particle as one noun, said as the verb: "plough-in" -> "ploughed in",
    "ploughing in", "ploughs in" ("the craft's ploughed in on the ramp"); "cave-in" -> "caved in"."""
    words = term.strip().lower().replace("-", " ").split()
    if len(words) != 2 or "-" not in term or words[1] not in ("in", "out", "up", "off", "over", "down") \
            or not words[0].isalpha() or len(words[0]) < 3:
        return []
    return [f"{v} {words[1]}" for v in _verb_forms(words[0])]


def _verb_forms(term: str) -> list[str]:
    """Other forms of a one-word glossary term that may be a verb: "undercut" -> "undercuts", "undercutting",
    "undercutted"; "flood" -> "flooding", "flooded"; "collapse" -> "collapsing", "collapsed"."""
    w = term.strip().lower()
    if not w.isalpha() or len(w) < 4 or " " in w:
        return []
    if w.endswith("e"):
        return [w + "s", w[:-1] + "ing", w + "d"]
    forms = [w + "s", w + "ing", w + "ed"]
    if w[-1] not in "aeiouwxy" and w[-2] in "aeiou" and w[-3] not in "aeiou":
        forms += [w + w[-1] + "ing", w + w[-1] + "ed"]  # ("undercutting")
    return forms


_EVENT_VERBS = {"tear": ("torn", "tore", "tearing"), "failure": ("failed", "failing", "fails", "gone", "given way", "burst"),
                "slip": ("slipped", "slipping", "slips"), "leak": ("leaking", "leaked", "leaks"),
                "overtopping": ("overtopped", "overtops", "overtopping"), "collapse": ("collapsed", "collapsing"),
                "breach": ("breached", "breaching"), "burst": ("burst", "bursting"), "split": ("split", "splitting"),
                "rupture": ("ruptured", "rupturing"), "breakout": ("breaking out", "broken out", "broke out"),
                "blowout": ("blown out", "blew out", "blowing out"), "fall": ("fallen", "fell", "falling"),
                "slide": ("sliding", "slid"), "slump": ("slumped", "slumping"), "washout": ("washed out",)}


def _event_forms(term: str) -> list[str]:
    """A glossary term that names a thing and what befell it, said as a clause: "liner tear" -> "liner torn" (so "the
    liner's torn"), "the liner is torn", "torn liner"; "bund failure" -> "bund failed", "the bund has failed";
    "gas breakout" -> "gas breaking out"."""
    words = term.strip().lower().split()
    if len(words) != 2 or words[1] not in _EVENT_VERBS or not words[0].isalpha():
        return []
    noun = words[0]
    out = []
    for form in _EVENT_VERBS[words[1]]:
        out += [f"{noun} {form}", f"{noun} is {form}", f"{noun} has {form}"]
        if " " not in form and form.endswith(("ed", "n", "t")):
            out.append(f"{form} {noun}")  # ("a torn liner", "the failed bund")
    return out


def _determined_forms(term: str) -> list[str]:
    """A two-word glossary term whose first word is a verb's participle, said with a determiner between:
    "dropped plug" -> "dropped her plug", "dropped a plug"; "blowing a gland" -> "blowing her gland"."""
    words = term.strip().lower().split()
    if len(words) == 3 and words[1] in ("a", "an", "the") and words[0].endswith(("ed", "ing")):
        words = [words[0], words[2]]
    if len(words) != 2 or not words[0].endswith(("ed", "ing")) or not all(w.isalpha() for w in words):
        return []
    return [f"{words[0]} {d} {words[1]}" for d in ("a", "the", "her", "his", "its", "their") if d != words[1]]


_WORD_SEARCHES = (("what", "dyou", "call", "it"), ("what", "do", "you", "call", "it"), ("what", "it", "called"),
                  ("what", "its", "name"), ("what", "the", "word"), ("what", "it"))


def _searched_words(toks: Tokens) -> Tokens:
    """"in the, what's it, the building just inside it": a speaker's search for a word, set off as a clause of its
    own (or asking what it is called), read as a hesitation ("um"); so is a word begun and then said whole ("the sch
    school")."""
    norms = toks.norms(0, len(toks))
    fixed = list(toks.tokens)
    for i in range(len(norms) - 1):
        f, w = toks.tokens[i].text.lower(), norms[i + 1]
        if f.isalpha() and 2 <= len(f) <= 4 and w.startswith(f) and len(w) >= len(f) + 2 and toks.gaps[i + 1] == " " \
                and f not in lx.FUNCTION_WORDS and f not in ("st", "mt", "ft", "dr") and not f.isupper():
            fixed[i] = replace(fixed[i], norm="um")  # "sm smoke in the sch school": a word begun, then said whole
    for i in range(len(norms)):
        if norms[i] != "what" or not toks.clause_start[i]:
            continue
        for key in _WORD_SEARCHES:
            e = i + len(key)
            if norms[i:e] == key and (key[-1] in ("called", "name", "word") or e == len(norms) or toks.clause_start[e]):
                for j in range(i, e):
                    fixed[j] = replace(fixed[j], norm="um")
                break
    return replace(toks, tokens=tuple(fixed)) if fixed != list(toks.tokens) else toks


def _indirect_questions(toks: Tokens, norms: tuple[str, ...]) -> set[int]:
    """"guests asking which roads are open", "wondering if the hall is safe", "can you tell me whether the bridge
    is passable": a question told, not asked; what it asks is no report. The tokens from the question word to
    the end of its clause."""
    out: set[int] = set()
    wh = {"which", "whether", "if", "where", "what", "when", "how"}
    for i in range(1, len(norms) - 1):
        w, q = norms[i - 1], norms[i]
        told = w in ("asking", "ask", "asked", "wondering", "wondered") and q in wh \
            or w == "know" and (q in ("if", "whether") or i >= 3 and norms[i - 3:i - 1] in (
                ("do", "you"), ("does", "anyone"), ("does", "anybody"), ("anyone", "d"))) and q in wh \
            or w == "me" and i >= 2 and norms[i - 2] in ("tell", "telling", "show") and q in wh \
            or w in ("check", "checking", "confirm") and q in ("if", "whether") \
            or w == "or" and q in ("is", "are") and norms[i + 1] in ("it", "they", "there", "that") \
            and any(norms[k] in ("can", "could") and norms[k + 1] in ("i", "we", "you", "they", "anyone")
                    or toks.sentence_start[k] and norms[k] in lx.QUESTION_OPENERS for k in range(max(0, i - 12), i))
        # ("can I get across the creaker or is it still, you know, stuck": the other half of a question)
        if not told:
            continue
        # (to the end of the sentence, past commas of speech, "if the west road is, er, passable", up to a new
        # clause with a subject of its own or one joined by "and" / "but")
        # ("you know" is a filler, no new clause)
        end = next((k for k in range(i + 1, len(norms)) if toks.sentence_start[k]
                    or toks.clause_start[k] and norms[k] in lx.CLAUSE_SUBJECTS and norms[k:k + 2] != ("you", "know")
                    or norms[k] in ("and", "but", "so") and norms[k - 1] not in wh), len(norms))
        out.update(range(i, end))
    return out


def _asks_if_true(words: tuple[str, ...], alone: bool = False) -> bool:
    """"..., is that right?", "is it true?": the sentence asks whether what it says is so. ``alone``: the
    sentence is only that check ("... by the square? is that, is that true?" asks about the one before)."""
    kept = [w for w in words if w not in lx.FILLERS - {"right"}]
    checks = (["is", "that", "right"], ["is", "that", "true"], ["is", "it", "true"], ["is", "that", "correct"])
    if kept[-3:] not in checks:
        return False
    return not alone or all(w in ("is", "that", "it", "true", "right", "correct") for w in kept)


def _after_station(norms: tuple[str, ...], a: int) -> bool:
    """Does token ``a`` come right after the station called ("control", "base", "this is"), past fillers, at
    the opening of the message?"""
    j = a - 1
    while j >= 0 and norms[j] in lx.FILLERS:
        j -= 1
    return j >= 0 and j <= 6 and (norms[j] in ("control", "base") or norms[j - 1:j + 1] == ("this", "is"))


def _subject_before(norms: tuple[str, ...], a: int, skip: tuple[str, ...]) -> int:
    """Where the word before token ``a`` stands, past the ``skip`` words (auxiliaries, adverbs) and fillers: the
    subject of the cue at ``a`` ("the bus is just stuck": "bus"); -1 if none."""
    j = a - 1
    while j >= 0 and (norms[j] in skip or norms[j] in lx.FILLERS):
        j -= 1
    return j


def _anchored_at(q: PlaceMention, landmark: str) -> bool:
    """Is ``q`` a place reached through a relation with ``landmark`` at its other end?"""
    return bool(q.via) and q.landmark != landmark and (q.via.startswith(landmark + " ") or q.via.endswith(" " + landmark))


_MADE_SAFE = frozenset({"negated by 'isolated'", "negated by 'been isolated'", "negated by 'made safe'",
                        "negated by 'been made safe'", "negated by 'is off'", "negated by 's off'",
                        "negated by 'turned off'", "negated by 'been turned off'", "negated by 'switched off'",
                        "negated by 'shut off'"})  # (a supply made safe, not the place's danger over: "the gas is off")
# Nouns for a stretch of something long (a wall, a road, a bank): "the stretch by the pump house" says where along
# the place already named, so the place after "by" is a reference point, not a claim.
_SEGMENT_HEADS = frozenset({"stretch", "section", "length", "portion"})
# Words a caller says before the place they call from ("I'm calling from the fishing village")
_CALLING_FROM = frozenset({("calling", "from"), ("ringing", "from"), ("phoning", "from")})
_HEAD_ADJECTIVES = frozenset({"open", "deep", "far", "near", "next", "other"})
# (with NAME_ADJECTIVES: "the open water the slip drops into", "the next stage the primary tanks send their flow to")
_SPATIAL_ENDINGS = frozenset({"beneath", "under", "underneath", "below", "above", "behind", "beside", "into",
                              "onto", "against", "inside", "over", "across", "through"})
_OWN_PARTICLES = frozenset({"up", "down", "off", "back", "out", "over"})  # (a verb's own: "looks out over")
_WAY_VERBS = frozenset({"leads", "lead", "climbs", "climb", "runs", "run", "goes", "go", "winds", "wind", "slopes", "slope",
                        "rises", "rise", "heads", "head", "drops", "drop", "descends", "descend", "steps", "step",
                        "carries", "carry", "takes", "take", "lifts", "lift"})  # (a lift or a gondola too)
_WHERE_ADVERBS = frozenset({"out", "west", "east", "north", "south", "over", "up", "down", "back", "there", "right", "just",
                            "way"})  # (between a place and where it stands: "the big pine out west by the quarry")
# Where a place sits, said without its posture ("the landing area beside it" for ``sits beside``): not "over" or "by"
_POSTURE_PLACES = frozenset({"beside", "behind", "alongside", "against", "beneath", "underneath", "below", "above", "next",
                             "outside"})
_POSTURES = frozenset({"sits", "stands", "lies", "sit", "stand", "lie"})  # verbs of where a place is, not what it does
_EMIT_VERBS = frozenset({"blows", "sends", "pours", "spills", "throws", "casts", "sheds", "vents", "drifts"})
_EMIT_ENDINGS = ("over", "onto", "across")  # (what one place puts over another and the other gets off it: "blows its smoke over")
_SIZE_WORDS = frozenset({"big", "small", "large", "little", "old", "new", "great", "long", "tall", "high", "low"})
_MATERIALS = frozenset({"stone", "brick", "wooden", "timber", "concrete", "steel", "iron", "glass", "tin"})
# Words for the whole site a KB covers, said before one of its places' names ("the works canteen")
_SITE_MODIFIERS = frozenset({"works", "factory", "site", "plant", "company", "complex", "compound"})
_PLAIN_ADJECTIVES = _SIZE_WORDS | _MATERIALS  # (said before a name without being part of it: "the big stone harbour wall")
_POSTURE_VERBS = frozenset({"sits", "stands", "lies", "sit", "stand", "lie"})
# The particle a verb of a description may carry, a cue word though it is ("the road coming down out of the
# cutting", "up where the skid road comes down from")
_VERB_PARTICLES = frozenset({"down", "up", "out", "off", "over", "back", "round", "in"})
_TO_PARTICLES = frozenset({"up", "down", "on", "out", "back", "over", "in", "off", "across", "along"})
_CALL_NOUNS = frozenset({"call", "calls", "message", "report", "phone", "text"})  # ("a 999 call from a lady up the terrace")
_OWNED = "owned:"  # the ``via`` of "the café's car park" (``_possessive_tail``)
_REPAIR_WORDS = frozenset({"no", "sorry", "correction", "mean", "rather", "wait", "scratch", "negative"})


def _letter_labelled(keys: set[tuple[str, ...]]) -> set[tuple[str, ...]]:
    """Of a KB's names (``keys``, as token keys), those whose first word is the letter "a" labelling one of a
    lettered series ("a wing" beside "b wing", "c wing"): the "a" is no article there."""
    bare = {k[1:] if k[:1] == ("the",) else k for k in keys}  # ("the a leg" beside "the c leg")
    lettered = {k for k in bare if len(k) >= 2 and k[0] == "a"
                and any(o[1:] == k[1:] and len(o[0]) == 1 and o[0].isalpha() and o[0] != "a" for o in bare)}
    return {k for k in keys if (k[1:] if k[:1] == ("the",) else k) in lettered}


def _phonetic_forms(kb: KnowledgeBase, keys: set[tuple[str, ...]],
                    labelled: set[tuple[str, ...]]) -> list[tuple[tuple[str, ...], str]]:
    """A lettered series' names in the radio alphabet: "bravo wing" for "b wing", "block charlie" for "block c";
    and the spoken letter alone ("fire on Delta") where two or more landmarks share the series' other words
    and the word names nothing else in the KB."""
    letters = {v: k for k, v in lx.PHONETIC_LETTERS.items() if k not in ("alfa", "juliett", "whisky")}
    forms: dict[tuple[str, ...], set[str]] = {}
    series: dict[tuple[int, tuple[str, ...]], set[str]] = {}
    owners: dict[str, set[str]] = {}
    for lm in kb.landmarks:
        for f in lm.surface_forms:
            for w in norm_phrase(f):
                owners.setdefault(w, set()).add(lm.name)
    for lm in kb.landmarks:
        for form in lm.surface_forms:
            key = norm_phrase(form)
            if len(key) < 2 or (key[0] in ("a", "an") and key not in labelled):
                continue
            for i, w in enumerate(key):
                if len(w) == 1 and w.isalpha() and (i in (0, len(key) - 1)) and w in letters:
                    spoken = letters[w]
                    forms.setdefault(key[:i] + (spoken,) + key[i + 1:], set()).add(lm.name)
                    series.setdefault((i, key[:i] + key[i + 1:]), set()).add(lm.name)
                    if owners.get(spoken, set()) <= {lm.name}:
                        forms.setdefault((spoken,), set()).add(lm.name)
    out = []
    for key, names in sorted(forms.items()):
        if len(names) != 1 or key in keys:
            continue
        name = next(iter(names))
        if len(key) == 1 and not any(len(v) >= 2 and name in v for v in series.values()):
            continue
        out.append((key, name))
    return out


def _cue_list_into(k: int, later: int, segs: list[tuple[int, int]], seg_cues: dict[int, list[CueMention]],
                   norms: tuple[str, ...]) -> bool:
    """Segment ``k`` is only a danger named as the first of a list that segment ``later`` goes on with
    ("sparks | and smoke coming off the water tower"): the list is said of the place it ends with."""
    a, b = segs[k]
    covered = {i for c in seg_cues.get(k, []) for i in range(c.start_tok, c.end_tok)}
    if not covered or any(i not in covered and norms[i] not in lx.FILLERS | lx.DETERMINERS | _LIST_OPENERS
                          for i in range(a, b)):
        return False
    a2 = segs[later][0]
    if norms[a2] != "and":
        return False
    i = a2 + 1
    while i < segs[later][1] and norms[i] in lx.FILLERS | lx.DETERMINERS:
        i += 1
    return any(c.start_tok == i for c in seg_cues.get(later, []))


# A sentence that says all is well guesses no claim for its places ("..., no problems seen")
_ALL_WELL = frozenset({("no", "problems"), ("no", "problem"), ("no", "issues"), ("nothing", "wrong"), ("all", "quiet"),
                       ("no", "damage"), ("to", "report")})  # ("nothing to report")
_PERSON_WORDS = frozenset(lx.PERSON_NOUNS) | {"pensioner", "residents", "neighbour", "neighbor", "tenant", "tenants",
                                              "lady", "gentleman", "family", "pupil", "kid", "child", "children"}
# Any word for people, a group said as a subject too ("the men in there", "the folk at the chapel")
_UNREACHABLE = (("cant", "get", "hold", "of"), ("not", "answering"), ("isnt", "answering"), ("hes", "not", "answering"),
                ("she", "not", "answering"), ("shes", "not", "answering"), ("not", "picking", "up"))
# Words of a relation name that put its subject higher or lower than its object ("is built over", "lies_beneath")
_UPPER_WORDS = frozenset({"over", "above", "atop", "uphill", "upslope"})
_LOWER_WORDS = frozenset({"under", "below", "beneath", "underneath", "downhill", "downslope"})


def _vertical_sense(phrase: str) -> int | None:
    """Does a relation name put its subject higher (1: "is built over", "sits above") or lower (-1: "lies_beneath",
    "is downhill of") than its object; None where it says neither (or a view: "looks out over")."""
    said = norm_phrase(phrase.replace("_", " "))
    words = set(said)
    if words & {"look", "looks", "overlook", "overlooks", "watch", "watches", "view", "views", "spill", "spills"}:
        return None
    if "over" in words and said[-1:] != ("over",):
        words = words - {"over"}  # ("leads over to": across, not above; "is built over": above)
    up, down = bool(words & _UPPER_WORDS), bool(words & _LOWER_WORDS)
    return None if up == down else (1 if up else -1)


# The parts of a place a relation's name may say in other words ("the foot of" / "the bottom of" / "the base of")
_PART_SYNONYMS = {"foot": ("bottom", "base"), "bottom": ("foot", "base"), "base": ("foot", "bottom")}
# Verbs of a check done by someone ("checked by the fire department": the doer, no place spoken of)
_CHECKED_BY = frozenset({"checked", "inspected", "searched", "cleared", "surveyed", "assessed", "swept", "declared",
                         "passed", "approved", "certified", "signed"})
# Words that add a place to what was said of the one before ("and on the building that looks down on the vents too")
_ADDING = frozenset({"too", "also", "as"})
# Words that place a place by another ("Graveyard behind Bethel is flooded")
_PLACING_PREPOSITIONS = frozenset({"behind", "beside", "next", "opposite", "above", "below", "beneath", "under", "near"})
# Vehicles that come and go through a place ("ambulance is coming in through the car park")
_MOVING_VEHICLES = frozenset({"ambulance", "ambulances", "appliance", "appliances", "truck", "van", "bus", "coach",
                              "helicopter"})
# Prepositions that bind a cue to the place after it ("he fell off the uh the water tank")
_BINDING_PREPOSITIONS = frozenset(lx.PREPOSITIONS | {"off"})
# First words of the direction families' members ("below", "down the hill", "further inland")
_DIRECTION_BARE = frozenset(m.split()[0] for fam in lx.DIRECTION_FAMILIES.values() for m in fam)
# The parts of a building that fall in ("the roof of the vehicle hangar is down": collapsed)
_FALLING_PARTS = frozenset({"roof", "ceiling", "gable", "chimney", "spire", "tower", "canopy", "floor"})
# The parts of a place that hold it up or hold water in ("the wall of the slurry pond has gone", "lagoon banks going")
_HOLDING_PARTS = frozenset({"wall", "walls", "bank", "banks"})
# What spans or holds back water, besides the structures of a building ("Jenny's arch has gone.": collapsed)
_SPANS = frozenset({"arch", "span", "viaduct", "weir", "dam", "bund", "embankment", "footbridge", "culvert",
                    "aqueduct", "pier", "jetty", "quay", "sluice", "lock", "gate"})
# Bodies of water that head a description of a place ("the pool the header tank feeds"; not "the drains", any drains)
# The reason a place "that <head>" takes up from a description said before carries ("whatever that pool drains into")
_THAT_MODIFIER = "modifier of 'that "
_WATER_HEADS = frozenset({"pool", "pond", "lake", "reservoir", "lagoon", "ditch", "canal", "channel", "moat", "tarn",
                          "cistern", "mere", "loch", "creek", "brook", "stream", "river"})
# Ground that water out of its bed runs over ("the ditch is over the road")
_OVERRUN_GROUND = frozenset({"road", "lane", "track", "path", "towpath", "footpath", "field", "fields", "drive",
                             "street", "causeway", "bank", "banks", "top"})
# Water that stands or is held, besides the flowing kind ("the dew pond's bone dry": no water in it)
_STILL_WATERS = frozenset({"pond", "pool", "reservoir", "ditch", "drain", "dyke", "rhyne", "well", "fountain", "lagoon",
                           "moat", "leat", "cistern", "tarn", "lido"})
# Collective nouns for people ("the school group", "the walking party").
# (word keys: "parties" is "partie")
_PEOPLE_GROUPS = frozenset({"group", "party", "partie", "class", "classe", "team", "crowd", "family", "familie", "tour",
                            "trip", "pupil", "children", "kid", "visitor", "guest", "resident", "staff"})
_PEOPLE_WORDS = _PERSON_WORDS | lx.LAY_PERSONS | lx.WORKER_PERSONS | {"men", "women", "folk", "folks"}
_PEOPLE_OR_GROUPS = _PEOPLE_WORDS | _PEOPLE_GROUPS
_LIST_OPENERS = frozenset({"and", "there", "theres", "is", "are", "lots", "of", "loads", "some", "also", "got", "weve"})


def _description_list_items(description: str) -> list[tuple[str, ...]]:
    """The items of a list a category description gives after a colon or a dash, as token keys of two or
    three words: "Storm damage - collapsed or loose masonry, fallen trees." -> loose masonry, fallen trees (a
    single word is left to the vocabulary: "checked", "rock", "vehicle" are too loose alone).

    >>> _description_list_items("Danger from the storm - loose masonry, fallen trees or downed power lines.")
    [('loose', 'masonry'), ('fallen', 'tree'), ('downed', 'power', 'line')]
    """
    out: list[tuple[str, ...]] = []
    for sentence in re.split(r"(?<=[a-z])\.\s|\.$", description):
        m = re.search(r":\s|\s[-\u2013\u2014]\s", sentence)
        if m is None:
            continue
        items = re.split(r"\s[-\u2013\u2014]\s", sentence[m.end():])[0]  # (to a second dash: "- that makes it ...")
        for part in re.split(r",|;|\bor\b|\band\b", items):
            key = norm_phrase(part)
            while key and key[0] in lx.DETERMINERS:
                key = key[1:]
            if 2 <= len(key) <= 3 and not set(key) & lx.FUNCTION_WORDS and all(len(w) >= 3 for w in key) \
                    and key not in out:
                out.append(key)
    return out


def _call_sign_at(toks: Tokens, norms: tuple[str, ...], p: PlaceMention) -> bool:
    """A sentence that is only a call sign and where it is: "Rescue Two at the gorge.", "Fire One, at the mill, over"."""
    s0 = p.start_tok
    while s0 > 0 and not toks.sentence_start[s0]:
        s0 -= 1
    before = [i for i in range(s0, p.start_tok) if norms[i] not in lx.FILLERS and norms[i] not in lx.ARTICLES]
    if len(before) == 4 and norms[before[2]] in ("up", "down", "out", "over", "round", "now"):
        before.pop(2)  # "Fire 3 up on the wall walk."
    if len(before) != 3 or norms[before[2]] not in ("at", "on", "by", "in") \
            or not toks.tokens[before[0]].text[:1].isupper() \
            or not (is_number(norms[before[1]]) or norms[before[1]] in lx.NUMBER_WORDS or norms[before[1]] == "one"):
        return False
    e = p.end_tok
    while e < len(norms) and not toks.sentence_start[e]:
        if norms[e] not in ("over", "here", "now") and norms[e] not in lx.FILLERS:
            return False
        e += 1
    return True


def _not_seen_yet(norms: tuple[str, ...], k: int) -> bool:
    """The words after a denied cue say only that it is not seen (yet): "no flames visible yet", "no flames yet"."""
    return norms[k:k + 1] in (("yet",), ("visible",)) or norms[k:k + 2] in (
        ("showing", "yet"), ("seen", "yet"), ("as", "yet"), ("that", "we"))


def _noun_phrase_start(norms: tuple[str, ...], p: PlaceMention) -> int:
    """Where the noun phrase of a place mention begins: at its article, if one stands before it."""
    return p.start_tok - 1 if p.start_tok >= 1 and norms[p.start_tok - 1] in lx.ARTICLES else p.start_tok


def _after_same(norms: tuple[str, ...], i: int) -> bool:
    """Token ``i`` follows "the same" / "that same" / "this same": the one said before."""
    return i >= 2 and norms[i - 1] == "same" and norms[i - 2] in ("the", "that", "this")


def _same_stem(a: str, b: str) -> bool:
    """Loose stem match of two word keys: "flooding"/"floodwater", "leak"/"leaking", "subsided"/"subsidence"."""
    n = min(len(a), len(b))
    if n < 4:
        return a == b
    k = max(4, n - 3)
    return a[:k] == b[:k] and (a.startswith(b[: len(b) - 3]) or b.startswith(a[: len(a) - 3]) or a[:5] == b[:5])


def _past_approach(norms: tuple[str, ...], b: int) -> int:
    """Past "the way into", "the approach to" from token ``b`` (where a relation phrase ends), to the anchor
    named after it; else ``b``.

    >>> _past_approach(("guarding", "the", "way", "into", "reception"), 1)
    4
    """
    if norms[b:b + 1] == ("the",) and b + 3 < len(norms) and norms[b + 1] in lx.APPROACH_NOUNS \
            and norms[b + 2] in ("into", "to", "of", "for"):
        return b + 3
    return b


def _phrases(phrases: Iterable[str]) -> PhraseMatcher[str]:
    """A longest-match, non-overlapping matcher of ``phrases`` (each its own payload)."""
    matcher: PhraseMatcher[str] = PhraseMatcher()
    for phrase in phrases:
        matcher.add(norm_phrase(phrase), phrase)
    return matcher


# The verbs of a relation that names a state ("is dug into the yard of", "stands in the shadow of")
_STATE_VERBS = frozenset({"is", "are", "was", "were", "stands", "sits", "lies", "stand", "sit", "lie"})
# Water a thing may fall into without the water being hit ("it's collapsed into the drain")
WATERCOURSE_WORDS = frozenset(lx.WATER_BODIES | {"drain", "dyke", "dike", "ditch", "leat", "goit", "lade", "water",
                                                  "channel", "cut", "pond", "reservoir", "estuary", "harbour", "dock"})
# Parts every building has: no head of a recombined name ("the fire doors" is no "the red doors" fire station)
_COMMON_PART_HEADS = frozenset({"door", "doors", "window", "windows", "step", "steps", "roof", "wall", "walls"})
# "don't know where it's coming from"; "source identified as": one hit per place in the text, the longest
_UNKNOWN_SOURCE = _phrases(lx.UNKNOWN_SOURCE)
_SOURCE_IS = _phrases(lx.SOURCE_IS)
# Coordinating phrases and false-alarm markers as token keys, computed once.
_COORDINATOR_KEYS = [norm_phrase(p) for p in lx.COORDINATOR_PHRASES]
_FALSE_ALARM_KEYS = [(p, norm_phrase(p)) for p in lx.FALSE_ALARM]
_EXERCISE_KEYS = [norm_phrase(p) for p in lx.EXERCISE_FRAME]
_CREW_POSITION = "in transit (a crew's position): no claim"
# Verbs of a danger or of people on the move: a place they go "towards" is not yet reached
_ON_THE_MOVE = frozenset({"running", "spreading", "moving", "heading", "creeping", "racing", "burning", "drifting",
                          "working", "making", "travelling", "traveling", "edging", "rolling", "flowing", "sliding",
                          "advancing", "pushing", "blowing", "going", "walking", "driving", "crawling", "jumping",
                          "takes", "take", "taking", "rowing", "paddling", "steering"})
_SIDE_WORDS = frozenset({"on", "at", "the", "east", "west", "north", "south", "far", "other", "near", "side", "end",
                         "edge", "of", "eastern", "western", "northern", "southern", "rim"})
_PERSON_KEYS = frozenset(w for p in lx.PERSON_NOUNS for w in norm_phrase(p))

# The withdrawal markers ("scratch that") as token keys joined by spaces.
_WITHDRAW_KEYS = frozenset(" ".join(norm_phrase(m)) for m in lx.WITHDRAW_MARKERS)


def _moved_from(norms: tuple[str, ...], p: PlaceMention, others: list[PlaceMention]) -> bool:
    """``p`` is where people were taken from: "from the hotel over to the town park" (another of ``others`` after
    it, with "to" between)."""
    return "from" in norms[max(0, p.start_tok - 2):p.start_tok] and any(
        r.start_tok > p.end_tok and "to" in norms[p.end_tok:r.start_tok] for r in others)


def _description_head(description: str) -> str | None:
    """The noun a landmark's description opens on: "The stream that runs from the spillway" -- "stream", "Tall stone
    draw-off tower standing in the reservoir" -- "tower", "Terrace of low cottages" -- "terrace"."""
    words = [w for w in norm_phrase(description)]
    while words and words[0] in lx.ARTICLES:
        words.pop(0)
    head = None
    for i, w in enumerate(words):
        nxt = words[i + 1] if i + 1 < len(words) else ""
        if w in ("that", "which", "with", "where", "who") or w in lx.PREPOSITIONS \
                or w.endswith(("ing", "ed")) and len(w) > 5 and w not in lx.GENERIC_HEADS \
                and nxt in lx.PREPOSITIONS | lx.ARTICLES:
            break
        if w == "and":
            continue  # ("Caravan and camping field below the quarry face")
        if w in ("just", "right", "directly", "immediately", "high", "low", "far", "well") \
                and nxt in lx.PREPOSITIONS | lx.SPATIAL_WORDS | lx.BARE_DIRECTIONS | {"behind", "beside", "under", "over"}:
            break  # ("Grated access walkway just above the waves": where it is begins)
        if w in lx.FUNCTION_WORDS:
            return None  # ("Small pharmacy shop built onto ...": no plain noun phrase to read a head from)
        head = w
    else:
        return None
    if head is None or not head.isalpha() or len(head) < 4 or head in lx.DESCRIPTIVE_WORDS | lx.RELATION_ENDINGS \
            or head in ("line", "group", "pair", "cluster", "series", "collection", "couple"):
        return None  # (a collective noun: "A line of turf-and-stone shooting butts")
    return head


def _withdraws(marker: tuple[str, ...]) -> bool:
    """Is a marker's wording a withdrawal ("scratch that"; said twice, "cancel that, cancel that")?"""
    words = " ".join(marker)
    return any(words == m or words.startswith(m + " ") for m in _WITHDRAW_KEYS)


class _CancelMatcher(PhraseMatcher[str]):
    """Phrases that cancel a claim before them; "he's out" (got out) is none in "he's out of it" / "he's out cold"
    (dazed, unconscious), "gone" none in "gone up" (caught fire) or "gone into" (moved), "stopped" none in
    "stopped short of"."""

    def match_at(self, norms: tuple[str, ...], i: int, blocked: Iterable[int] = ()) -> tuple[int, str] | None:
        hit = super().match_at(norms, i, blocked)
        if hit is not None and hit[1].endswith(" out") and (
                norms[hit[0]:hit[0] + 2] == ("of", "it") or norms[hit[0]:hit[0] + 1] == ("cold",)):
            return None
        if hit is not None and hit[1].endswith("gone") and norms[hit[0]:hit[0] + 1] in (
                ("up",), ("into",), ("onto",), ("through",), ("across",), ("over",)):
            return None  # "the gas ring's gone up", "sparks have gone into the dry grass": caught fire, moved; not gone
        if hit is not None and hit[1].endswith(" over") and norms[hit[0]:hit[0] + 1] in (
                ("topping",), ("flowing",), ("spilling",), ("running",)):
            return None  # "the lagoon is over-topping": the word written apart, the danger itself; nothing over
        if hit is not None and hit[1].endswith("landed") and norms[hit[0]:hit[0] + 1] in (
                ("on",), ("in",), ("at",), ("onto",), ("near",), ("by",), ("across",)):
            return None  # "embers landed on the thatch": where they fell, nothing set down safely
        if hit is not None and hit[1].endswith("stopped") and "short" in norms[hit[0]:hit[0] + 2]:
            return None  # "the debris stopped short of the track": the danger is there, only not as far as that
        return hit


# Verbs that send water or stuff somewhere ("the pumps push water up to"), before a cue phrase that is a relation's
_PUSHING_VERBS = frozenset(w for v in ("push", "pushes", "pump", "pumps", "send", "sends", "pipe", "pipes", "feed", "feeds",
                                        "lift", "lifts", "carry", "carries", "drive", "drives", "force", "forces")
                            for w in (v, *norm_phrase(v)))  # (as the tokens are normalised: "pushes" is "pushe")


def _stranded_relation_cue(norms: tuple[str, ...], a: int, b: int) -> bool:
    """"the tank the pumps push water up to has split": a cue phrase ("water up to") that ends on a preposition with
    no object, after a verb of sending, is the words of a relation whose object was said before it."""
    if b - a >= 2 and norms[b - 1] in ("the", "that", "this") and norms[b - 2] in ("to", "into", "onto"):
        b -= 1  # ("water up to the": the cue took the object's article)
    return norms[b - 1] in ("to", "into", "onto") and a > 0 and norms[a - 1] in _PUSHING_VERBS \
        and (b == len(norms) or norms[b] in lx.COPULAS | {"has", "have", "had"}
             or norms[b] in ("the", "that", "this", "it", "them") and a >= 2
             and norms[a - 2] in ("whatever", "what", "thing", "one", "that", "which"))
    # (or the relation said forward, from a description: "whatever pushes water up to the tower")


def _stove_in(toks: Tokens, norms: tuple[str, ...], a: int) -> bool:
    """"the front wall's stove in", "the door's been stove in": smashed in (not "the stove in the refuge")."""
    return a > 0 and (norms[a - 1] in ("s", "is", "been", "was", "were", "are", "got", "get", "had", "has", "have",
                                       "all", "completely")
                      or toks.tokens[a - 1].text.lower().replace("’", "'").endswith("'s")) \
        and norms[a + 2:a + 3] not in (("the",), ("a",), ("an",), ("our",), ("their",), ("there",), ("here",))


_ANIMAL_STATE_KEYS = frozenset(norm_phrase(s) for s in lx.ANIMAL_STATES)
# "down there", "up there": said between a description's head and its "where"
# Particles after a participle of where a thing is put ("tucked in behind", "set back from", "hidden away behind")
_TUCKED_PARTICLES = frozenset({"in", "away", "up", "back", "off", "down", "out"})
_THERE_ADVERBS = frozenset({(w, "there") for w in ("down", "up", "over", "in", "under", "out", "back")})
# Where a part of a place is, said before the place ("from under the stadium, the room down there where ...")
_UNDER_WORDS = frozenset({"under", "beneath", "underneath", "below", "behind", "above"})
_COMPASS = frozenset({"north", "south", "east", "west", "northeast", "northwest", "southeast", "southwest"})
# Closed-class words that never head a description.
_NOT_HEADS = lx.PREPOSITIONS | lx.COPULAS | lx.FILLERS | lx.PRONOUNS | lx.INVERSE_VERBS | lx.DETERMINERS


# Plain outbuilding nouns a description may head whatever the place is called ("the shed where they keep the oxygen
# and acetylene bottles" for a "mesh-walled store")
_SHED_HEADS = frozenset({"shed", "hut", "cabin"})
# The parts of a building said in the plural ("the shed roofs", "the cottage doors")
_PART_PLURALS = frozenset({w + "s" for w in lx.STOREY_WORDS | lx.PART_NOUNS} | {"doors", "windows"})
# Words of a repair said between a name cut off and the one put in its stead ("st— no hang on, it's the")
_REPAIR_GAP_WORDS = frozenset({"no", "wait", "hang", "on", "sorry", "i", "mean", "its", "it", "is", "s", "the", "a", "an",
                               "oh", "actually", "correction", "at", "in"})
# What a place may go under that is water, not a thing ("gone under a foot of water", "went under a wave")
_UNDER_AMOUNTS = frozenset({"foot", "feet", "metre", "metres", "meter", "meters", "yard", "few", "lot", "couple", "sheet",
                            "wave", "boat", "bit", "good"})
# ... and all that "gone under a ..." may be the flood again (both "gone under" readers take this one set)
_UNDER_WATER = _UNDER_AMOUNTS | lx.WATER_WORDS | lx.WATER_BODIES | {"surface", "ice"}
# A person's state that being got out of a place does not end ("unconscious ..., we've pulled him out")
_STILL_ILL = frozenset({("unconscious",), ("not", "breathing"), ("not", "responding"), ("unresponsive",), ("cpr",),
                        ("cardiac", "arrest"), ("seizure",), ("fitting",), ("near", "drowning")})


def _out_and_still_ill(phrase: str, said: tuple[str, ...]) -> bool:
    """"a guest is unconscious in the rotenburo, we've pulled him out": got out of the place (``phrase``, a cancel
    phrase), and the state said of the person (``said``, a cue's words) goes on; nothing is taken back."""
    return phrase.split()[0] in ("pulled", "got", "gotten", "taken", "took", "brought") and phrase.endswith(" out") \
        and said in _STILL_ILL


def _walked_out_to(norms: tuple[str, ...], hit: tuple[int, str]) -> bool:
    """"frostbite case in the hut, she walked out there through the herbie": "walked out" (``hit``, a cancel match)
    to somewhere, where she went, not out of it."""
    return hit[1] == "walked out" and norms[hit[0]:hit[0] + 1] in (("there",), ("to",), ("towards",))
# Words that say someone is lost ("missing in the dorms", "the separated child"): a lost one's people and finding
_LOST_WORDS = frozenset({"lost", "missing", "separated"})
# Of two critical categories, the one for the lost: its description says lost or missing and no hurt; what a phrase
# says of someone lost ("can't find my nan", "overdue") or hurt ("fainted", "chest pains") picks between them
_LOST_CATEGORY_WORDS = frozenset(norm_phrase("lost missing"))
_HURT_CATEGORY_WORDS = frozenset(norm_phrase("hurt injured ill injury trapped"))
_SAID_LOST_WORDS = _LOST_CATEGORY_WORDS | frozenset(norm_phrase(
    "unaccounted overdue separated seen wandered wandering find found contact whereabouts"))
_SAID_HURT_WORDS = frozenset(norm_phrase(
    "fainted faint collapsed collapse hurt injured injury bleeding blood burn burned burnt unconscious broken fell fall "
    "stung bitten breathing cut down trapped pinned stroke attack chest pains casualty casualties hypothermic"))
# Words with "lost" that are no one missing ("lost a finger", "lost consciousness", "lost his footing")
_LOST_NOT_MISSING = frozenset({"finger", "fingers", "consciousness", "blood", "footing", "grip", "balance", "brakes",
                               "power", "control"})
# A lost child's people ("mum's turned up")
_KIN = frozenset({"mum", "mom", "mam", "dad", "nan", "gran", "grandma", "grandad", "mother", "father", "parents", "parent",
                  "family"})
# Substances that, said before a noun, only say what a thing holds or runs on ("the diesel day tank")
_SUBSTANCE_MODIFIERS = frozenset({"diesel", "petrol", "fuel", "oil", "chlorine", "ammonia", "kerosene", "avgas"})
# ... and the nouns after them that are the danger itself ("chlorine release", "diesel slick")
_SUBSTANCE_EVENTS = frozenset({"release", "leak", "leaks", "spill", "spills", "cloud", "smell", "fume", "fumes", "vapour",
                               "escape", "slick", "sheen", "everywhere", "gas", "film", "spray", "mist", "plume"})
_DERIVING_ENDINGS = ("er", "ers", "ing", "ings")


def _derived_word(word: str, known: frozenset[str], endings: tuple[str, ...] = _DERIVING_ENDINGS) -> bool:
    """An English word the vocabulary holds only by its stem and a common ending: "heater" ("heat"), "planking",
    "beached"."""
    return any(word.endswith(e) and len(word) - len(e) >= 4 and word[:-len(e)] in known for e in endings)


def _still_to_come(norms: tuple[str, ...], end: int) -> bool:
    """Words right after a destination (ending at token ``end``) that put the move later: "moving them to the first aid
    post shortly", "... in a minute"."""
    return norms[end:end + 1] in (("shortly",), ("soon",), ("later",)) or norms[end:end + 3] in (
        ("in", "a", "minute"), ("in", "a", "bit"), ("in", "a", "moment"), ("in", "a", "sec"))


def _names_what_came(norms: tuple[str, ...], p: PlaceMention) -> bool:
    """A one-word name that here says what came, not where: "it's got the river in the bar" (the flood come in),
    "the path has been buried by the slip" (the landslip that did it)."""
    a = p.start_tok
    if p.end_tok - a != 1 or a < 2 or norms[a - 1] != "the":
        return False
    if norms[a] in ("rock", "stone", "boulder", "rubble", "debris", "tree", "log") and norms[a - 2] in (
            "under", "beneath", "underneath") and any(w in ("trapped", "pinned", "buried", "stuck", "crushed")
                                                     for w in norms[max(0, a - 5):a - 2]):
        return True  # "Rockfall on the track ..., and a walker's trapped under the rocks": what fell on him
    if norms[a] in lx.WATER_BODIES and norms[a - 2] in ("got", "get", "getting") \
            and norms[p.end_tok:p.end_tok + 1] in (("in",), ("into",)):
        return True
    if norms[a] in lx.WATER_BODIES and a >= 3 and norms[a - 2] == "by" and norms[a - 3] in (
            "off", "surrounded", "stranded", "isolated", "marooned"):
        return True  # "stranded on the picnic field, cut off by the river": the water that strands them
    return norms[a] in lx.EVENT_NOUNS and a >= 3 and norms[a - 2] == "by" and norms[a - 3] in lx.CAUSED_BY_VERBS


def _exercise_frame(norms: tuple[str, ...]) -> bool:
    """The report is an exercise or training message: it opens "Exercise, exercise" or says "this is an
    exercise", "simulated casualty", "training scenario" (not "this is not a training scenario")."""
    said = [w for w in norms if w not in lx.FILLERS]
    if tuple(said[:2]) == lx.EXERCISE_OPENING:
        return True
    for key in _EXERCISE_KEYS:
        for i in range(len(norms) - len(key) + 1):
            if norms[i:i + len(key)] == key and not {"not", "no", "isnt", "never"} & set(norms[max(0, i - 2):i]):
                return True
    return False


def _is_log(toks: Tokens) -> bool:
    """A control-room log: some sentence opens with a time ("0455 BLEVE risk LPG plant", "02:14 SER ...")."""
    for i in range(len(toks)):
        if not toks.sentence_start[i]:
            continue
        text = toks.tokens[i].text  # "0455", or "02:14", which the tokenizer splits at the colon
        if text.isdigit() and (len(text) == 4 or len(text) <= 2 and i + 1 < len(toks)
                               and toks.gaps[i + 1] == ":" and toks.tokens[i + 1].text.isdigit()):
            return True
    return False


_ACROSS_THE = re.compile(r"^across the \w+ from$")
_TRAILING_DIRECTIONS = {"above", "below", "beneath", "under", "underneath", "behind"}


_PARTICLES = frozenset({"on", "onto", "off", "down", "up", "from", "to", "into", "over", "under", "in", "out", "at",
                        "with", "by", "of", "across", "along", "through", "past", "behind", "above", "below"})


_SAME_PARTICLE = {"on": ("onto",), "onto": ("on",), "in": ("into",), "into": ("in",)}


# Adverbs a relation name may carry that another says in its place ("comes straight after" / "right after")
_ORDER_ADVERBS = ("straight", "right", "just", "directly")
_GROUP_VERBS = {"neighbours": "next to", "neighbors": "next to", "neighbour": "next to", "neighbor": "next to"}


def _relation_core(phrase: str) -> str:
    """The synonym group a relation name belongs to, read through its extra words: without its leading
    adverbs ("directly above" -> "above"), its final direction ("on the levee above" -> "above"), or the
    thing it crosses ("across the channel from" -> "across from").

    >>> [_relation_core(p) for p in ("directly above", "on the levee above", "across the tracks from", "feeds",
    ...                              "built onto the side of", "is built against", "stands opposite")]
    ['above', 'above', 'across from', 'feeds', 'built onto', 'built against', 'opposite']
    """
    words = phrase.split()
    while len(words) > 1 and (words[0] in lx.RELATION_ADVERBS or words[0] in ("is", "are")):
        words = words[1:]  # ("is built against" is a "built against" relation)
    if len(words) > 1 and words[-1] in _TRAILING_DIRECTIONS:
        return words[-1]
    if len(words) == 2 and words[0] in _POSTURES and words[1] in ("opposite", "beside", "alongside", "facing"):
        words = words[1:]  # ("stands opposite" is an "opposite" relation: "the building across the road from")
    if len(words) > 3 and words[-3] == "the" and words[-2] in lx.PART_NOUNS and words[-1] == "of":
        words = words[:-3]  # "built onto the side of" is an "attached to" relation
    core = " ".join(words)
    # (a relation named by a verb of its group's words only: ``museum neighbours players' pavilion`` is "next to";
    # "neighbours" said in a report stays people)
    return "across from" if _ACROSS_THE.match(core) else _GROUP_VERBS.get(core, core)


def _nobody_said(norms: tuple[str, ...], start: int, end: int) -> bool:
    """Does "nobody" ("noone", "no one") begin between ``start`` and ``end`` (``start`` clipped at 0)?

    >>> _nobody_said(("nobody", "has", "brought", "him"), -1, 2), _nobody_said(("no", "one", "out"), 0, 1)
    (True, True)
    """
    return _nobody_at(norms, start, end) is not None


def _nobody_at(norms: tuple[str, ...], start: int, end: int) -> int | None:
    """Where the last "nobody" ("noone", "no one") between ``start`` and ``end`` begins (``start`` clipped at 0), if any.

    >>> _nobody_at(("one", "hurt", "nobody", "at", "the", "tombola", "hurt"), 0, 6)
    2
    """
    return next((j for j in range(end - 1, max(0, start) - 1, -1)
                 if norms[j] in ("nobody", "noone") or norms[j:j + 2] == ("no", "one")), None)


def _reduced_relative_opener(word: str) -> bool:
    """A participle that may open a reduced relative clause ("the tower feeding the boiler", "the house hidden behind").

    >>> [_reduced_relative_opener(w) for w in ("feeding", "hidden", "stacked", "floor", "shed")]
    [True, True, True, False, False]
    """
    w = word.lower()
    return w.isalpha() and len(w) >= 5 and (w.endswith(("ing", "ed")) and w not in ("thing", "nothing", "something",
                                                                                     "building", "ceiling", "landing")
                                            or w in _IRREGULAR_PARTICIPLES)


def _verb_like(word: str) -> bool:
    """A word that may be a clause's verb by its form alone ("powers", "drains", "hidden", "feeding", "built").

    >>> [_verb_like(w) for w in ("drains", "backed", "feeding", "stuck", "road", "past", "its")]
    [True, True, True, True, False, False, False]
    """
    w = word.lower()
    return _reduced_relative_opener(w) or w.isalpha() and len(w) >= 4 and w.endswith("s") and not w.endswith("ss") \
        and w not in lx.FUNCTION_WORDS or w in _IRREGULAR_PARTICIPLES


_MOVING_CREWS = frozenset(lx.CREW_NOUNS | {"crews", "teams", "we"})
_CREW_MOVES = frozenset({"moving", "heading", "going", "headed", "moved", "redeploying", "relocating", "transferring"})
_SUBJECT_PRONOUNS = frozenset({"they", "we", "you", "i", "he", "she", "people", "everyone"})
def _named_passive(phrase: str) -> bool:
    """A KB relation named in the passive ("is_fed_by"): its object is the doer.

    >>> [_named_passive(p) for p in ("is_fed_by", "gravity feeds", "stands by")]
    [True, False, True]
    """
    return phrase.replace("_", " ").endswith(" by")


def _anchor_receives(rel: Relation, anchor: str) -> bool:
    """``anchor`` is what ``rel`` is done to (its object, or the subject of a relation named in the passive)."""
    return (rel.object == anchor) != _named_passive(rel.phrase)


# Words of danger phrases a caller's spelling or speech-to-text writes as another word ("ammonia leek").
_SOUND_ALIKE_WORDS = {"leak": "leek", "leaking": "leeking", "leaked": "leeked", "hole": "whole"}
# Who may clear a place of people ("we've cleared it"), not a danger that has cleared.
_CLEARING_SUBJECTS = frozenset({"ive", "weve", "theyve", "they", "theyre", "ve", "re", "we", "i"})
# The reason of a "cleared" that only says a danger said before it has gone, after "but": it takes no safety back
_CLEARED_AFTER_BUT = "the danger before it was cleared, after 'but'"
# Things, not people, that clear a danger away ("the extraction fans have cleared it": the fumes, not a search)
_CLEARING_THINGS = frozenset({"fan", "fans", "extraction", "extractor", "extractors", "ventilation", "vents", "wind",
                              "breeze", "rain", "pump", "pumps"})
# Danger words that name no kind of danger, only to keep out or get out ("keep everyone out of it").
_UNSPECIFIC_DANGERS = frozenset(norm_phrase(p) for p in (
    "everyone out", "get everyone out", "everybody out", "keep out", "stay out", "stay away", "keep away", "keep clear",
    "no entry", "do not enter", "don't go in", "evacuate", "evacuating", "unsafe", "dangerous", "danger"))
# Verbs of supplying one place from another, whose active voice says which end the doer is ("feeds the tank").
_SUPPLY_VERBS = frozenset({"feeds", "feed", "fed", "supplies", "supply", "supplied", "fills", "fill", "filled",
                           "powers", "power", "powered", "pumps", "pump", "pumped", "drains", "drain", "drained",
                           "serves", "serve", "served", "heats", "heat", "heated", "waters", "water", "watered",
                           "cools", "cool", "cooled", "chills", "chill", "chilled", "lights", "light", "lit",
                           "runs", "drives", "drive", "driven", "empties", "empty", "emptied", "tops", "top",
                           "supplie", "emptie"})  # (the keys of "supplies", "empties")
# Prepositions a relative clause leaves at its end ("the water the pump house draws from")
_STRANDED_ENDS = frozenset({"from", "to", "into", "onto", "off", "over", "under"})
# Heads that say a building ("the building at the shore end of it"), and the name words of landmarks that are none.
_BUILDING_HEADS = frozenset({"building", "house", "hut", "shed", "block", "office"})
_OPEN_OR_AFLOAT = frozenset({"float", "floats", "barge", "scow", "boat", "boats", "pontoon", "pontoons", "raft", "hulk",
                             "ship", "vessel", "tender", "wharf", "quay", "jetty", "pier", "dock", "berth", "mooring",
                             "moorings", "slipway", "ways", "flats",
                             "mudflats", "beach", "field", "meadow", "paddock", "yard", "lot", "park", "green",
                             "river", "creek", "stream", "beck", "pond", "lake", "lagoon", "canal", "ditch", "road",
                             "track", "lane", "path", "walkway", "boardwalk", "bridge", "dam", "dike", "bank",
                             "bluff", "knoll", "hill", "ridge", "dunes", "bog", "marsh", "swamp", "bed", "beds"})
# Nouns for a way along which people go, besides the road words ("the catwalk down to the stinker").
_WAY_NOUNS = frozenset({"walkway", "catwalk", "boardwalk", "footpath", "causeway", "gangway", "towpath", "steps",
                        "stairs", "ladder", "ramp", "slipway", "trail", "alley", "passage", "tunnel"})
_DOERS = frozenset(lx.LAY_PERSONS) | frozenset(lx.WORKER_PERSONS) | frozenset(lx.PERSON_NOUNS)  # ("a woman visiting ...")
_IRREGULAR_PARTICIPLES = frozenset({"hidden", "built", "stuck", "tucked", "set", "dug", "cut", "bolted", "sunk", "hung",
                                    "wedged", "perched", "known", "run", "kept", "held", "fed", "lit", "laid", "left"})


def _reads_backwards(link: str, phrase: str, inverse: bool) -> bool:
    """The direction of a relation form as a linking phrase says it: an antonym in the phrase
    ("downhill" against "uphill") reads it the other way."""
    flip = any(lx.ANTONYMS.get(w) in phrase.split() for w in link.split()) != _ends_opposite(link, phrase)
    return not inverse if flip else inverse


def _ends_opposite(link: str, phrase: str) -> bool:
    """Does a linking phrase end on "from" where a relation name ends on "to" (or the other way round)? "wherever
    the pump house draws its fuel from" said against ``pumps fuel out to``: the fuel comes the other way."""
    ends = link.split()[-1:], phrase.replace("_", " ").split()[-1:]
    return ends[0] == ["from"] and ends[1] in (["to"], ["into"], ["onto"]) \
        or ends[1] == ["from"] and ends[0] in (["to"], ["into"], ["onto"])


def _name_head(form: str) -> str:
    """The head word of a landmark's name, the word before a trailing number or letter ("refuge bay 4",
    "cabin row A") and the last part of a hyphenated one; "" for a one-word name.

    >>> _name_head("refuge bay 4"), _name_head("cross-passage 2"), _name_head("east portal"), _name_head("gym")
    ('bay', 'passage', 'portal', '')
    """
    words = list(name_words(form))
    if len(words) >= 2 and (words[-1].isdigit() or len(words[-1]) == 1 or words[-1] in lx.NUMBER_WORDS):
        words = words[:-1]
    return words[-1].split("-")[-1] if len(words) >= 2 and words[-1].isalpha() else ""


def _passive_name(phrase: str) -> bool:
    """Is a relation name passive the way ``_relation_keywords`` reads voices ("supplied by": its verb, said,
    reads the relation backwards)?

    >>> _passive_name("supplied by"), _passive_name("supplies power to"), _passive_name("fed by the main from")
    (True, False, False)
    """
    words = phrase.split()
    return len(words) >= 2 and words[-1] == "by"


def _direction_word(word: str) -> bool:
    """Does the word set a direction ("upstream", "north") rather than a voice ("feeds" / "fed")?

    >>> _direction_word("upstream"), _direction_word("feeds"), _direction_word("paired")
    (True, False, False)
    """
    other = lx.ANTONYMS.get(word)
    return other is not None and not (_link_stems(word, synonyms=False) & _link_stems(other, synonyms=False))


def _link_stems(word: str, synonyms: bool = True) -> set[str]:
    """Stems of a word of a relation phrase, with its link synonyms.

    >>> sorted(_link_stems("tunnelled")) == sorted(_link_stems("tunnels"))
    True
    >>> "feed" in _link_stems("supplied") and "feed" in _link_stems("fed")
    True
    """
    w = word.lower().replace("'", "").replace("’", "")
    w = lx.IRREGULAR_PARTICIPLES.get(w, w)
    for suffix, repl in (("ies", "y"), ("ied", "y"), ("ing", ""), ("ed", ""), ("es", ""), ("s", "")):
        if w.endswith(suffix) and len(w) - len(suffix) >= 3 and not (suffix == "s" and w.endswith("ss")):
            w = w[: -len(suffix)] + repl
            break
    if len(w) > 4 and w[-1] == w[-2] and w[-1] not in "aeiou":
        w = w[:-1]  # tunnell -> tunnel
    if len(w) > 3 and w[-1] in "ey":
        w = w[:-1]
    stems = {w}
    if not synonyms:
        return stems
    for group in lx.LINK_SYNONYMS:
        if w in group:
            stems |= group
    return stems


def _relation_forms(phrase: str) -> list[tuple[str, bool]]:
    """Forward and inverse surface forms of a KB relation name.

    >>> ("overlooked by", True) in _relation_forms("overlooks")
    True
    >>> ("downstream of", True) in _relation_forms("upstream of")
    True
    >>> ("on the front of", False) in _relation_forms("is built onto the front of")
    True
    """
    words = phrase.split()
    out: list[tuple[str, bool]] = [(phrase, False)]
    if len(words) >= 5 and words[-4] in ("onto", "against", "on", "to") and words[-3] == "the" \
            and words[-2] in ("front", "back", "side", "end", "rear") and words[-1] == "of":
        # "is built onto the front of": the shop "on the front of" the hangar, "at the back of" it
        out.extend((f"{prep} the {words[-2]} of", False) for prep in ("on", "at") if prep != words[-4])
    # "guards the approach to" said short: "the yard the gatehouse guards", "the cross it overlooks"
    cut = next((i for i, w in enumerate(words) if i >= 1 and w in lx.ARTICLES), None)
    if cut is not None and words[0].endswith("s") and not words[0].endswith("ss") and words[0] not in lx.GENERIC_VERBS \
            and words[0] not in lx.COPULAS and not _direction_word(words[0]):
        out.extend(_relation_forms(" ".join(words[:cut])))
    if len(words) >= 4 and words[0].endswith("s") and not words[0].endswith("ss") and words[0] not in lx.COPULAS \
            and words[1].isalpha() and words[1] not in lx.FUNCTION_WORDS and words[-1] in lx.RELATION_ENDINGS:
        # "the pavilion that draws its cooling water from the lake" for ``draws cooling water from``
        out.extend((" ".join([words[0], owner, *words[1:]]), False) for owner in ("its", "their"))
    if len(words) == 3 and words[0].endswith("s") and not words[0].endswith("ss") and words[0] not in lx.COPULAS \
            and words[1].isalpha() and len(words[1]) >= 4 and words[1] not in lx.FUNCTION_WORDS \
            and words[1] not in lx.DIRECTION_FAMILIES and not _direction_word(words[1]) \
            and words[2] in ("from", "to", "into", "onto"):
        # "the plant that draws from the pond" for ``draws water from``: what it draws left unsaid
        out.extend(f for f in _relation_forms(f"{words[0]} {words[2]}") if not f[1])
    if len(words) >= 4 and words[0].endswith("s") and words[1] in ("up", "down") \
            and words[2] in ("out", "off", "over", "into", "onto", "through"):
        # "the ramp that climb out of the test hall" for ``climbs up out of``
        out.extend(f for f in _relation_forms(" ".join([words[0], *words[2:]])) if not f[1])
    # direction words: "seaward of" is also "on the sea side of"; "landward of" reads it backwards
    for i, w in enumerate(words):
        if w not in lx.DIRECTION_FAMILIES:
            continue
        tail = words[i + 1 :]
        tails = [tail] if not tail or tail[0] not in ("of", "from") else [["of"], ["from"]]
        # a posture said or not: "lies upstream of" is "the building downstream of it" read backwards
        heads = [words[:i]] + ([[]] if i == 1 and words[0] in _POSTURES else [])
        for family, inverse in ((w, False), (lx.OPPOSITE_DIRECTION[w], True)):
            for member in lx.DIRECTION_FAMILIES[family]:
                for t in ([[]] if member in lx.BARE_DIRECTIONS else tails):
                    out.extend((" ".join(head + [member] + t), inverse) for head in heads)
    # "faces across the burn to": the place "across the burn from" the other, read forwards
    for i, w in enumerate(words):
        if w == "across" and i + 3 < len(words) and words[i + 1] == "the" and words[i + 3] in ("to", "from", "at"):
            for end in ("from", "to"):
                out.append((" ".join(["across", "the", words[i + 2], end]), False))
    # antonym swap reads the relation backwards: "upstream of" -> "downstream of"
    swapped = [lx.ANTONYMS.get(w, w) for w in words]
    if swapped != words:
        out.append((" ".join(swapped), True))
    # (an adverb inside said another way: "whatever comes right before the wax tunnel" for ``comes straight after``)
    for ws, inverse in ((words, False), (swapped, True)) if swapped != words else ((words, False),):
        if len(ws) == 2 and ws[0] in _ORDER_ADVERBS:
            out.append((ws[1], inverse))  # ("the feature before the final jump": the adverb left unsaid)
        for i, w in enumerate(ws[:-1]):  # ("straight after" said "the section right before ...", read backwards)
            if w in _ORDER_ADVERBS and (i > 0 or len(ws) == 2):
                out.extend((" ".join([*ws[:i], other, *ws[i + 1:]]), inverse) for other in _ORDER_ADVERBS if other != w)
    if words[0] in ("sits", "stands", "lies") and len(words) >= 4 and words[-1] in ("with", "to", "of"):
        out.append((" ".join(words[1:]), False))  # "the cottage cheek by jowl with the tea room": the posture unsaid
    elif words[0] in ("runs", "stretches", "extends") and len(words) >= 4 and words[1] in ("along", "across", "around",
                                                                                          "round", "beside", "below") \
            and words[-1] == "of":
        out.append((" ".join(words[1:]), False))  # "the canal along the foot of the dyke road": the way it runs unsaid
    elif words[0] in _POSTURES and 2 <= len(words) <= 3 and words[1] in _POSTURE_PLACES \
            and words[-1] in lx.RELATION_ENDINGS | _SPATIAL_ENDINGS | {"outside"}:
        out.append((" ".join(words[1:]), False))  # "the landing area beside it" for ``sits beside``
    if len(words) >= 4 and words[1] in ("out", "up", "down", "back", "along") and words[0].endswith("s") \
            and words[2] in ("in", "on", "at", "by", "to", "into", "onto", "over", "under", "behind", "beside") \
            and words[-1] in ("of", "to", "with", "from", "onto", "into"):
        out.append((" ".join(words[1:]), False))  # ("spreads out in front of": "the car park out in front of")
    verb = words[0]
    rest = " ".join(words[1:])
    # a plural subject's verb ("flower stalls | huddle under the eaves of"; "river stairs | lead down to")
    plain_verb = len(words) >= 2 and verb.isalpha() and len(verb) >= 3 and verb not in lx.NOT_VERBS \
        and not verb.endswith(("ed", "ing", "ly", "s")) and not _direction_word(verb)
    if verb in ("is", "are") and len(words) >= 3 and words[1] in lx.ARTICLES:
        out.append((" ".join(words[1:]), False))  # "is the local of": "the pub that's the local of it"
        return _finished_forms(phrase, out)
    if verb in ("is", "are", "was", "were") and len(words) >= 3:
        # "is drawn off above": a state, no verb to inflect ("the channel that's drawn off above the weir",
        # "the leat, drawn off above the weir", "the houses which are stacked on top of ...")
        for copula in ("is", "are", "was", "were"):
            out.extend(((f"{copula} {rest}", False), (f"that {copula} {rest}", False), (f"which {copula} {rest}", False)))
        out.extend(((f"that {rest}", False), (rest, False)))
        if words[1].endswith("ed") or words[1] in lx.IRREGULAR_PARTICIPLES:
            # a passive said with "get": "the water the log deck gets restocked from"
            out.extend((f"{get} {rest}", False) for get in ("gets", "get", "got", "getting"))
            # "is dug beneath" said of whoever did it: "the pit they dug beneath the old pad"; in the making:
            # "the cell that's being dug out below it"
            if words[-1] in _SPATIAL_ENDINGS:  # (not "was dug for": "the pit they dug to whiten the horse")
                out.extend((f"{who} {rest}", False) for who in ("they", "theyve", "we", "weve"))
            out.extend((f"{pre} being {rest}", False) for pre in ("is", "are", "s", "that is", "that s", "thats", "which is"))
        # ("the houses below the visitor centre" for "is downhill of": a direction word's family said bare too)
        out.extend((f[3:], inv) for f, inv in list(out) if f.startswith("is ") and f[3:].split()[0] in _DIRECTION_BARE)
        if len(words) == 3 and words[1].endswith(("ed", "lt", "wn")) and words[2] in ("against", "onto", "into", "on"):
            # "the stretch of boundary the vets are built up against" for ``is built against``
            out.extend(((f"{words[1]} up {words[2]}", False), (f"is {words[1]} up {words[2]}", False),
                        (f"are {words[1]} up {words[2]}", False)))
        if len(words) == 4 and words[1].endswith("ed") and words[2] in ("in", "up", "away", "out") \
                and words[3] in lx.RELATION_ENDINGS:
            # "is tucked in behind" said without its particle: "the tent they're tucked behind"
            out.append((f"{words[1]} {words[3]}", False))
        if cut is not None and cut >= 3 and words[-1] == "of":
            # "whatever the dry dock is dug into" for "is dug into the yard of": said short, the noun unsaid
            out.extend(_relation_forms(" ".join(words[:cut])))
        if words[-1] == "by" and len(words) >= 3 and words[1].endswith(("ed", "id", "lt", "ht", "wn", "en")):
            # "was paid for by" said actively, read backwards: "whoever paid for the football ground"
            active = " ".join(words[1:-1])
            out.extend(((active, True), (f"that {active}", True), (f"who {active}", True)))
            if len(words) == 3 and words[1].endswith("ed") and words[1] not in lx.IRREGULAR_PARTICIPLES:
                # "is undermined by" said in the present: "the other one the brine pits undermine"
                part = words[1]
                stems = {part[:-3] + "y"} if part.endswith("ied") else {part[:-1], part[:-2]}
                for stem in stems:
                    ing = (stem[:-1] if stem.endswith("e") else stem) + "ing"
                    for v in (stem, stem + "s", ing):
                        out.extend(((v, True), (f"that {v}", True)))
        return _finished_forms(phrase, out)
    if not (len(words) == 1 or verb.endswith("s") or plain_verb) or _direction_word(verb) or verb.endswith("ss"):
        return _finished_forms(phrase, out)
    stems = {verb[:-1]} if verb.endswith("s") and len(verb) > 3 else {verb}
    for stem in list(stems):
        base = stem[:-1] if stem.endswith("e") else stem
        ings = {base + "ing"}
        if stem.endswith("ie"):
            ings.add(stem[:-2] + "ying")  # "lies" -> "lying"
        if len(stem) <= 4 and len(stem) >= 3 and stem[-1] not in "aeiouwxy" and stem[-2] in "aeiou" \
                and stem[-3] not in "aeiou":
            ings.add(stem + stem[-1] + "ing")  # "runs" -> "running", "sits" -> "sitting"
        for v in (stem, stem + "s", *sorted(ings)):
            out.append((f"{v} {rest}".strip(), False))
            out.append((f"that {v} {rest}".strip(), False))
        for v in (base + "ed", _participle(stem), *(k for k, val in lx.IRREGULAR_PARTICIPLES.items() if val == stem)):
            out.append((f"{v} by", True))  # ("those pipes fed by the tower" for ``feeds water into``)
        if plain_verb and len(words) >= 2:
            # "the stalls huddled under the eaves of the market hall": the participle reads it forwards
            for v in {base + "ed", *(k for k, val in lx.IRREGULAR_PARTICIPLES.items() if val == stem)}:
                out.append((f"{v} {rest}", False))
    return _finished_forms(phrase, out)


def _finished_forms(phrase: str, out: list[tuple[str, bool]]) -> list[tuple[str, bool]]:
    """The forms of a relation name with its group's inverses and the ways its noun and last word are said
    ("pumps the diesel for", "holding the spare keys to"), each once, in order."""
    _with_group_inverses(phrase, out)
    _with_article_before_noun(phrase, out)
    _with_other_preposition(phrase, out)
    _with_receiver_forms(phrase, out)
    _with_shared_its(phrase, out)
    _with_verb_synonyms(out)
    _with_its_noun(phrase, out)
    _with_their(out)
    _with_dropped_to(phrase, out)
    _with_way_up_to(phrase, out)
    return list(dict.fromkeys(out))


def _noun_of(phrase: str) -> tuple[int, int] | None:
    """Where the noun of a relation named "... the <noun> of" stands (``is_dug_into_the_yard_of``), as a word span."""
    words = phrase.replace("_", " ").split()
    k = next((i for i, w in enumerate(words) if w == "the" and i >= 1), None)
    if k is None or words[-1] != "of" or len(words) - 1 - (k + 1) < 1 or len(words) - 1 - (k + 1) > 2:
        return None
    return k + 1, len(words) - 1


def _with_its_noun(phrase: str, out: list[tuple[str, bool]]) -> None:
    """"is dug into the yard of" said of the place before: "the dock that's dug into its yard"."""
    span = _noun_of(phrase)
    if span is None or phrase.replace("_", " ").split()[0] not in _STATE_VERBS:
        return  # (a state only: "keeps the tractors of" said "its tractors" is read as a possessive)
    noun = " ".join(phrase.replace("_", " ").split()[span[0]:span[1]])
    for form, inv in list(out):
        if not inv and form.endswith(f" the {noun} of"):
            out.append((form[: -len(f" the {noun} of")] + f" its {noun}", False))


def _with_their(out: list[tuple[str, bool]]) -> None:
    """"slakes its thirst at" said of a plural: "the pub where the board lads slake their thirst"."""
    out.extend((" ".join("their" if w == "its" else w for w in form.split()), inv) for form, inv in list(out)
               if "its" in form.split())


def _with_dropped_to(phrase: str, out: list[tuple[str, bool]]) -> None:
    """"wherever the gravel park sends its shuttle buses": "sends its shuttle buses to" with its "to" left
    unsaid, as "wherever" asks where to. Only for a verb, an object noun phrase and "to"."""
    words = phrase.split()
    if len(words) < 3 or words[-1] not in ("to", "at") or not words[0].endswith("s") or words[0].endswith("ss") \
            or words[-2] in lx.NOT_VERBS | lx.RELATION_ENDINGS or words[1] in _TO_PARTICLES | lx.RELATION_ENDINGS:
        return  # (a noun after the verb: not "spreads out at")
    # (and "at": "the pub where the lads slake their thirst"; with the article or "its" said where the name has
    # none: "where the education centre runs its school sessions" for ``runs_school_sessions_at``)
    last = f" {words[-1]}"
    out.extend((form[:-len(last)], inv) for form, inv in list(out)
               if form.endswith(last) and not inv and len(form.split()) >= 4
               and form.split()[1 + (form.split()[0] == "that")] in ("its", "their", "the", "a"))


def _with_way_up_to(phrase: str, out: list[tuple[str, bool]]) -> None:
    """A final "to" said with a particle before it: "guards the road to" said "the hut that guards the road up to
    it" (a way's noun, "road", "path", ..., takes "up" or "down"); "sends flow to" said "the next stage those tanks
    send their flow on to" (onward: "on")."""
    words = phrase.split()
    if len(words) < 2 or words[-1] != "to" or words[-2] in lx.NOT_VERBS | _TO_PARTICLES:
        return
    ways = ("up", "down", "on") if words[-2] in lx.WAY_NOUNS else ("on",)
    for form, inv in list(out):
        if form.endswith(" to") and form.split()[-2] not in lx.NOT_VERBS | _TO_PARTICLES:
            out.extend((f"{form[:-3]} {way} to", inv) for way in ways)


def _with_verb_synonyms(out: list[tuple[str, bool]]) -> None:
    """"keeps the padlock keys to" said "whoever holds the padlock keys for the gas cage": verbs of having (and of
    getting and sending) that say the same of a relation's noun."""
    for form, inv in list(out):
        ws = form.split()
        at = 1 if ws[:1] == ["that"] else 0
        if len(ws) - at >= 3 and ws[at] in lx.NOUN_VERB_SYNONYMS and ws[at + 1] in lx.ARTICLES | {"its", "their"}:
            out.extend((" ".join(ws[:at] + [other] + ws[at + 1:]), inv) for other in lx.NOUN_VERB_SYNONYMS[ws[at]])


def _shares_a_noun_with(phrase: str) -> bool:
    """A relation named "shares a <noun> with" (``shares_a_vestry_wall_with``), said with "its" for the place
    before ("the hall that shares its vestry wall")."""
    words = phrase.replace("_", " ").split()
    return len(words) >= 4 and words[0].startswith("share") and words[1] in ("a", "the") and words[-1] == "with"


def _with_shared_its(phrase: str, out: list[tuple[str, bool]]) -> None:
    """"shares_a_vestry_wall_with" said of the place before: "the hall that shares its vestry wall"."""
    if not _shares_a_noun_with(phrase):
        return
    words = phrase.replace("_", " ").split()
    noun = " ".join(words[2:-1])
    for verb in ("shares", "share", "sharing"):
        for whose in ("its", "our"):  # ("the shed that shares our fence": the speaker's place)
            out.append((f"{verb} {whose} {noun}", False))
            out.append((f"that {verb} {whose} {noun}", False))


def _participle(stem: str) -> str:
    """The regular past participle of a verb's stem: "pipe" -> "piped", "pump" -> "pumped"."""
    return stem + ("d" if stem.endswith("e") else "ed")


def _with_receiver_forms(phrase: str, out: list[tuple[str, bool]]) -> None:
    """"pipes_gas_to" said from the other end: "the hut that gets its gas from the compound", "wherever the
    clubhouse gets its gas from" (what one place sends the other gets from it: the relation read backwards)."""
    words = phrase.split()
    if words[:1] and words[0] in ("the", "a"):
        return
    if len(words) == 4 and words[1] in lx.ARTICLES | {"its", "their"}:
        words = [words[0], words[2], words[3]]
    if len(words) != 3 or words[2] not in ("to", "for", "into") and not (
            words[2] in _EMIT_ENDINGS and words[0] in _EMIT_VERBS) or not words[0].endswith("s") \
            or words[0].endswith("ss") or not words[1].isalpha() or len(words[1]) < 3 \
            or words[1] in lx.NOT_VERBS | lx.ARTICLES | lx.RELATION_ENDINGS | lx.DETERMINERS:
        return
    noun = words[1]
    part = _participle(words[0][:-1])  # ("the tank that gets its water piped in from ...")
    for verb in ("gets", "get", "getting", "got", "takes", "take", "taking", "draws", "draw", "drawing"):
        for det in ("its", "their", "the", "", "all the", "all its"):
            # ("the place that gets all the smoke off the kipper house" for ``blows its smoke over``)
            for tail in (("from",), (part, "in", "from"), (part, "from"), *((("off",),) if words[2] in _EMIT_ENDINGS else ())):
                out.append((" ".join(w for w in (verb, det, noun, *tail) if w), True))
                out.append((" ".join(w for w in ("that", verb, det, noun, *tail) if w), True))


def _with_group_inverses(phrase: str, out: list[tuple[str, bool]]) -> None:
    """Add the synonyms of the opposite relation group as inverse forms."""
    for canon, syns in lx.RELATION_SYNONYMS.items():
        if phrase == canon or phrase in syns:
            opposite = lx.INVERSE_PHRASES.get(canon)
            if opposite:
                out.extend((syn, True) for syn in lx.RELATION_SYNONYMS.get(opposite, []))


def _with_article_before_noun(phrase: str, out: list[tuple[str, bool]]) -> None:
    """"pumps_diesel_for" said "the pontoon that pumps the diesel for ...": an article before the relation's noun
    ("winds_wagons_down" said "winds the wagons down", "loads_slate_from" said "loads its slate from")."""
    words = phrase.split()
    if len(words) >= 3 and words[0] not in ("is", "are", "was", "were") \
            and words[1] not in lx.ARTICLES | lx.NOT_VERBS | lx.RELATION_ENDINGS \
            and words[-1] in lx.RELATION_ENDINGS | {"for", "of", "into", "down", "up", "in", "at"} and words[1].isalpha() \
            and not words[1].endswith(("ly", "ing")):
        for form, inv in list(out):
            ws = form.split()
            at = next((n for n in (1, 2) if ws[n:n + 1] == [words[1]] and ws[n - 1] not in lx.ARTICLES), None)
            if at is not None and not inv:
                out.extend((" ".join(ws[:at] + [det] + ws[at:]), inv) for det in ("the", "its"))  # ("their": _with_their)


def _with_other_preposition(phrase: str, out: list[tuple[str, bool]]) -> None:
    """"holds the spare keys for" said "holding the spare keys to": a noun's "for" and "to" name the same object
    ("is the local of" said "the local for": a noun after an article takes "of" and "for" alike)."""
    words = phrase.split()
    if len(words) >= 3 and words[-1] in ("onto", "into") and words[-2] in ("down", "up", "out", "back"):
        other = "into" if words[-1] == "onto" else "onto"  # ("hauls its boat down into it" for "down onto")
        shorter = "on" if words[-1] == "onto" else "in"  # ("wherever the bridge comes down on the south bank")
        out.extend((f"{form[:-len(words[-1])]}{o}", inv) for form, inv in list(out) for o in (other, shorter)
                   if form.endswith(f" {words[-1]}") and len(form.split()) >= 3)
        return
    if len(words) >= 3 and words[-1] in ("for", "to", "of") and words[-2] not in lx.ARTICLES \
            and words[-2] not in lx.NOT_VERBS and (words[-1] != "of" or words[-3] in lx.ARTICLES):
        others = {"for": ["to"], "to": ["for"], "of": ["for"]}[words[-1]]
        out.extend((f"{form[:-len(words[-1])]}{other}", inv) for form, inv in list(out) for other in others
                   if form.endswith(f" {words[-1]}") and len(form.split()) >= 3)
    if len(words) >= 3 and words[-1] == "into" and words[-2] not in lx.ARTICLES and words[-2] not in lx.NOT_VERBS:
        # "the room that tank pipes water to" for ``pipes_water_into``
        out.extend((f"{form[:-4]}to", inv) for form, inv in list(out) if form.endswith(" into") and len(form.split()) >= 3)
    if len(words) >= 3 and words[-1] == "from" and words[-2] not in lx.ARTICLES and any(w in lx.ARTICLES for w in words):
        # "the crane that works the cargo off the Sea Tern" for ``works_the_cargo_from``: a noun taken "off" a place
        out.extend((f"{form[:-4]}off", inv) for form, inv in list(out) if form.endswith(" from") and len(form.split()) >= 3)
    for i, w in enumerate(words[:-1]):
        if w in _PART_SYNONYMS and words[i + 1] == "of":
            # "wraps round the bottom of" for ``wraps round the foot of``
            out.extend((f.replace(f" {w} of", f" {other} of"), inv) for f, inv in list(out) if f" {w} of" in f
                       for other in _PART_SYNONYMS[w])
    if len(words) >= 2 and words[-1] in ("inside", "within") and words[-2].endswith(("ed", "lt", "wn", "en")):
        # "the passage buried in it" for ``is_buried_inside``: a participle's "inside" said "in"
        out.extend((f"{form[:-len(words[-1])]}in", inv) for form, inv in list(out)
                   if form.endswith(f" {words[-1]}") and len(form.split()) >= 2)
    elif words[0] in _POSTURE_VERBS and "inside" in words[1:-1] and words[-1] == "of":
        # "the compound the golf ball sits in" for ``sits inside the fence of``: said short, its noun unsaid
        short = _relation_forms(" ".join(words[: words.index("inside") + 1]))
        out.extend(short)
        out.extend((f"{form[:-6]}in", inv) for form, inv in short if form.endswith(" inside") and len(form.split()) >= 2)
    if len(words) >= 3 and words[-1] in ("across", "over") and words[-2] not in lx.ARTICLES:
        # "the bridge carrying the towpath over the weir" for ``carries the towpath across``
        other = "over" if words[-1] == "across" else "across"
        out.extend((f"{form[:-len(words[-1])]}{other}", inv) for form, inv in list(out)
                   if form.endswith(f" {words[-1]}") and len(form.split()) >= 3)


def analyze(analyzer: ReportAnalyzer, text: str) -> tuple[Extraction, Classification]:
    ex = analyzer.extract(text)
    return ex, analyzer.classify(ex)


__all__ = ["Claim", "Classification", "CueMention", "Extraction", "PlaceMention", "ReportAnalyzer", "analyze", "norm"]

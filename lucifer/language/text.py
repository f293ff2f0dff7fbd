"""Tokenisation with character offsets, boundaries and a longest-match phrase matcher."""

from __future__ import annotations

import itertools
import re
import unicodedata
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Generic, TypeVar

T = TypeVar("T")

# ("A&E", "B & B": letters joined by an ampersand are one word)
# (letters with accents are letters: "café" is one word, keyed "cafe")
_TOKEN = re.compile(r"(?<![^\W_])[^\W_] ?& ?[^\W_](?![^\W_])(?:['’][a-z]+)?|[^\W_]+(?:['’][^\W_]+)*")
_SENTENCE_END = re.compile(r"[.!?]")
_PAUSE_AFTER_END = re.compile(r"[.!?]\s*[—–,]|[.!?]\s+-\s")
_CLAUSE = re.compile(r"[,;:()\[\]—–/]|\s-\s|--|^-|-$|\.\.\.|…")


# Short words whose "'s" is kept in their key ("it's" is "its", not "it").
_KEEP_S = {"it", "he", "she", "who", "let", "how", "what", "where", "there", "that", "here", "one"}


# Log and radio shorthand read as the word it stands for ("police stn", "bldg opp st marys", "2 inj").
ABBREVIATIONS = {"stn": "station", "stuk": "stuck", "trapt": "trapped", "bldg": "building", "opp": "opposite", "ppl": "people", "inj": "injured",
                 "veh": "vehicle", "hosp": "hospital", "frm": "from", "pls": "please", "plz": "please",
                 "rprtd": "reported", "approx": "approximately", "hse": "house", "plnt": "plant", "twr": "tower",
                 "whse": "warehouse", "wkshp": "workshop", "rd": "road", "nr": "near", "adj": "adjacent",
                 "bhd": "behind", "dn": "down", "clr": "clear", "mkt": "market", "vlg": "village",
                 "cntr": "centre", "ctr": "centre", "upd": "update", "rf": "roof", "flr": "floor", "blk": "block",
                 "apt": "apartment", "gdn": "garden", "corr": "correction", "cas": "casualty", "invlvd": "involved",
                 "consc": "conscious", "uncon": "unconscious", "uncons": "unconscious", "evac": "evacuation",
                 "crk": "crack", "chan": "channel", "est": "established",
                 # texting ("sorry ment the shower blok", "send sum1 asap")
                 "ment": "meant", "smel": "smell", "realy": "really", "sum1": "someone", "some1": "someone",
                 "any1": "anyone", "every1": "everyone", "evry1": "everyone", "thru": "through", "tho": "though",
                 "saint": "st"}  # ("Saint Brendan" reads as a KB's "st brendan")
# Shorthand written with a full stop that does not end the sentence before a lower-case word.
_PERIOD_ABBREVIATIONS = set(ABBREVIATIONS) | {"est", "st", "vs", "etc"}


def norm(word: str) -> str:
    """Matching key of a word: lower case, no apostrophes, a plural/possessive 's' dropped.

    >>> [norm(w) for w in ["Bakeries", "chemist's", "gas", "Fires", "isn't", "class", "op's", "it's", "1's"]]
    ['bakerie', 'chemist', 'gas', 'fire', 'isnt', 'class', 'op', 'its', '1']
    """
    w = word.lower().replace("’", "'").replace(" ", "")
    if not w.isascii():
        w = "".join(ch for ch in unicodedata.normalize("NFKD", w) if not unicodedata.combining(ch))
    if w.endswith("'s") and (len(w) > 3 or w[:-2].isdigit() or len(w) == 3 and word[:1].isupper()) \
            and w[:-2] not in _KEEP_S:  # ("stair A's swept": the label's possessive)
        w = w[:-2]  # "op's" -> "op" (a short word's possessive, as in "Co-op's")
    w = w.replace("'", "")
    if len(w) > 3 and w.endswith("s") and not w.endswith("ss") and not w.endswith("us") and not w.endswith("is"):
        w = w[:-1]
    return ABBREVIATIONS.get(w, w)


def norm_phrase(phrase: str) -> tuple[str, ...]:
    """Token keys of a phrase. ``norm_phrase("The Baker's")`` -> ``('the', 'baker')``."""
    return tuple(norm(m.group()) for m in _TOKEN.finditer(phrase))


def name_words(name: str) -> tuple[str, ...]:
    """Token keys of a place name without its articles: how names and aliases are compared.
    ``name_words("The Baker's")`` -> ``('baker',)``."""
    words = list(norm_phrase(name))
    while words and words[0] in ("the", "a", "an"):
        words.pop(0)
    # ("turnstiles A", "Block A": a letter that labels the place, not an article)
    return tuple(w for i, w in enumerate(words) if w != "the" and not (w in ("a", "an") and i < len(words) - 1))


@dataclass(frozen=True)
class Token:
    i: int
    text: str
    norm: str
    start: int
    end: int


@dataclass(frozen=True)
class Tokens:
    text: str
    tokens: tuple[Token, ...]
    gaps: tuple[str, ...]  # gaps[i] = raw text between token i-1 and token i (gaps[0]: before the first)
    sentence_start: tuple[bool, ...]  # token i starts a new sentence
    clause_start: tuple[bool, ...]  # token i starts a new clause (sentence starts included)
    sentence_of: tuple[int, ...] = ()  # index of the sentence token i belongs to

    def __len__(self) -> int:
        return len(self.tokens)

    def span_text(self, a: int, b: int) -> str:
        return self.text[self.tokens[a].start : self.tokens[b - 1].end]

    def norms(self, a: int, b: int) -> tuple[str, ...]:
        """Token keys of ``a:b``; the whole report's keys carry its sentence starts, which no phrase spans."""
        if a == 0 and b == len(self.tokens):
            return Norms((t.norm for t in self.tokens), (i for i, s in enumerate(self.sentence_start) if s and i > 0))
        return tuple(t.norm for t in self.tokens[a:b])


class Norms(tuple):  # type: ignore[type-arg]
    """Token keys of a whole report, with the indices where a new sentence starts ("Hang on. Fire ..."
    is not "on fire")."""

    breaks: frozenset[int]

    def __new__(cls, keys: Iterable[str], breaks: Iterable[int] = ()) -> Norms:
        self = super().__new__(cls, keys)
        self.breaks = frozenset(breaks)
        return self


def _spans_break(norms: tuple[str, ...], i: int, end: int) -> bool:
    breaks = getattr(norms, "breaks", None)
    return bool(breaks) and any(i < k < end for k in breaks)


_CUT_OFF_GAP = re.compile(r"\s*(?:--|—|–|-)\s+")


def _cut_off_of(fragment: str, word: str) -> bool:
    """Is ``fragment`` a cut-off start of ``word``, three letters or more ("inhal" of "inhalation")?

    >>> _cut_off_of("inhal", "inhalation"), _cut_off_of("ban", "bakery"), _cut_off_of("gen", "gen")
    (True, False, False)
    """
    f, w = fragment.lower(), word.lower()
    return f.isalpha() and len(f) >= 3 and len(f) < len(w) and w.startswith(f)


def _stutter_of(fragment: str, word: str) -> bool:
    """Is ``fragment`` a stuttered start of ``word`` ("st" of "station", "c" of "control")?"""
    f, w = fragment.lower(), word.lower()
    return f.isalpha() and len(f) <= 3 and len(f) < len(w) and w.startswith(f)


_CONTRAST_NEXT = frozenset({"at", "in", "on", "the", "by", "inside", "behind", "up", "down", "over", "actually",
                            "definitely", "really"})


def _unpunctuated_contrast(toks: list[Token], i: int) -> bool:
    """"it's" (or "its") that opens the second half of "not X it's Y" with no comma between: a "not" in the five words
    before, a word of the denied place just before, a place word (an article or a preposition) after."""
    if i < 3 or i + 1 >= len(toks) or toks[i].text.lower().replace("\u2019", "'") not in ("it's", "its"):
        return False
    before = [t.text.lower() for t in toks[max(0, i - 5):i]]
    return "not" in before and toks[i - 1].norm not in _CONTRAST_NEXT | {"not", "a", "an", "of", "to"} \
        and toks[i + 1].norm in _CONTRAST_NEXT


# A hesitation and then a subject start a clause in unpunctuated speech ("... um someone slipped ...")
_HESITATION_WORDS = frozenset({"um", "uh", "er", "erm", "umm", "uhh"})
_SUBJECT_WORDS = frozenset({"someone", "somebody", "he", "she", "they", "we", "i", "there's", "theres", "there’s"})


# Words after "one" that place an item of a count ("two hurt, one at the hare, one at the ha-ha")
_COUNTED_AT = frozenset({"at", "in", "on", "up", "down", "by", "inside", "outside"})
# Words before "one" that make it part of a noun phrase ("the one at the gate"), not a count's next item
_BEFORE_A_ONE = frozenset({"the", "that", "this", "which", "each", "every", "no", "only", "just", "number", "any", "a",
                           "another", "other", "last", "first", "big", "little", "old", "new", "said", "is", "s", "was"})


_AFTERTHOUGHT_FILLERS = frozenset({"like"})
_LINKS = frozenset({"are", "it's", "he's", "she's", "they're", "that's", "there's", "we're"})


def tokenize(text: str) -> Tokens:
    toks: list[Token] = []
    gaps: list[str] = []
    prev_end = 0
    for m in _TOKEN.finditer(text):
        word, gap = m.group(), text[prev_end : m.start()]
        m_start = m.start()
        while gap == "-" and toks and _stutter_of(toks[-1].text, word):
            # "st-station", "c-c-control": a stuttered start of the word after it is no word of its own
            m_start = toks.pop().start
            gap = gaps.pop()
        if toks and _CUT_OFF_GAP.fullmatch(gap) and _cut_off_of(toks[-1].text, word):
            # "smoke inhal-- inhalation": a word cut off and said again whole is said once
            m_start = toks.pop().start
            gap = gaps.pop()
        toks.append(Token(len(toks), word, norm(word), m_start, m.end()))
        gaps.append(gap)
        prev_end = m.end()
    sent: list[bool] = []
    clause: list[bool] = []
    for i, gap in enumerate(gaps):
        g = gap.replace("...", " , ").replace("…", " , ")
        # "— or is it the school? — the post office": a terminator followed by a dash or comma is a pause
        is_sent = i == 0 or (bool(_SENTENCE_END.search(g)) and not _PAUSE_AFTER_END.search(gap)) or "\n" in gap
        if is_sent and i > 0 and gap.strip() == "." and toks[i - 1].text.lower() in _PERIOD_ABBREVIATIONS \
                and toks[i].text[:1].islower():
            is_sent = False  # "RVP est. taxi rank", "bldg across chan. from": an abbreviation's point
        sent.append(is_sent)
        # a hyphen inside a word ("no-go", "x-ray", "cut-off") is no pause; a stutter's ("th-th-the") is none either
        hyphenated = gap == "-" and i > 0 and len(toks[i].text) > 1 \
            and not toks[i].text.lower().startswith(toks[i - 1].text.lower()[:1])
        starts = is_sent or (not hyphenated and (bool(_CLAUSE.search(gap.strip())) or bool(_CLAUSE.search(g))))
        if starts and not is_sent and i >= 1 and toks[i].text.lower() == toks[i - 1].text.lower() \
                and re.search(r"[—–-]", gap) is not None and toks[i].text.lower().replace("’", "'") in _LINKS \
                and "'" in toks[i].text.replace("’", "'"):
            starts = False  # "the fire at the pump shed that's-- that's out now": the word begun again
        if starts and not is_sent and i >= 1 and (
                toks[i].text.lower() in _AFTERTHOUGHT_FILLERS and toks[i - 1].text.lower().replace("’", "'") in _LINKS
                or i >= 2 and toks[i - 1].text.lower() in _AFTERTHOUGHT_FILLERS
                and toks[i - 2].text.lower().replace("’", "'") in _LINKS):
            starts = False  # "the heavies are, like, still going on": a filler inside the clause, set off by commas
        if not starts and gap.strip() == "" and _unpunctuated_contrast(toks, i):
            starts = True  # "the fire's not at the kestrel it's at the marisol": the place meant, said without a pause
        if not starts and gap.strip() == "" and i >= 2 and toks[i - 1].text.lower() in _HESITATION_WORDS \
                and toks[i].text.lower() in _SUBJECT_WORDS and gaps[i - 1].strip() == "":
            starts = True  # "black ice at the fuel pumps um someone slipped at the canteen": a new subject, unpunctuated
        if not starts and gap.strip() == "" and i >= 3 and toks[i].text.lower() == "one" and i + 1 < len(toks) \
                and toks[i + 1].text.lower() in _COUNTED_AT \
                and toks[i - 1].text.lower() not in _BEFORE_A_ONE and any(
                    t.text.lower() == "one" and toks[j + 1].text.lower() in _COUNTED_AT for j, t in enumerate(toks[:i - 1])):
            starts = True  # "two casualties one at the giant hare one at the ha-ha": the second of a count, unpunctuated
        clause.append(starts)
    sentence_of = tuple(itertools.accumulate(int(x) for x in sent)) if sent else ()
    return Tokens(text, tuple(toks), tuple(gaps), tuple(sent), tuple(clause), tuple(n - 1 for n in sentence_of))


class PhraseMatcher(Generic[T]):
    """Longest-match lookup of token-key phrases, each carrying a payload."""

    def __init__(self, skippable: Iterable[str] = ()) -> None:
        self._by_first: dict[str, list[tuple[tuple[str, ...], T]]] = {}
        # words the text may insert inside a phrase ("roof's partly down" matches "roof down")
        self.skippable = frozenset(skippable)

    def add(self, key: tuple[str, ...], payload: T) -> None:
        if not key:
            return
        bucket = self._by_first.setdefault(key[0], [])
        bucket.append((key, payload))
        bucket.sort(key=lambda kv: -len(kv[0]))

    def match_at(self, norms: tuple[str, ...], i: int, blocked: Iterable[int] = ()) -> tuple[int, T] | None:
        """The longest phrase starting at token ``i``: ``(end, payload)`` or ``None``."""
        blocked_set = set(blocked)
        for key, payload in self._by_first.get(norms[i], ()):
            end = i + len(key)
            if end <= len(norms) and norms[i:end] == key and not blocked_set.intersection(range(i, end)) \
                    and not _spans_break(norms, i, end):
                return end, payload
        if self.skippable:
            for key, payload in self._by_first.get(norms[i], ()):
                end = self._loose_end(norms, i, key)
                if end is not None and not blocked_set.intersection(range(i, end)) and not _spans_break(norms, i, end):
                    return end, payload
        return None

    def _loose_end(self, norms: tuple[str, ...], i: int, key: tuple[str, ...]) -> int | None:
        """End of ``key`` matched from ``i`` with skippable words allowed between its words."""
        j = i
        for n, word in enumerate(key):
            if n:
                while j < len(norms) and norms[j] != word and norms[j] in self.skippable:
                    j += 1
            if j >= len(norms) or norms[j] != word:
                return None
            j += 1
        return j

    def find_all(self, norms: tuple[str, ...], blocked: set[int] | None = None) -> list[tuple[int, int, T]]:
        """Non-overlapping longest matches, left to right, skipping ``blocked`` tokens."""
        blocked = blocked or set()
        out: list[tuple[int, int, T]] = []
        i = 0
        while i < len(norms):
            if i in blocked:
                i += 1
                continue
            hit = self.match_at(norms, i, blocked)
            if hit is None:
                i += 1
                continue
            end, payload = hit
            out.append((i, end, payload))
            i = end
        return out

"""Numbered parts of a place: "floors 9-12", "level 3", "bays 10 to 20" in a KB; "floor ten", "the seventh
floor", "bay 14" in a report.

A KB may make numbered ranges of one building its landmarks ("upper wards (floors 9-12)"); a report then
names the place only by its number. :func:`text_ranges` reads the ranges from a landmark's names, aliases
and description; :func:`number_at` reads a number said in digits, words or as an ordinal.
"""

from __future__ import annotations

import re

# unit words, folded onto one key each ("storey" is a floor; "level" is its own unit, a car park's)
UNITS = {"floor": "floor", "floors": "floor", "storey": "floor", "storeys": "floor", "story": "floor",
         "stories": "floor", "level": "level", "levels": "level", "bay": "bay", "bays": "bay", "gate": "gate",
         "gates": "gate", "platform": "platform", "platforms": "platform", "pitch": "pitch", "pitches": "pitch",
         "berth": "berth", "berths": "berth", "deck": "deck", "decks": "deck", "ward": "ward", "wards": "ward",
         "clinic": "clinic", "clinics": "clinic", "room": "room", "rooms": "room", "theatre": "theatre",
         "theatres": "theatre", "hangar": "hangar", "hangars": "hangar"}
# a unit a report may say for another where the KB numbers only that one ("level 10" of a tower of floors)
SIBLING_UNITS = {"floor": "level", "level": "floor"}

_ONES = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"]
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90}
_ORD_ONES = ["zeroth", "first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth",
             "eleventh", "twelfth", "thirteenth", "fourteenth", "fifteenth", "sixteenth", "seventeenth", "eighteenth",
             "nineteenth"]
_ORD_TENS = {"twentieth": 20, "thirtieth": 30, "fortieth": 40, "fiftieth": 50}

CARDINALS: dict[str, int] = {w: i for i, w in enumerate(_ONES)} | _TENS
ORDINALS: dict[str, int] = {w: i for i, w in enumerate(_ORD_ONES)} | _ORD_TENS

_UNIT_RE = "|".join(sorted(UNITS, key=len, reverse=True))
_NUM = r"(\d{1,3})(?:st|nd|rd|th)?"
_DIGITS = re.compile(r"(\d{1,3})(st|nd|rd|th)?")  # "14", "7th": a number written in digits
_DASH = r"\s*(?:-|–|—|to|through|thru|and)\s*"
# "floors 9-12", "levels 1 to 3", "bays 10–20"
_UNIT_FIRST = re.compile(rf"\b({_UNIT_RE})\s+{_NUM}(?:{_DASH}{_NUM})?\b", re.IGNORECASE)
# "9th-12th floors", "1-4 floors"
_UNIT_LAST = re.compile(rf"\b{_NUM}{_DASH}{_NUM}\s+({_UNIT_RE})\b", re.IGNORECASE)


def text_ranges(text: str, at_end: bool = False) -> list[tuple[str, int, int]]:
    """(unit, low, high) of every numbered range or number a text gives: "wards on floors 9-12" ->
    [("floor", 9, 12)]; "car park level 3" -> [("level", 3, 3)]. ``at_end``: only one the text ends with, as
    a name that is the numbered thing ("tower floors 1-4", not "deck 8 cabins")."""
    out: list[tuple[str, int, int]] = []
    end = len(text.rstrip(" ."))
    for m in _UNIT_FIRST.finditer(text):
        if at_end and m.end() != end:
            continue
        lo = int(m.group(2))
        hi = int(m.group(3)) if m.group(3) else lo
        out.append((UNITS[m.group(1).lower()], min(lo, hi), max(lo, hi)))
    for m in _UNIT_LAST.finditer(text):
        if at_end and m.end() != end:
            continue
        lo, hi = int(m.group(1)), int(m.group(2))
        out.append((UNITS[m.group(3).lower()], min(lo, hi), max(lo, hi)))
    return out


def spoken_forms(digits: str) -> list[tuple[str, ...]]:
    """How a number written in one or two digits is said on the radio: digit by digit, and as a number.

    >>> spoken_forms("26"), spoken_forms("7"), spoken_forms("40")
    ([('two', 'six'), ('twenty', 'six')], [('seven',)], [('four', 'zero'), ('forty',)])
    """
    tens = {v: w for w, v in _TENS.items()}
    v = int(digits)
    out = [tuple(_ONES[int(d)] for d in digits)] if len(digits) > 1 else []
    if v < 20:
        out.append((_ONES[v],))
    elif v < 100:
        out.append((tens[v - v % 10],) if v % 10 == 0 else (tens[v - v % 10], _ONES[v % 10]))
    return out


def number_at(norms: tuple[str, ...], i: int) -> tuple[int, int] | None:
    """(value, end) of a number said at token ``i``: "14", "ten", "twenty one", "twenty-first", "7th",
    "seventh"; None where there is none."""
    w = norms[i]
    if "-" in w:  # "twenty-one", "twenty-first"
        parts = tuple(w.split("-"))
        if len(parts) == 2 and parts[0] in _TENS:
            got = number_at(parts, 0)
            return (got[0], i + 1) if got is not None and got[1] == 2 else None
    m = _DIGITS.fullmatch(w)
    if m:
        return int(m.group(1)), i + 1
    if w in ORDINALS:
        return ORDINALS[w], i + 1
    if w in CARDINALS:
        v = CARDINALS[w]
        if w in _TENS and i + 1 < len(norms):
            nxt = norms[i + 1]
            if nxt in CARDINALS and 0 < CARDINALS[nxt] < 10:
                return v + CARDINALS[nxt], i + 2
            if nxt in ORDINALS and 0 < ORDINALS[nxt] < 10:
                return v + ORDINALS[nxt], i + 2
        return v, i + 1
    return None


def is_number(word: str) -> bool:
    return number_at((word,), 0) is not None


def is_ordinal(word: str) -> bool:
    """"seventh", "10th", "twenty-first"."""
    m = _DIGITS.fullmatch(word)
    return word in ORDINALS or bool(m and m.group(2)) or (
        "-" in word and word.split("-")[-1] in ORDINALS)

"""Numbered parts of a place: ranges a KB gives its landmarks, numbers a report says."""

from __future__ import annotations

import pytest

from lucifer.language.numbers import is_ordinal, number_at, text_ranges


@pytest.mark.parametrize(("text", "expected"), [
    ("Wards on floors 9-12 of the tower.", [("floor", 9, 12)]),
    ("Car park level 3", [("level", 3, 3)]),
    ("the 9th to 12th floors", [("floor", 9, 12)]),
    ("Pier with gates 5 to 8.", [("gate", 5, 8)]),
    ("bays 20–10", [("bay", 10, 20)]),
    ("A five-storey building with a flat roof.", []),
    ("Two floors of offices.", []),
])
def test_text_ranges(text, expected):
    assert text_ranges(text) == expected


def test_a_name_is_the_numbered_thing_only_when_it_ends_with_the_number():
    assert text_ranges("tower floors 1-4", at_end=True) == [("floor", 1, 4)]
    assert text_ranges("deck 8 cabins", at_end=True) == []


@pytest.mark.parametrize(("norms", "expected"), [
    (("14",), (14, 1)), (("ten",), (10, 1)), (("seventh",), (7, 1)), (("7th",), (7, 1)),
    (("twenty", "one"), (21, 2)), (("twenty", "first"), (21, 2)), (("twenty-one",), (21, 1)),
    (("twenty",), (20, 1)), (("fire",), None),
])
def test_number_at(norms, expected):
    assert number_at(norms, 0) == expected


def test_is_ordinal():
    assert is_ordinal("seventh") and is_ordinal("10th") and is_ordinal("twenty-first")
    assert not is_ordinal("ten") and not is_ordinal("14")

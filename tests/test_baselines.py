"""The rule and ner baselines: real behaviour on a few reports, on both shipped KBs."""

from __future__ import annotations

import builtins
from pathlib import Path

import pytest

from lucifer.baselines import BASELINES, get_baseline
from lucifer.baselines.rule import RuleExtractor
from lucifer.kb import load_kb

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def kb():
    return load_kb(ROOT / "knowledge_base")


@pytest.fixture(scope="module")
def riverbend():
    return load_kb(ROOT / "knowledge_bases" / "riverbend")


def _pairs(objs: list[dict]) -> set[tuple[str, str]]:
    return {(o["location"], o["category"]) for o in objs}


def _check_shape(text: str, objs: list[dict]) -> None:
    for o in objs:
        assert set(o) == {"entity", "location", "category", "span"}
        s, e = o["span"]
        assert text[s:e] == o["entity"]


@pytest.fixture(scope="module", params=sorted(BASELINES))
def extractor_cls(request):
    if request.param == "ner":
        pytest.importorskip("spacy")
        from lucifer.baselines.ner import NerUnavailable, load_spacy

        try:
            load_spacy()
        except NerUnavailable as exc:
            pytest.skip(str(exc))
    return get_baseline(request.param)


def test_clean_multi_place_report(extractor_cls, kb) -> None:
    text = "Base, team two. Fire at the bakery, people trapped in the school, and the church is all clear. Over."
    objs = extractor_cls(kb).extract(text)
    _check_shape(text, objs)
    assert _pairs(objs) == {("bakery", "hazard"), ("school", "victim"), ("church", "safe_zone")}


def test_aliases_glossary_and_landmark_words_that_look_like_keywords(extractor_cls, kb) -> None:
    text = "Rubble zone at the chemist's. Man down at the fire hall."
    objs = extractor_cls(kb).extract(text)
    _check_shape(text, objs)
    assert _pairs(objs) == {("pharmacy", "hazard"), ("fire station", "victim")}


def test_no_claim_yields_nothing(extractor_cls, kb) -> None:
    assert extractor_cls(kb).extract("Team two heading to the bank, over.") == []
    assert extractor_cls(kb).extract("Radio check, do you copy?") == []


def test_follows_the_kb_it_is_given(extractor_cls, riverbend) -> None:
    text = "Flashover at the brewhouse. Walking wounded at the jetty."
    objs = extractor_cls(riverbend).extract(text)
    _check_shape(text, objs)
    assert _pairs(objs) == {("brewery", "threat"), ("ferry landing", "casualty")}


def test_baselines_do_not_understand_repairs_or_relations(extractor_cls, kb) -> None:
    """The comparison the paper draws: keyword baselines ground the retracted place too."""
    ex = extractor_cls(kb)
    assert ("bank", "hazard") in _pairs(ex.extract("the bank — no, the bakery — is on fire"))
    rel = _pairs(ex.extract("people trapped in the shop attached to the bakery"))
    assert ("pharmacy", "victim") not in rel and ("bakery", "victim") in rel


def test_rule_prefers_the_longest_name(kb) -> None:
    objs = RuleExtractor(kb).extract("survivors on the roof of the tower block")
    assert _pairs(objs) == {("apartment block", "victim")}
    assert objs[0]["entity"] == "tower block"


def test_rule_ignores_negated_keywords(kb) -> None:
    assert RuleExtractor(kb).extract("no fire at the library") == []


def test_unknown_baseline_is_rejected() -> None:
    with pytest.raises(ValueError, match="rule"):
        get_baseline("regex")


def test_ner_names_the_missing_extra(kb, monkeypatch) -> None:
    from lucifer.baselines import ner

    real_import = builtins.__import__

    def no_spacy(name, *args, **kwargs):
        if name == "spacy" or name.startswith("spacy."):
            raise ImportError("No module named 'spacy'")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_spacy)
    with pytest.raises(ner.NerUnavailable, match=r"pip install 'lucifer\[ner\]'"):
        ner.NerExtractor(kb)


def test_ner_missing_model_is_named(kb) -> None:
    pytest.importorskip("spacy")
    from lucifer.baselines import ner

    with pytest.raises(ner.NerUnavailable, match="no_such_model"):
        ner.NerExtractor(kb, model="no_such_model")

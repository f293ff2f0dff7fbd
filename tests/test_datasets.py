"""The grounding datasets are well-formed and every label exists in their knowledge base."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from lucifer.kb import load_kb

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "datasets" / "grounding"
REGIMES = ("standard", "messy", "advanced_messy")

# file -> (KB directory, minimum reports per regime)
DATASETS = {
    "standard.jsonl": ("knowledge_base", 150),
    "messy.jsonl": ("knowledge_base", 150),
    "advanced_messy.jsonl": ("knowledge_base", 150),
    "riverbend.jsonl": ("knowledge_bases/riverbend", 30),
    "heldout/standard.jsonl": ("knowledge_base", 50),
    "heldout/messy.jsonl": ("knowledge_base", 50),
    "heldout/advanced_messy.jsonl": ("knowledge_base", 50),
    "heldout_b/market_square.jsonl": ("knowledge_base", 50),
    "heldout_b/riverbend.jsonl": ("knowledge_bases/riverbend", 20),
    "heldout_c/market_square.jsonl": ("knowledge_base", 50),
    "heldout_c/riverbend.jsonl": ("knowledge_bases/riverbend", 20),
}


def _rows(name: str) -> list[dict]:
    path = DATA / name
    if not path.exists():
        pytest.skip(f"{name} not written yet")
    rows = []
    for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        assert line.strip(), f"{name}:{i}: blank line"
        rows.append(json.loads(line))
    return rows


@pytest.mark.parametrize("name", sorted(DATASETS))
def test_lines_are_well_formed(name: str) -> None:
    for r in _rows(name):
        assert {"id", "regime", "report", "expected"} <= set(r), r
        assert r["regime"] in REGIMES, r["id"]
        assert isinstance(r["report"], str) and r["report"].strip(), r["id"]
        assert isinstance(r["expected"], list), r["id"]
        for obj in r["expected"]:
            assert set(obj) == {"location", "category"}, r["id"]
        pairs = [(o["location"], o["category"]) for o in r["expected"]]
        assert len(pairs) == len(set(pairs)), f"{r['id']}: duplicate expected object"
        assert r.get("source", "hand") in ("hand", "gen"), r["id"]


@pytest.mark.parametrize("name", sorted(DATASETS))
def test_labels_exist_in_the_kb(name: str) -> None:
    kb = load_kb(ROOT / DATASETS[name][0])
    for r in _rows(name):
        for obj in r["expected"]:
            assert obj["location"] in kb.landmark_by_name, f"{r['id']}: unknown landmark {obj['location']!r}"
            assert obj["category"] in kb.category_by_name, f"{r['id']}: unknown category {obj['category']!r}"


def test_ids_are_unique_across_all_files() -> None:
    seen: dict[str, str] = {}
    for name in sorted(DATASETS):
        path = DATA / name
        if not path.exists():
            continue
        for r in _rows(name):
            assert r["id"] not in seen, f"{r['id']} in {name} and {seen.get(r['id'])}"
            seen[r["id"]] = name


def test_reports_are_unique_within_a_file() -> None:
    for name in sorted(DATASETS):
        if not (DATA / name).exists():
            continue
        texts = [r["report"].strip().lower() for r in _rows(name)]
        assert len(texts) == len(set(texts)), name


@pytest.mark.parametrize("name", sorted(DATASETS))
def test_counts_and_empty_share(name: str) -> None:
    rows = _rows(name)
    minimum = DATASETS[name][1]
    for regime in {r["regime"] for r in rows}:
        mine = [r for r in rows if r["regime"] == regime]
        assert len(mine) >= minimum, f"{name}/{regime}: {len(mine)} < {minimum}"
        empty = sum(1 for r in mine if not r["expected"]) / len(mine)
        assert 0.07 <= empty <= 0.14, f"{name}/{regime}: {empty:.0%} reports with no claim"


def test_single_regime_files_hold_their_regime() -> None:
    for regime in REGIMES:
        for prefix in ("", "heldout/"):
            name = f"{prefix}{regime}.jsonl"
            if (DATA / name).exists():
                assert {r["regime"] for r in _rows(name)} == {regime}, name


def test_second_kb_is_a_different_town() -> None:
    """Riverbend shares no landmark name, relation name or category name with Market Square."""
    a = load_kb(ROOT / "knowledge_base")
    b = load_kb(ROOT / "knowledge_bases" / "riverbend")
    forms = lambda kb: {f.lower() for lm in kb.landmarks for f in lm.surface_forms}  # noqa: E731
    assert not forms(a) & forms(b)
    assert not {r.relation for r in a.relations} & {r.relation for r in b.relations}
    assert not set(a.category_by_name) & set(b.category_by_name)
    assert len(b.landmarks) >= 14 and len(b.relations) >= 8 and len(b.glossary) >= 15
    assert {r["regime"] for r in _rows("riverbend.jsonl")} == set(REGIMES)


def test_generator_is_deterministic_and_keeps_hand_lines() -> None:
    from lucifer.evals.datagen import TARGETS, build, read_jsonl

    for target in TARGETS:
        on_disk = read_jsonl(ROOT / target.path)
        rebuilt = build(target, ROOT)
        assert rebuilt == on_disk, f"{target.path} is stale: run python -m lucifer.evals.datagen"
        assert build(target, ROOT) == rebuilt
        hand = [r for r in on_disk if r.get("source") == "hand"]
        assert hand == [r for r in rebuilt if r.get("source") == "hand"]

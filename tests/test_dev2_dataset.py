"""The hand-written dev2 grounding sets are well-formed and every label exists in their KB."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
DEV2 = ROOT / "datasets" / "grounding" / "dev2"
REGIMES = ("standard", "messy", "advanced_messy")

# file -> (KB directory, reports per regime, id prefix per regime)
FILES = {
    "market_square.jsonl": (
        "knowledge_base",
        40,
        {"standard": "d2-s-", "messy": "d2-m-", "advanced_messy": "d2-a-"},
    ),
    "riverbend.jsonl": (
        "knowledge_bases/riverbend",
        20,
        {"standard": "d2-rb-s-", "messy": "d2-rb-m-", "advanced_messy": "d2-rb-a-"},
    ),
}


def _rows(name: str) -> list[dict]:
    rows = []
    lines = (DEV2 / name).read_text(encoding="utf-8").splitlines()
    for i, line in enumerate(lines, 1):
        assert line.strip(), f"{name}:{i}: blank line"
        rows.append(json.loads(line))
    return rows


def _kb(kb_dir: str) -> tuple[set[str], set[str]]:
    base = ROOT / kb_dir
    space = yaml.safe_load((base / "information_space.yaml").read_text(encoding="utf-8"))
    world = yaml.safe_load((base / "map.yaml").read_text(encoding="utf-8"))
    categories = {c["name"] for c in space["categories"]}
    landmarks = {lm["name"] for lm in world["landmarks"]}
    return landmarks, categories


@pytest.mark.parametrize("name", sorted(FILES))
def test_rows_are_well_formed(name: str) -> None:
    for row in _rows(name):
        assert set(row) >= {"id", "regime", "report", "expected"}, row
        assert row["regime"] in REGIMES, row["id"]
        assert isinstance(row["report"], str) and row["report"].strip(), row["id"]
        assert isinstance(row["expected"], list), row["id"]
        for item in row["expected"]:
            assert set(item) == {"location", "category"}, row["id"]
        pairs = [(e["location"], e["category"]) for e in row["expected"]]
        assert len(pairs) == len(set(pairs)), f"{row['id']}: duplicate expected pair"


@pytest.mark.parametrize("name", sorted(FILES))
def test_ids_unique_and_prefixed(name: str) -> None:
    rows = _rows(name)
    ids = [r["id"] for r in rows]
    assert len(ids) == len(set(ids)), [i for i, n in Counter(ids).items() if n > 1]
    prefixes = FILES[name][2]
    for row in rows:
        assert row["id"].startswith(prefixes[row["regime"]]), row["id"]


@pytest.mark.parametrize("name", sorted(FILES))
def test_labels_exist_in_kb(name: str) -> None:
    landmarks, categories = _kb(FILES[name][0])
    for row in _rows(name):
        for item in row["expected"]:
            assert item["location"] in landmarks, f"{row['id']}: {item['location']!r}"
            assert item["category"] in categories, f"{row['id']}: {item['category']!r}"


@pytest.mark.parametrize("name", sorted(FILES))
def test_counts_per_regime(name: str) -> None:
    rows = _rows(name)
    per_regime = FILES[name][1]
    counts = Counter(r["regime"] for r in rows)
    assert counts == dict.fromkeys(REGIMES, per_regime), counts
    for regime in REGIMES:
        empty = sum(1 for r in rows if r["regime"] == regime and not r["expected"])
        # about 10% of every regime makes no groundable claim
        assert 0.05 * per_regime <= empty <= 0.2 * per_regime, (regime, empty)


@pytest.mark.parametrize("name", sorted(FILES))
def test_reports_are_distinct(name: str) -> None:
    reports = [r["report"].strip().lower() for r in _rows(name)]
    assert len(reports) == len(set(reports))

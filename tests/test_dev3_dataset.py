"""The hand-written dev3 grounding set (Market Square) is well-formed and its labels exist in the KB."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
DATASET = ROOT / "datasets" / "grounding" / "dev3" / "market_square.jsonl"
KB = ROOT / "knowledge_base"
PREFIXES = {"advanced_messy": "d3-a-", "messy": "d3-m-"}
COUNTS = {"advanced_messy": 60, "messy": 40}


def _rows() -> list[dict]:
    rows = []
    for i, line in enumerate(DATASET.read_text(encoding="utf-8").splitlines(), 1):
        assert line.strip(), f"line {i}: blank line"
        rows.append(json.loads(line))
    return rows


def _kb() -> tuple[set[str], set[str]]:
    space = yaml.safe_load((KB / "information_space.yaml").read_text(encoding="utf-8"))
    world = yaml.safe_load((KB / "map.yaml").read_text(encoding="utf-8"))
    return {lm["name"] for lm in world["landmarks"]}, {c["name"] for c in space["categories"]}


def test_rows_are_well_formed() -> None:
    for row in _rows():
        assert set(row) >= {"id", "regime", "report", "expected"}, row
        assert row["regime"] in PREFIXES, row["id"]
        assert row.get("source", "hand") == "hand", row["id"]
        assert isinstance(row["report"], str) and row["report"].strip(), row["id"]
        assert isinstance(row["expected"], list), row["id"]
        for item in row["expected"]:
            assert set(item) == {"location", "category"}, row["id"]
        pairs = [(e["location"], e["category"]) for e in row["expected"]]
        assert len(pairs) == len(set(pairs)), f"{row['id']}: duplicate expected pair"


def test_ids_unique_and_prefixed() -> None:
    rows = _rows()
    ids = [r["id"] for r in rows]
    assert len(ids) == len(set(ids)), [i for i, n in Counter(ids).items() if n > 1]
    for row in rows:
        prefix = PREFIXES[row["regime"]]
        assert row["id"].startswith(prefix), row["id"]
        assert row["id"][len(prefix) :].isdigit(), row["id"]


def test_labels_exist_in_kb() -> None:
    landmarks, categories = _kb()
    for row in _rows():
        for item in row["expected"]:
            assert item["location"] in landmarks, f"{row['id']}: {item['location']!r}"
            assert item["category"] in categories, f"{row['id']}: {item['category']!r}"


def test_counts_and_no_claim_share() -> None:
    rows = _rows()
    assert Counter(r["regime"] for r in rows) == COUNTS
    for regime, n in COUNTS.items():
        empty = sum(1 for r in rows if r["regime"] == regime and not r["expected"])
        # about 10% of every regime makes no groundable claim
        assert 0.05 * n <= empty <= 0.2 * n, (regime, empty)


def test_reports_are_distinct() -> None:
    reports = [r["report"].strip().lower() for r in _rows()]
    assert len(reports) == len(set(reports))

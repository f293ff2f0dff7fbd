"""Adjusted Accuracy of the LUCIFER paper (SPEC §3): one deterministic scorer for every evaluator."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class ReportScore:
    """Counts for one report."""

    expected: int  # |expected|
    found: int  # expected locations that were predicted
    classified: int  # expected (location, category) pairs that were predicted
    hallucinated: int  # predicted locations that were not expected

    @property
    def perfect(self) -> bool:
        return self.found == self.expected and self.classified == self.expected and self.hallucinated == 0


def score_report(expected: Iterable[Mapping[str, Any]], predicted: Iterable[Mapping[str, Any]]) -> ReportScore:
    """Score one report.

    >>> score_report([{"location": "bakery", "category": "hazard"}],
    ...              [{"location": "bakery", "category": "victim"}, {"location": "bank", "category": "hazard"}])
    ReportScore(expected=1, found=1, classified=0, hallucinated=1)
    """
    exp = list(expected)
    pred = list(predicted)
    exp_locs = {e["location"] for e in exp}
    pred_locs = {p["location"] for p in pred}
    pred_pairs = {(p["location"], p["category"]) for p in pred}
    found = sum(1 for e in exp if e["location"] in pred_locs)
    classified = sum(1 for e in exp if (e["location"], e["category"]) in pred_pairs)
    hallucinated = len(pred_locs - exp_locs)
    return ReportScore(len(exp), found, classified, hallucinated)


def adjusted_accuracy(scores: Iterable[ReportScore]) -> float:
    """max(0, Σfound + Σclassified − 2·Σhallucinated) / (2·Σ|expected|) × 100.

    Reports with nothing expected add only their hallucinations; a regime with nothing expected
    at all scores 100 if nothing was hallucinated, else 0.

    >>> adjusted_accuracy([ReportScore(2, 2, 1, 0), ReportScore(0, 0, 0, 0)])
    75.0
    """
    s = list(scores)
    total = sum(x.expected for x in s)
    num = sum(x.found for x in s) + sum(x.classified for x in s) - 2 * sum(x.hallucinated for x in s)
    if total == 0:
        return 100.0 if num >= 0 else 0.0
    return max(0.0, num) / (2 * total) * 100

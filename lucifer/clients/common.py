"""What every client shares: ablation configurations and per-episode / per-run records."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np

ConfigName = Literal["baseline", "+G", "+D", "+D+G"]
CONFIGS: tuple[ConfigName, ...] = ("baseline", "+G", "+D", "+D+G")


def flags(config: str) -> tuple[bool, bool]:
    """(grounding, discovery) of a configuration name.

    >>> flags("+D+G"), flags("baseline")
    ((True, True), (False, False))
    """
    if config not in CONFIGS:
        raise ValueError(f"unknown configuration {config!r}; expected one of {', '.join(CONFIGS)}")
    return "G" in config, "D" in config


@dataclass
class EpisodeResult:
    """One mission: outcome, safety and query decisions (``path`` only when recorded)."""

    success: bool
    collisions: int
    queries: int
    correct_queries: int
    steps: int
    layout: str = ""
    path: list[int] = field(default_factory=list)

    @property
    def safe_success(self) -> bool:
        return self.success and self.collisions == 0


@dataclass
class RunResult:
    """Aggregates of one run (percent)."""

    msr: float
    csr: float
    sms: float
    episodes: int

    @classmethod
    def from_counts(cls, episodes: int, successes: int, safe: int, queries: int, correct: int) -> RunResult:
        return cls(
            msr=100.0 * successes / max(1, episodes),
            csr=100.0 * correct / max(1, queries),
            sms=100.0 * safe / max(1, episodes),
            episodes=episodes,
        )

    @classmethod
    def from_episodes(cls, eps: list[EpisodeResult]) -> RunResult:
        return cls.from_counts(
            len(eps),
            sum(e.success for e in eps),
            sum(e.safe_success for e in eps),
            sum(e.queries for e in eps),
            sum(e.correct_queries for e in eps),
        )


def mean_std(values: list[float]) -> list[float]:
    """[mean, std] rounded to 0.1 (population std, as across runs).

    >>> mean_std([1.0, 3.0])
    [2.0, 1.0]
    """
    a = np.asarray(values, dtype=float)
    return [round(float(a.mean()), 1), round(float(a.std()), 1)] if a.size else [0.0, 0.0]

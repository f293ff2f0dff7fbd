"""``lucifer eval discovery``: replay the discovery benchmark through the discovery graph (SPEC §4).

Memory is a temporary SQLite file seeded from the benchmark's ``memory_seed.jsonl``, so every
run starts from the same telemetry. By default the 600 in-memory decision points
(``decision_points.jsonl``) and the held-out novel points (``novel.jsonl``) are replayed one at
a time; ``--dataset FILE`` replays that file instead (its points whose signature is absent
from memory count as novel).

Metrics: ``n`` and ``accuracy`` over the main file; ``accuracy_novel`` over every replayed
point whose signature is absent from memory; ``ece`` (10 equal-width bins) and latency
percentiles over every replayed point.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
import tempfile
import time
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from lucifer.errors import BadRequest


class DecisionPoint(BaseModel):
    """One benchmark line: a discovery request and the correct option."""

    model_config = ConfigDict(extra="ignore")
    id: str
    signature: str
    trace: list[str] = Field(default_factory=list)
    options: list[str] = Field(min_length=1)
    answer: str
    split: str = "memory"


@dataclass(frozen=True)
class Outcome:
    """The scored answer to one decision point."""

    id: str
    main: bool  # from the main file (counts in n / accuracy)
    novel: bool  # signature absent from memory
    correct: bool
    confidence: float
    latency_s: float
    status: str


def expected_calibration_error(confidences: list[float], correct: list[bool], bins: int = 10) -> float:
    """ECE with equal-width confidence bins: sum over bins of |accuracy - confidence| * share.

    >>> expected_calibration_error([0.9, 0.9, 0.9, 0.9], [True, True, True, False])
    0.15
    >>> expected_calibration_error([1.0, 0.55], [True, False])
    0.275
    """
    if not confidences:
        return 0.0
    conf = np.asarray(confidences, dtype=float)
    ok = np.asarray(correct, dtype=float)
    which = np.minimum((conf * bins).astype(int), bins - 1)
    total = 0.0
    for b in range(bins):
        mask = which == b
        if mask.any():
            total += abs(ok[mask].mean() - conf[mask].mean()) * mask.mean()
    return round(float(total), 6)


def load_points(path: Path) -> list[DecisionPoint]:
    if not path.is_file():
        raise BadRequest(f"discovery dataset not found: {path}")
    points: list[DecisionPoint] = []
    for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip():
            continue
        try:
            points.append(DecisionPoint.model_validate_json(line))
        except ValidationError as exc:
            msg = "; ".join(f"{'.'.join(map(str, e['loc'])) or 'line'}: {e['msg']}" for e in exc.errors())
            raise BadRequest(f"{path}:{i}: {msg}") from None
    return points


def _percentile(values: list[float], q: float) -> float:
    return round(float(np.percentile(values, q)), 6) if values else 0.0


def summarise(outcomes: list[Outcome], backend: str) -> dict[str, Any]:
    """The SPEC §4 summary (plus a few extra keys) from scored outcomes."""
    main = [o for o in outcomes if o.main]
    novel = [o for o in outcomes if o.novel]
    seen = [o for o in outcomes if not o.novel]

    def acc(rows: list[Outcome]) -> float | None:
        return round(100.0 * sum(o.correct for o in rows) / len(rows), 2) if rows else None

    lat = [o.latency_s for o in outcomes]
    return {
        "n": len(main),
        "accuracy": acc(main),
        "accuracy_novel": acc(novel),
        "ece": expected_calibration_error([o.confidence for o in outcomes], [o.correct for o in outcomes]),
        "latency_p50_s": _percentile(lat, 50),
        "latency_p95_s": _percentile(lat, 95),
        "backend": backend,
        "n_novel": len(novel),
        "n_total": len(outcomes),
        "ece_in_memory": expected_calibration_error([o.confidence for o in seen], [o.correct for o in seen]),
        "ece_novel": expected_calibration_error([o.confidence for o in novel], [o.correct for o in novel]),
        "latency_p50_in_memory_s": _percentile([o.latency_s for o in seen], 50),
        "latency_p50_novel_s": _percentile([o.latency_s for o in novel], 50),
        "mean_confidence": round(float(np.mean([o.confidence for o in outcomes])), 4) if outcomes else None,
        "statuses": dict(Counter(o.status for o in outcomes)),
    }


async def replay(
    discoverer: Any, files: list[tuple[Path, bool]], progress: bool = False
) -> list[Outcome]:
    """Answer every decision point of ``files`` (path, is_main) one at a time."""
    outcomes: list[Outcome] = []
    index = discoverer.resources.index
    for path, is_main in files:
        for k, p in enumerate(load_points(path)):
            request = {"signature": p.signature, "trace": p.trace, "options": p.options, "request_id": p.id}
            start = time.perf_counter()
            result = await discoverer.discover(request)
            latency = time.perf_counter() - start
            outcomes.append(
                Outcome(
                    id=p.id,
                    main=is_main,
                    novel=not index.is_known(p.signature),
                    correct=result.recommendation == p.answer,
                    confidence=result.confidence,
                    latency_s=latency,
                    status=result.status.value,
                )
            )
            if progress and (k + 1) % 100 == 0:
                print(f"  {path.name}: {k + 1}", file=sys.stderr)
    return outcomes


def seeded_memory(path: Path, seed_file: Path) -> Any:
    """A fresh telemetry memory at ``path`` holding the records of ``seed_file``."""
    from lucifer.telemetry import benchmark

    if not seed_file.is_file():
        raise BadRequest(f"memory seed not found: {seed_file}")
    try:
        return benchmark.seeded_memory(path, seed_file)
    except (ValidationError, ValueError) as exc:
        raise BadRequest(f"{seed_file}: invalid telemetry record: {exc}") from None


async def run_eval(
    kb: str | None,
    model: str | None,
    dataset: str | None,
    *,
    limit: int | None = None,
    progress: bool = False,
) -> dict[str, Any]:
    """Replay the benchmark and return the summary (see module docstring)."""
    from lucifer.graphs.discovery import Discoverer
    from lucifer.telemetry.benchmark import DECISIONS_FILE, DEFAULT_DIR, MEMORY_FILE, NOVEL_FILE

    if dataset is not None:
        files = [(Path(dataset), True)]
        seed = Path(dataset).parent / MEMORY_FILE
        if not seed.is_file():
            seed = DEFAULT_DIR / MEMORY_FILE
    else:
        files = [(DEFAULT_DIR / DECISIONS_FILE, True), (DEFAULT_DIR / NOVEL_FILE, False)]
        seed = DEFAULT_DIR / MEMORY_FILE
    if limit is not None:
        files = [(_head(p, limit), main) for p, main in files]
    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="lucifer-discovery-") as tmp:
        memory = seeded_memory(Path(tmp) / "memory.sqlite", seed)
        discoverer = Discoverer(kb, memory=memory, model=model)
        try:
            discoverer.resources.warm_up()
            outcomes = await replay(discoverer, files, progress=progress)
        finally:
            discoverer.close()
    summary = summarise(outcomes, discoverer.backend)
    summary["wall_s"] = round(time.perf_counter() - start, 3)
    return summary


def _head(path: Path, n: int) -> Path:
    """A temporary copy of the first ``n`` lines of ``path``."""
    lines = path.read_text(encoding="utf-8").splitlines()[:n]
    out = Path(tempfile.mkdtemp(prefix="lucifer-head-")) / path.name
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return out


def cmd_eval_discovery(args: argparse.Namespace) -> int:
    summary = asyncio.run(
        run_eval(
            getattr(args, "kb", None),
            getattr(args, "model", None),
            getattr(args, "dataset", None),
            limit=getattr(args, "limit", None),
            progress=sys.stderr.isatty(),
        )
    )
    text = json.dumps(summary, indent=2)
    print(text)
    if getattr(args, "json_out", None):
        out = Path(args.json_out)
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(text + "\n", encoding="utf-8")
    return 0

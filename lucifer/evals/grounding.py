"""``lucifer eval grounding``: async batch evaluation of a grounding dataset (SPEC §3)."""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
import time
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from lucifer.errors import BadRequest
from lucifer.evals.scoring import ReportScore, adjusted_accuracy, score_report

REGIMES = ("standard", "messy", "advanced_messy")


class ExpectedObject(BaseModel):
    model_config = ConfigDict(extra="ignore")
    location: str
    category: str


class DatasetRow(BaseModel):
    model_config = ConfigDict(extra="allow")
    id: str
    regime: str
    report: str
    expected: list[ExpectedObject] = Field(default_factory=list)


def load_dataset(paths: list[str]) -> list[DatasetRow]:
    """Read JSONL datasets; every malformed line is reported with file and line number."""
    rows: list[DatasetRow] = []
    problems: list[str] = []
    seen: set[str] = set()
    for path in paths:
        p = Path(path)
        if not p.is_file():
            raise BadRequest(f"dataset {path} does not exist")
        for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
            if not line.strip():
                continue
            try:
                row = DatasetRow.model_validate_json(line)
            except ValidationError as exc:
                err = exc.errors()[0]
                problems.append(f"{path}:{n}: {'.'.join(map(str, err['loc'])) or 'line'}: {err['msg']}")
                continue
            if row.id in seen:
                problems.append(f"{path}:{n}: duplicate id {row.id!r}")
                continue
            seen.add(row.id)
            rows.append(row)
    if problems:
        shown = "\n  ".join(problems[:20])
        more = f"\n  ... and {len(problems) - 20} more" if len(problems) > 20 else ""
        raise BadRequest(f"invalid dataset line(s):\n  {shown}{more}")
    return rows


@dataclass
class RowResult:
    row: DatasetRow
    predicted: list[dict[str, Any]]
    score: ReportScore
    latency_s: float
    trace_id: str
    status: str
    error: str | None = None


@dataclass
class EvalReport:
    results: list[RowResult]
    backend: str
    wall_s: float
    regimes: dict[str, dict[str, Any]] = field(default_factory=dict)

    def summary(self) -> dict[str, Any]:
        return {"regimes": self.regimes, "backend": self.backend, "wall_s": round(self.wall_s, 3),
                "n": len(self.results)}


def _aggregate(results: list[RowResult]) -> dict[str, Any]:
    lat = np.array([r.latency_s for r in results]) if results else np.array([0.0])
    no_claim = [r for r in results if not r.row.expected]
    return {
        "adjusted_accuracy": round(adjusted_accuracy(r.score for r in results), 2),
        "n": len(results),
        "perfect": sum(r.score.perfect for r in results),
        "hallucinated": sum(r.score.hallucinated for r in results),
        "no_claim_hallucinated": sum(r.score.hallucinated for r in no_claim),
        "latency_p50_s": round(float(np.percentile(lat, 50)), 4),
        "latency_p95_s": round(float(np.percentile(lat, 95)), 4),
        "latency_mean_s": round(float(lat.mean()), 4),
        "errors": sum(1 for r in results if r.error),
    }


async def evaluate(grounder: Any, rows: list[DatasetRow], concurrency: int = 8, progress: bool = False) -> EvalReport:
    """Ground every row, ``concurrency`` at a time, and score it."""
    sem = asyncio.Semaphore(max(1, concurrency))
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=len(rows), desc="grounding", unit="report", file=sys.stderr, leave=False)

    async def one(row: DatasetRow) -> RowResult:
        async with sem:
            t0 = time.perf_counter()
            try:
                res = await grounder.ground(row.report, report_id=row.id)
                pred = [{"location": o.location, "category": o.category, "cells": o.cells} for o in res.objects]
                out = RowResult(row, pred, score_report([e.model_dump() for e in row.expected], pred),
                                res.latency_s, res.trace_id, res.status.value)
            except Exception as exc:  # a failing report is recorded, never silently dropped
                out = RowResult(row, [], score_report([e.model_dump() for e in row.expected], []),
                                time.perf_counter() - t0, "", "error", f"{type(exc).__name__}: {exc}")
            if bar is not None:
                bar.update(1)
            return out

    t0 = time.perf_counter()
    results = await asyncio.gather(*(one(r) for r in rows))
    wall = time.perf_counter() - t0
    if bar is not None:
        bar.close()
    report = EvalReport(list(results), getattr(grounder, "model", "?"), wall)
    by_regime: dict[str, list[RowResult]] = defaultdict(list)
    for r in results:
        by_regime[r.row.regime].append(r)
    order = [g for g in REGIMES if g in by_regime] + sorted(set(by_regime) - set(REGIMES))
    report.regimes = {g: _aggregate(by_regime[g]) for g in order}
    report.regimes["overall"] = _aggregate(list(results))
    return report


def format_table(report: EvalReport) -> str:
    head = f"{'regime':<16}{'n':>5}{'adj.acc':>9}{'perfect':>9}{'halluc.':>9}{'p50 ms':>9}{'p95 ms':>9}"
    lines = [head, "-" * len(head)]
    for g, m in report.regimes.items():
        lines.append(f"{g:<16}{m['n']:>5}{m['adjusted_accuracy']:>9.1f}{m['perfect']:>9}{m['hallucinated']:>9}"
                     f"{m['latency_p50_s'] * 1000:>9.1f}{m['latency_p95_s'] * 1000:>9.1f}")
    lines.append(f"backend: {report.backend}   reports: {len(report.results)}   wall: {report.wall_s:.2f} s")
    return "\n".join(lines)


def format_errors(report: EvalReport) -> str:
    lines = []
    for r in report.results:
        if r.score.perfect and not r.error:
            continue
        exp = sorted(f"{e.location}/{e.category}" for e in r.row.expected)
        got = sorted(f"{p['location']}/{p['category']}" for p in r.predicted)
        lines.append(f"[{r.row.id}] ({r.row.regime}) {r.row.report}")
        lines.append(f"    expected: {', '.join(exp) or '(nothing)'}")
        lines.append(f"    got:      {', '.join(got) or '(nothing)'}")
        lines.append(f"    trace:    {r.trace_id or '-'}" + (f"   error: {r.error}" if r.error else "")
                     + (f"   status: {r.status}" if r.status not in ("ok", "error") else ""))
    return "\n".join(lines) if lines else "no misses"


def cmd_eval_grounding(args: argparse.Namespace) -> int:
    from lucifer.grounding import Grounder

    rows = load_dataset(args.dataset)
    if args.limit:
        rows = rows[: args.limit]

    async def run() -> EvalReport:
        g = Grounder(args.kb, args.model, chroma_url=args.chroma_url, base_url=args.base_url,
                     retries=args.retries, timeout_s=args.timeout)
        try:
            return await evaluate(g, rows, args.concurrency, progress=not args.no_progress and sys.stderr.isatty())
        finally:
            await g.aclose()

    report = asyncio.run(run())
    if args.predictions:
        with open(args.predictions, "w", encoding="utf-8") as fh:
            for r in report.results:
                line = {"id": r.row.id, "objects": r.predicted, "latency_s": round(r.latency_s, 4),
                        "trace_id": r.trace_id, "status": r.status}
                if r.error:
                    line["error"] = r.error
                fh.write(json.dumps(line, ensure_ascii=False) + "\n")
    if args.errors:
        print(format_errors(report))
        print()
    print(format_table(report))
    if args.json_out:
        Path(args.json_out).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json_out).write_text(json.dumps(report.summary(), indent=1))
    return 0

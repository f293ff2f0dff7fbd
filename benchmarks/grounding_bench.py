#!/usr/bin/env python
"""Grounding latency benchmark: cold CLI, warm in-process, and a 450-report batch.

    .venv/bin/python benchmarks/grounding_bench.py [--out benchmarks/results/grounding_bench.json]

Measures, with the builtin backend and the shipped KB:

(a) cold: wall time of one ``lucifer ground --json TEXT`` process, median of ``--runs`` runs
    (OS cache warm, vector index already built), plus one first-ever run with an empty
    ``LUCIFER_HOME`` (the index is built inside that run), reported separately;
(b) warm: ``Grounder.ground`` latency per report over ``--warm-n`` dev reports, one at a time,
    with tracing on (the default, as users run it): p50 / p95 / mean;
(c) batch: wall time of ``lucifer eval grounding`` over the 450 dev reports, ``--concurrency 8``.

Targets: cold <= 4 s, warm p50 <= 50 ms, batch 450 <= 20 s. Every number is wall-clock on the
machine it runs on (this repo's: 2 CPU cores shared with other processes), so medians are
reported and the load average is recorded before and after. Results go to stdout and ``--out``.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
KB = ROOT / "knowledge_base"
DEV = [ROOT / "datasets" / "grounding" / f"{g}.jsonl" for g in ("standard", "messy", "advanced_messy")]
REPORT = "Engine 4 to base: fire at the bakery, uh, no, the bank, and someone hurt next to the school."
TARGETS = {"cold_s": 4.0, "warm_p50_ms": 50.0, "batch_450_s": 20.0}


def lucifer_cmd() -> list[str]:
    exe = Path(sys.executable).with_name("lucifer")
    return [str(exe)] if exe.is_file() else [sys.executable, "-m", "lucifer.cli"]


def bench_env(home: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("LUCIFER_MODEL", "LUCIFER_KB", "LUCIFER_CHROMA_URL")}
    env["LUCIFER_HOME"] = str(home)
    env.setdefault("HF_HUB_OFFLINE", "1")
    return env


def timed(cmd: list[str], env: dict[str, str]) -> tuple[float, subprocess.CompletedProcess[str]]:
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True, cwd=ROOT)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(cmd[:4])} ... failed ({proc.returncode}):\n{proc.stderr[-2000:]}")
    return wall, proc


def bench_cold(home: Path, runs: int) -> dict[str, Any]:
    cmd = lucifer_cmd() + ["ground", "--kb", str(KB), "--json", REPORT]
    with tempfile.TemporaryDirectory(prefix="lucifer-bench-first-") as fresh:
        first, proc = timed(cmd, bench_env(Path(fresh)))
    objects = json.loads(proc.stdout)["objects"]
    timed(cmd, bench_env(home))  # builds the index and warms the OS cache; not counted
    walls = [timed(cmd, bench_env(home))[0] for _ in range(runs)]
    return {
        "median_s": round(statistics.median(walls), 3),
        "runs_s": [round(w, 3) for w in walls],
        "first_ever_s": round(first, 3),
        "first_ever_note": "empty LUCIFER_HOME: the vector index is built inside this run",
        "objects": [f"{o['location']}/{o['category']}" for o in objects],
    }


async def _warm(home: Path, n: int) -> dict[str, Any]:
    os.environ.update({"LUCIFER_HOME": str(home), "HF_HUB_OFFLINE": os.environ.get("HF_HUB_OFFLINE", "1")})
    from lucifer.evals.backends import round_robin
    from lucifer.evals.grounding import load_dataset
    from lucifer.grounding import Grounder

    rows = round_robin(load_dataset([str(p) for p in DEV]))
    g = Grounder(KB, model="builtin")  # trace=True: checkpoints and the trace index, as users run it
    try:
        for r in rows[-5:]:  # load models and compile the traced graph; not counted
            await g.ground(r.report)
        lat = []
        for r in rows[:n]:
            t0 = time.perf_counter()
            await g.ground(r.report, report_id=r.id)
            lat.append(time.perf_counter() - t0)
    finally:
        await g.aclose()
    q = statistics.quantiles(lat, n=100, method="inclusive")
    return {"n": len(lat), "p50_ms": round(statistics.median(lat) * 1000, 2), "p95_ms": round(q[94] * 1000, 2),
            "mean_ms": round(statistics.fmean(lat) * 1000, 2), "max_ms": round(max(lat) * 1000, 2),
            "trace": True}


def bench_batch(home: Path, concurrency: int) -> dict[str, Any]:
    with tempfile.TemporaryDirectory(prefix="lucifer-bench-batch-") as tmp:
        summary = Path(tmp) / "summary.json"
        cmd = lucifer_cmd() + ["eval", "grounding", "--kb", str(KB), "--concurrency", str(concurrency),
                               "--no-progress", "--json", str(summary)]
        for p in DEV:
            cmd += ["--dataset", str(p)]
        wall, _ = timed(cmd, bench_env(home))
        s = json.loads(summary.read_text())
    return {"n": s["n"], "concurrency": concurrency, "wall_s": round(wall, 2),
            "eval_wall_s": s.get("wall_s"), "note": "wall_s is the whole process, eval_wall_s the grounding alone",
            "adjusted_accuracy": {g: m["adjusted_accuracy"] for g, m in s["regimes"].items()}}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "results" / "grounding_bench.json"))
    ap.add_argument("--runs", type=int, default=5, help="cold CLI runs (median reported)")
    ap.add_argument("--warm-n", type=int, default=200, help="reports for the warm latency")
    ap.add_argument("--concurrency", type=int, default=8)
    a = ap.parse_args(argv)

    home = Path(tempfile.mkdtemp(prefix="lucifer-bench-home-"))
    load_before = os.getloadavg()
    t0 = time.perf_counter()
    try:
        print("[bench] cold CLI ...", file=sys.stderr, flush=True)
        cold = bench_cold(home, a.runs)
        print("[bench] warm Grounder.ground ...", file=sys.stderr, flush=True)
        warm = asyncio.run(_warm(home, a.warm_n))
        print("[bench] batch eval grounding ...", file=sys.stderr, flush=True)
        batch = bench_batch(home, a.concurrency)
    finally:
        shutil.rmtree(home, ignore_errors=True)
    result = {
        "generated_at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "backend": "builtin",
        "machine": {"cpus": os.cpu_count(), "python": platform.python_version(), "platform": platform.platform(),
                    "load_avg_1m_before": round(load_before[0], 2), "load_avg_1m_after": round(os.getloadavg()[0], 2),
                    "note": "2 CPU cores shared with other processes; medians, wall-clock"},
        "cold": cold,
        "warm": warm,
        "batch": batch,
        "targets": TARGETS,
        "meets_target": {
            "cold_s": cold["median_s"] <= TARGETS["cold_s"],
            "warm_p50_ms": warm["p50_ms"] <= TARGETS["warm_p50_ms"],
            "batch_450_s": batch["wall_s"] <= TARGETS["batch_450_s"],
        },
        "bench_wall_s": round(time.perf_counter() - t0, 1),
    }
    out = Path(a.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=1) + "\n")
    print(json.dumps(result, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python
"""Regenerate every benchmark result under benchmarks/results/ (``make bench``).

Runs, in order: the grounding latency bench, ``lucifer eval backends``, and, where the
command exists in this checkout, ``lucifer eval discovery`` and ``lucifer eval ablation
--client planner``. A command that does not exist yet is skipped with a printed note; a
command that fails is reported and the rest still run (exit status 1 at the end).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import importlib.util
import io
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results"


def lucifer_cmd() -> list[str]:
    exe = Path(sys.executable).with_name("lucifer")
    return [str(exe)] if exe.is_file() else [sys.executable, "-m", "lucifer.cli"]


def eval_command_exists(name: str) -> tuple[bool, str]:
    """Is ``lucifer eval NAME`` declared, and is the module behind it importable?"""
    from lucifer.cli import build_parser

    parser = build_parser()
    try:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            parser.parse_args(["eval", name, "--help"])
    except SystemExit as exc:  # argparse exits 0 after --help, 2 for an unknown command
        if exc.code != 0:
            return False, f"`lucifer eval {name}` is not declared"
    module, func = {"backends": ("lucifer.evals.backends", "cmd_eval_backends"),
                    "discovery": ("lucifer.evals.discovery", "cmd_eval_discovery"),
                    "ablation": ("lucifer.evals.ablation", "cmd_eval_ablation")}[name]
    if importlib.util.find_spec(module) is None:
        return False, f"{module} does not exist yet"
    try:
        if not callable(getattr(importlib.import_module(module), func, None)):
            return False, f"{module}.{func} does not exist yet"
    except Exception as exc:  # an import error means the command cannot run; say why
        return False, f"{module} does not import: {type(exc).__name__}: {exc}"
    return True, ""


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--llm-limit", type=int, default=30, help="passed to `lucifer eval backends`")
    a = ap.parse_args(argv)
    RESULTS.mkdir(parents=True, exist_ok=True)
    steps: list[tuple[str, str | None, list[str]]] = [
        ("grounding bench", None, [sys.executable, str(ROOT / "benchmarks" / "grounding_bench.py"),
                                   "--out", str(RESULTS / "grounding_bench.json")]),
        ("eval backends", "backends", lucifer_cmd() + ["eval", "backends", "--out", str(RESULTS),
                                                       "--llm-limit", str(a.llm_limit)]),
        ("eval discovery", "discovery", lucifer_cmd() + ["eval", "discovery", "--json",
                                                         str(RESULTS / "discovery.json")]),
        ("eval ablation planner", "ablation", lucifer_cmd() + ["eval", "ablation", "--client", "planner", "--json",
                                                               str(RESULTS / "ablation_planner.json")]),
    ]
    summary = []
    for label, eval_name, cmd in steps:
        if eval_name is not None:
            ok, why = eval_command_exists(eval_name)
            if not ok:
                print(f"[run_all] skipping {label}: {why}", flush=True)
                summary.append((label, "skipped", 0.0))
                continue
        print(f"[run_all] {label}: {' '.join(cmd[1:] if cmd[0] == sys.executable else cmd)}", flush=True)
        t0 = time.perf_counter()
        rc = subprocess.run(cmd, cwd=ROOT).returncode
        summary.append((label, "ok" if rc == 0 else f"failed (exit {rc})", time.perf_counter() - t0))
    print("\n[run_all] summary")
    for label, status, wall in summary:
        print(f"  {label:<24}{status:<20}{wall:8.1f} s")
    return 1 if any(s.startswith("failed") for _, s, _ in summary) else 0


if __name__ == "__main__":
    sys.exit(main())

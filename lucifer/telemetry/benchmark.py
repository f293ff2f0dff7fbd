"""Generate the shipped discovery benchmark (``datasets/discovery/``) from a seed.

Files (JSON Lines unless noted):

* ``memory_seed.jsonl``: telemetry records ``{signature, trace, option, outcome, episode,
  client}``; 24 signatures per option from the ``seen`` phrasing pool, 5 to 8 records each.
  The correct option is tried at least 3 times and succeeds with probability 0.9; other
  options succeed with probability 0.1, so memory is informative but noisy.
* ``decision_points.jsonl``: 600 decision points ``{id, split: "memory", signature, trace,
  options, answer}`` at signatures present in memory, with 4 to 6 candidate options.
* ``novel.jsonl``: 210 held-out decision points (``split: "novel"``) whose signatures use
  the ``novel`` phrasing pool: no cue or place phrase of theirs occurs in memory.
* ``dev.jsonl``: 150 calibration points (``split: "dev"``) from the ``dev`` pool; the
  confidence temperature is fitted on them, never on the test files.
* ``calibration.json`` (written by ``lucifer.graphs.discovery.calibration``): the fitted
  temperature.

Regenerate with ``python -m lucifer.telemetry.benchmark`` (same seed, same files).
"""

from __future__ import annotations

import argparse
import json
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np

from lucifer.telemetry.memory import TelemetryMemory, signature_key
from lucifer.telemetry.scenarios import OPTIONS, Pool, sample_candidates, sample_signature


def _default_dir() -> Path:
    """``datasets/discovery`` of the repository this package lives in, else of the cwd."""
    repo = Path(__file__).resolve().parents[2] / "datasets" / "discovery"
    return repo if repo.is_dir() else Path("datasets/discovery")


DEFAULT_DIR = _default_dir()
MEMORY_FILE = "memory_seed.jsonl"
DECISIONS_FILE = "decision_points.jsonl"
NOVEL_FILE = "novel.jsonl"
DEV_FILE = "dev.jsonl"

SIGNATURES_PER_OPTION = 24
N_DECISIONS = 600
N_NOVEL = 210
N_DEV = 150
P_SUCCESS_CORRECT = 0.9
P_SUCCESS_WRONG = 0.1

_TRACE_STEPS = (
    "entered the square from the north road",
    "moved two cells east",
    "moved one cell south",
    "radio check with base, all clear",
    "report received: smoke seen in town",
    "waited for the team to regroup",
    "turned back from a blocked street",
    "reached the information location",
    "previous query found nothing useful",
    "marked the last cell as visited",
    "battery at half charge",
    "received an updated map from base",
)


def _trace(rng: np.random.Generator) -> list[str]:
    k = int(rng.integers(1, 4))
    return [_TRACE_STEPS[int(i)] for i in rng.choice(len(_TRACE_STEPS), size=k, replace=False)]


def memory_records(rng: np.random.Generator) -> tuple[list[dict[str, Any]], dict[str, str]]:
    """Seed telemetry records, and the option that generated each signature (by key)."""
    records: list[dict[str, Any]] = []
    truth: dict[str, str] = {}
    episode = 0
    for option in OPTIONS:
        seen: set[str] = set()
        while len(seen) < SIGNATURES_PER_OPTION:
            sig = sample_signature(option, rng, pool="seen")
            if signature_key(sig) in seen:
                continue
            seen.add(signature_key(sig))
            truth[signature_key(sig)] = option
            n = int(rng.integers(5, 9))
            tried = [option] * 3 + [
                option if rng.random() < 0.3 else str(rng.choice([o for o in OPTIONS if o != option]))
                for _ in range(n - 3)
            ]
            rng.shuffle(tried)
            for opt in tried:
                episode += 1
                p = P_SUCCESS_CORRECT if opt == option else P_SUCCESS_WRONG
                records.append(
                    {
                        "signature": sig,
                        "trace": "; ".join(_trace(rng)),
                        "option": opt,
                        "outcome": 1.0 if rng.random() < p else 0.0,
                        "episode": f"seed-{episode:05d}",
                        "client": "benchmark",
                    }
                )
    order = rng.permutation(len(records))
    return [records[int(i)] for i in order], truth


def decision_points(
    rng: np.random.Generator,
    n: int,
    split: Pool | str,
    memory: list[dict[str, Any]],
    truth: dict[str, str],
) -> list[dict[str, Any]]:
    """``n`` points; ``split="memory"`` draws signatures from ``memory`` (answers from
    ``truth``), any other split samples fresh signatures from that phrasing pool."""
    points: list[dict[str, Any]] = []
    known: dict[str, str] = {}
    for r in memory:
        known.setdefault(signature_key(r["signature"]), r["signature"])
    if split == "memory":
        keys = sorted(truth)
        for i in range(n):
            key = keys[int(rng.integers(len(keys)))]
            points.append(_point(f"d-{i + 1:04d}", "memory", known[key], truth[key], rng))
        return points
    pool: Pool = split  # type: ignore[assignment]
    prefix = {"novel": "n", "dev": "c", "seen": "s"}[pool]
    for i in range(n):
        option = OPTIONS[i % len(OPTIONS)]
        while True:
            sig = sample_signature(option, rng, pool=pool)
            if signature_key(sig) not in known:
                break
        points.append(_point(f"{prefix}-{i + 1:04d}", pool, sig, option, rng))
    return points


def _point(pid: str, split: str, sig: str, option: str, rng: np.random.Generator) -> dict[str, Any]:
    return {
        "id": pid,
        "split": split,
        "signature": sig,
        "trace": _trace(rng),
        "options": sample_candidates(option, rng),
        "answer": option,
    }


def seeded_memory(path: str | Path, seed_file: Path | None = None, **kwargs: Any) -> TelemetryMemory:
    """A telemetry memory at ``path`` holding the shipped seed telemetry (or ``seed_file``).

    Clients that want discovery to start with experience use this; the eval does too.
    """
    memory = TelemetryMemory(path, **kwargs)
    try:
        memory.seed_from(seed_file or DEFAULT_DIR / MEMORY_FILE)
    except BaseException:
        memory.close()
        raise
    return memory


def write_jsonl(path: Path, rows: Iterable[dict[str, Any]]) -> int:
    n = 0
    with path.open("w", encoding="utf-8") as f:
        for row in rows:
            f.write(json.dumps(row, ensure_ascii=False) + "\n")
            n += 1
    return n


def read_jsonl(path: Path) -> list[dict[str, Any]]:
    with path.open(encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


def generate(out: Path = DEFAULT_DIR, seed: int = 0) -> dict[str, int]:
    """Write the benchmark files under ``out``; returns line counts per file."""
    out.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    memory, truth = memory_records(rng)
    counts = {MEMORY_FILE: write_jsonl(out / MEMORY_FILE, memory)}
    for name, n, split in (
        (DECISIONS_FILE, N_DECISIONS, "memory"),
        (NOVEL_FILE, N_NOVEL, "novel"),
        (DEV_FILE, N_DEV, "dev"),
    ):
        counts[name] = write_jsonl(out / name, decision_points(rng, n, split, memory, truth))
    return counts


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    p.add_argument("--out", type=Path, default=DEFAULT_DIR)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--no-calibrate", action="store_true", help="skip fitting calibration.json")
    args = p.parse_args(argv)
    for name, n in generate(args.out, args.seed).items():
        print(f"{args.out / name}: {n} lines")
    if not args.no_calibrate:
        from lucifer.graphs.discovery.calibration import calibrate_dir

        print(f"{args.out / 'calibration.json'}: {calibrate_dir(args.out)}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())

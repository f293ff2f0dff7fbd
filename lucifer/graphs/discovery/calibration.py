"""Confidence calibration: one softmax temperature fitted on the ``dev`` split.

The dev split (``datasets/discovery/dev.jsonl``) uses its own phrasing pool, disjoint from
memory and from the novel test set, so the fitted temperature is not tuned on test data. The
fit minimises the negative log-likelihood of the correct option over a grid of temperatures
and is stored in ``calibration.json`` next to the benchmark; every discovery run reads it.
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from lucifer.graphs.discovery.context import DEFAULT_TEMPERATURE

CALIBRATION_FILE = "calibration.json"
TEMPERATURES = tuple(float(t) for t in np.round(np.exp(np.linspace(np.log(0.2), np.log(8.0), 121)), 4))


def load_temperature(directory: Path | None = None) -> float:
    """The fitted temperature, or the default when no calibration file is shipped."""
    from lucifer.telemetry.benchmark import DEFAULT_DIR

    path = (directory or DEFAULT_DIR) / CALIBRATION_FILE
    if not path.is_file():
        return DEFAULT_TEMPERATURE
    return float(json.loads(path.read_text())["temperature"])


def fit_temperature(logits: list[np.ndarray], answers: list[int]) -> float:
    """Temperature minimising the NLL of ``answers`` under softmax(logits / T)."""
    best, best_nll = DEFAULT_TEMPERATURE, float("inf")
    for t in TEMPERATURES:
        nll = 0.0
        for z, y in zip(logits, answers, strict=True):
            s = z / t
            m = s.max()
            nll -= s[y] - m - np.log(np.exp(s - m).sum())
        if nll < best_nll:
            best, best_nll = t, nll
    return best


async def dev_logits(directory: Path) -> tuple[list[np.ndarray], list[int]]:
    """Builtin logits and answer indices of the dev split, with memory seeded from the benchmark."""
    from lucifer.graphs.discovery import Discoverer, policy
    from lucifer.graphs.discovery.graph import builtin_tool_calls
    from lucifer.graphs.discovery.state import DiscoveryRequest
    from lucifer.telemetry.benchmark import DEV_FILE, MEMORY_FILE, read_jsonl
    from lucifer.telemetry.memory import TelemetryMemory, TelemetryRecord

    with tempfile.TemporaryDirectory() as tmp:
        memory = TelemetryMemory(Path(tmp) / "memory.sqlite")
        memory.append(TelemetryRecord(**r) for r in read_jsonl(directory / MEMORY_FILE))
        disc = Discoverer(memory=memory, temperature=1.0)
        res, ctx = disc.resources, disc.context
        res.warm_up()
        tools = {t.name: t for t in res.tools}
        logits, answers = [], []
        for row in read_jsonl(directory / DEV_FILE):
            req = DiscoveryRequest(signature=row["signature"], trace=row["trace"], options=row["options"])
            evidence: dict[str, Any] = {}
            for call in builtin_tool_calls(req, ctx):
                evidence[call["name"]] = (await tools[call["name"]].ainvoke(call)).artifact
            logits.append(policy.builtin_logits(evidence, req.options, ctx, req.episodic_outcomes()))
            answers.append(req.options.index(row["answer"]))
        memory.close()
    return logits, answers


def calibrate_dir(directory: Path) -> dict[str, Any]:
    """Fit the temperature on ``directory``'s dev split and write ``calibration.json``."""
    import asyncio

    logits, answers = asyncio.run(dev_logits(directory))
    t = fit_temperature(logits, answers)
    acc = float(np.mean([int(np.argmax(z) == y) for z, y in zip(logits, answers, strict=True)]))
    out = {"temperature": t, "fitted_on": "dev.jsonl", "n": len(answers), "dev_accuracy": round(100 * acc, 2)}
    (directory / CALIBRATION_FILE).write_text(json.dumps(out, indent=2) + "\n")
    return out

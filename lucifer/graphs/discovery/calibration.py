"""Confidence calibration: softmax temperatures fitted on the ``dev`` split.

Two regimes get their own temperature: ``temperature`` when telemetry memory offers evidence
(the seeded benchmark memory), ``temperature_cold`` when it offers none (an empty memory, so
only the option descriptions speak).


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
TEMPERATURES = tuple(float(t) for t in np.round(np.exp(np.linspace(np.log(0.02), np.log(20.0), 241)), 4))


def load_calibration(directory: Path | None = None) -> dict[str, float]:
    """Fitted context settings (``temperature``, ``temperature_cold``); empty if none shipped."""
    from lucifer.telemetry.benchmark import DEFAULT_DIR

    path = (directory or DEFAULT_DIR) / CALIBRATION_FILE
    if not path.is_file():
        return {}
    data = json.loads(path.read_text())
    return {k: float(data[k]) for k in ("temperature", "temperature_cold") if k in data}


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


async def dev_logits(directory: Path, with_memory: bool = True) -> tuple[list[np.ndarray], list[int]]:
    """Builtin logits and answer indices of the dev split, with memory seeded from the
    benchmark (or, ``with_memory=False``, with an empty memory)."""
    from lucifer.graphs.discovery import Discoverer, policy
    from lucifer.graphs.discovery.graph import builtin_tool_calls
    from lucifer.graphs.discovery.state import DiscoveryRequest
    from lucifer.telemetry.benchmark import DEV_FILE, MEMORY_FILE, read_jsonl
    from lucifer.telemetry.memory import TelemetryMemory, TelemetryRecord

    with tempfile.TemporaryDirectory() as tmp:
        memory = TelemetryMemory(Path(tmp) / "memory.sqlite")
        if with_memory:
            memory.append(TelemetryRecord(**r) for r in read_jsonl(directory / MEMORY_FILE))
        disc = Discoverer(memory=memory, temperature=1.0, temperature_cold=1.0)
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

    out: dict[str, Any] = {"fitted_on": "dev.jsonl"}
    for key, with_memory in (("temperature", True), ("temperature_cold", False)):
        logits, answers = asyncio.run(dev_logits(directory, with_memory))
        acc = float(np.mean([int(np.argmax(z) == y) for z, y in zip(logits, answers, strict=True)]))
        out[key] = fit_temperature(logits, answers)
        out["n"] = len(answers)
        out["dev_accuracy" if with_memory else "dev_accuracy_cold"] = round(100 * acc, 2)
    (directory / CALIBRATION_FILE).write_text(json.dumps(out, indent=2) + "\n")
    return out

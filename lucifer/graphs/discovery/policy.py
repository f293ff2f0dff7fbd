"""The builtin discovery policy: tool evidence in, P(u | x_t, xi, D) out. No LLM.

For each clause of the signature the policy scores every candidate option by

    memory_weight * log(share of the k nearest known clauses' signatures where the option
                        worked best, + vote_smoothing)
  + prototype_weight * cosine(clause, the option's prototype: the mean of the known clauses
                              where it worked best)
  + semantic_weight * cosine(clause, option description)

normalises the scores into a log-distribution over U(x_t), and adds the clauses up, each
weighted by its focus: how concentrated the votes of its nearest known clauses are over all
options (a place phrase like "near the school" was seen with every option and barely counts).
Without memory evidence a clause counts by its best cosine to an option description. When the signature itself is in memory, each option's net successes there
(+1 per success, -1 per failure, times exact_weight) are added, and likewise the
outcomes of queries the episodic trace says were already run here in this episode. The logits go through a softmax at the
calibrated temperature; the confidence is the probability of the recommendation.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from lucifer.graphs.discovery.context import DiscoveryContext
from lucifer.graphs.discovery.tools import (
    OPTION_FIT,
    SIGNATURE_OUTCOMES,
    SIMILAR_SIGNATURES,
)


def _log_softmax(x: np.ndarray) -> np.ndarray:
    m = x.max()
    return x - m - np.log(np.exp(x - m).sum())


def builtin_logits(
    evidence: dict[str, dict[str, Any]],
    options: list[str],
    ctx: DiscoveryContext,
    episodic: dict[str, tuple[int, float]] | None = None,
) -> np.ndarray:
    """Unnormalised log-probabilities of ``options`` from whatever tool evidence is present,
    plus ``episodic`` outcomes (queries already run here in this episode, from the trace)."""
    z = np.zeros(len(options))
    similar = evidence.get(SIMILAR_SIGNATURES)
    fit = evidence.get(OPTION_FIT)
    n_clauses = len(similar["clauses"]) if similar else len(fit["clauses"]) if fit else 0
    for i in range(n_clauses):
        score = np.zeros(len(options))
        weight = 0.0
        if similar:
            c = similar["clauses"][i]
            score += ctx.memory_weight * np.log(np.array([c["votes"][o] for o in options]) + ctx.vote_smoothing)
            if c.get("prototype"):
                score += ctx.prototype_weight * np.array([c["prototype"][o] for o in options])
            weight = c["focus"]
        if fit:
            sem = np.array([fit["similarity"][o][i] for o in options])
            score += ctx.semantic_weight * sem
            if not similar or similar["clauses"][i]["match"] is None:  # no memory to judge by
                weight = max(weight, float(sem.max()))
        z += float(np.clip(weight, 0.0, 1.0)) * _log_softmax(score)
    exact = evidence.get(SIGNATURE_OUTCOMES)
    if exact and exact["known"]:
        for j, o in enumerate(options):
            s = exact["options"].get(o)
            if s:  # net successes: +1 per success, -1 per failure
                z[j] += ctx.exact_weight * (2.0 * s["total"] - s["n"])
    for j, o in enumerate(options):
        if episodic and o in episodic:
            n, total = episodic[o]
            z[j] += ctx.exact_weight * (2.0 * total - n)
    return z


def has_memory_evidence(evidence: dict[str, dict[str, Any]]) -> bool:
    """Whether telemetry memory said anything: a known signature or a matched known clause."""
    exact = evidence.get(SIGNATURE_OUTCOMES)
    similar = evidence.get(SIMILAR_SIGNATURES)
    return bool(exact and exact["known"]) or bool(
        similar and any(c["match"] is not None for c in similar["clauses"])
    )


def distribution(logits: np.ndarray, options: list[str], temperature: float) -> dict[str, float]:
    """Softmax at ``temperature``, as ``{option: probability}`` (sums to 1).

    >>> distribution(np.array([0.0, 0.0]), ["a", "b"], 1.0)
    {'a': 0.5, 'b': 0.5}
    """
    p = np.exp(_log_softmax(logits / max(temperature, 1e-6)))
    return {o: float(v) for o, v in zip(options, p, strict=True)}


def recommend(dist: dict[str, float]) -> tuple[str, float]:
    """u* = argmax (ties broken by the order of U(x_t)) and its probability."""
    best = max(dist, key=lambda o: dist[o])
    return best, dist[best]

"""Tools over telemetry memory and the KB's query options.

Each tool has a plain evidence function (``*_evidence``) returning JSON-able data, and a
LangChain tool wrapping it: the content is compact JSON for a chat model, the artifact the full
evidence the builtin policy reads. The builtin backend and a chat model call the same tools.
"""

from __future__ import annotations

import json
from typing import Any

from langchain_core.tools import BaseTool, StructuredTool

from lucifer.graphs.discovery.context import DiscoveryContext
from lucifer.graphs.discovery.resources import DiscoveryResources

SIGNATURE_OUTCOMES = "signature_outcomes"
SIMILAR_SIGNATURES = "similar_signatures"
OPTION_STATS = "option_stats"
OPTION_FIT = "option_fit"
TOOL_NAMES = (SIGNATURE_OUTCOMES, SIMILAR_SIGNATURES, OPTION_STATS, OPTION_FIT)


def _options(res: DiscoveryResources, options: list[str] | None) -> list[str]:
    if not options:
        return list(res.options)
    unknown = [o for o in options if o not in res.options]
    if unknown:
        raise ValueError(f"unknown option(s): {', '.join(unknown)}; known: {', '.join(res.options)}")
    return list(options)


def signature_outcomes_evidence(res: DiscoveryResources, signature: str) -> dict[str, Any]:
    stats = res.index.signature_stats(signature)
    return {
        "signature": signature,
        "known": bool(stats),
        "options": {o: {"n": s.n, "total": s.total} for o, s in sorted(stats.items())},
    }


def similar_signatures_evidence(
    res: DiscoveryResources, ctx: DiscoveryContext, signature: str, options: list[str] | None, k: int
) -> dict[str, Any]:
    opts = _options(res, options)
    clauses, vecs = res.index.embed_clauses(signature)
    matches = res.index.clause_evidence(
        clauses, vecs, opts, k=ctx.clause_k, tau=ctx.clause_tau, prior_strength=ctx.prior_strength
    )
    neighbors = res.index.neighbors(vecs, k=max(1, min(k, 20)))
    return {
        "clauses": [
            {"clause": m.clause, "match": m.match, "similarity": m.similarity, "success": m.success,
             "votes": m.votes, "focus": m.focus,
             "prototype": m.prototype}
            for m in matches
        ],
        "neighbors": [
            {
                "signature": n.signature,
                "similarity": round(n.similarity, 4),
                "best_option": n.best_option,
                "options": {o: s.as_dict() for o, s in sorted(n.stats.items())},
            }
            for n in neighbors
        ],
    }


def option_stats_evidence(res: DiscoveryResources, options: list[str] | None) -> dict[str, Any]:
    opts = _options(res, options)
    stats = res.index.option_stats()
    return {
        o: {
            "n": stats[o].n if o in stats else 0,
            "mean_outcome": round(stats[o].mean, 4) if o in stats else None,
            "prior_success": round(res.index.option_prior(o), 4),
            "info_type": res.options[o].info_type,
            "description": res.options[o].description,
        }
        for o in opts
    }


def option_fit_evidence(res: DiscoveryResources, signature: str, options: list[str] | None) -> dict[str, Any]:
    opts = _options(res, options)
    clauses, vecs = res.index.embed_clauses(signature)
    sims = {o: (vecs @ res.option_vectors(o).T).max(axis=1) for o in opts}  # per clause
    return {"clauses": clauses, "similarity": {o: [float(x) for x in s] for o, s in sims.items()}}


def _dumps(data: Any) -> str:
    return json.dumps(data, separators=(",", ":"), ensure_ascii=False)


def make_tools(res: DiscoveryResources, ctx: DiscoveryContext) -> list[BaseTool]:
    """The four discovery tools, bound to one set of resources and settings."""

    def signature_outcomes(signature: str) -> tuple[str, dict[str, Any]]:
        ev = signature_outcomes_evidence(res, signature)
        content = {
            "known": ev["known"],
            "options": {
                o: {"n": s["n"], "mean_outcome": round(s["total"] / s["n"], 3)} for o, s in ev["options"].items()
            },
        }
        return _dumps(content), ev

    def similar_signatures(
        signature: str, options: list[str] | None = None, k: int = ctx.neighbors_k
    ) -> tuple[str, dict[str, Any]]:
        ev = similar_signatures_evidence(res, ctx, signature, options, k)
        content = {
            "neighbors": [
                {"signature": n["signature"], "similarity": n["similarity"], "best_option": n["best_option"]}
                for n in ev["neighbors"]
            ],
            "per_clause_success": [
                {"clause": c["clause"], "nearest_known": c["match"],
                 "best_option_share": {o: round(v, 3) for o, v in c["votes"].items() if v > 0.005}}
                for c in ev["clauses"]
            ],
        }
        return _dumps(content), ev

    def option_stats(options: list[str] | None = None) -> tuple[str, dict[str, Any]]:
        ev = option_stats_evidence(res, options)
        return _dumps(ev), ev

    def option_fit(signature: str, options: list[str] | None = None) -> tuple[str, dict[str, Any]]:
        ev = option_fit_evidence(res, signature, options)
        content = {o: round(max(s), 3) for o, s in ev["similarity"].items()}
        return _dumps(content), ev

    specs = (
        (signature_outcomes, SIGNATURE_OUTCOMES,
         "Outcomes recorded in telemetry memory at exactly this location signature: per query "
         "option, how many times it was run and its mean outcome (1 = found the information)."),
        (similar_signatures, SIMILAR_SIGNATURES,
         "The known signatures most similar in meaning to this one (MiniLM embeddings) with the "
         "option that worked best there, and per clause the share of similar known clauses "
         "where each option worked best. Use it when the signature is not known."),
        (option_stats, OPTION_STATS,
         "Statistics of query options over the whole memory (runs, mean outcome) with their "
         "descriptions and the information type each reveals."),
        (option_fit, OPTION_FIT,
         "How well the signature's meaning fits each option's description (cosine similarity, "
         "higher is better); works for signatures never seen before."),
    )

    def _async(fn: Any) -> Any:
        async def run(**kwargs: Any) -> Any:
            return fn(**kwargs)

        return run

    return [
        StructuredTool.from_function(
            func=fn, coroutine=_async(fn), name=name, description=desc, response_format="content_and_artifact"
        )
        for fn, name, desc in specs
    ]

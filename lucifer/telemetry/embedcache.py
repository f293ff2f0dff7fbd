"""A persistent cache of sentence embeddings (SQLite, one row per text and model).

Embedding memory clauses with MiniLM costs milliseconds per text; the cache makes a fresh
process (``lucifer discover``, an evaluation with a temporary memory) start without
re-embedding clauses it has seen before. Default file: ``$LUCIFER_HOME/embeddings.sqlite``.
"""

from __future__ import annotations

import os
import sqlite3
import threading
from collections.abc import Iterable
from pathlib import Path

import numpy as np

from lucifer.paths import home


class EmbeddingCache:
    def __init__(self, path: str | os.PathLike[str] | None = None):
        self.path = Path(path) if path is not None else home() / "embeddings.sqlite"
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._local = threading.local()
        con = self._conn()
        con.execute(
            "CREATE TABLE IF NOT EXISTS embeddings (text TEXT NOT NULL, model TEXT NOT NULL, "
            "vec BLOB NOT NULL, PRIMARY KEY (text, model))"
        )

    def _conn(self) -> sqlite3.Connection:
        con: sqlite3.Connection | None = getattr(self._local, "con", None)
        if con is None:
            con = sqlite3.connect(self.path, timeout=30.0, isolation_level=None)
            con.execute("PRAGMA busy_timeout = 30000")
            con.execute("PRAGMA journal_mode = WAL")
            self._local.con = con
        return con

    def get(self, texts: Iterable[str], model: str) -> dict[str, np.ndarray]:
        """Stored vectors for these texts (missing ones are simply absent)."""
        wanted = list(dict.fromkeys(texts))
        found: dict[str, np.ndarray] = {}
        con = self._conn()
        for i in range(0, len(wanted), 500):
            chunk = wanted[i : i + 500]
            marks = ",".join("?" * len(chunk))
            for text, vec in con.execute(
                f"SELECT text, vec FROM embeddings WHERE model = ? AND text IN ({marks})", (model, *chunk)
            ):
                found[text] = np.frombuffer(vec, dtype=np.float32).copy()
        return found

    def put(self, vectors: dict[str, np.ndarray], model: str) -> None:
        if not vectors:
            return
        con = self._conn()
        con.execute("BEGIN IMMEDIATE")
        try:
            con.executemany(
                "INSERT OR REPLACE INTO embeddings (text, model, vec) VALUES (?, ?, ?)",
                [(t, model, np.asarray(v, dtype=np.float32).tobytes()) for t, v in vectors.items()],
            )
        except BaseException:
            con.execute("ROLLBACK")
            raise
        con.execute("COMMIT")

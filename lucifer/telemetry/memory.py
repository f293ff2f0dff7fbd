"""Telemetry memory: cross-episode records of which query was run where, and how it went.

One record is ``(location signature, episodic trace summary, query option, outcome)``. Clients
append records as they act; the discovery graph reads them back as evidence. The store is a
single SQLite file (default :func:`lucifer.paths.telemetry_db`) in WAL mode with a busy
timeout, so several threads and processes can append at once and readers never block writers.
It is bounded: after each append the oldest records beyond ``max_records`` are evicted in the
same transaction. It survives restarts because it is just a file.

>>> import tempfile, os
>>> with tempfile.TemporaryDirectory() as d:
...     mem = TelemetryMemory(os.path.join(d, "t.sqlite"), max_records=2)
...     mem.append([TelemetryRecord(signature="smell of gas", option="gas_sniffer", outcome=1.0)] * 3)
...     (mem.count(), mem.outcomes("Smell of  gas")["gas_sniffer"].n)
3
(2, 2)
"""

from __future__ import annotations

import os
import sqlite3
import threading
import time
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field, field_validator

from lucifer.paths import telemetry_db

DEFAULT_MAX_RECORDS = 100_000
_SCHEMA = """
CREATE TABLE IF NOT EXISTS records (
    id INTEGER PRIMARY KEY AUTOINCREMENT,
    signature TEXT NOT NULL,
    sig_key TEXT NOT NULL,
    trace TEXT NOT NULL DEFAULT '',
    option TEXT NOT NULL,
    outcome REAL NOT NULL,
    episode TEXT,
    client TEXT,
    created_at REAL NOT NULL
);
CREATE INDEX IF NOT EXISTS records_sig_key ON records(sig_key);
"""


def signature_key(signature: str) -> str:
    """Normalised form used to match signatures exactly (case and spacing do not matter).

    >>> signature_key("  Muffled KNOCKING,  under debris ")
    'muffled knocking, under debris'
    """
    return " ".join(signature.lower().split())


class TelemetryRecord(BaseModel):
    """One query outcome. Clients send these; they are validated before they are stored."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    signature: str = Field(min_length=1, max_length=1000, description="Location signature x.")
    trace: str = Field(default="", max_length=4000, description="Summary of the episodic trace.")
    option: str = Field(min_length=1, max_length=200, description="The query option run there.")
    outcome: float = Field(ge=0.0, le=1.0, description="1 = the query found the information.")
    episode: str | None = Field(default=None, max_length=200)
    client: str | None = Field(default=None, max_length=200)
    created_at: float | None = Field(default=None, description="Unix time; now if omitted.")

    @field_validator("signature", "option")
    @classmethod
    def _clean(cls, v: str) -> str:
        v = " ".join(v.split())
        if not v:
            raise ValueError("must be a non-empty string")
        return v


@dataclass(frozen=True)
class OptionStat:
    """How an option did: ``n`` records, ``total`` summed outcome."""

    n: int
    total: float

    @property
    def mean(self) -> float:
        return self.total / self.n if self.n else 0.0

    def as_dict(self) -> dict[str, float | int]:
        return {"n": self.n, "mean_outcome": round(self.mean, 4)}


class TelemetryMemory:
    """Bounded, concurrent-safe, persistent store of :class:`TelemetryRecord`.

    One SQLite connection per thread; every write is one ``BEGIN IMMEDIATE`` transaction.
    """

    def __init__(
        self,
        path: str | os.PathLike[str] | None = None,
        *,
        max_records: int = DEFAULT_MAX_RECORDS,
        busy_timeout_s: float = 30.0,
    ):
        if max_records < 1:
            raise ValueError("max_records must be at least 1")
        self.path = Path(path) if path is not None else telemetry_db()
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.max_records = max_records
        self.busy_timeout_s = busy_timeout_s
        self._local = threading.local()
        self._conns: list[sqlite3.Connection] = []
        self._conns_lock = threading.Lock()
        self._init_schema()

    # -- connections -------------------------------------------------------------------
    def _conn(self) -> sqlite3.Connection:
        con: sqlite3.Connection | None = getattr(self._local, "con", None)
        if con is None:
            con = sqlite3.connect(
                self.path, timeout=self.busy_timeout_s, isolation_level=None, check_same_thread=False
            )
            con.execute(f"PRAGMA busy_timeout = {int(self.busy_timeout_s * 1000)}")
            con.execute("PRAGMA journal_mode = WAL")
            con.execute("PRAGMA synchronous = NORMAL")
            self._local.con = con
            with self._conns_lock:
                self._conns.append(con)
        return con

    def _init_schema(self) -> None:
        with self._write() as con:
            for stmt in _SCHEMA.split(";"):
                if stmt.strip():
                    con.execute(stmt)

    @contextmanager
    def _write(self) -> Iterator[sqlite3.Connection]:
        con = self._conn()
        con.execute("BEGIN IMMEDIATE")
        try:
            yield con
        except BaseException:
            con.execute("ROLLBACK")
            raise
        con.execute("COMMIT")

    def close(self) -> None:
        """Close every connection this object opened (all threads)."""
        with self._conns_lock:
            for con in self._conns:
                con.close()
            self._conns.clear()
        self._local = threading.local()

    def __enter__(self) -> TelemetryMemory:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- writes ------------------------------------------------------------------------
    def append(self, records: TelemetryRecord | Iterable[TelemetryRecord]) -> int:
        """Store records atomically, then evict the oldest beyond ``max_records``.

        Returns the number of records appended.
        """
        batch = [records] if isinstance(records, TelemetryRecord) else list(records)
        if not batch:
            return 0
        now = time.time()
        rows = [
            (
                r.signature,
                signature_key(r.signature),
                r.trace,
                r.option,
                float(r.outcome),
                r.episode,
                r.client,
                r.created_at if r.created_at is not None else now,
            )
            for r in batch
        ]
        with self._write() as con:
            con.executemany(
                "INSERT INTO records (signature, sig_key, trace, option, outcome, episode, client, created_at)"
                " VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                rows,
            )
            con.execute(
                "DELETE FROM records WHERE id <= "
                "(SELECT id FROM records ORDER BY id DESC LIMIT 1 OFFSET ?)",
                (self.max_records,),
            )
        return len(rows)

    def seed_from(self, jsonl: str | os.PathLike[str]) -> int:
        """Append every record of a JSON Lines file (e.g. the shipped seed telemetry)."""
        import json

        with open(jsonl, encoding="utf-8") as f:
            records = [TelemetryRecord.model_validate(json.loads(line)) for line in f if line.strip()]
        return self.append(records)

    # -- reads -------------------------------------------------------------------------
    def count(self) -> int:
        return int(self._conn().execute("SELECT COUNT(*) FROM records").fetchone()[0])

    def version(self) -> tuple[int, int]:
        """Changes whenever records are appended or evicted: ``(max id, count)``."""
        row = self._conn().execute("SELECT COALESCE(MAX(id), 0), COUNT(*) FROM records").fetchone()
        return int(row[0]), int(row[1])

    def outcomes(self, signature: str) -> dict[str, OptionStat]:
        """Per-option statistics of the records at exactly this signature (normalised)."""
        rows = self._conn().execute(
            "SELECT option, COUNT(*), SUM(outcome) FROM records WHERE sig_key = ? GROUP BY option",
            (signature_key(signature),),
        ).fetchall()
        return {opt: OptionStat(int(n), float(s)) for opt, n, s in rows}

    def option_stats(self) -> dict[str, OptionStat]:
        """Per-option statistics over the whole memory."""
        rows = self._conn().execute(
            "SELECT option, COUNT(*), SUM(outcome) FROM records GROUP BY option"
        ).fetchall()
        return {opt: OptionStat(int(n), float(s)) for opt, n, s in rows}

    def signature_table(self, after_id: int = 0) -> list[tuple[int, str, str, str, float]]:
        """``(id, signature, sig_key, option, outcome)`` for records with ``id > after_id``."""
        return [
            (int(i), sig, key, opt, float(out))
            for i, sig, key, opt, out in self._conn().execute(
                "SELECT id, signature, sig_key, option, outcome FROM records WHERE id > ? ORDER BY id",
                (after_id,),
            )
        ]

    def records(self, limit: int | None = None) -> list[TelemetryRecord]:
        """Stored records, oldest first (``limit`` keeps the newest N)."""
        sql = "SELECT id, signature, trace, option, outcome, episode, client, created_at FROM records"
        if limit is not None:
            sql = f"SELECT * FROM ({sql} ORDER BY id DESC LIMIT {int(limit)}) ORDER BY id"
        else:
            sql += " ORDER BY id"
        return [
            TelemetryRecord(
                signature=s, trace=t, option=o, outcome=out, episode=e, client=c, created_at=ts
            )
            for _, s, t, o, out, e, c, ts in self._conn().execute(sql)
        ]

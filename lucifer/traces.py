"""Run traces: every grounding run is checkpointed by LangGraph's SQLite checkpointer.

The checkpoint of a run (thread id = trace id) holds the graph state, including one ``trace``
entry per node run with what the node read and wrote. A small ``lucifer_runs`` table in the
same file indexes runs for ``lucifer trace list``.
"""

from __future__ import annotations

import asyncio
import json
import os
import sqlite3
import threading
import time
from pathlib import Path
from typing import Any

from lucifer.errors import LuciferError
from lucifer.paths import traces_db

RUNS_DDL = """CREATE TABLE IF NOT EXISTS lucifer_runs (
    trace_id TEXT PRIMARY KEY, created REAL, report TEXT, backend TEXT, status TEXT,
    n_objects INTEGER, kb TEXT)"""


DEFAULT_KEEP = 20_000  # runs; one builtin run's trace is about 7 KB
CHECKPOINT_TABLES = ("checkpoints", "writes")  # langgraph-checkpoint-sqlite's tables, keyed by thread_id


class TraceNotFound(LuciferError):
    pass


def trace_keep() -> int | None:
    """How many runs the store keeps: ``$LUCIFER_TRACE_KEEP`` (0 = keep everything), else 20,000."""
    raw = os.environ.get("LUCIFER_TRACE_KEEP", "").strip()
    if not raw:
        return DEFAULT_KEEP
    try:
        keep = int(raw)
    except ValueError:
        raise LuciferError(f"LUCIFER_TRACE_KEEP must be a whole number of runs (0 keeps all), got {raw!r}") from None
    if keep < 0:
        raise LuciferError(f"LUCIFER_TRACE_KEEP must not be negative, got {keep}")
    return keep or None


def _prune_sql(keep: int | None, before: float | None) -> tuple[str, tuple[Any, ...]]:
    """The trace ids to delete: older than ``before`` (epoch seconds), and all but the newest ``keep``."""
    clauses, params = [], []
    if before is not None:
        clauses.append("created < ?")
        params.append(before)
    if keep is not None:
        clauses.append("trace_id NOT IN (SELECT trace_id FROM lucifer_runs ORDER BY created DESC LIMIT ?)")
        params.append(keep)
    if not clauses:
        raise ValueError("prune needs keep or before")
    return f"SELECT trace_id FROM lucifer_runs WHERE {' OR '.join(clauses)}", tuple(params)


def _prune_statements(keep: int | None, before: float | None,
                      tables: tuple[str, ...] = CHECKPOINT_TABLES) -> list[tuple[str, tuple[Any, ...]]]:
    """The DELETEs that remove those runs from the checkpointer's ``tables`` and then from the run index."""
    query, params = _prune_sql(keep, before)
    return [(f"DELETE FROM {table} WHERE thread_id IN ({query})", params) for table in tables] \
        + [(f"DELETE FROM lucifer_runs WHERE trace_id IN ({query})", params)]


class TraceStore:
    """Owns the async SQLite connection shared by the checkpointer and the run index."""

    def __init__(self, path: Path | None = None, keep: int | None = None):
        self.path = Path(path or traces_db())
        self.keep = trace_keep() if keep is None else (keep or None)
        self._conn: Any = None
        self.saver: Any = None
        self._lock = asyncio.Lock()

    async def open(self) -> Any:
        async with self._lock:
            if self.saver is None:
                import aiosqlite
                from langgraph.checkpoint.sqlite.aio import AsyncSqliteSaver

                self.path.parent.mkdir(parents=True, exist_ok=True)
                conn = aiosqlite.connect(str(self.path), timeout=30)
                # A Grounder left open at exit (no aclose) must not hang the interpreter, which joins
                # non-daemon threads before anything could close the connection. Every write is
                # committed when it is made, so nothing is lost when the worker thread dies with it.
                worker = getattr(conn, "_thread", None)
                if isinstance(worker, threading.Thread) and not worker.is_alive():
                    worker.daemon = True
                self._conn = await conn
                await self._conn.execute("PRAGMA journal_mode=WAL")
                await self._conn.execute("PRAGMA synchronous=NORMAL")
                await self._conn.execute(RUNS_DDL)
                await self._conn.commit()
                self.saver = AsyncSqliteSaver(self._conn)
                await self.saver.setup()
                await self._enforce_retention()
        return self.saver

    async def _enforce_retention(self) -> None:
        """Drop the oldest runs once the store holds a tenth more than ``keep`` (freed pages are reused)."""
        if self.keep is None:
            return
        async with self._conn.execute("SELECT count(*) FROM lucifer_runs") as cur:
            (n,) = await cur.fetchone()
        if n <= self.keep + max(100, self.keep // 10):
            return
        for sql, params in _prune_statements(self.keep, None):
            await self._conn.execute(sql, params)
        await self._conn.commit()

    async def record(self, trace_id: str, report: str, backend: str, status: str, n_objects: int, kb: str) -> None:
        await self._conn.execute(
            "INSERT OR REPLACE INTO lucifer_runs VALUES (?, ?, ?, ?, ?, ?, ?)",
            (trace_id, time.time(), report[:500], backend, status, n_objects, kb),
        )
        await self._conn.commit()

    async def close(self) -> None:
        if self._conn is not None:
            await self._conn.close()
            self._conn = None
            self.saver = None


def list_runs(limit: int = 20, path: Path | None = None) -> list[dict[str, Any]]:
    p = Path(path or traces_db())
    if not p.is_file():
        return []
    con = sqlite3.connect(str(p))
    try:
        con.execute(RUNS_DDL)
        rows = con.execute(
            "SELECT trace_id, created, report, backend, status, n_objects, kb FROM lucifer_runs "
            "ORDER BY created DESC LIMIT ?", (limit,)).fetchall()
    finally:
        con.close()
    keys = ("trace_id", "created", "report", "backend", "status", "n_objects", "kb")
    return [dict(zip(keys, r, strict=True)) for r in rows]


def prune_runs(keep: int | None = None, older_than_days: float | None = None, path: Path | None = None,
               vacuum: bool = True) -> dict[str, Any]:
    """Delete the traces of all but the newest ``keep`` runs and/or of runs older than ``older_than_days``;
    ``vacuum`` then gives the freed space back to the disk."""
    if keep is None and older_than_days is None:
        raise ValueError("say what to prune: keep=N and/or older_than_days=D")
    if keep is not None and keep < 0:
        raise ValueError(f"keep must not be negative, got {keep}")
    if older_than_days is not None and older_than_days < 0:
        raise ValueError(f"older_than_days must not be negative, got {older_than_days}")
    p = Path(path or traces_db())
    if not p.is_file():
        return {"path": str(p), "removed": 0, "kept": 0, "bytes_before": 0, "bytes_after": 0}
    size = p.stat().st_size
    before = None if older_than_days is None else time.time() - older_than_days * 86400
    query, params = _prune_sql(keep, before)
    con = sqlite3.connect(str(p), timeout=30)
    try:
        con.execute(RUNS_DDL)
        tables = {r[0] for r in con.execute("SELECT name FROM sqlite_master WHERE type='table'")}
        (removed,) = con.execute(f"SELECT count(*) FROM ({query})", params).fetchone()
        with con:
            for sql, stmt_params in _prune_statements(keep, before, tuple(t for t in CHECKPOINT_TABLES if t in tables)):
                con.execute(sql, stmt_params)
        (kept,) = con.execute("SELECT count(*) FROM lucifer_runs").fetchone()
        if vacuum and removed:
            con.execute("VACUUM")
    finally:
        con.close()
    return {"path": str(p), "removed": removed, "kept": kept, "bytes_before": size, "bytes_after": p.stat().st_size}


async def load_run(trace_id: str, path: Path | None = None) -> dict[str, Any]:
    """The final state of a run and its node-by-node history."""
    from lucifer.graphs.grounding import compile_graph

    p = Path(path or traces_db())
    if not p.is_file():
        raise TraceNotFound(f"no traces recorded yet ({p} does not exist)")
    store = TraceStore(p)
    saver = await store.open()
    try:
        graph = compile_graph(checkpointer=saver)
        config = {"configurable": {"thread_id": trace_id}}
        snap = await graph.aget_state(config)
        if not snap.values:
            raise TraceNotFound(f"no trace with id {trace_id!r} (see `lucifer trace list`)")
        order = []
        async for h in graph.aget_state_history(config):
            order.append({"step": h.metadata.get("step"), "next": list(h.next)})
        order.reverse()
        # a run that raised is checkpointed where it stopped: ``next`` names the node that failed
        return {"trace_id": trace_id, "values": snap.values, "checkpoints": order, "unfinished": list(snap.next)}
    finally:
        await store.close()


def format_run(run: dict[str, Any]) -> str:
    v = run["values"]
    lines = [f"trace {run['trace_id']}", f"report: {v.get('report')!r}", f"status: {v.get('status')}"]
    for i, step in enumerate(v.get("trace", []), 1):
        lines.append(f"\n[{i}] {step['node']}  ({step.get('ms', 0):.1f} ms)")
        lines.append("  input:  " + json.dumps(step.get("input"), ensure_ascii=False)[:2000])
        out = step.get("output") or {}
        for key, val in out.items():
            if isinstance(val, list):
                lines.append(f"  {key}:")
                lines.extend(f"    - {x if isinstance(x, str) else json.dumps(x, ensure_ascii=False)}" for x in val)
                if not val:
                    lines.append("    (none)")
            else:
                lines.append(f"  {key}: {val}")
    if run.get("unfinished"):
        lines.append(f"\nrun did not finish: it failed in {', '.join(run['unfinished'])}")
        return "\n".join(lines)
    objs = v.get("objects", [])
    lines.append("\nresult: " + (", ".join(f"{o['location']}/{o['category']}" for o in objs) or "(no objects)"))
    return "\n".join(lines)

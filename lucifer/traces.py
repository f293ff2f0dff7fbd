"""Run traces: every grounding run is checkpointed by LangGraph's SQLite checkpointer.

The checkpoint of a run (thread id = trace id) holds the graph state, including one ``trace``
entry per node run with what the node read and wrote. A small ``lucifer_runs`` table in the
same file indexes runs for ``lucifer trace list``.
"""

from __future__ import annotations

import asyncio
import json
import sqlite3
import time
from pathlib import Path
from typing import Any

from lucifer.errors import LuciferError
from lucifer.paths import traces_db

RUNS_DDL = """CREATE TABLE IF NOT EXISTS lucifer_runs (
    trace_id TEXT PRIMARY KEY, created REAL, report TEXT, backend TEXT, status TEXT,
    n_objects INTEGER, kb TEXT)"""


class TraceNotFound(LuciferError):
    pass


class TraceStore:
    """Owns the async SQLite connection shared by the checkpointer and the run index."""

    def __init__(self, path: Path | None = None):
        self.path = Path(path or traces_db())
        self._conn: Any = None
        self.saver: Any = None
        self._lock = asyncio.Lock()

    async def open(self) -> Any:
        async with self._lock:
            if self.saver is None:
                import aiosqlite
                from langgraph.checkpoint.sqlite.aio import AsyncSqliteSaver

                self.path.parent.mkdir(parents=True, exist_ok=True)
                self._conn = await aiosqlite.connect(str(self.path), timeout=30)
                await self._conn.execute("PRAGMA journal_mode=WAL")
                await self._conn.execute("PRAGMA synchronous=NORMAL")
                await self._conn.execute(RUNS_DDL)
                await self._conn.commit()
                self.saver = AsyncSqliteSaver(self._conn)
                await self.saver.setup()
        return self.saver

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
        return {"trace_id": trace_id, "values": snap.values, "checkpoints": order}
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
    objs = v.get("objects", [])
    lines.append("\nresult: " + (", ".join(f"{o['location']}/{o['category']}" for o in objs) or "(no objects)"))
    return "\n".join(lines)

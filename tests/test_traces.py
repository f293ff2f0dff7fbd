"""The trace store: every run stays inspectable until retention or `lucifer trace prune` removes it."""

from __future__ import annotations

import os
import sqlite3
import subprocess
import sys
import time

import pytest
from conftest import KB, ROOT

from lucifer.errors import LuciferError
from lucifer.grounding import Grounder
from lucifer.traces import TraceNotFound, TraceStore, list_runs, load_run, prune_runs, trace_keep

REPORTS = ["fire at the bakery", "people trapped at the school", "gas leak by the bank"]


async def _three_runs(db) -> list[str]:
    async with Grounder(KB, traces_path=db) as g:
        ids = []
        for text in REPORTS:
            ids.append((await g.ground(text)).trace_id)
            time.sleep(0.01)  # distinct creation times, oldest first
    return ids


async def test_prune_keeps_the_newest_runs_and_their_checkpoints(tmp_path):
    db = tmp_path / "traces.sqlite"
    ids = await _three_runs(db)
    r = prune_runs(keep=1, path=db)
    assert (r["removed"], r["kept"]) == (2, 1)
    assert [x["trace_id"] for x in list_runs(path=db)] == [ids[-1]]
    assert (await load_run(ids[-1], db))["values"]["report"] == REPORTS[-1]
    for gone in ids[:2]:
        with pytest.raises(TraceNotFound):
            await load_run(gone, db)
    con = sqlite3.connect(db)
    assert {t for (t,) in con.execute("SELECT DISTINCT thread_id FROM checkpoints")} == {ids[-1]}
    con.close()


async def test_prune_by_age(tmp_path):
    db = tmp_path / "traces.sqlite"
    ids = await _three_runs(db)
    assert prune_runs(older_than_days=1, path=db)["removed"] == 0
    con = sqlite3.connect(db)
    with con:
        con.execute("UPDATE lucifer_runs SET created = created - 3 * 86400 WHERE trace_id = ?", (ids[0],))
    con.close()
    r = prune_runs(older_than_days=2, path=db, vacuum=False)
    assert (r["removed"], r["kept"]) == (1, 2)
    assert {x["trace_id"] for x in list_runs(path=db)} == set(ids[1:])


async def test_store_enforces_its_retention_limit_when_opened(tmp_path):
    db = tmp_path / "traces.sqlite"
    ids = await _three_runs(db)
    con = sqlite3.connect(db)
    with con:  # 150 older runs in the index, as a long-lived store would hold
        con.executemany("INSERT INTO lucifer_runs VALUES (?, ?, 'old', 'builtin', 'ok', 0, 'kb')",
                        [(f"old{i}", time.time() - 1000 - i) for i in range(150)])
    con.close()
    store = TraceStore(db, keep=2)
    await store.open()
    await store.close()
    assert [x["trace_id"] for x in list_runs(path=db)] == ids[:0:-1]
    with pytest.raises(TraceNotFound):
        await load_run(ids[0], db)
    unlimited = TraceStore(db, keep=0)  # 0 keeps everything
    assert unlimited.keep is None


def test_trace_keep_setting(monkeypatch):
    monkeypatch.delenv("LUCIFER_TRACE_KEEP", raising=False)
    assert trace_keep() == 20_000
    monkeypatch.setenv("LUCIFER_TRACE_KEEP", "500")
    assert trace_keep() == 500
    monkeypatch.setenv("LUCIFER_TRACE_KEEP", "lots")
    with pytest.raises(LuciferError, match="LUCIFER_TRACE_KEEP must be a whole number"):
        trace_keep()


def test_cli_trace_prune(tmp_path):
    import asyncio

    db = tmp_path / "traces.sqlite"
    asyncio.run(_three_runs(db))
    env = os.environ | {"LUCIFER_TRACES": str(db)}

    def cli(*args):
        return subprocess.run([sys.executable, "-m", "lucifer.cli", "trace", *args], capture_output=True, text=True,
                              cwd=ROOT, env=env, timeout=120)

    out = cli("prune")
    assert out.returncode == 2 and "--keep N and/or --older-than DAYS" in out.stderr
    out = cli("prune", "--keep", "-3")
    assert out.returncode == 2 and "--keep must not be negative" in out.stderr
    assert len(list_runs(path=db)) == 3  # nothing was deleted by the bad calls
    out = cli("prune", "--keep", "2")
    assert out.returncode == 0 and out.stdout.startswith("removed 1 runs, kept 2")
    assert len(list_runs(path=db)) == 2


def test_a_grounder_left_open_does_not_hang_the_interpreter(tmp_path):
    """A script that never calls aclose() (a Grounder at module level, reused across asyncio.run calls)
    exits promptly and keeps both runs."""
    db = tmp_path / "traces.sqlite"
    script = (
        "import asyncio, sys\n"
        "from lucifer.grounding import Grounder\n"
        f"g = Grounder({str(KB)!r}, traces_path={str(db)!r})\n"
        "for text in ('fire at the bakery', 'people trapped at the school'):\n"
        "    r = asyncio.run(g.ground(text))\n"
        "    print(r.objects[0].location)\n"
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, timeout=180,
                         env=os.environ | {"HF_HUB_OFFLINE": "1"})
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.split() == ["bakery", "school"]
    assert "Traceback" not in out.stderr
    assert [r["report"] for r in list_runs(path=db)] == ["people trapped at the school", "fire at the bakery"]

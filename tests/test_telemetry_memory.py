"""Telemetry memory: persistence, bounds, concurrent writers; the signature index; scenarios."""

from __future__ import annotations

import hashlib
import json
import multiprocessing as mp
import threading
from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from lucifer.kb import load_kb
from lucifer.telemetry import scenarios
from lucifer.telemetry.benchmark import DEFAULT_DIR, MEMORY_FILE, NOVEL_FILE, read_jsonl
from lucifer.telemetry.index import SignatureIndex, split_clauses
from lucifer.telemetry.memory import TelemetryMemory, TelemetryRecord, signature_key


def rec(sig: str = "smell of gas", option: str = "gas_sniffer", outcome: float = 1.0, **kw) -> TelemetryRecord:
    return TelemetryRecord(signature=sig, option=option, outcome=outcome, **kw)


def test_append_and_read_back(tmp_path: Path) -> None:
    mem = TelemetryMemory(tmp_path / "t.sqlite")
    assert mem.append([rec(), rec(outcome=0.0), rec(option="hazmat_test", outcome=0.0, trace="moved east")]) == 3
    stats = mem.outcomes("  SMELL of   gas ")  # matching ignores case and spacing
    assert stats["gas_sniffer"].n == 2 and stats["gas_sniffer"].total == 1.0
    assert stats["hazmat_test"].mean == 0.0
    assert mem.option_stats()["gas_sniffer"].n == 2
    assert [r.trace for r in mem.records()] == ["", "", "moved east"]
    assert mem.outcomes("never seen") == {}


def test_survives_restart(tmp_path: Path) -> None:
    path = tmp_path / "t.sqlite"
    with TelemetryMemory(path) as mem:
        mem.append(rec(episode="e1", client="rl"))
    reopened = TelemetryMemory(path)
    [r] = reopened.records()
    assert (r.signature, r.option, r.outcome, r.episode, r.client) == ("smell of gas", "gas_sniffer", 1.0, "e1", "rl")
    assert r.created_at is not None


def test_bounded_keeps_the_newest(tmp_path: Path) -> None:
    mem = TelemetryMemory(tmp_path / "t.sqlite", max_records=5)
    for i in range(12):
        mem.append(rec(sig=f"place {i}"))
    assert mem.count() == 5
    assert [r.signature for r in mem.records()] == [f"place {i}" for i in range(7, 12)]
    mem.append([rec(sig=f"batch {i}") for i in range(8)])  # one batch larger than the bound
    assert [r.signature for r in mem.records()] == [f"batch {i}" for i in range(3, 8)]


def test_rejects_invalid_records() -> None:
    with pytest.raises(ValidationError):
        rec(outcome=1.5)
    with pytest.raises(ValidationError):
        rec(sig="   ")
    with pytest.raises(ValidationError):
        TelemetryRecord.model_validate({"signature": "x", "option": "y", "outcome": 1, "extra": 1})


def test_concurrent_threads_share_one_memory(tmp_path: Path) -> None:
    mem = TelemetryMemory(tmp_path / "t.sqlite")

    def writer(k: int) -> None:
        for i in range(40):
            mem.append(rec(sig=f"t{k} p{i}"))

    threads = [threading.Thread(target=writer, args=(k,)) for k in range(6)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert mem.count() == 240
    assert len({r.signature for r in mem.records()}) == 240


def _process_writer(path: str, k: int, n: int, max_records: int) -> None:
    mem = TelemetryMemory(path, max_records=max_records)
    for i in range(n):
        mem.append(TelemetryRecord(signature=f"proc {k} step {i}", option="scout_route", outcome=0.5))
    mem.close()


@pytest.mark.parametrize("max_records", [10_000, 50])
def test_concurrent_processes(tmp_path: Path, max_records: int) -> None:
    path = str(tmp_path / "t.sqlite")
    TelemetryMemory(path, max_records=max_records).close()  # create the schema first
    ctx = mp.get_context("spawn")
    procs = [ctx.Process(target=_process_writer, args=(path, k, 30, max_records)) for k in range(4)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(timeout=120)
        assert p.exitcode == 0
    mem = TelemetryMemory(path, max_records=max_records)
    assert mem.count() == min(120, max_records)
    if max_records >= 120:
        assert {r.signature for r in mem.records()} == {f"proc {k} step {i}" for k in range(4) for i in range(30)}


class HashEmbedder:
    """A deterministic stand-in for MiniLM: bag of hashed words, unit norm (keeps tests fast)."""

    name = "hash-embedder"

    def embed(self, texts: list[str]) -> np.ndarray:
        out = np.zeros((len(texts), 384), dtype=np.float32)
        for i, t in enumerate(texts):
            for w in t.lower().split():
                out[i, int(hashlib.md5(w.encode()).hexdigest(), 16) % 384] += 1.0
            out[i] /= max(np.linalg.norm(out[i]), 1e-9)
        return out


def test_index_follows_memory(tmp_path: Path) -> None:
    mem = TelemetryMemory(tmp_path / "t.sqlite", max_records=6)
    index = SignatureIndex(mem, HashEmbedder())  # type: ignore[arg-type]
    mem.append([rec("knocking under rubble", "acoustic_listen", 1.0), rec("knocking under rubble", "gas_sniffer", 0.0)])
    assert index.refresh() is True
    assert index.refresh() is False  # nothing changed
    assert index.signature_stats("Knocking under rubble")["acoustic_listen"].n == 1
    clauses, vecs = index.embed_clauses("loud knocking, near the school")
    assert clauses == ["loud knocking", "near the school"]
    [knock, school] = index.clause_evidence(clauses, vecs, ["acoustic_listen", "gas_sniffer"])
    assert knock.match == "knocking under rubble"
    assert knock.votes["acoustic_listen"] == pytest.approx(1.0) and knock.votes["gas_sniffer"] == 0.0
    assert knock.success["acoustic_listen"] > knock.success["gas_sniffer"]
    # appended records are folded in; evicted ones disappear from the statistics
    mem.append([rec("smell of gas", "gas_sniffer", 1.0)] * 5)
    assert index.refresh() is True
    assert index.signature_stats("knocking under rubble").keys() == {"gas_sniffer"}
    assert index.signature_stats("smell of gas")["gas_sniffer"].n == 5
    assert index.neighbors(index.embed_clauses("gas smell")[1], k=1)[0].signature == "smell of gas"


def test_split_clauses() -> None:
    assert split_clauses("Knocking; under  debris. near the school!") == ["knocking", "under debris", "near the school"]


def test_scenarios_are_seeded_and_pools_disjoint() -> None:
    a = [scenarios.sample_signature(o, np.random.default_rng(7), novel=True) for o in scenarios.OPTIONS]
    b = [scenarios.sample_signature(o, np.random.default_rng(7), novel=True) for o in scenarios.OPTIONS]
    assert a == b
    for x, y in (("seen", "dev"), ("seen", "novel"), ("dev", "novel")):
        assert not scenarios.all_phrases(x) & scenarios.all_phrases(y)  # type: ignore[arg-type]
    rng = np.random.default_rng(0)
    for option in scenarios.OPTIONS:
        sig = scenarios.sample_signature(option, rng)
        assert any(sig.startswith(c) for c in scenarios.cue_phrases(option))
        cands = scenarios.sample_candidates(option, rng)
        assert option in cands and len(set(cands)) == len(cands) >= 4


def test_query_options_in_kb_match_scenarios() -> None:
    kb = load_kb("knowledge_base")
    assert tuple(o.name for o in kb.query_options) == scenarios.OPTIONS
    assert {o.name: o.info_type for o in kb.query_options} == scenarios.QUERY_INFO_TYPE
    assert all(o.description for o in kb.query_options)


def test_novel_benchmark_signatures_are_absent_from_memory() -> None:
    memory = read_jsonl(DEFAULT_DIR / MEMORY_FILE)
    keys = {signature_key(r["signature"]) for r in memory}
    novel = read_jsonl(DEFAULT_DIR / NOVEL_FILE)
    assert novel and all(signature_key(p["signature"]) not in keys for p in novel)
    text = json.dumps(memory)
    for phrase in scenarios.all_phrases("novel"):
        assert phrase not in text

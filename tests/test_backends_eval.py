"""``lucifer eval backends``: the table builder on a tiny slice with the real builtin and rule backends."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from lucifer.evals.backends import (
    PAPER,
    Split,
    build_table,
    first_per_regime,
    render_markdown,
    write_outputs,
)
from lucifer.evals.grounding import REGIMES, load_dataset

ROOT = Path(__file__).resolve().parents[1]
KB = ROOT / "knowledge_base"
HELDOUT = ROOT / "datasets" / "grounding" / "heldout"
BOGUS = "llamacpp:/nonexistent.gguf"


@pytest.fixture(scope="module")
def tiny_split(tmp_path_factory: pytest.TempPathFactory) -> Split:
    """Two reports of every held-out regime, written to a private file."""
    rows = first_per_regime(load_dataset([str(HELDOUT / f"{g}.jsonl") for g in REGIMES]), 2)
    path = tmp_path_factory.mktemp("slice") / "tiny.jsonl"
    path.write_text("".join(r.model_dump_json() + "\n" for r in rows))
    return Split("heldout", str(KB), (str(path),))


@pytest.fixture(scope="module")
def table(tiny_split: Split) -> dict:
    return build_table(["builtin", "rule", BOGUS], [tiny_split], llm_limit=1)


def test_first_per_regime_keeps_file_order() -> None:
    rows = load_dataset([str(HELDOUT / f"{g}.jsonl") for g in REGIMES])
    picked = first_per_regime(rows, 3)
    assert [r.regime for r in picked] == [g for g in REGIMES for _ in range(3)]
    assert picked[0].id == rows[0].id
    assert first_per_regime(rows, None) == rows


def test_every_backend_has_a_row(table: dict) -> None:
    assert [r["backend"] for r in table["backends"]] == ["builtin", "rule", BOGUS]
    for row in table["backends"][:2]:
        assert row["status"] == "ok", row
        regimes = row["splits"]["heldout"]["regimes"]
        assert set(REGIMES) | {"overall"} == set(regimes)
        for g in REGIMES:
            assert 0.0 <= regimes[g]["adjusted_accuracy"] <= 100.0
            assert regimes[g]["n"] == 2
        assert row["s_per_report"] >= 0.0
        assert row["limit"] is None  # only LLM backends are cut to --llm-limit


def test_an_unusable_backend_is_an_unavailable_row(table: dict) -> None:
    row = table["backends"][2]
    assert row["status"] == "unavailable"
    assert "nonexistent.gguf" in row["reason"] or "llamacpp" in row["reason"]
    assert row["splits"] == {}


def test_markdown_and_chart(table: dict, tmp_path: Path) -> None:
    md = render_markdown(table)
    lines = md.splitlines()
    assert lines[0].startswith("| backend | held-out std | held-out messy | held-out adv |")
    assert any(line.startswith("| `builtin` |") for line in lines)
    bogus = next(line for line in lines if line.startswith(f"| `{BOGUS}` |"))
    assert "unavailable: " in bogus
    for name in PAPER:
        assert f"| {name} (paper) |" in md
    paths = write_outputs(table, tmp_path)
    assert json.loads(paths["json"].read_text())["backends"][0]["backend"] == "builtin"
    assert paths["png"].read_bytes()[:4] == b"\x89PNG"
    assert paths["md"].read_text() == md


def test_a_crashing_backend_does_not_abort_the_table(tiny_split: Split, monkeypatch: pytest.MonkeyPatch) -> None:
    import lucifer.evals.backends as backends

    def boom(*_a: object, **_k: object) -> dict:
        raise RuntimeError("index exploded")

    monkeypatch.setattr(backends, "run_backend", boom)
    table = build_table(["rule"], [tiny_split])
    assert table["backends"][0]["status"] == "unavailable"
    assert "index exploded" in table["backends"][0]["reason"]


def test_round_robin_interleaves_regimes() -> None:
    from lucifer.evals.backends import round_robin

    rows = first_per_regime(load_dataset([str(HELDOUT / f"{g}.jsonl") for g in REGIMES]), 2)
    assert [r.regime for r in round_robin(rows)] == list(REGIMES) * 2


def test_a_spent_time_budget_gives_a_partial_row(tiny_split: Split) -> None:
    import asyncio

    from lucifer.evals.backends import run_backend

    row = asyncio.run(run_backend("rule", [tiny_split], budget_s=0.0))
    assert row["status"] == "partial"
    assert "budget" in row["reason"]
    assert "| `rule` |" in render_markdown(
        {"splits": [{"name": "heldout"}], "backends": [row], "llm_limit": None,
         "machine": {"load_avg_1m": 0.0}, "paper": PAPER})


def test_a_segfaulting_child_becomes_an_unavailable_row(tiny_split: Split, monkeypatch: pytest.MonkeyPatch) -> None:
    import subprocess

    import lucifer.evals.backends as backends

    def crashed(cmd: list[str], **_k: object) -> subprocess.CompletedProcess:
        return subprocess.CompletedProcess(cmd, -11, "", "Fatal Python error: Segmentation fault\n")

    monkeypatch.setattr(backends.subprocess, "run", crashed)
    row = backends.run_backend_isolated("llamacpp:gemma3-270m", [tiny_split], limit=1)
    assert row["status"] == "unavailable"
    assert row["reason"] == "crashed (signal 11, SIGSEGV)"


class _RefusingModel:
    """A chat model whose server is down: every call is refused."""

    def bind_tools(self, *_a: object, **_k: object) -> _RefusingModel:
        return self

    async def ainvoke(self, *_a: object, **_k: object) -> None:
        raise ConnectionRefusedError("connection refused by fake server")


def test_a_model_that_only_falls_back_is_unavailable(tiny_split: Split) -> None:
    from lucifer.models import set_chat_model_factory

    set_chat_model_factory(lambda *_a: _RefusingModel())
    try:
        table = build_table(["openai:down"], [tiny_split], llm_limit=2, isolate_llm=False)
    finally:
        set_chat_model_factory(None)
    row = table["backends"][0]
    assert row["status"] == "unavailable"
    assert "connection refused" in row["reason"] and "fell back to builtin" in row["reason"]
    assert row["splits"] == {}


def test_a_subset_refreshes_its_rows_and_keeps_the_others(table: dict, tiny_split: Split, tmp_path: Path,
                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    import argparse

    from lucifer.evals import backends as mod

    old = dict(table)
    old["backends"] = [{"backend": "llamacpp:slow", "status": "partial", "reason": "kept", "splits": {}},
                       *[dict(r, reason="stale") for r in table["backends"] if r["backend"] == "rule"]]
    (tmp_path / "backends.json").write_text(json.dumps(old))
    monkeypatch.setattr(mod, "default_splits", lambda kb: [tiny_split])
    args = argparse.Namespace(backends="rule", kb=None, llm_limit=2, out=str(tmp_path))
    assert mod.cmd_eval_backends(args) == 0
    rows = json.loads((tmp_path / "backends.json").read_text())["backends"]
    assert [r["backend"] for r in rows] == ["llamacpp:slow", "rule"]
    assert rows[0]["reason"] == "kept" and rows[1].get("reason") != "stale"

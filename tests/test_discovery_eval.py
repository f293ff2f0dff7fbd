"""``lucifer eval discovery``: scoring helpers, a real builtin replay on a slice, the shipped files."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

from lucifer.errors import BadRequest
from lucifer.evals.discovery import (
    Outcome,
    cmd_eval_discovery,
    expected_calibration_error,
    load_points,
    run_eval,
    summarise,
)
from lucifer.telemetry.benchmark import (
    DECISIONS_FILE,
    DEFAULT_DIR,
    DEV_FILE,
    MEMORY_FILE,
    NOVEL_FILE,
    generate,
)

SPEC_KEYS = {"n", "accuracy", "accuracy_novel", "ece", "latency_p50_s", "latency_p95_s", "backend"}


def test_ece() -> None:
    assert expected_calibration_error([], []) == 0.0
    assert expected_calibration_error([0.75] * 4, [True, True, True, False]) == 0.0
    assert expected_calibration_error([0.95, 0.15], [True, True]) == pytest.approx(0.45)
    # confidences land in their own bins: |1 - 0.95| and |0 - 0.15|, each with weight 1/2
    assert expected_calibration_error([0.95, 0.15], [True, False]) == pytest.approx(0.1)


def test_summarise_splits_main_and_novel() -> None:
    def o(main: bool, novel: bool, ok: bool) -> Outcome:
        return Outcome("x", main, novel, ok, 0.9 if ok else 0.6, 0.002 if main else 0.02, "ok")

    s = summarise([o(True, False, True)] * 3 + [o(True, False, False)] + [o(False, True, True), o(False, True, False)], "b")
    assert s["n"] == 4 and s["accuracy"] == 75.0 and s["accuracy_novel"] == 50.0 and s["n_novel"] == 2
    assert s["latency_p50_s"] == 0.002 and s["backend"] == "b"


def test_load_points_reports_bad_lines(tmp_path: Path) -> None:
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"id": "a", "signature": "s", "options": ["x"], "answer": "x"}\n{"id": "b", "options": []}\n')
    with pytest.raises(BadRequest, match=r"bad.jsonl:2"):
        load_points(bad)
    with pytest.raises(BadRequest, match="not found"):
        load_points(tmp_path / "missing.jsonl")


@pytest.fixture(autouse=True)
def _isolated_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("LUCIFER_HOME", str(tmp_path / "home"))


async def test_builtin_replay_on_a_slice() -> None:
    s = await run_eval(None, None, None, limit=40)
    assert SPEC_KEYS <= s.keys()
    assert s["n"] == 40 and s["n_novel"] == 40 and s["backend"] == "builtin"
    assert s["accuracy"] >= 98.0
    assert s["accuracy_novel"] >= 75.0
    assert 0.0 <= s["ece"] <= 0.15
    assert s["statuses"] == {"ok": 80}


def test_cmd_writes_the_spec_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    small = tmp_path / "small.jsonl"
    small.write_text("\n".join((DEFAULT_DIR / NOVEL_FILE).read_text().splitlines()[:8]) + "\n")
    out = tmp_path / "out" / "summary.json"
    args = argparse.Namespace(kb=None, model=None, json_out=str(out), dataset=str(small))
    assert cmd_eval_discovery(args) == 0
    written = json.loads(out.read_text())
    assert written == json.loads(capsys.readouterr().out)
    assert SPEC_KEYS <= written.keys()
    assert written["n"] == 8 and written["n_novel"] == 8  # memory seed from the shipped benchmark


def test_shipped_benchmark_is_reproducible(tmp_path: Path) -> None:
    counts = generate(tmp_path, seed=0)
    assert counts == {MEMORY_FILE: 2323, DECISIONS_FILE: 600, NOVEL_FILE: 210, DEV_FILE: 150}
    for name in counts:
        assert (tmp_path / name).read_bytes() == (DEFAULT_DIR / name).read_bytes(), name
    calib = json.loads((DEFAULT_DIR / "calibration.json").read_text())
    assert calib["fitted_on"] == DEV_FILE and 0.05 < calib["temperature"] < 20

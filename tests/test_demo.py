"""``lucifer demo``: a short mission with streamed reports, finished safely, with a PNG."""

from __future__ import annotations

import pytest
from test_clients_standins import StandInDiscoverer, StandInGrounder

from lucifer.demo import run_demo
from lucifer.kb import load_kb


async def test_demo_mission_completes_safely(tmp_path):
    kb = load_kb("knowledge_base")
    lines: list[str] = []
    summary = await run_demo(kb="knowledge_base", seed=0, out=tmp_path, write=lines.append,
                             grounder=StandInGrounder(kb), discoverer=StandInDiscoverer())
    assert summary["success"] and summary["collisions"] == 0
    assert summary["correct_queries"] == summary["queries"] == 3
    assert (tmp_path / "demo.png").stat().st_size > 10_000
    text = "\n".join(lines)
    assert text.count("radio>") == summary["reports"]  # every report streamed
    assert "contract v1" in text and "discovery u*" in text and "COMPLETE" in text


@pytest.mark.integration
async def test_demo_with_the_real_backends(tmp_path):
    summary = await run_demo(kb="knowledge_base", seed=1, out=tmp_path, write=lambda s: None)
    assert summary["success"] and summary["collisions"] == 0

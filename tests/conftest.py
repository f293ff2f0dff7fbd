"""Shared fixtures: every test session gets its own LUCIFER_HOME (indexes, traces, caches)."""

from __future__ import annotations

import os
import shutil
import socket
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
KB = ROOT / "knowledge_base"
RIVERBEND = ROOT / "knowledge_bases" / "riverbend"


@pytest.fixture(scope="session", autouse=True)
def _lucifer_home(tmp_path_factory: pytest.TempPathFactory):
    home = tmp_path_factory.mktemp("lucifer-home")
    old = {k: os.environ.get(k) for k in ("LUCIFER_HOME", "LUCIFER_MODEL", "LUCIFER_KB", "LUCIFER_CHROMA_URL",
                                           "HF_HUB_OFFLINE")}
    os.environ["LUCIFER_HOME"] = str(home)
    os.environ["HF_HUB_OFFLINE"] = "1"
    for k in ("LUCIFER_MODEL", "LUCIFER_KB", "LUCIFER_CHROMA_URL"):
        os.environ.pop(k, None)
    yield home
    for k, v in old.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v


@pytest.fixture
def kb_copy(tmp_path: Path) -> Path:
    """A private, editable copy of the shipped knowledge base."""
    dst = tmp_path / "kb"
    shutil.copytree(KB, dst)
    return dst


def free_port() -> int:
    """A TCP port on loopback that nothing listens on right now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]

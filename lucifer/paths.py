"""Where LUCIFER keeps its state: vector indexes, traces and telemetry memory.

Everything lives under ``$LUCIFER_HOME`` (default ``~/.cache/lucifer``), one vector-index
directory per knowledge-base path.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path


def home() -> Path:
    root = Path(os.environ.get("LUCIFER_HOME") or Path.home() / ".cache" / "lucifer")
    root.mkdir(parents=True, exist_ok=True)
    return root


def index_dir(kb_root: Path) -> Path:
    """Persistent Chroma directory for one KB path."""
    key = hashlib.sha256(str(Path(kb_root).resolve()).encode()).hexdigest()[:12]
    d = home() / "index" / f"{Path(kb_root).resolve().name}-{key}"
    d.mkdir(parents=True, exist_ok=True)
    return d


def traces_db() -> Path:
    return Path(os.environ.get("LUCIFER_TRACES") or home() / "traces.sqlite")


def telemetry_db() -> Path:
    return Path(os.environ.get("LUCIFER_TELEMETRY") or home() / "telemetry.sqlite")

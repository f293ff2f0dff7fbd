"""``lucifer discover``: one discovery request, JSON in and out.

The request is JSON text, a file path, or ``-`` (stdin): ``{"signature": ..., "trace": [...],
"options": [...]}``. The answer is one JSON object (:class:`DiscoveryResult`). An empty
telemetry memory is first seeded with the shipped seed telemetry, so a fresh install has
experience to draw on; ``--memory FILE`` picks another memory.
"""

from __future__ import annotations

import argparse
import asyncio
import sys


def cmd_discover(args: argparse.Namespace) -> int:
    from lucifer.graphs.discovery import Discoverer, dumps_result, load_request_arg, parse_request
    from lucifer.telemetry.benchmark import DEFAULT_DIR, MEMORY_FILE
    from lucifer.telemetry.memory import TelemetryMemory

    request = parse_request(load_request_arg(getattr(args, "request", None)))
    memory = TelemetryMemory(getattr(args, "memory", None))
    seed = DEFAULT_DIR / MEMORY_FILE
    if memory.count() == 0 and seed.is_file():
        n = memory.seed_from(seed)
        print(f"lucifer: telemetry memory {memory.path} was empty; seeded it with {n} records from {seed}",
              file=sys.stderr)
    discoverer = Discoverer(getattr(args, "kb", None), memory=memory, model=getattr(args, "model", None))
    try:
        result = asyncio.run(discoverer.discover(request))
    finally:
        discoverer.close()
    print(dumps_result(result))
    return 0

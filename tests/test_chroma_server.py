"""Client/server mode: a real `chroma run` on loopback."""

from __future__ import annotations

import os
import shutil
import subprocess
import time
from pathlib import Path

import pytest
from conftest import KB, free_port

from lucifer.grounding import Grounder
from lucifer.retrieval import ChromaUnavailable

pytestmark = pytest.mark.integration
CHROMA = shutil.which("chroma") or str(Path(os.sys.executable).parent / "chroma")


@pytest.fixture(scope="module")
def chroma_server(tmp_path_factory):
    if not Path(CHROMA).exists():
        pytest.skip("the chroma CLI is not installed")
    port = free_port()
    data = tmp_path_factory.mktemp("chroma-data")
    proc = subprocess.Popen([CHROMA, "run", "--path", str(data), "--host", "127.0.0.1", "--port", str(port)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    import chromadb
    from chromadb.config import Settings

    deadline = time.time() + 60
    while time.time() < deadline:
        try:
            chromadb.HttpClient(host="127.0.0.1", port=port, settings=Settings(anonymized_telemetry=False)).heartbeat()
            break
        except Exception:  # not up yet
            if proc.poll() is not None:
                pytest.fail("chroma run exited during start-up")
            time.sleep(0.5)
    else:
        proc.kill()
        pytest.fail("chroma run did not start in 60 s")
    yield f"http://127.0.0.1:{port}", port
    proc.terminate()
    proc.wait(timeout=30)


async def test_grounding_through_a_chroma_server(chroma_server):
    url, port = chroma_server
    async with Grounder(KB, chroma_url=url) as g:
        res = await g.ground("people trapped in the shop attached to the bakery")
        assert g.last_sync is not None and len(g.last_sync.added) > 40
    assert [(o.location, o.category) for o in res.objects] == [("pharmacy", "victim")]
    import chromadb
    from chromadb.config import Settings

    client = chromadb.HttpClient(host="127.0.0.1", port=port, settings=Settings(anonymized_telemetry=False))
    names = [c.name if hasattr(c, "name") else c for c in client.list_collections()]
    assert any(str(n).startswith("lucifer-kb-") for n in names)
    # a second grounder finds the index already in sync on the server
    async with Grounder(KB, chroma_url=url) as g2:
        assert g2.last_sync is not None and g2.last_sync.skipped


def test_unreachable_chroma_server_is_a_clear_error():
    with pytest.raises(ChromaUnavailable, match="cannot reach the Chroma server"):
        Grounder(KB, chroma_url=f"http://127.0.0.1:{free_port()}")

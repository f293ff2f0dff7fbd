"""The discovery graph: the real builtin path, and the tool-calling loop with a fake chat model."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from langchain_core.language_models.fake_chat_models import GenericFakeChatModel
from langchain_core.messages import AIMessage, BaseMessage, ToolMessage

from lucifer.errors import BadRequest
from lucifer.graphs.discovery import Discoverer, DiscoveryRequest, parse_request
from lucifer.graphs.discovery.graph import build_graph
from lucifer.graphs.discovery.tools import TOOL_NAMES
from lucifer.telemetry.benchmark import DEFAULT_DIR, MEMORY_FILE
from lucifer.telemetry.embedcache import EmbeddingCache
from lucifer.telemetry.memory import TelemetryMemory
from lucifer.types import Status

OPTIONS = ["acoustic_listen", "drone_overflight", "gas_sniffer", "check_traffic_cameras"]


class FakeToolModel(GenericFakeChatModel):
    """Replays scripted AI messages (tool calls or answers) and records what it was sent."""

    seen: list[list[BaseMessage]] = []

    def bind_tools(self, tools: Any, **kwargs: Any) -> FakeToolModel:
        return self

    async def _agenerate(self, messages: list[BaseMessage], *args: Any, **kwargs: Any) -> Any:
        self.seen.append(list(messages))
        return await super()._agenerate(messages, *args, **kwargs)


class BrokenModel(FakeToolModel):
    error: Any = None

    async def _agenerate(self, messages: list[BaseMessage], *args: Any, **kwargs: Any) -> Any:
        raise self.error


def fake(*replies: AIMessage) -> FakeToolModel:
    it: Iterator[AIMessage] = iter(replies)
    return FakeToolModel(messages=it, seen=[])


def call(name: str, args: dict[str, Any], i: int = 0) -> dict[str, Any]:
    return {"name": name, "args": args, "id": f"call-{name}-{i}", "type": "tool_call"}


def answer(rec: str, conf: float = 0.8, dist: dict[str, float] | None = None) -> AIMessage:
    body: dict[str, Any] = {"recommendation": rec, "confidence": conf}
    if dist is not None:
        body["distribution"] = dist
    return AIMessage(content="Here you go:\n```json\n" + json.dumps(body) + "\n```")


@pytest.fixture(scope="module")
def seeded(tmp_path_factory: pytest.TempPathFactory) -> tuple[TelemetryMemory, EmbeddingCache]:
    d = tmp_path_factory.mktemp("discovery")
    mem = TelemetryMemory(d / "memory.sqlite")
    mem.seed_from(DEFAULT_DIR / MEMORY_FILE)
    return mem, EmbeddingCache(d / "embeddings.sqlite")


@pytest.fixture(scope="module")
def builtin(seeded: tuple[TelemetryMemory, EmbeddingCache]) -> Discoverer:
    mem, cache = seeded
    return Discoverer("knowledge_base", memory=mem, embedding_cache=cache)


def with_model(seeded: tuple[TelemetryMemory, EmbeddingCache], chat: Any, **kw: Any) -> Discoverer:
    mem, cache = seeded
    return Discoverer("knowledge_base", memory=mem, embedding_cache=cache, chat_model=chat, **kw)


# -- builtin -------------------------------------------------------------------------------


async def test_builtin_known_signature(builtin: Discoverer) -> None:
    row = json.loads((DEFAULT_DIR / "decision_points.jsonl").read_text().splitlines()[0])
    r = await builtin.discover({"signature": row["signature"], "options": row["options"], "trace": row["trace"]})
    assert r.recommendation == row["answer"]
    assert r.status == Status.OK and r.backend == "builtin" and r.known_signature
    assert r.tools_called == list(TOOL_NAMES)  # the builtin agent goes through the same tools
    assert list(r.distribution) == row["options"]
    assert sum(r.distribution.values()) == pytest.approx(1.0)
    assert r.confidence == pytest.approx(max(r.distribution.values()))


@pytest.mark.parametrize(
    ("signature", "expected"),
    [
        ("a child heard whimpering somewhere beneath the fallen gym roof", "acoustic_listen"),
        ("petrol fumes drifting from a cracked fuel line", "gas_sniffer"),
        ("nobody knows which roads out of the valley are still open", "drone_overflight"),
    ],
)
async def test_builtin_generalises_to_unseen_signatures(builtin: Discoverer, signature: str, expected: str) -> None:
    r = await builtin.discover(DiscoveryRequest(signature=signature, options=OPTIONS))
    assert not r.known_signature
    assert r.recommendation == expected
    assert 1 / len(OPTIONS) < r.confidence <= 1.0


async def test_appended_telemetry_changes_the_answer(seeded: tuple[TelemetryMemory, EmbeddingCache]) -> None:
    mem, cache = seeded
    d = Discoverer("knowledge_base", memory=mem, embedding_cache=cache)
    req = {"signature": "grey steel door with a yellow stripe", "options": ["scout_route", "hazmat_test"]}
    before = await d.discover(req)
    assert not before.known_signature
    other = "hazmat_test" if before.recommendation == "scout_route" else "scout_route"
    for _ in range(4):
        d.record(req["signature"], other, 1.0, trace=["walked in"], episode="t")
        d.record(req["signature"], before.recommendation, 0.0, episode="t")
    after = await d.discover(req)
    assert after.known_signature and after.recommendation == other


async def test_bad_requests(builtin: Discoverer) -> None:
    with pytest.raises(BadRequest, match="unknown query option"):
        await builtin.discover({"signature": "x", "options": ["teleport"]})
    with pytest.raises(BadRequest, match="invalid discovery request"):
        await builtin.discover('{"signature": "x", "options": [')
    with pytest.raises(BadRequest, match="unique"):
        parse_request({"signature": "x", "options": ["a", "a"]})
    with pytest.raises(BadRequest, match="signature"):
        parse_request({"signature": "   ", "options": ["a"]})
    assert parse_request({"signature": "x", "options": ["a"], "trace": "one step"}).trace == ["one step"]


def test_graph_topology() -> None:
    g = build_graph([]).compile().get_graph()
    assert set(g.nodes) == {"__start__", "plan_queries", "run_tools", "validate_answer", "fall_back", "__end__"}
    edges = {(e.source, e.target) for e in g.edges}
    assert {("run_tools", "plan_queries"), ("validate_answer", "plan_queries"), ("validate_answer", "fall_back"),
            ("plan_queries", "plan_queries"),
            ("plan_queries", "fall_back"), ("fall_back", "__end__")} <= edges


# -- chat model ----------------------------------------------------------------------------

SIG = "faint tapping under the collapsed car park"


async def test_chat_model_calls_tools_then_answers(seeded: Any) -> None:
    model = fake(
        AIMessage(content="", tool_calls=[call("signature_outcomes", {"signature": SIG}),
                                          call("similar_signatures", {"signature": SIG, "k": 3})]),
        answer("acoustic_listen", 0.7, {"acoustic_listen": 0.7, "gas_sniffer": 0.1, "drone_overflight": 0.2}),
    )
    d = with_model(seeded, model, model="fake:tools")
    r = await d.discover({"signature": SIG, "options": OPTIONS})
    assert (r.recommendation, r.status, r.backend) == ("acoustic_listen", Status.OK, "fake:tools")
    assert r.tools_called == ["signature_outcomes", "similar_signatures"]
    assert r.distribution["check_traffic_cameras"] == 0.0 and r.confidence == 0.7
    tool_msgs = [m for m in model.seen[1] if isinstance(m, ToolMessage)]
    assert [m.name for m in tool_msgs] == ["signature_outcomes", "similar_signatures"]
    assert json.loads(tool_msgs[1].content)["neighbors"]  # real memory evidence reached the model
    assert SIG in model.seen[0][1].content and "acoustic_listen:" in model.seen[0][1].content


async def test_invalid_option_is_retried(seeded: Any) -> None:
    model = fake(answer("teleport"), answer("gas_sniffer", 0.6))
    r = await with_model(seeded, model).discover({"signature": SIG, "options": OPTIONS})
    assert (r.recommendation, r.status) == ("gas_sniffer", Status.RETRIED)
    assert any("teleport" in e for e in r.errors)
    assert "rejected" in model.seen[1][-1].content and "teleport" in model.seen[1][-1].content


async def test_invalid_answers_fall_back_after_the_cap(seeded: Any) -> None:
    model = fake(answer("teleport"), AIMessage(content="I think listening is best"), answer("ask_bystanders"))
    r = await with_model(seeded, model, max_retries=2).discover({"signature": SIG, "options": OPTIONS})
    assert r.status == Status.LLM_INVALID
    assert r.backend.startswith("builtin (fallback from")
    assert r.recommendation == "acoustic_listen"  # the builtin answer
    assert len(model.seen) == 3 and len(r.errors) == 3


async def test_tool_error_goes_back_to_the_model(seeded: Any) -> None:
    model = fake(
        AIMessage(content="", tool_calls=[call("option_fit", {"signature": SIG, "options": ["warp_drive"]}),
                                          call("no_such_tool", {})]),
        answer("acoustic_listen", 0.9),
    )
    r = await with_model(seeded, model).discover({"signature": SIG, "options": OPTIONS})
    assert (r.recommendation, r.status) == ("acoustic_listen", Status.OK)
    errors = [m for m in model.seen[1] if isinstance(m, ToolMessage)]
    assert [m.status for m in errors] == ["error", "error"]
    assert "warp_drive" in errors[0].content


@pytest.mark.parametrize(
    ("error", "status"),
    [(TimeoutError("slow"), Status.LLM_TIMEOUT), (ConnectionError("refused"), Status.LLM_UNAVAILABLE),
     (RuntimeError("boom"), Status.LLM_ERROR)],
)
async def test_model_failure_falls_back(seeded: Any, error: Exception, status: Status) -> None:
    model = BrokenModel(messages=iter([]), seen=[], error=error)
    r = await with_model(seeded, model).discover({"signature": SIG, "options": OPTIONS})
    assert r.status == status and r.recommendation == "acoustic_listen"
    assert r.tools_called == [] and type(error).__name__ in r.errors[0]


async def test_tool_rounds_are_capped(seeded: Any) -> None:
    loop = [AIMessage(content="", tool_calls=[call("option_stats", {}, i)]) for i in range(3)]
    model = fake(*loop, answer("drone_overflight"))
    r = await with_model(seeded, model, max_tool_rounds=3).discover({"signature": SIG, "options": OPTIONS})
    assert r.recommendation == "drone_overflight" and r.tools_called == ["option_stats"] * 3


def test_unknown_backend_is_a_clear_error(seeded: Any) -> None:
    from lucifer.errors import BackendError

    mem, cache = seeded
    with pytest.raises(BackendError):
        Discoverer("knowledge_base", memory=mem, embedding_cache=cache, model="nonsense")


def test_cli_discover(tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    from lucifer.cli import main

    monkeypatch.setenv("LUCIFER_HOME", str(tmp_path / "home"))
    req = tmp_path / "req.json"
    req.write_text(json.dumps({"signature": "hissing gas pipe behind the bakery", "options": OPTIONS}))
    assert main(["discover", "--memory", str(tmp_path / "m.sqlite"), str(req)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["recommendation"] == "gas_sniffer" and out["status"] == "ok"
    assert main(["discover", "--memory", str(tmp_path / "m.sqlite"), '{"signature": "x", "options": ["nope"]}']) == 2
    assert "unknown query option" in capsys.readouterr().err


async def test_episodic_trace_counts_queries_already_run_here(builtin: Discoverer) -> None:
    opts = ["acoustic_listen", "search_dog"]
    plain = await builtin.discover({"signature": SIG, "options": opts})
    assert plain.recommendation == "acoustic_listen"
    failed = {"option": "acoustic_listen", "outcome": 0.0}
    elsewhere = {**failed, "signature": "a different street"}
    same = await builtin.discover({"signature": SIG, "options": opts, "trace": ["arrived", elsewhere] * 3})
    assert same.distribution == pytest.approx(plain.distribution)  # other places do not count
    after = await builtin.discover({"signature": SIG, "options": opts, "trace": ["arrived", *[failed] * 4]})
    assert after.recommendation == "search_dog"
    with pytest.raises(BadRequest):
        parse_request({"signature": SIG, "options": opts, "trace": [{"option": "x", "outcome": 3}]})


class FlakyModel(FakeToolModel):
    failures: int = 1

    async def _agenerate(self, messages: list[BaseMessage], *args: Any, **kwargs: Any) -> Any:
        if self.failures > 0:
            self.failures -= 1
            raise RuntimeError("provider hiccup")
        return await super()._agenerate(messages, *args, **kwargs)


async def test_model_error_is_retried_then_falls_back(seeded: Any) -> None:
    ok = FlakyModel(messages=iter([answer("gas_sniffer")]), seen=[], failures=1)
    r = await with_model(seeded, ok).discover({"signature": SIG, "options": OPTIONS})
    assert (r.recommendation, r.status) == ("gas_sniffer", Status.RETRIED)
    assert r.errors == ["chat model failed: RuntimeError: provider hiccup"]
    bad = FlakyModel(messages=iter([answer("gas_sniffer")]), seen=[], failures=5)
    r = await with_model(seeded, bad, max_retries=2).discover({"signature": SIG, "options": OPTIONS})
    assert r.status == Status.LLM_ERROR and r.recommendation == "acoustic_listen" and len(r.errors) == 3


async def test_cold_memory_answers_from_kb_descriptions_which_are_editable(tmp_path: Path) -> None:
    import shutil

    import yaml

    kb_dir = tmp_path / "kb"
    shutil.copytree("knowledge_base", kb_dir)
    cache = EmbeddingCache(tmp_path / "emb.sqlite")
    req = {"signature": "hissing from a cracked pipe by the boiler", "options": ["gas_sniffer", "acoustic_listen"]}
    d = Discoverer(kb_dir, memory=TelemetryMemory(tmp_path / "empty.sqlite"), embedding_cache=cache)
    r = await d.discover(req)
    assert (r.recommendation, r.status, r.known_signature) == ("gas_sniffer", Status.OK, False)
    assert 0.5 < r.confidence < 1.0
    # swap the two descriptions in the KB file: the answer follows the meaning, not the name
    path = kb_dir / "query_options.yaml"
    data = yaml.safe_load(path.read_text())
    by_name = {o["name"]: o for o in data["options"]}
    gas, listen = by_name["gas_sniffer"], by_name["acoustic_listen"]
    gas["description"], listen["description"] = listen["description"], gas["description"]
    path.write_text(yaml.safe_dump(data))
    d2 = Discoverer(kb_dir, memory=TelemetryMemory(tmp_path / "empty2.sqlite"), embedding_cache=cache)
    assert (await d2.discover(req)).recommendation == "acoustic_listen"

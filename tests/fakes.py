"""Fake chat models for wiring and failure-path tests (never used by product code)."""

from __future__ import annotations

import asyncio
from collections.abc import Sequence
from typing import Any

from langchain_core.language_models.chat_models import BaseChatModel
from langchain_core.messages import AIMessage, BaseMessage
from langchain_core.outputs import ChatGeneration, ChatResult


class ScriptedChatModel(BaseChatModel):
    """Replays a script: each item is an AIMessage to return, an exception to raise, or a
    ``("sleep", seconds)`` pair. Records the messages it was called with."""

    script: list[Any]
    calls: list[list[BaseMessage]] = []

    @property
    def _llm_type(self) -> str:
        return "scripted-fake"

    def bind_tools(self, tools: Sequence[Any], **kwargs: Any) -> ScriptedChatModel:
        return self

    def _next(self, messages: list[BaseMessage]) -> Any:
        self.calls.append(list(messages))
        if not self.script:
            raise AssertionError("the fake chat model ran out of scripted answers")
        return self.script.pop(0)

    def _generate(self, messages: list[BaseMessage], stop: Any = None, run_manager: Any = None, **kw: Any) -> ChatResult:
        item = self._next(messages)
        if isinstance(item, BaseException):
            raise item
        return ChatResult(generations=[ChatGeneration(message=item)])

    async def _agenerate(self, messages: list[BaseMessage], stop: Any = None, run_manager: Any = None, **kw: Any) -> ChatResult:
        item = self._next(messages)
        if isinstance(item, tuple) and item[0] == "sleep":
            await asyncio.sleep(item[1])
            item = AIMessage("")
        if isinstance(item, BaseException):
            raise item
        return ChatResult(generations=[ChatGeneration(message=item)])


def tool_answer(objects: list[dict[str, str]], call_id: str = "call-1") -> AIMessage:
    """An AIMessage calling the grounding tool with these objects."""
    return AIMessage("", tool_calls=[{"name": "ReportObjects", "args": {"objects": objects}, "id": call_id}])

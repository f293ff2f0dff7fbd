"""Chroma client and collection for a knowledge base: local persistent store or a server."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any
from urllib.parse import urlparse

from chromadb.api.types import Documents, EmbeddingFunction, Embeddings

from lucifer.embeddings import Embedder, get_embedder
from lucifer.errors import LuciferError
from lucifer.paths import index_dir

COLLECTION_PREFIX = "lucifer-kb"


class ChromaUnavailable(LuciferError):
    """The configured Chroma server cannot be reached."""


class MiniLMEmbeddingFunction(EmbeddingFunction[Documents]):
    """Chroma embedding function backed by LUCIFER's offline MiniLM embedder."""

    def __init__(self, embedder: Embedder | None = None, engine: str | None = None):
        self._embedder = embedder or get_embedder(engine)

    def __call__(self, input: Documents) -> Embeddings:
        return list(self._embedder.embed(list(input)))

    @staticmethod
    def name() -> str:
        return "lucifer-minilm"

    def get_config(self) -> dict[str, Any]:
        return {"engine": self._embedder.engine}

    @staticmethod
    def build_from_config(config: dict[str, Any]) -> MiniLMEmbeddingFunction:
        return MiniLMEmbeddingFunction(engine=config.get("engine"))

    def default_space(self) -> str:  # type: ignore[override]
        return "cosine"


def resolve_chroma_url(url: str | None) -> str | None:
    """Explicit argument first, then ``$LUCIFER_CHROMA_URL``; ``None`` means a local store."""
    return url if url is not None else (os.environ.get("LUCIFER_CHROMA_URL") or None)


def make_client(kb_root: Path, chroma_url: str | None = None) -> Any:
    import chromadb
    from chromadb.config import Settings

    settings = Settings(anonymized_telemetry=False, allow_reset=False)
    url = resolve_chroma_url(chroma_url)
    if url:
        parsed = urlparse(url if "://" in url else f"http://{url}")
        try:
            client = chromadb.HttpClient(
                host=parsed.hostname or "localhost",
                port=parsed.port or 8000,
                ssl=parsed.scheme == "https",
                settings=settings,
            )
            client.heartbeat()
        except Exception as exc:  # connection errors come in many types
            raise ChromaUnavailable(f"cannot reach the Chroma server at {url}: {exc}") from exc
        return client
    return chromadb.PersistentClient(path=str(index_dir(kb_root)), settings=settings)


def collection_name(kb_root: Path) -> str:
    """One collection per KB path, so a server can hold several knowledge bases."""
    import hashlib

    key = hashlib.sha256(str(Path(kb_root).resolve()).encode()).hexdigest()[:10]
    return f"{COLLECTION_PREFIX}-{key}"


def open_collection(client: Any, kb_root: Path, embedder: Embedder | None = None) -> Any:
    return client.get_or_create_collection(
        name=collection_name(kb_root),
        embedding_function=MiniLMEmbeddingFunction(embedder),
        metadata={"hnsw:space": "cosine"},
    )

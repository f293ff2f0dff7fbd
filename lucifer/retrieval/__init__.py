"""Retrieval: a Chroma index of the knowledge base, synced by content hash."""

from lucifer.retrieval.documents import KBDocument, kb_documents
from lucifer.retrieval.retriever import Retrieved, Retriever
from lucifer.retrieval.store import (
    ChromaUnavailable,
    MiniLMEmbeddingFunction,
    make_client,
    open_collection,
)
from lucifer.retrieval.sync import SyncReport, sync_index

__all__ = [
    "ChromaUnavailable",
    "KBDocument",
    "MiniLMEmbeddingFunction",
    "Retrieved",
    "Retriever",
    "SyncReport",
    "kb_documents",
    "make_client",
    "open_collection",
    "sync_index",
]

"""Keep the vector index in step with the KB: re-embed only what changed, drop what was deleted."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from lucifer.embeddings import Embedder
from lucifer.kb import KnowledgeBase
from lucifer.retrieval.documents import kb_documents

FINGERPRINT_KEY = "lucifer:kb_fingerprint"


@dataclass
class SyncReport:
    added: list[str] = field(default_factory=list)
    updated: list[str] = field(default_factory=list)
    deleted: list[str] = field(default_factory=list)
    unchanged: int = 0
    skipped: bool = False  # the KB fingerprint matched; nothing was compared

    @property
    def changed(self) -> bool:
        return bool(self.added or self.updated or self.deleted)

    def summary(self) -> str:
        if self.skipped:
            return "index up to date"
        return (
            f"index synced: {len(self.added)} added, {len(self.updated)} updated, "
            f"{len(self.deleted)} deleted, {self.unchanged} unchanged"
        )


def _stored_fingerprint(collection: Any) -> str | None:
    meta = collection.metadata or {}
    return meta.get(FINGERPRINT_KEY)


def sync_index(kb: KnowledgeBase, collection: Any, embedder: Embedder, force: bool = False) -> SyncReport:
    """Bring ``collection`` to exactly the documents of ``kb``.

    Compares per-document content hashes stored in the metadata, embeds only new or changed
    documents, deletes documents whose KB entry is gone, then records the KB fingerprint so
    the next call with an unchanged KB returns at once.
    """
    if not force and _stored_fingerprint(collection) == kb.fingerprint:
        return SyncReport(skipped=True)
    report = SyncReport()
    docs = {d.id: d for d in kb_documents(kb)}
    existing = collection.get(include=["metadatas"])
    stored = {i: (m or {}).get("hash") for i, m in zip(existing["ids"], existing["metadatas"], strict=True)}
    to_write = []
    for doc_id, doc in docs.items():
        if doc_id not in stored:
            report.added.append(doc_id)
            to_write.append(doc)
        elif stored[doc_id] != doc.content_hash:
            report.updated.append(doc_id)
            to_write.append(doc)
        else:
            report.unchanged += 1
    report.deleted = sorted(set(stored) - set(docs))
    if report.deleted:
        collection.delete(ids=report.deleted)
    if to_write:
        vectors = embedder.embed([d.text for d in to_write])
        collection.upsert(
            ids=[d.id for d in to_write],
            documents=[d.text for d in to_write],
            metadatas=[d.metadata for d in to_write],
            embeddings=[v.tolist() for v in vectors],
        )
    meta = dict(collection.metadata or {})
    meta.pop("hnsw:space", None)  # immutable after creation; modify() rejects it
    meta[FINGERPRINT_KEY] = kb.fingerprint
    collection.modify(metadata=meta)
    return report

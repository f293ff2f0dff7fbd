"""Query-only access to the KB index (retrieval never writes)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from lucifer.embeddings import Embedder


@dataclass(frozen=True)
class Retrieved:
    id: str
    kind: str
    name: str
    text: str
    score: float  # cosine similarity in [-1, 1]

    def as_dict(self) -> dict[str, Any]:
        return {"id": self.id, "kind": self.kind, "name": self.name, "score": round(self.score, 4)}


class Retriever:
    def __init__(self, collection: Any, embedder: Embedder):
        self._collection = collection
        self._embedder = embedder

    def retrieve(self, queries: list[str], k: int = 8, kinds: tuple[str, ...] | None = None) -> list[Retrieved]:
        """Top-``k`` KB documents for each query, merged (best score per document).

        ``kinds`` restricts the search to some document kinds (``landmark``, ``relation``, ...).
        """
        queries = [q for q in queries if q.strip()]
        if not queries:
            return []
        vectors = self._embedder.embed(queries)
        res = self._collection.query(
            query_embeddings=[v.tolist() for v in vectors],
            n_results=k,
            where={"kind": {"$in": list(kinds)}} if kinds else None,
            include=["metadatas", "documents", "distances"],
        )
        best: dict[str, Retrieved] = {}
        for ids, metas, texts, dists in zip(res["ids"], res["metadatas"], res["documents"], res["distances"], strict=True):
            for doc_id, meta, text, dist in zip(ids, metas, texts, dists, strict=True):
                item = Retrieved(doc_id, meta.get("kind", ""), meta.get("name", ""), text, 1.0 - float(dist))
                if doc_id not in best or item.score > best[doc_id].score:
                    best[doc_id] = item
        return sorted(best.values(), key=lambda r: -r.score)

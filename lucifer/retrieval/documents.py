"""Turn a knowledge base into retrieval documents with stable ids and content hashes."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass

from lucifer.kb import KnowledgeBase


@dataclass(frozen=True)
class KBDocument:
    id: str
    kind: str  # landmark | relation | glossary | category | query_option
    text: str
    name: str  # the KB entry the document describes

    @property
    def content_hash(self) -> str:
        return hashlib.sha256(f"{self.kind}\x00{self.name}\x00{self.text}".encode()).hexdigest()[:16]

    @property
    def metadata(self) -> dict[str, str]:
        return {"kind": self.kind, "name": self.name, "hash": self.content_hash}


def kb_documents(kb: KnowledgeBase) -> list[KBDocument]:
    """One document per landmark, relation, glossary term, category and query option.

    >>> from lucifer.kb import load_kb
    >>> docs = kb_documents(load_kb("knowledge_base"))
    >>> next(d for d in docs if d.id == "landmark:bakery").text.split(".")[0]
    'bakery (also: bread shop, the baker's, bakehouse)'
    """
    docs: list[KBDocument] = []
    for lm in kb.landmarks:
        aka = f" (also: {', '.join(lm.aliases)})" if lm.aliases else ""
        docs.append(KBDocument(f"landmark:{lm.name}", "landmark", f"{lm.name}{aka}. {lm.description}".strip(), lm.name))
    for rel in kb.relations:
        text = f"{rel.subject} is {rel.phrase} {rel.object}"
        docs.append(KBDocument(f"relation:{rel.subject}|{rel.relation}|{rel.object}", "relation", text, rel.subject))
    for term in kb.glossary:
        docs.append(KBDocument(f"glossary:{term.term}", "glossary", f"{term.term} means {term.category}", term.term))
    for cat in kb.categories:
        docs.append(KBDocument(f"category:{cat.name}", "category", f"{cat.name} ({cat.role.value}): {cat.description}", cat.name))
    for opt in kb.query_options:
        docs.append(KBDocument(f"query_option:{opt.name}", "query_option", f"{opt.name}: {opt.description}", opt.name))
    return docs

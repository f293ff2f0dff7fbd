"""Knowledge base: the editable YAML data every other part of LUCIFER reads."""

from lucifer.kb.loader import (
    DEFAULT_KB,
    KBError,
    KBProblem,
    KnowledgeBase,
    kb_fingerprint,
    load_kb,
    resolve_kb_dir,
)
from lucifer.kb.models import Category, GlossaryTerm, Landmark, QueryOption, Relation, Role

__all__ = [
    "DEFAULT_KB",
    "Category",
    "GlossaryTerm",
    "KBError",
    "KBProblem",
    "KnowledgeBase",
    "Landmark",
    "QueryOption",
    "Relation",
    "Role",
    "kb_fingerprint",
    "load_kb",
    "resolve_kb_dir",
]

"""Load and validate a knowledge-base directory (SPEC §1).

Everything is validated before anything is returned, so a KB is either loaded whole or
rejected with :class:`KBError`, whose ``problems`` name the file, the entry and the rule.
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import yaml
from pydantic import BaseModel, ValidationError

from lucifer.errors import LuciferError
from lucifer.kb.models import (
    Category,
    Glossary,
    GlossaryTerm,
    InformationSpace,
    Landmark,
    MapFile,
    QueryOption,
    QueryOptions,
    Relation,
    Role,
)

INFORMATION_SPACE = "information_space.yaml"
MAP = "map.yaml"
GLOSSARY = "glossary.yaml"
QUERY_OPTIONS = "query_options.yaml"  # optional extension: discovery's query options
REQUIRED_FILES = (INFORMATION_SPACE, MAP)
OPTIONAL_FILES = (GLOSSARY, QUERY_OPTIONS)

DEFAULT_KB = "knowledge_base"


@dataclass(frozen=True)
class KBProblem:
    file: str
    entry: str
    rule: str

    def __str__(self) -> str:
        return f"{self.file}: {self.entry}: {self.rule}"


class KBError(LuciferError, ValueError):
    """The knowledge base breaks a rule; nothing of it was loaded."""

    def __init__(self, root: Path | str, problems: Iterable[KBProblem]):
        self.root = Path(root)
        self.problems = list(problems)
        lines = "\n".join(f"  - {p}" for p in self.problems)
        super().__init__(f"invalid knowledge base {self.root}:\n{lines}")


@dataclass(frozen=True)
class KnowledgeBase:
    """A validated knowledge base. Immutable; reload the directory to see edits."""

    root: Path
    categories: tuple[Category, ...]
    rows: int
    cols: int
    landmarks: tuple[Landmark, ...]
    relations: tuple[Relation, ...]
    glossary: tuple[GlossaryTerm, ...]
    query_options: tuple[QueryOption, ...]
    fingerprint: str = field(compare=False)

    @cached_property
    def landmark_by_name(self) -> dict[str, Landmark]:
        return {lm.name: lm for lm in self.landmarks}

    @cached_property
    def category_by_name(self) -> dict[str, Category]:
        return {c.name: c for c in self.categories}

    def categories_with_role(self, role: Role | str) -> list[Category]:
        return [c for c in self.categories if c.role == Role(role)]

    def cells_of(self, landmark: str) -> list[list[int]]:
        return [list(c) for c in self.landmark_by_name[landmark].cells]

    @cached_property
    def cell_owner(self) -> dict[tuple[int, int], str]:
        """Map each covered cell to the landmark that covers it.

        Landmarks may overlap (a refuge bay inside a tunnel bore, a shop inside a service area): a
        shared cell goes to the landmark that covers the fewest cells, the most specific place, and
        between equals to the one listed first.
        """
        owner: dict[tuple[int, int], str] = {}
        for lm in self.landmarks:
            for c in lm.cells:
                held = owner.get(tuple(c))  # type: ignore[arg-type]
                if held is None or len(lm.cells) < len(self.landmark_by_name[held].cells):
                    owner[tuple(c)] = lm.name  # type: ignore[index]
        return owner


def resolve_kb_dir(kb: str | os.PathLike[str] | None = None) -> Path:
    """``--kb`` if given, else ``$LUCIFER_KB``, else ``knowledge_base/``."""
    if kb is not None:
        return Path(kb)
    return Path(os.environ.get("LUCIFER_KB") or DEFAULT_KB)


def kb_fingerprint(root: Path) -> str:
    """Content hash of the KB files; changes whenever a file is edited."""
    h = hashlib.sha256()
    for name in (*REQUIRED_FILES, *OPTIONAL_FILES):
        p = root / name
        if p.is_file():
            h.update(name.encode())
            h.update(p.read_bytes())
    return h.hexdigest()[:16]


def _read_yaml(path: Path, problems: list[KBProblem]) -> Any:
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        problems.append(KBProblem(path.name, "file", f"not valid UTF-8 ({exc.reason})"))
        return None
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as exc:
        where = ""
        mark = getattr(exc, "problem_mark", None)
        if mark is not None:
            where = f" at line {mark.line + 1}, column {mark.column + 1}"
        problems.append(KBProblem(path.name, "file", f"malformed YAML{where}: {getattr(exc, 'problem', exc)}"))
        return None


def _entry_label(data: Any, loc: tuple[Any, ...]) -> str:
    """Human label for a pydantic error location, e.g. ``landmarks[3] (bakery).cells``."""
    parts: list[str] = []
    node = data
    for item in loc:
        if isinstance(item, int):
            label = f"[{item}]"
            if isinstance(node, list) and 0 <= item < len(node):
                node = node[item]
                if isinstance(node, dict):
                    ident = node.get("name") or node.get("term") or node.get("subject")
                    if ident:
                        label += f" ({ident})"
            else:
                node = None
            parts.append(label)
        else:
            parts.append(("." if parts else "") + str(item))
            node = node.get(item) if isinstance(node, dict) else None
    return "".join(parts) or "top level"


def _parse(model: type[BaseModel], data: Any, file: str, problems: list[KBProblem]) -> Any:
    if data is None:
        data = {}
    if not isinstance(data, dict):
        problems.append(KBProblem(file, "top level", "must be a mapping (key: value), got " + type(data).__name__))
        return None
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        for err in exc.errors():
            problems.append(KBProblem(file, _entry_label(data, err["loc"]), err["msg"]))
        return None


def load_kb(kb: str | os.PathLike[str] | None = None) -> KnowledgeBase:
    """Load and validate a KB directory; raise :class:`KBError` listing every problem."""
    root = resolve_kb_dir(kb)
    problems: list[KBProblem] = []
    if not root.is_dir():
        raise KBError(root, [KBProblem(str(root), "directory", "knowledge base directory does not exist")])
    raw: dict[str, Any] = {}
    for name in REQUIRED_FILES:
        if not (root / name).is_file():
            problems.append(KBProblem(name, "file", "required file is missing"))
        else:
            raw[name] = _read_yaml(root / name, problems)
    for name in OPTIONAL_FILES:
        if (root / name).is_file():
            raw[name] = _read_yaml(root / name, problems)
    if problems:
        raise KBError(root, problems)

    space = _parse(InformationSpace, raw.get(INFORMATION_SPACE), INFORMATION_SPACE, problems)
    mapf = _parse(MapFile, raw.get(MAP), MAP, problems)
    glossary = _parse(Glossary, raw.get(GLOSSARY), GLOSSARY, problems) if GLOSSARY in raw else Glossary()
    qopts = (
        _parse(QueryOptions, raw.get(QUERY_OPTIONS), QUERY_OPTIONS, problems)
        if QUERY_OPTIONS in raw
        else QueryOptions()
    )
    if problems:
        raise KBError(root, problems)
    assert space is not None and mapf is not None and glossary is not None and qopts is not None

    _check_cross_rules(space, mapf, glossary, qopts, problems)
    if problems:
        raise KBError(root, problems)
    return KnowledgeBase(
        root=root.resolve(),
        categories=tuple(space.categories),
        rows=mapf.grid.rows,
        cols=mapf.grid.cols,
        landmarks=tuple(mapf.landmarks),
        relations=tuple(mapf.relations),
        glossary=tuple(glossary.terms),
        query_options=tuple(qopts.options),
        fingerprint=kb_fingerprint(root),
    )


def _check_cross_rules(
    space: InformationSpace,
    mapf: MapFile,
    glossary: Glossary,
    qopts: QueryOptions,
    problems: list[KBProblem],
) -> None:
    seen_cat: set[str] = set()
    for i, c in enumerate(space.categories):
        if c.name in seen_cat:
            problems.append(KBProblem(INFORMATION_SPACE, f"categories[{i}] ({c.name})", "duplicate category name"))
        seen_cat.add(c.name)

    rows, cols = mapf.grid.rows, mapf.grid.cols
    names: dict[str, str] = {}  # lowercased surface form -> owning landmark
    for i, lm in enumerate(mapf.landmarks):
        label = f"landmarks[{i}] ({lm.name})"
        key = lm.name.lower()
        if key in names:
            problems.append(KBProblem(MAP, label, f"duplicate name: '{lm.name}' is already used by landmark '{names[key]}'"))
        else:
            names[key] = lm.name
        for alias in lm.aliases:
            akey = alias.lower()
            if akey in names and names[akey] != lm.name:
                problems.append(KBProblem(MAP, label, f"duplicate name: alias '{alias}' is already used by landmark '{names[akey]}'"))
            else:
                names[akey] = lm.name
        for cell in lm.cells:
            r, c = cell
            if not (0 <= r < rows and 0 <= c < cols):
                problems.append(KBProblem(MAP, label, f"cell [{r}, {c}] is outside the {rows}x{cols} grid"))
    canon = {lm.name for lm in mapf.landmarks}
    for i, rel in enumerate(mapf.relations):
        label = f"relations[{i}] ({rel.subject} {rel.relation} {rel.object})"
        for role_name, value in (("subject", rel.subject), ("object", rel.object)):
            if value not in canon:
                problems.append(KBProblem(MAP, label, f"{role_name} '{value}' is not a landmark in the KB"))
        if rel.subject == rel.object:
            problems.append(KBProblem(MAP, label, "a landmark cannot be related to itself"))
    seen_terms: set[str] = set()
    for i, t in enumerate(glossary.terms):
        label = f"terms[{i}] ({t.term})"
        if t.category not in seen_cat:
            problems.append(KBProblem(GLOSSARY, label, f"unknown category '{t.category}' (Information Space has: {', '.join(sorted(seen_cat))})"))
        if t.term.lower() in seen_terms:
            problems.append(KBProblem(GLOSSARY, label, "duplicate term"))
        seen_terms.add(t.term.lower())
    seen_opt: set[str] = set()
    for i, o in enumerate(qopts.options):
        if o.name in seen_opt:
            problems.append(KBProblem(QUERY_OPTIONS, f"options[{i}] ({o.name})", "duplicate option name"))
        seen_opt.add(o.name)

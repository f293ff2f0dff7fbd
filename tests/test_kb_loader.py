"""The KB loader: the shipped KBs load; every broken KB is rejected naming file, entry and rule."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
import yaml
from conftest import KB, RIVERBEND

from lucifer.kb import KBError, load_kb, resolve_kb_dir
from lucifer.kb.models import Role


def test_shipped_kb_meets_the_issue_minimums():
    kb = load_kb(KB)
    assert (kb.rows, kb.cols) == (5, 5)
    assert len(kb.landmarks) >= 12 and all(lm.aliases and lm.description for lm in kb.landmarks)
    assert len(kb.relations) >= 6
    assert len(kb.glossary) >= 15
    assert {c.role for c in kb.categories} == set(Role)


def test_second_kb_loads_and_differs():
    a, b = load_kb(KB), load_kb(RIVERBEND)
    assert not {lm.name for lm in a.landmarks} & {lm.name for lm in b.landmarks}
    assert not {c.name for c in a.categories} & {c.name for c in b.categories}


def test_kb_dir_resolution_prefers_the_argument(monkeypatch):
    monkeypatch.setenv("LUCIFER_KB", "/from/env")
    assert resolve_kb_dir("explicit") == Path("explicit")
    assert resolve_kb_dir(None) == Path("/from/env")
    monkeypatch.delenv("LUCIFER_KB")
    assert resolve_kb_dir(None) == Path("knowledge_base")


def _edit(path: Path, fn) -> None:
    data = yaml.safe_load(path.read_text())
    fn(data)
    path.write_text(yaml.safe_dump(data, sort_keys=False))


# name -> (file, mutation or raw text, substrings the error must contain)
BROKEN = {
    "unknown_category_in_glossary": (
        "glossary.yaml", lambda d: d["terms"].append({"term": "lava", "category": "volcano"}),
        ["glossary.yaml", "lava", "unknown category 'volcano'"]),
    "cell_outside_grid": (
        "map.yaml", lambda d: d["landmarks"][0].update(cells=[[7, 1]]),
        ["map.yaml", "town hall", "cell [7, 1] is outside the 5x5 grid"]),
    "duplicate_landmark_name": (
        "map.yaml", lambda d: d["landmarks"].append({"name": "bakery", "cells": [[0, 0]]}),
        ["map.yaml", "bakery", "duplicate name"]),
    "alias_clashes_with_other_landmark": (
        "map.yaml", lambda d: d["landmarks"][0]["aliases"].append("bread shop"),
        ["map.yaml", "landmarks[8] (bakery)", "alias 'bread shop' is already used by landmark 'town hall'"]),
    "relation_to_unknown_landmark": (
        "map.yaml", lambda d: d["relations"].append({"subject": "casino", "relation": "next_to", "object": "bank"}),
        ["map.yaml", "casino next_to bank", "subject 'casino' is not a landmark"]),
    "unknown_role": (
        "information_space.yaml", lambda d: d["categories"][0].update(role="scary"),
        ["information_space.yaml", "categories[0] (hazard).role", "undesirable"]),
    "duplicate_category": (
        "information_space.yaml", lambda d: d["categories"].append(dict(d["categories"][0])),
        ["information_space.yaml", "hazard", "duplicate category name"]),
    "missing_cells": (
        "map.yaml", lambda d: d["landmarks"][2].pop("cells"),
        ["map.yaml", "landmarks[2] (school).cells", "Field required"]),
    "typo_in_field_name": (
        "map.yaml", lambda d: d["landmarks"][1].update(alias=["x"]),
        ["map.yaml", "landmarks[1] (library).alias", "Extra inputs are not permitted"]),
    "malformed_yaml": ("glossary.yaml", "terms:\n  - {term: smoke, category: hazard\n", ["glossary.yaml", "malformed YAML", "line"]),
    "not_a_mapping": ("map.yaml", "- just\n- a list\n", ["map.yaml", "must be a mapping"]),
    "empty_name": (
        "map.yaml", lambda d: d["landmarks"][3].update(name="   "),
        ["map.yaml", "landmarks[3]", "non-empty"]),
}


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_broken_kb_is_rejected_with_file_entry_and_rule(case, tmp_path):
    kb_dir = tmp_path / case
    shutil.copytree(KB, kb_dir)
    file, change, expected = BROKEN[case]
    if callable(change):
        _edit(kb_dir / file, change)
    else:
        (kb_dir / file).write_text(change)
    with pytest.raises(KBError) as err:
        load_kb(kb_dir)
    message = str(err.value)
    for part in expected:
        assert part in message, f"{part!r} not in:\n{message}"


def test_missing_required_file_and_directory(tmp_path):
    kb_dir = tmp_path / "kb"
    shutil.copytree(KB, kb_dir)
    (kb_dir / "map.yaml").unlink()
    with pytest.raises(KBError, match="map.yaml: file: required file is missing"):
        load_kb(kb_dir)
    with pytest.raises(KBError, match="does not exist"):
        load_kb(tmp_path / "nowhere")


def test_every_problem_is_reported_at_once(tmp_path):
    kb_dir = tmp_path / "kb"
    shutil.copytree(KB, kb_dir)
    _edit(kb_dir / "map.yaml", lambda d: (d["landmarks"][0].update(cells=[[9, 9]]),
                                          d["relations"].append({"subject": "x", "relation": "r", "object": "bank"})))
    with pytest.raises(KBError) as err:
        load_kb(kb_dir)
    assert len(err.value.problems) == 2


def test_optional_files_may_be_absent(tmp_path):
    kb_dir = tmp_path / "kb"
    shutil.copytree(KB, kb_dir)
    (kb_dir / "glossary.yaml").unlink()
    (kb_dir / "query_options.yaml").unlink(missing_ok=True)
    kb = load_kb(kb_dir)
    assert kb.glossary == () and kb.query_options == ()


def test_landmarks_may_overlap_and_a_shared_cell_goes_to_the_smaller_one(tmp_path):
    # SPEC §1 does not ask for disjoint landmarks: a kiosk inside a square, a refuge bay inside a tunnel
    kb_dir = tmp_path / "kb"
    shutil.copytree(KB, kb_dir)
    before = load_kb(kb_dir).cell_owner
    _edit(kb_dir / "map.yaml", lambda d: d["landmarks"].extend([
        {"name": "south quarter", "cells": [[4, 0], [4, 1], [4, 2], [4, 3], [4, 4]]},
        {"name": "flower kiosk", "cells": [[4, 1]], "description": "A kiosk inside the park."},
    ]))
    kb = load_kb(kb_dir)
    assert kb.cells_of("flower kiosk") == [[4, 1]]
    assert kb.cells_of("south quarter") == [[4, c] for c in range(5)]
    # the big one listed later takes no cell from the smaller ones; a one-cell place listed later
    # than another one-cell place leaves it its cell
    assert kb.cell_owner == before
    _edit(kb_dir / "map.yaml", lambda d: d["landmarks"].insert(0, {"name": "phone box", "cells": [[4, 1]]}))
    assert load_kb(kb_dir).cell_owner[(4, 1)] == "phone box"

"""Mission layouts of the SAR testbed on the shipped Market Square town (5×5, every cell a place).

A layout names places of the knowledge base, never cells, so it survives edits that move a
landmark. :func:`resolve_layouts` turns layouts into cell indices against a loaded KB and
rejects a layout whose places are missing, overlap, or are unreachable without crossing a
hazard.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

from lucifer.clients.envs.core.actions import MOVE_DELTAS
from lucifer.errors import LuciferError
from lucifer.kb import KnowledgeBase


@dataclass(frozen=True)
class Layout:
    """One mission: where the team starts, the hidden hazards and the information locations.

    ``hazards`` maps a place to the kind of danger the radio reports for it;
    ``info`` maps each information type (victim, hazard, safe_route) to the place that holds it.
    """

    name: str
    start: str
    hazards: dict[str, str]
    info: dict[str, str]


@dataclass(frozen=True)
class ResolvedLayout:
    """A layout in cell indices (``row * cols + col``) for one knowledge base."""

    layout: Layout
    start: int
    hazard_cells: frozenset[int]
    info_cells: tuple[int, int, int]  # indexed like INFO_TYPES
    info_places: tuple[str, str, str]


#: Ten layouts. Hazards sit between the start and the information locations, so a planner
#: that cannot see them walks into them; every location stays reachable on safe cells.
LAYOUTS: tuple[Layout, ...] = (
    Layout("bakery_fire", "sports hall",
           {"bakery": "fire", "pharmacy": "fire", "bus station": "smoke", "hardware store": "gas leak"},
           {"victim": "post office", "hazard": "cafe", "safe_route": "church"}),
    Layout("gas_west", "water tower",
           {"garage": "gas leak", "hardware store": "gas leak", "supermarket": "collapse", "cafe": "smoke"},
           {"victim": "library", "hazard": "bus station", "safe_route": "hotel"}),
    Layout("south_flood", "town hall",
           {"park": "flooding", "sports hall": "flooding", "bus station": "flooding", "church": "collapse"},
           {"victim": "apartment block", "hazard": "garage", "safe_route": "clinic"}),
    Layout("chemical_east", "warehouse",
           {"pharmacy": "chemical spill", "clinic": "chemical spill", "cafe": "smoke", "hotel": "fire"},
           {"victim": "fire station", "hazard": "supermarket", "safe_route": "school"}),
    Layout("square_collapse", "park",
           {"market square": "collapse", "post office": "live wires", "police station": "fire"},
           {"victim": "school", "hazard": "hotel", "safe_route": "pharmacy"}),
    Layout("north_fire", "apartment block",
           {"library": "fire", "school": "fire", "church": "smoke", "supermarket": "collapse"},
           {"victim": "town hall", "hazard": "bakery", "safe_route": "bank"}),
    Layout("live_wires", "fire station",
           {"bus station": "live wires", "supermarket": "live wires", "cafe": "fire", "hotel": "collapse"},
           {"victim": "park", "hazard": "police station", "safe_route": "hardware store"}),
    Layout("smoke_plume", "bank",
           {"bakery": "smoke", "cafe": "smoke", "garage": "fire", "clinic": "gas leak"},
           {"victim": "water tower", "hazard": "post office", "safe_route": "sports hall"}),
    Layout("warehouse_rubble", "pharmacy",
           {"warehouse": "collapse", "church": "collapse", "supermarket": "fire", "school": "smoke"},
           {"victim": "hotel", "hazard": "library", "safe_route": "park"}),
    Layout("gas_bottles", "school",
           {"hardware store": "gas leak", "garage": "fire", "post office": "live wires", "clinic": "flooding"},
           {"victim": "police station", "hazard": "church", "safe_route": "apartment block"}),
)


def _reachable(start: int, blocked: frozenset[int], rows: int, cols: int) -> set[int]:
    seen = {start}
    todo = deque([start])
    while todo:
        cell = todo.popleft()
        r, c = divmod(cell, cols)
        for dr, dc in MOVE_DELTAS:
            nr, nc = r + dr, c + dc
            nxt = nr * cols + nc
            if 0 <= nr < rows and 0 <= nc < cols and nxt not in blocked and nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen


def resolve_layouts(kb: KnowledgeBase, layouts: tuple[Layout, ...] = LAYOUTS) -> tuple[ResolvedLayout, ...]:
    """Cell indices of every layout; raise :class:`LuciferError` naming the layout and rule."""
    from lucifer.clients.envs.core.constants import INFO_TYPES

    out: list[ResolvedLayout] = []
    for lay in layouts:
        def cells(place: str, lay: Layout = lay) -> list[int]:
            if place not in kb.landmark_by_name:
                raise LuciferError(f"layout {lay.name!r}: place {place!r} is not a landmark of {kb.root}")
            return [r * kb.cols + c for r, c in kb.landmark_by_name[place].cells]

        hazard_cells = frozenset(c for place in lay.hazards for c in cells(place))
        start = cells(lay.start)[0]
        info_cells = tuple(cells(lay.info[t])[0] for t in INFO_TYPES)
        if start in hazard_cells or any(c in hazard_cells for c in info_cells):
            raise LuciferError(f"layout {lay.name!r}: the start or an information location is a hazard")
        if len({start, *info_cells}) != 4:
            raise LuciferError(f"layout {lay.name!r}: start and information locations must be distinct")
        reach = _reachable(start, hazard_cells, kb.rows, kb.cols)
        if not all(c in reach for c in info_cells):
            raise LuciferError(f"layout {lay.name!r}: an information location is unreachable on safe cells")
        out.append(ResolvedLayout(lay, start, hazard_cells, info_cells,  # type: ignore[arg-type]
                                  tuple(lay.info[t] for t in INFO_TYPES)))  # type: ignore[arg-type]
    return tuple(out)

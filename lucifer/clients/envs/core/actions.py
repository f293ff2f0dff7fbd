"""Action enum of the SAR grid world, in the style of ``minigrid.core.actions``."""

from __future__ import annotations

from enum import IntEnum


class Actions(IntEnum):
    """Movement and mission actions. Query actions follow as ``QUERY_0 + k``.

    Action ``QUERY_0 + k`` runs the k-th query option of the knowledge base
    (``knowledge_base/query_options.yaml`` order) at the agent's information location.
    """

    north = 0  # row - 1
    south = 1  # row + 1
    west = 2  # col - 1
    east = 3  # col + 1
    done = 4  # transmit the situation report: ends the mission once all types are collected
    QUERY_0 = 5


N_MOVES = 4
#: (d_row, d_col) of each movement action
MOVE_DELTAS: tuple[tuple[int, int], ...] = ((-1, 0), (1, 0), (0, -1), (0, 1))

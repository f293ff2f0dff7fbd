"""Building blocks of the SAR testbed: actions, constants, layouts and radio reports."""

from lucifer.clients.envs.core.actions import MOVE_DELTAS, N_MOVES, Actions
from lucifer.clients.envs.core.constants import INFO_TYPE_INDEX, INFO_TYPES
from lucifer.clients.envs.core.layouts import LAYOUTS, Layout, ResolvedLayout, resolve_layouts
from lucifer.clients.envs.core.reports import STYLES, briefing_reports, info_report

__all__ = [
    "INFO_TYPES",
    "INFO_TYPE_INDEX",
    "LAYOUTS",
    "MOVE_DELTAS",
    "N_MOVES",
    "STYLES",
    "Actions",
    "Layout",
    "ResolvedLayout",
    "briefing_reports",
    "info_report",
    "resolve_layouts",
]

"""Constants shared by the SAR environment and its clients."""

from __future__ import annotations

#: The mission's three required information types, in observation order.
INFO_TYPES: tuple[str, str, str] = ("victim", "hazard", "safe_route")
INFO_TYPE_INDEX: dict[str, int] = {t: i for i, t in enumerate(INFO_TYPES)}

#: Default number of failed query attempts after which an information location goes silent.
MAX_QUERIES_PER_LOCATION = 15

# Rewards (the env's own; clients may shape on top of them).
REWARD_MOVE = -0.01
REWARD_COLLISION = -1.0
REWARD_WRONG_QUERY = -0.05
REWARD_COLLECT = 0.3
REWARD_SUCCESS = 1.0

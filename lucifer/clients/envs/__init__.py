"""Gymnasium environments of the LUCIFER testbed, registered on import.

>>> import gymnasium as gym, lucifer.clients.envs  # doctest: +SKIP
>>> env = gym.make("LuciferSAR-v0")  # doctest: +SKIP
"""

from __future__ import annotations

from gymnasium.envs.registration import register, registry

from lucifer.clients.envs.sar import SAREnv

ENV_IDS: dict[str, dict[str, object]] = {
    "LuciferSAR-v0": {"max_steps": 100},
    "LuciferSAR-S30-v0": {"max_steps": 30},
    "LuciferSAR-Novel-v0": {"max_steps": 100, "novel_signatures": True},
}


#: MiniGrid's lava crossing turned into a SAR mission (see :mod:`lucifer.clients.minigrid_client`)
LAVA_ID = "LuciferLavaSAR-v0"


def register_envs() -> None:
    for env_id, kwargs in ENV_IDS.items():
        if env_id not in registry:
            register(id=env_id, entry_point="lucifer.clients.envs.sar:SAREnv", kwargs=dict(kwargs))
    if LAVA_ID not in registry:
        register(id=LAVA_ID, entry_point="lucifer.clients.minigrid_client:LavaSARWrapper")


register_envs()

__all__ = ["ENV_IDS", "LAVA_ID", "SAREnv", "register_envs"]

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


def register_envs() -> None:
    for env_id, kwargs in ENV_IDS.items():
        if env_id not in registry:
            register(id=env_id, entry_point="lucifer.clients.envs.sar:SAREnv", kwargs=dict(kwargs))


register_envs()

__all__ = ["ENV_IDS", "SAREnv", "register_envs"]

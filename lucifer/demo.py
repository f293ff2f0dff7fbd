"""``lucifer demo``: one short SAR mission, end to end.

Radio reports stream in and are grounded one by one; after each, the Signal Contract is
rebuilt and the demo shows what changed (new hazards X_u, goals, the constraints U'(x) at
the team's position). The hybrid planner then runs the mission on the contract alone: at
each information location it asks discovery for u*, and it never reads a report. The run
ends with a summary and a PNG of the episode (hazards, constraints, potentials, path).
"""

from __future__ import annotations

import argparse
import asyncio
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

MOVE_NAMES = ("north", "south", "west", "east")


def _place(env: Any, cell: int) -> str:
    return env.cell_labels().get(cell, f"cell {divmod(cell, env.cols)}")


def _cells(env: Any, flags: list[bool]) -> list[str]:
    names = dict.fromkeys(_place(env, c) for c, f in enumerate(flags) if f)
    return list(names)


async def run_demo(kb: str | None = None, seed: int = 0, out: str | Path = "out/demo",
                   write: Any = print, model: str = "builtin", grounder: Any = None,
                   discoverer: Any = None) -> dict[str, Any]:
    """Run the demo mission; returns a summary dict (also printed through ``write``).

    ``grounder`` / ``discoverer`` replace the real backends (tests).
    """
    from lucifer.clients.envs.sar import SAREnv
    from lucifer.clients.middleware import Middleware
    from lucifer.clients.planner import HybridPlanner
    from lucifer.evals.ablation import picture_of, prior_missions
    from lucifer.kb import load_kb

    t0 = time.perf_counter()
    kbo = load_kb(kb)
    env = SAREnv(kbo, max_steps=100)
    out_dir = Path(out)
    out_dir.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="lucifer-demo-") as tmp:
        mw = Middleware(kbo, grounding=True, discovery=True, model=model, trace_grounding=True,
                        record_outcomes=True, memory=os.path.join(tmp, "telemetry.sqlite"),
                        grounder=grounder, discoverer=discoverer)
        mw.record_many(prior_missions(env, np.random.default_rng(seed)), client="demo-prior")
        rng = np.random.default_rng(seed)
        options = {"layout": seed % len(env.layouts), "style": "messy"}
        _, info = env.reset(seed=seed, options=options)
        lay = env.layout
        write(f"LUCIFER demo: mission '{lay.layout.name}' on {kbo.root.name} ({kbo.rows}x{kbo.cols}), "
              f"team at the {_place(env, env.agent)}")
        write("information to collect: " + ", ".join(
            f"{t} at the {_place(env, c)}" for t, c in zip(("victim", "hazard", "safe route"), lay.info_cells, strict=True)))
        write("")
        write("1. reports stream in; the contract updates after each")
        reports: list[str] = []
        prev: Any = None
        for text in info["reports"]:
            reports.append(text)
            res = await mw.ground(text)
            sig = await mw.signals(reports)
            claims = ", ".join(f"{o.location}: {o.category}" for o in res.objects) or "nothing groundable"
            write(f"  radio> {text}")
            write(f"    grounded [{claims}]  trace {res.trace_id}")
            new_h = [p for p in _cells(env, sig.hazard) if prev is None or p not in _cells(env, prev.hazard)]
            new_g = [p for p in _cells(env, sig.goal) if prev is None or p not in _cells(env, prev.goal)]
            here = env.agent
            blocked = [MOVE_NAMES[a] for a in range(4) if env.next_cell[here][a] >= 0 and not sig.admissible[here][a]]
            write(f"    contract v{sig.version}: +X_u {new_h or '-'}  +goals {new_g or '-'}  "
                  f"Φ(here)={sig.phi[here]:+.2f}  U'(here) excludes {blocked or 'nothing'}")
            prev = sig
        write("")
        write("2. the hybrid planner runs the mission on contract signals only (+D+G)")
        planner = HybridPlanner(env, mw, rng)
        shown = len(reports)

        def show(event: str, payload: dict[str, Any]) -> None:
            nonlocal shown
            if event == "signals" and len(payload["reports"]) > shown:
                for text in payload["reports"][shown:]:
                    objs = mw._ground_cache[text].objects
                    write(f"  radio> {text}  -> [{', '.join(f'{o.location}: {o.category}' for o in objs)}]")
                shown = len(payload["reports"])
            if event == "discover":
                adv = payload["advice"]
                write(f"  at the {_place(env, env.agent)}: discovery u* = {adv.option} "
                      f"(confidence {adv.confidence:.2f})")

        mw.observer = show
        ep = await planner.run_episode(seed=seed, record_path=True, options=options)
        mw.observer = None
        n_rec = mw.flush()
        write(f"  the client appended {n_rec} query outcomes to telemetry memory")
        await mw.aclose()
        png = await picture_of(env, mw, ep, out_dir / "demo.png",
                               title=f"demo: {lay.layout.name}, {'mission complete' if ep.success else 'mission failed'}, "
                                     f"{ep.collisions} collisions")
    summary = {
        "mission": lay.layout.name,
        "success": ep.success,
        "collisions": ep.collisions,
        "steps": ep.steps,
        "queries": ep.queries,
        "correct_queries": ep.correct_queries,
        "reports": len(env.episode_reports()),
        "png": str(png),
        "wall_s": round(time.perf_counter() - t0, 1),
    }
    write("")
    write("3. summary")
    write(f"  mission {'COMPLETE' if ep.success else 'FAILED'} in {ep.steps} steps, "
          f"{ep.collisions} hazard collisions, {ep.correct_queries}/{ep.queries} queries right, "
          f"{summary['reports']} reports grounded")
    write(f"  picture: {png}")
    return summary


def cmd_demo(args: argparse.Namespace) -> int:
    summary = asyncio.run(run_demo(kb=args.kb, seed=args.seed, out=args.out,
                                   write=lambda s: print(s, flush=True)))
    return 0 if summary["success"] and summary["collisions"] == 0 else 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(cmd_demo(argparse.Namespace(kb=None, seed=0, out="out/demo")))

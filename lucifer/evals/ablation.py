"""System-level ablation (SPEC §5): baseline / +G / +D / +D+G for one client.

``lucifer eval ablation --client rl|planner|minigrid [--runs 40] [--episodes 1000] [--seed 0]
[--json OUT] [--charts DIR]``

Protocol:

1. The parent process builds the client's environment and one middleware with the real
   grounder and discoverer. Telemetry memory is a fresh SQLite file seeded with *prior
   missions* (a past team at every location signature the environment can show, trying
   queries until one worked), so discovery has the experience that telemetry gives it in
   the field. The parent then grounds every distinct report and asks discovery at every
   distinct signature once (concurrently); identical requests are answered from that cache.
2. ``runs`` × 4 configurations are spread over a pool of worker processes (2 by default).
   Run ``i`` uses the same seed in every configuration (paired comparison): seed sequence
   ``(seed, i)`` drives the environment's layouts and the client's randomness.
3. Per run: MSR = missions completed / episodes, CSR = correct query decisions / all query
   decisions, SMS = missions completed with no hazard collision / episodes (percent).
   Reported as ``[mean, std]`` across runs.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import pickle
import sys
import tempfile
import time
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from lucifer.clients.common import CONFIGS, RunResult, flags, mean_std
from lucifer.kb import KnowledgeBase, load_kb

# --------------------------------------------------------------------------- clients


@dataclass
class Prepared:
    """Everything a process needs to run one client: its KB, env and client factories."""

    kb: KnowledgeBase
    make_env: Callable[[], Any]
    make_client: Callable[[Any, Any, np.random.Generator], Any]
    default_episodes: int | None = None


def _prepare_rl(kb_arg: str | None) -> Prepared:
    from lucifer.clients.envs.sar import SAREnv
    from lucifer.clients.hierq import HierQ, rl_env_kwargs

    kb = load_kb(kb_arg)
    return Prepared(kb, lambda: SAREnv(kb, **rl_env_kwargs()), HierQ)


def _prepare_planner(kb_arg: str | None) -> Prepared:
    from lucifer.clients.envs.sar import SAREnv
    from lucifer.clients.planner import HybridPlanner, planner_env_kwargs

    kb = load_kb(kb_arg)
    return Prepared(kb, lambda: SAREnv(kb, **planner_env_kwargs()), HybridPlanner)


def _prepare_minigrid(kb_arg: str | None) -> Prepared:
    from lucifer.clients.minigrid_client import prepare_minigrid

    return prepare_minigrid(kb_arg)


CLIENTS: dict[str, Callable[[str | None], Prepared]] = {
    "rl": _prepare_rl,
    "planner": _prepare_planner,
    "minigrid": _prepare_minigrid,
}

# --------------------------------------------------------------------------- workers

_WORKER: dict[str, Any] = {}


def _init_worker(client: str, kb_arg: str | None, cache_dir: str, memory: str, model: str) -> None:
    _WORKER.clear()
    _WORKER.update(client=client, kb_arg=kb_arg, cache_dir=cache_dir, memory=memory, model=model, mws={})
    _WORKER["prepared"] = CLIENTS[client](kb_arg)


def _middleware(config: str) -> Any:
    """This process's middleware for ``config``; grounding/discovery answers come from the warm cache."""
    from lucifer.clients.middleware import Middleware

    mws = _WORKER["mws"]
    if config not in mws:
        g, d = flags(config)
        mw = Middleware(_WORKER["prepared"].kb, grounding=g, discovery=d, memory=_WORKER["memory"],
                        model=_WORKER["model"], **_WORKER.get("backends", {}))
        # Each part of the warm cache is read when a configuration first needs it, so runs that
        # need less (the baseline: nothing; +D: discovery only) start while the parent warms.
        for part, needed in (("advice", d), ("ground", g)):
            if needed:
                if part not in _WORKER:
                    _WORKER[part] = _read_part(os.path.join(_WORKER["cache_dir"], f"{part}.pkl"))
                mw.import_cache({part: _WORKER[part]})
        mws[config] = mw
    return mws[config]


def _read_part(path: str, timeout_s: float = 900.0) -> Any:
    """A warm-cache part, waiting for the parent to publish it (it is written atomically)."""
    deadline = time.monotonic() + timeout_s
    while not os.path.exists(path):
        if time.monotonic() > deadline:
            raise TimeoutError(f"warm-up cache {path} never appeared")
        time.sleep(0.05)
    with open(path, "rb") as fh:
        return pickle.load(fh)


def run_seeds(seed: int, run: int) -> tuple[int, np.random.Generator]:
    """(first env reset seed, client rng) of run ``run`` under ``--seed seed``; same for every config."""
    ss = np.random.SeedSequence([seed, run])
    env_ss, client_ss = ss.spawn(2)
    return int(env_ss.generate_state(1)[0]), np.random.default_rng(client_ss)


async def _run(prepared: Prepared, mw: Any, seed: int, run: int, episodes: int, curve: bool) -> dict[str, Any]:
    env = prepared.make_env()
    env_seed, rng = run_seeds(seed, run)
    client = prepared.make_client(env, mw, rng)
    n = succ = safe = queries = correct = 0
    outcomes: list[int] = []
    for i in range(episodes):
        ep = await client.run_episode(seed=env_seed if i == 0 else None)
        n += 1
        succ += ep.success
        safe += ep.safe_success
        queries += ep.queries
        correct += ep.correct_queries
        if curve:
            outcomes.append(int(ep.success))
    r = RunResult.from_counts(n, succ, safe, queries, correct)
    return {"msr": r.msr, "csr": r.csr, "sms": r.sms, "curve": outcomes}


def _batch(tasks: list[tuple[str, int, int, int, bool]]) -> list[tuple[str, int, dict[str, Any]]]:
    """Several runs in one worker, in order."""
    return [_task(*t) for t in tasks]


def _task(config: str, seed: int, run: int, episodes: int, curve: bool) -> tuple[str, int, dict[str, Any]]:
    t0 = time.perf_counter()
    mw = _middleware(config)
    before = dict(mw.calls)
    out = asyncio.run(_run(_WORKER["prepared"], mw, seed, run, episodes, curve))
    out["wall_s"] = time.perf_counter() - t0
    out["calls"] = {k: v - before[k] for k, v in mw.calls.items()}
    return config, run, out


# --------------------------------------------------------------------------- parent


def prior_missions(env: Any, rng: np.random.Generator) -> list[tuple[str, str, float]]:
    """Telemetry of a past team at every signature the env can show: random queries until one worked."""
    records: list[tuple[str, str, float]] = []
    options = list(env.query_options)
    for k, pool in enumerate(env.signature_pool()):
        for sig in pool:
            for j in rng.permutation(len(options)):
                records.append((sig, options[int(j)], 1.0 if int(j) == k else 0.0))
                if int(j) == k:
                    break
    return records


async def _warm(mw: Any, env: Any, cache_dir: str, on_part: Callable[[str], None], concurrency: int = 8) -> None:
    """Discovery first (fast), then grounding; each part is written as soon as it is complete."""
    reports, sigs = env.distinct_texts()
    try:
        for part, texts in (("advice", ([], sigs)), ("ground", (reports, []))):
            await mw.warm(*texts, concurrency=concurrency)
            final = os.path.join(cache_dir, f"{part}.pkl")
            with open(final + ".tmp", "wb") as fh:
                pickle.dump(mw.export_cache()[part], fh)
            os.replace(final + ".tmp", final)  # readers never see half a file
            on_part(part)
    finally:
        await mw.aclose()


def run_ablation(
    client: str,
    *,
    kb: str | None = None,
    runs: int = 40,
    episodes: int = 1000,
    seed: int = 0,
    workers: int | None = None,
    model: str = "builtin",
    memory: str | None = None,
    curves: bool = False,
    progress: Callable[[str], None] | None = None,
    grounder: Any = None,
    discoverer: Any = None,
) -> dict[str, Any]:
    """Run the four configurations and return the SPEC §5 result (plus ``extra`` details).

    ``grounder`` / ``discoverer`` replace the real backends (tests); they are used in this
    process only, so pass them with ``workers=1``.
    """
    if client not in CLIENTS:
        raise ValueError(f"unknown client {client!r}; choose from {', '.join(CLIENTS)}")
    say = progress or (lambda s: None)
    t0 = time.perf_counter()
    prepared = CLIENTS[client](kb)
    env = prepared.make_env()

    from lucifer.clients.middleware import Middleware

    tmp = None
    if memory is None:
        tmp = tempfile.TemporaryDirectory(prefix="lucifer-ablation-")
        memory = os.path.join(tmp.name, "telemetry.sqlite")
    try:
        cache_dir = tmp.name if tmp else tempfile.mkdtemp(prefix="lucifer-ablation-")
        results: dict[str, list[dict[str, Any]]] = {c: [{}] * runs for c in CONFIGS}
        n_workers = workers or min(2, os.cpu_count() or 1)
        tasks = [(cfg, seed, r, episodes, curves and r == 0) for r in range(runs) for cfg in CONFIGS]
        # Scheduling: the runs that need no grounding (baseline, +D) go to one worker as a single
        # batch at once (+D waits there for the discovery part of the cache, which comes first),
        # leaving the other core to the warm-up; the grounding runs go to both workers after it.
        early = [t for t in tasks if t[0] in ("baseline", "+D")]
        late = [t for t in tasks if t[0] not in ("baseline", "+D")]
        mw = Middleware(prepared.kb, grounding=True, discovery=True, memory=memory, model=model,
                        grounder=grounder, discoverer=discoverer)

        def warm(submit: Callable[[str], None]) -> float:
            mw.record_many(prior_missions(env, np.random.default_rng(seed)), client=f"{client}-prior")
            asyncio.run(_warm(mw, env, cache_dir, submit))
            s = time.perf_counter() - t0
            say(f"warm-up: {mw.calls['ground']} reports grounded, {mw.calls['discover']} signatures "
                f"discovered in {s:.1f}s")
            return s

        if n_workers <= 1:
            warm_s = warm(lambda part: None)
            _init_worker(client, kb, cache_dir, memory, model)
            _WORKER["backends"] = {"grounder": grounder, "discoverer": discoverer}
            for t in tasks:
                cfg, r, out = _task(*t)
                results[cfg][r] = out
        else:
            import multiprocessing as mp

            ctx = mp.get_context("spawn")
            with ProcessPoolExecutor(n_workers, mp_context=ctx, initializer=_init_worker,
                                     initargs=(client, kb, cache_dir, memory, model)) as pool:

                nb = max(1, n_workers - 1)
                batches = [pool.submit(_batch, early[i::nb]) for i in range(nb)]
                warm_s = warm(lambda part: None)
                futs = [pool.submit(_task, *t) for t in late]
                for i, f in enumerate(futs, 1):
                    cfg, r, out = f.result()
                    results[cfg][r] = out
                    if i % max(1, len(futs) // 4) == 0:
                        say(f"  {i}/{len(futs)} grounding runs done ({time.perf_counter() - t0:.0f}s)")
                for b in batches:
                    for cfg, r, out in b.result():
                        results[cfg][r] = out
    finally:
        if tmp is not None:
            tmp.cleanup()

    configs = {
        cfg: {m: mean_std([o[m] for o in results[cfg]]) for m in ("msr", "csr", "sms")} for cfg in CONFIGS
    }
    out: dict[str, Any] = {
        "client": client,
        "runs": runs,
        "episodes": episodes,
        "wall_s": round(time.perf_counter() - t0, 1),
        "configs": configs,
    }
    out["extra"] = {
        "warm_s": round(warm_s, 1),
        "workers": n_workers,
        "middleware_calls_warm": dict(mw.calls),
        "middleware_calls_runs": {
            cfg: {k: sum(o["calls"][k] for o in results[cfg]) for k in ("ground", "discover", "contract")}
            for cfg in CONFIGS
        },
        "pattern": check_pattern(configs),
    }
    if curves:
        out["extra"]["curves"] = {cfg: results[cfg][0]["curve"] for cfg in CONFIGS}
    return out


def check_pattern(configs: dict[str, dict[str, list[float]]]) -> dict[str, bool]:
    """The paper's system-level pattern, claim by claim.

    >>> c = {"baseline": {"msr": [50, 0], "csr": [10, 0], "sms": [20, 0]},
    ...      "+G": {"msr": [55, 0], "csr": [10, 0], "sms": [55, 0]},
    ...      "+D": {"msr": [70, 0], "csr": [99.5, 0], "sms": [40, 0]},
    ...      "+D+G": {"msr": [80, 0], "csr": [99.6, 0], "sms": [80, 0]}}
    >>> all(check_pattern(c).values())
    True
    """
    b, g, d, dg = (configs[c] for c in CONFIGS)
    return {
        "+G: SMS equals MSR": g["sms"][0] == g["msr"][0],
        "+G: SMS above baseline": g["sms"][0] > b["sms"][0],
        "+D: CSR >= 99": d["csr"][0] >= 99.0,
        "+D+G: CSR >= 99": dg["csr"][0] >= 99.0,
        "+D+G: best MSR": dg["msr"][0] >= max(c["msr"][0] for c in configs.values()),
        "+D+G: best SMS": dg["sms"][0] >= max(c["sms"][0] for c in configs.values()),
        "+D+G: SMS equals MSR": dg["sms"][0] == dg["msr"][0],
    }


def format_table(result: dict[str, Any]) -> str:
    """A markdown table of the result."""
    lines = [
        f"| {result['client']} | MSR | CSR | SMS |",
        "|---|---|---|---|",
    ]
    for cfg, m in result["configs"].items():
        lines.append(f"| {cfg} | " + " | ".join(f"{m[k][0]:.1f} ± {m[k][1]:.1f}" for k in ("msr", "csr", "sms")) + " |")
    return "\n".join(lines)


def write_charts(result: dict[str, Any], directory: str | Path, kb: str | None = None, seed: int = 0) -> list[Path]:
    """The bar chart, the learning curves (if any) and one +D+G episode picture."""
    from lucifer.clients.plots import plot_ablation, plot_curves

    d = Path(directory)
    name = result["client"]
    paths = [plot_ablation(d / f"ablation_{name}.png", result)]
    curves = result.get("extra", {}).get("curves")
    if curves and name == "rl":  # only the learning client has a curve worth drawing
        paths.append(plot_curves(d / f"curves_{name}.png", curves, f"{name}: run 0, success per 50 episodes"))
    paths.append(asyncio.run(episode_picture(name, d / f"episode_{name}.png", kb=kb, seed=seed)))
    return paths


async def episode_picture(client: str, png: str | Path, *, kb: str | None = None, seed: int = 0, train: int = 1000) -> Path:
    """Train the client briefly under +D+G, then draw one recorded episode."""
    from lucifer.clients.middleware import Middleware

    prepared = CLIENTS[client](kb)
    env = prepared.make_env()
    with tempfile.TemporaryDirectory(prefix="lucifer-picture-") as tmp:
        memory = os.path.join(tmp, "telemetry.sqlite")
        mw = Middleware(prepared.kb, grounding=True, discovery=True, memory=memory)
        mw.record_many(prior_missions(env, np.random.default_rng(seed)))
        env_seed, rng = run_seeds(seed, 0)
        c = prepared.make_client(env, mw, rng)
        for i in range(train if hasattr(c, "q_nav") else 0):
            await c.run_episode(seed=env_seed if i == 0 else None)
        if hasattr(c, "epsilon"):
            c.epsilon = 0.0
        ep = await c.run_episode(seed=env_seed + 1, record_path=True)
        await mw.aclose()
        return await picture_of(env, mw, ep, png, title=f"{client} +D+G: {ep.layout}, "
                                f"{'success' if ep.success else 'failure'}, {ep.collisions} collisions, "
                                f"{ep.correct_queries}/{ep.queries} queries right")


async def picture_of(env: Any, mw: Any, ep: Any, png: str | Path, title: str) -> Path:
    """Draw an episode of a SAR-like env with the contract after its reports."""
    from lucifer.clients.plots import plot_episode

    u = env
    sig = await mw.signals(u.episode_reports())
    names = {cell: name for cell, name in u.cell_labels().items()}
    return plot_episode(
        png, rows=u.rows, cols=u.cols, phi=sig.phi, admissible=sig.admissible, believed_hazards=sig.hazard,
        true_hazards=sorted(u.layout.hazard_cells), info_cells=u.layout.info_cells, start=u.layout.start,
        path=ep.path, labels=names, title=title,
    )


# --------------------------------------------------------------------------- CLI


def cmd_eval_ablation(args: argparse.Namespace) -> int:
    def say(s: str) -> None:
        print(s, file=sys.stderr, flush=True)

    say(f"ablation: client {args.client}, {args.runs} runs x {args.episodes} episodes, 4 configurations")
    result = run_ablation(args.client, kb=args.kb, runs=args.runs, episodes=args.episodes, seed=args.seed,
                          curves=bool(getattr(args, "charts", None)), progress=say)
    print(format_table(result))
    print(f"wall_s: {result['wall_s']}")
    for claim, ok in result["extra"]["pattern"].items():
        print(f"  [{'x' if ok else ' '}] {claim}")
    if args.json_out:
        Path(args.json_out).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json_out).write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
        say(f"wrote {args.json_out}")
    if getattr(args, "charts", None):
        for p in write_charts(result, args.charts, kb=args.kb, seed=args.seed):
            say(f"wrote {p}")
    return 0

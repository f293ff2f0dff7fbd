"""``lucifer eval backends``: the README backends table (the paper's Table 1 analogue).

One command regenerates ``backends.json``, ``backends.md`` and ``backends.png``:

* every backend (``builtin``, ``rule``, ``ner``, ``llamacpp:gemma3-270m``, ``llamacpp:smollm2``
  by default) grounds the held-out split (the headline), the dev split and Riverbend (a second
  KB), one report at a time, and is scored per regime with the Adjusted Accuracy of SPEC §3;
* the slow LLM backends see only the first ``--llm-limit`` reports of every regime;
* LLM backends run in a child process (``python -m lucifer.evals.backends --one MODEL``), because
  llama.cpp can take the whole process down; a crash, a timeout or a model that cannot load
  becomes an explicit ``unavailable: <reason>`` row, never an aborted table.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from collections import Counter
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from lucifer.evals.grounding import REGIMES, DatasetRow, _aggregate, evaluate, load_dataset
from lucifer.models import is_builtin

DEFAULT_BACKENDS = ("builtin", "rule", "ner", "llamacpp:gemma3-270m", "llamacpp:smollm2")
REPO_ROOT = Path(__file__).resolve().parents[2]
DATASETS = REPO_ROOT / "datasets" / "grounding"
RIVERBEND_KB = REPO_ROOT / "knowledge_bases" / "riverbend"

#: Table 1 of the LUCIFER paper (its own dataset): adjusted accuracy standard / messy / advanced.
PAPER: dict[str, dict[str, float]] = {
    "Qwen3 8B": {"standard": 97.0, "messy": 100.0, "advanced_messy": 91.0},
    "rule-based": {"standard": 75.3, "messy": 20.8, "advanced_messy": 22.5},
    "FLAIR NER+keywords": {"standard": 91.7, "messy": 72.0, "advanced_messy": 36.7},
}

#: This many first reports ending in nothing but model failures mark the backend unavailable.
FAIL_FAST_N = 3
MODEL_FAILURES = ("llm_unavailable", "llm_error", "llm_timeout")
#: Seconds one LLM backend may spend over all splits: no report is started after that (the row
#: is then ``partial`` and says how many reports each cell scored). On 2 shared CPU cores a
#: 270M-parameter model needs 10-40 s per report, so --llm-limit 30 over three splits would
#: take hours; the budget keeps `lucifer eval backends` to well under an hour.
LLM_BUDGET_S = 720.0
#: Seconds one chat-model call may take before that report falls back to builtin.
LLM_CALL_TIMEOUT_S = 180.0
#: Extra seconds the parent waits past the budget (model load, the last report) before killing.
LLM_GRACE_S = 3 * LLM_CALL_TIMEOUT_S + 300.0
WARMUP_REPORT = "Radio check, over."
REGIME_SHORT = {"standard": "std", "messy": "messy", "advanced_messy": "adv"}


@dataclass(frozen=True)
class Split:
    """One evaluation split: its name, the KB it is grounded against and its JSONL files."""

    name: str
    kb: str
    files: tuple[str, ...]
    label: str = ""


def default_splits(kb: str | None = None) -> list[Split]:
    """Held-out (headline), dev and Riverbend, with the KB each is annotated against."""
    from lucifer.kb import resolve_kb_dir

    main_kb = str(resolve_kb_dir(kb))
    return [
        Split("heldout", main_kb, tuple(str(DATASETS / "heldout" / f"{g}.jsonl") for g in REGIMES),
              "held-out (hand-written, never tuned against)"),
        Split("dev", main_kb, tuple(str(DATASETS / f"{g}.jsonl") for g in REGIMES), "dev"),
        Split("riverbend", str(RIVERBEND_KB), (str(DATASETS / "riverbend.jsonl"),), "Riverbend (second KB)"),
    ]


def first_per_regime(rows: list[DatasetRow], limit: int | None) -> list[DatasetRow]:
    """The first ``limit`` rows of every regime, in file order (all rows when ``limit`` is falsy)."""
    if not limit:
        return list(rows)
    taken: Counter[str] = Counter()
    out = []
    for r in rows:
        if taken[r.regime] < limit:
            taken[r.regime] += 1
            out.append(r)
    return out


def is_llm(model: str) -> bool:
    return not is_builtin(model)


# --------------------------------------------------------------------------- one backend
def _unavailable(model: str, reason: str, limit: int | None, **extra: Any) -> dict[str, Any]:
    return {"backend": model, "status": "unavailable", "reason": reason, "limit": limit, "splits": {}} | extra


async def _preflight(grounder: Any, chat: Any = None) -> str | None:
    """Load the backend (and warm a builtin one up); return why it cannot run, or None.

    An LLM backend is only loaded (``chat`` is one already loaded for an earlier split): a
    throw-away generation could take minutes of the time budget, and a report that times out
    is scored as the fallback it became, not as a missing backend.
    """
    if is_llm(grounder.model):
        from lucifer.models import load_chat_model

        try:
            grounder.resources._chat_model = chat or load_chat_model(grounder.model, grounder.base_url,
                                                                     grounder.timeout_s)
        except Exception as exc:  # recorded as the row's reason
            return f"{type(exc).__name__}: {exc}"
        return None
    try:
        res = await grounder.ground(WARMUP_REPORT, report_id="warmup")
    except Exception as exc:  # recorded as the row's reason
        return f"{type(exc).__name__}: {exc}"
    if res.status.value in MODEL_FAILURES:
        return (res.errors[0] if res.errors else res.status.value)[:300]
    return None


def round_robin(rows: list[DatasetRow]) -> list[DatasetRow]:
    """Interleave regimes (1st standard, 1st messy, 1st advanced, 2nd standard, ...).

    A run cut short by its time budget then has about as many reports in every regime.
    """
    by_regime: dict[str, list[DatasetRow]] = {}
    for r in rows:
        by_regime.setdefault(r.regime, []).append(r)
    queues = list(by_regime.values())
    out = []
    for i in range(max((len(q) for q in queues), default=0)):
        out += [q[i] for q in queues if i < len(q)]
    return out


class _ErrorRecorder:
    """Passes ``ground`` through to a Grounder and keeps the backend's error messages."""

    def __init__(self, grounder: Any):
        self.grounder = grounder
        self.model = grounder.model
        self.errors: list[str] = []

    async def ground(self, text: str, report_id: str | None = None) -> Any:
        res = await self.grounder.ground(text, report_id=report_id)
        self.errors += [f"{report_id}: {e}"[:300] for e in res.errors]
        return res


def _split_result(results: list[Any], planned: list[DatasetRow], wall_s: float) -> dict[str, Any]:
    by_regime: dict[str, list[Any]] = {}
    for r in results:
        by_regime.setdefault(r.row.regime, []).append(r)
    order = [g for g in REGIMES if g in by_regime] + sorted(set(by_regime) - set(REGIMES))
    regimes = {g: _aggregate(by_regime[g]) for g in order}
    regimes["overall"] = _aggregate(results)
    for g, n in Counter(r.regime for r in planned).items():
        if g in regimes:
            regimes[g]["planned"] = n
    regimes["overall"]["planned"] = len(planned)
    statuses = Counter(r.status for r in results)
    return {
        "regimes": regimes,
        "n": len(results),
        "planned": len(planned),
        "wall_s": round(wall_s, 3),
        "latency_mean_s": round(sum(r.latency_s for r in results) / len(results), 4) if results else 0.0,
        "statuses": dict(statuses),
        "fallbacks": sum(v for k, v in statuses.items() if k.startswith("llm_")),
        "errors": [f"{r.row.id}: {r.error}" for r in results if r.error][:5],
    }


async def run_backend(model: str, splits: list[Split], limit: int | None = None,
                      budget_s: float | None = None, on_progress: Any = None) -> dict[str, Any]:
    """Evaluate one backend in this process, one report at a time, split after split.

    ``limit`` keeps the first reports of every regime; within a split the regimes are
    interleaved, and once ``budget_s`` seconds have passed no further report is started (the
    row is then ``partial`` and every cell says how many reports it scored).
    ``on_progress(row)`` is called with the row so far after every split and every 10 reports.
    """
    from lucifer.grounding import Grounder

    t_start = time.perf_counter()
    out: dict[str, Any] = {"backend": model, "status": "ok", "reason": None, "limit": limit,
                           "budget_s": budget_s, "splits": {}}
    chat = None
    for split in splits:
        try:
            rows = round_robin(first_per_regime(load_dataset(list(split.files)), limit))
            g = Grounder(split.kb, model=model, trace=False,
                         timeout_s=LLM_CALL_TIMEOUT_S if is_llm(model) else None)
        except Exception as exc:  # a backend or KB that cannot even start is a row, not a crash
            why = f"{type(exc).__name__}: {exc}"[:300]
            if out["splits"]:
                out["status"], out["reason"] = "partial", f"{split.name}: {why}"
                return _finish(out)
            return _unavailable(model, why, limit)
        try:
            why = await _preflight(g, chat)
            if why is not None:
                if out["splits"]:  # it ran before: keep what finished, say what did not
                    out["status"], out["reason"] = "partial", f"{split.name}: {why}"
                    return _finish(out)
                return _unavailable(model, why, limit)
            chat = g.resources._chat_model
            rec = _ErrorRecorder(g)
            results: list[Any] = []
            t0 = time.perf_counter()
            for row in rows:
                if budget_s is not None and time.perf_counter() - t_start > budget_s:
                    out["status"] = "partial"
                    out["reason"] = f"time budget of {budget_s:.0f} s reached"
                    break
                results += (await evaluate(rec, [row], 1)).results
                if len(results) == FAIL_FAST_N and all(r.status in MODEL_FAILURES for r in results):
                    break  # the model does not run; spending the budget on fallbacks tells nothing
                if on_progress is not None and len(results) % 10 == 0:
                    out["splits"][split.name] = _split_result(results, rows, time.perf_counter() - t0)
                    on_progress(_finish(out))
            if results and all(r.status in MODEL_FAILURES for r in results):
                out["splits"].pop(split.name, None)
                why = (rec.errors[0] if rec.errors else f"every report ended {results[0].status}")
                why = f"{why} (all {len(results)} reports tried fell back to builtin)"
                if not out["splits"]:
                    return _unavailable(model, why, limit, errors=rec.errors[:5])
                out["status"], out["reason"] = "partial", f"{split.name}: {why}"
                return _finish(out)
            split_errors = rec.errors[:5]
        finally:
            await g.aclose()
        if results:
            out["splits"][split.name] = _split_result(results, rows, time.perf_counter() - t0)
            out["splits"][split.name]["backend_errors"] = split_errors
        if on_progress is not None:
            on_progress(_finish(out))
        if out["status"] == "partial":
            break
    return _finish(out)


def _finish(row: dict[str, Any]) -> dict[str, Any]:
    """Add the per-report mean over every split and the fallback count."""
    splits = row.get("splits") or {}
    n = sum(s["n"] for s in splits.values())
    if n:
        row["s_per_report"] = round(sum(s["latency_mean_s"] * s["n"] for s in splits.values()) / n, 4)
        row["n"] = n
        row["fallbacks"] = sum(s["fallbacks"] for s in splits.values())
    return row


def run_backend_isolated(model: str, splits: list[Split], limit: int | None = None,
                         budget_s: float | None = LLM_BUDGET_S) -> dict[str, Any]:
    """Run :func:`run_backend` in a child process so a segfault or hang becomes a row.

    The child rewrites its result file as it goes, so a crash or a kill keeps what finished.
    """
    with tempfile.TemporaryDirectory(prefix="lucifer-backend-") as tmp:
        result_file = Path(tmp) / "result.json"
        cmd = [sys.executable, "-X", "faulthandler", "-m", "lucifer.evals.backends", "--one", model,
               "--splits", json.dumps([asdict(s) for s in splits]), "--result", str(result_file)]
        if limit:
            cmd += ["--limit", str(limit)]
        if budget_s is not None:
            cmd += ["--budget-s", str(budget_s)]
        timeout_s = None if budget_s is None else budget_s + LLM_GRACE_S
        t0 = time.perf_counter()
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout_s, cwd=REPO_ROOT)
            rc, stderr, why = proc.returncode, proc.stderr, None
        except subprocess.TimeoutExpired as exc:
            err = exc.stderr or b""
            rc, stderr = None, err.decode(errors="replace") if isinstance(err, bytes) else err
            why = f"killed after {timeout_s:.0f} s (hung)"
        wall = round(time.perf_counter() - t0, 1)
        partial = json.loads(result_file.read_text()) if result_file.is_file() else None
    tail = [ln for ln in (stderr or "").strip().splitlines() if ln.strip()][-6:]
    if rc is not None and rc < 0:
        try:
            name = signal.Signals(-rc).name
        except ValueError:
            name = "?"
        why = f"crashed (signal {-rc}, {name})"
    elif rc not in (None, 0):
        why = f"child exited with status {rc}: {tail[-1] if tail else 'no output'}"[:300]
    if why is None and partial is not None:
        return partial | {"wall_s": wall}
    if partial and partial.get("splits"):  # crashed or killed part-way: keep what finished
        done = ", ".join(f"{k} ({v['n']} reports)" for k, v in partial["splits"].items())
        return _finish(partial | {"status": "partial", "reason": f"{why} after {done}", "wall_s": wall,
                                  "stderr_tail": tail})
    return _unavailable(model, why or "no result written", limit, wall_s=wall, stderr_tail=tail)


# --------------------------------------------------------------------------- the table
def build_table(backends: list[str], splits: list[Split], llm_limit: int | None = 30,
                isolate_llm: bool = True, llm_budget_s: float | None = LLM_BUDGET_S,
                log: Any = None) -> dict[str, Any]:
    """Evaluate every backend; a backend that cannot run is an ``unavailable`` row."""
    rows = []
    t0 = time.perf_counter()
    for model in backends:
        t1 = time.perf_counter()
        if log:
            log(f"[backends] {model} ...")
        if is_llm(model):
            row = (run_backend_isolated(model, splits, llm_limit, llm_budget_s) if isolate_llm
                   else _run_guarded(model, splits, llm_limit, llm_budget_s))
        else:
            row = _run_guarded(model, splits, None)
        row.setdefault("wall_s", round(time.perf_counter() - t1, 1))
        rows.append(row)
        if log:
            log(f"[backends] {model}: {row['status']}{' (' + row['reason'] + ')' if row.get('reason') else ''}"
                f" in {row['wall_s']} s")
    return {
        "generated_at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "splits": [asdict(s) | {"files": [_rel(f) for f in s.files], "kb": _rel(s.kb)} for s in splits],
        "llm_limit": llm_limit,
        "llm_budget_s": llm_budget_s,
        "concurrency": 1,
        "machine": {"cpus": os.cpu_count(), "load_avg_1m": round(os.getloadavg()[0], 2)},
        "wall_s": round(time.perf_counter() - t0, 1),
        "backends": rows,
        "paper": PAPER,
    }


def _run_guarded(model: str, splits: list[Split], limit: int | None, budget_s: float | None = None,
                 on_progress: Any = None) -> dict[str, Any]:
    try:
        return asyncio.run(run_backend(model, splits, limit, budget_s, on_progress))
    except Exception as exc:  # one broken backend must not abort the table; its reason is the row
        return _unavailable(model, f"{type(exc).__name__}: {exc}"[:300], limit)


def _rel(p: str) -> str:
    try:
        return str(Path(p).resolve().relative_to(REPO_ROOT))
    except ValueError:
        return str(p)


def _acc(row: dict[str, Any], split: str, regime: str) -> float | None:
    s = (row.get("splits") or {}).get(split)
    if not s or regime not in s["regimes"]:
        return None
    return float(s["regimes"][regime]["adjusted_accuracy"])


def _fmt(v: float | None) -> str:
    return "—" if v is None else f"{v:.1f}"


def _cell(row: dict[str, Any], split: str, regime: str) -> str:
    """``81.2``, or ``40.0 (n=4/30)`` where the time budget cut the cell short."""
    v = _acc(row, split, regime)
    if v is None:
        return "—"
    m = row["splits"][split]["regimes"][regime]
    planned = m.get("planned", m["n"])
    return _fmt(v) + (f" (n={m['n']}/{planned})" if m["n"] < planned else "")


def render_markdown(table: dict[str, Any]) -> str:
    """The README table: held-out first (headline), then dev, Riverbend and seconds per report."""
    names = [s["name"] for s in table["splits"]]
    per_regime = [n for n in names if n != "riverbend"]
    head = ["backend"]
    for n in per_regime:
        label = "held-out" if n == "heldout" else n
        head += [f"{label} {REGIME_SHORT[g]}" for g in REGIMES]
    if "riverbend" in names:
        head.append("Riverbend")
    head += ["s / report", "notes"]
    lines = ["| " + " | ".join(head) + " |", "|" + "|".join(["---"] + ["---:"] * (len(head) - 2) + ["---"]) + "|"]
    limit = table.get("llm_limit")
    for row in table["backends"]:
        cells = [f"`{row['backend']}`"]
        if row["status"] == "unavailable":
            cells += ["—"] * (len(head) - 2) + [f"unavailable: {row['reason']}".replace("|", "/")]
            lines.append("| " + " | ".join(cells) + " |")
            continue
        for n in per_regime:
            cells += [_cell(row, n, g) for g in REGIMES]
        if "riverbend" in names:
            cells.append(_cell(row, "riverbend", "overall"))
        spr = row.get("s_per_report")
        cells.append("—" if spr is None else (f"{spr:.3f}" if spr < 10 else f"{spr:.1f}"))
        notes = []
        if row.get("limit"):
            notes.append(f"first {row['limit']} reports per regime")
        if is_llm(row["backend"]) and row.get("fallbacks"):
            notes.append(f"{row['fallbacks']}/{row.get('n', '?')} reports fell back to builtin")
        if row["status"] == "partial":
            notes.append(f"partial: {row['reason']}")
        cells.append("; ".join(notes).replace("|", "/") or "")
        lines.append("| " + " | ".join(cells) + " |")
    sizes = _split_sizes(table)
    foot = [
        "",
        f"Adjusted accuracy (SPEC §3, percent) per regime; held-out ({sizes.get('heldout', '?')}) is the "
        f"headline, dev ({sizes.get('dev', '?')}) is what the rules were developed against, Riverbend "
        f"({sizes.get('riverbend', '?')}) is a second KB (all regimes pooled). "
        f"LLM backends see only the first {limit} reports of every regime (regimes interleaved) and "
        f"start no report after {table.get('llm_budget_s') or 0:.0f} s; a cell cut short shows n=scored/planned. "
        "s / report: mean grounding latency, one report at a time, on a shared 2-core CPU "
        f"(load average {table['machine']['load_avg_1m']} when the table was made).",
        "",
        "Paper (Table 1, its own dataset; not comparable report for report):",
        "",
        "| paper | standard | messy | advanced_messy |",
        "|---|---:|---:|---:|",
    ]
    for name, vals in table["paper"].items():
        foot.append(f"| {name} (paper) | " + " | ".join(f"{vals[g]:.1f}" for g in REGIMES) + " |")
    return "\n".join(lines + foot) + "\n"


def _split_sizes(table: dict[str, Any]) -> dict[str, str]:
    sizes: dict[str, str] = {}
    for row in table["backends"]:
        for name, s in (row.get("splits") or {}).items():
            if not row.get("limit"):
                sizes.setdefault(name, f"{s['n']} reports")
    return sizes


def render_chart(table: dict[str, Any], path: str | os.PathLike[str]) -> None:
    """Grouped bars: adjusted accuracy per regime per backend, held-out and dev, paper hatched."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = [s["name"] for s in table["splits"] if s["name"] in ("heldout", "dev")] or ["heldout"]
    ran = [r for r in table["backends"] if r["status"] != "unavailable"]
    missing = [r["backend"] for r in table["backends"] if r["status"] == "unavailable"]
    series = [(r["backend"] + _limit_note(r), r) for r in ran]
    n_series = len(series) + len(table["paper"])
    width = 0.8 / max(1, n_series)
    fig, axes = plt.subplots(1, len(panels), figsize=(6.5 * len(panels), 4.6), sharey=True, squeeze=False)
    colors = plt.get_cmap("tab10").colors
    for ax, split in zip(axes[0], panels, strict=True):
        xs = range(len(REGIMES))
        for i, (label, row) in enumerate(series):
            vals = [_acc(row, split, g) for g in REGIMES]
            pos = [x - 0.4 + width * (i + 0.5) for x in xs]
            bars = ax.bar(pos, [v or 0 for v in vals], width, label=label, color=colors[i % 10])
            for b, v in zip(bars, vals, strict=True):
                if v is not None:
                    ax.annotate(f"{v:.0f}", (b.get_x() + b.get_width() / 2, v), ha="center", va="bottom", fontsize=7)
        for j, (name, vals) in enumerate(table["paper"].items()):
            i = len(series) + j
            pos = [x - 0.4 + width * (i + 0.5) for x in xs]
            ax.bar(pos, [vals[g] for g in REGIMES], width, label=f"paper: {name}", facecolor="white",
                   edgecolor=("0.15", "0.4", "0.6")[j % 3], hatch=("//", "\\\\", "..")[j % 3], linestyle="--")
        ax.set_xticks(list(xs), list(REGIMES))
        ax.set_ylim(0, 110)
        ax.set_title("held-out split (headline)" if split == "heldout" else f"{split} split")
        ax.grid(axis="y", alpha=0.3)
    axes[0][0].set_ylabel("adjusted accuracy (%)")
    handles, labels = axes[0][0].get_legend_handles_labels()
    title = "backend" + (f" — unavailable: {', '.join(missing)}" if missing else "")
    fig.legend(handles, labels, loc="lower center", ncol=min(4, len(labels)), fontsize=8, title=title,
               title_fontsize=8, frameon=False)
    fig.suptitle("LUCIFER grounding backends vs. the paper's Table 1")
    fig.tight_layout(rect=(0, 0.16, 1, 1))
    fig.savefig(path, dpi=130)
    plt.close(fig)


def _limit_note(row: dict[str, Any]) -> str:
    if not row.get("limit"):
        return ""
    if row["status"] == "partial":
        done = ", ".join(f"{k} {v['n']}/{v['planned']}" for k, v in row["splits"].items())
        return f" (time budget: {done or 'nothing'} scored)"
    return f" (first {row['limit']}/regime)"


def write_outputs(table: dict[str, Any], out_dir: str | os.PathLike[str]) -> dict[str, Path]:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths = {"json": out / "backends.json", "md": out / "backends.md", "png": out / "backends.png"}
    paths["json"].write_text(json.dumps(table, indent=1) + "\n")
    paths["md"].write_text(render_markdown(table))
    render_chart(table, paths["png"])
    return paths


def cmd_eval_backends(args: argparse.Namespace) -> int:
    backends = [b.strip() for b in (args.backends or ",".join(DEFAULT_BACKENDS)).split(",") if b.strip()]
    splits = default_splits(args.kb)
    table = build_table(backends, splits, args.llm_limit or None,
                        log=lambda m: print(m, file=sys.stderr, flush=True))
    previous = Path(args.out) / "backends.json"
    if args.backends and previous.is_file():
        # a subset refreshes its rows and keeps the others (an LLM row can take an hour to redo)
        old = json.loads(previous.read_text())
        fresh = {r["backend"]: r for r in table["backends"]}
        order = [r["backend"] for r in old.get("backends", [])] + [b for b in fresh if b not in
                                                                    {r["backend"] for r in old.get("backends", [])}]
        kept = {r["backend"]: r for r in old.get("backends", [])}
        table["backends"] = [fresh.get(b) or kept[b] for b in order]
    paths = write_outputs(table, args.out)
    print(paths["md"].read_text())
    print("wrote " + ", ".join(str(p) for p in paths.values()))
    return 0


# --------------------------------------------------------------------------- child process
def _child(argv: list[str]) -> int:
    p = argparse.ArgumentParser(prog="python -m lucifer.evals.backends",
                                description="evaluate one backend (the isolated half of `lucifer eval backends`)")
    p.add_argument("--one", required=True, metavar="BACKEND")
    p.add_argument("--splits", required=True, help="JSON list of {name, kb, files, label}")
    p.add_argument("--result", required=True, help="JSON file, rewritten after every split")
    p.add_argument("--limit", type=int, default=None)
    p.add_argument("--budget-s", type=float, default=None)
    a = p.parse_args(argv)
    splits = [Split(s["name"], s["kb"], tuple(s["files"]), s.get("label", "")) for s in json.loads(a.splits)]
    result = Path(a.result)

    def save(row: dict[str, Any]) -> None:
        tmp = result.with_suffix(".tmp")
        tmp.write_text(json.dumps(row))
        tmp.replace(result)

    save(_run_guarded(a.one, splits, a.limit, a.budget_s, on_progress=save))
    return 0


if __name__ == "__main__":
    sys.exit(_child(sys.argv[1:]))

"""Write RESULTS.md (README-ready tables and images) from the ablation JSON files here.

    lucifer eval ablation --client rl       --json benchmarks/ablation/rl.json       --charts benchmarks/ablation
    lucifer eval ablation --client planner  --json benchmarks/ablation/planner.json  --charts benchmarks/ablation
    lucifer eval ablation --client minigrid --json benchmarks/ablation/minigrid.json --charts benchmarks/ablation
    python benchmarks/ablation/make_results.py
"""

from __future__ import annotations

import json
from pathlib import Path

HERE = Path(__file__).parent
CLIENTS = (
    ("rl", "HierQ (hierarchical tabular RL), SAR testbed"),
    ("planner", "Hybrid planner (A* + heuristics), SAR testbed"),
    ("minigrid", "A* planner on Farama MiniGrid LavaCrossingS9N2 (generated KB)"),
)
PAPER = {"rl": {"msr": 66.5, "csr": 99.9, "sms": 66.5}, "planner": {"msr": 100.0, "csr": 96.8, "sms": 100.0}}


def main() -> None:
    lines = ["# System-level ablation (SPEC §5)", ""]
    for name, title in CLIENTS:
        path = HERE / f"{name}.json"
        if not path.is_file():
            continue
        r = json.loads(path.read_text())
        lines += [f"## {title}", "",
                  f"`lucifer eval ablation --client {name} --runs {r['runs']} --episodes {r['episodes']}`"
                  f" — wall {r['wall_s']} s on 2 cores", "",
                  "| config | MSR | CSR | SMS |", "|---|---|---|---|"]
        for cfg, m in r["configs"].items():
            lines.append(f"| {cfg} | " + " | ".join(f"{m[k][0]:.1f} ± {m[k][1]:.1f}" for k in ("msr", "csr", "sms")) + " |")
        if name in PAPER:
            p = PAPER[name]
            lines.append(f"| paper +D+G | {p['msr']} | {p['csr']} | {p['sms']} |")
        lines += [""]
        pattern = r.get("extra", {}).get("pattern", {})
        if pattern:
            lines += ["Pattern: " + "; ".join(f"{'✓' if ok else '✗'} {claim}" for claim, ok in pattern.items()), ""]
        for img in (f"ablation_{name}.png", f"curves_{name}.png", f"episode_{name}.png"):
            if (HERE / img).is_file():
                lines.append(f"![{img}](benchmarks/ablation/{img})")
        lines.append("")
    (HERE / "RESULTS.md").write_text("\n".join(lines), encoding="utf-8")
    print((HERE / "RESULTS.md").read_text())


if __name__ == "__main__":
    main()

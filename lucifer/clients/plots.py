"""PNG pictures of the testbed: one episode on the grid, and ablation bar charts.

Matplotlib is imported inside the functions (Agg backend), so importing this module is cheap.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

_INFO_MARK = {0: ("V", "victim"), 1: ("H", "hazard info"), 2: ("S", "safe route")}


def _plt() -> Any:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig: Any, path_png: str | Path) -> Path:
    """Lay out, write (creating the folder) and close a figure."""
    fig.tight_layout()
    out = Path(path_png)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out)
    _plt().close(fig)
    return out


def plot_episode(
    path_png: str | Path,
    *,
    rows: int,
    cols: int,
    phi: Sequence[float],
    admissible: Sequence[Sequence[bool]],
    believed_hazards: Sequence[bool],
    true_hazards: Sequence[int],
    info_cells: Sequence[int],
    start: int,
    path: Sequence[int],
    labels: Mapping[int, str] | None = None,
    title: str = "",
    moves: Sequence[tuple[int, int]] = ((-1, 0), (1, 0), (0, -1), (0, 1)),
) -> Path:
    """One episode: Φ as a heat map, hazards, U'(x) constraints and the path taken.

    A red bar on a cell's edge marks a move the contract excludes from U'(x); true hazard
    cells get a red cross, believed ones (X_u) a hatched red outline.
    """
    import numpy as np

    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.4, 6.0), dpi=120)
    grid = np.asarray(phi, dtype=float).reshape(rows, cols)
    im = ax.imshow(grid, cmap="RdYlGn", vmin=-1, vmax=1)
    fig.colorbar(im, ax=ax, fraction=0.046, pad=0.04, label="potential Φ(x)")
    for cell in range(rows * cols):
        r, c = divmod(cell, cols)
        if labels and cell in labels:
            ax.text(c, r + 0.36, labels[cell], ha="center", va="center", fontsize=6, color="#333")
        if believed_hazards[cell]:
            ax.add_patch(plt.Rectangle((c - 0.5, r - 0.5), 1, 1, fill=False, hatch="///", edgecolor="#b2182b", lw=0))
        for a, (dr, dc) in enumerate(moves):
            nr, nc = r + dr, c + dc
            if 0 <= nr < rows and 0 <= nc < cols and not admissible[cell][a]:
                x0, y0 = c + 0.42 * dc, r + 0.42 * dr
                if dr:
                    ax.plot([x0 - 0.25, x0 + 0.25], [y0, y0], color="#b2182b", lw=2.2)
                else:
                    ax.plot([x0, x0], [y0 - 0.25, y0 + 0.25], color="#b2182b", lw=2.2)
    for cell in true_hazards:
        r, c = divmod(cell, cols)
        ax.plot(c, r, marker="x", color="#67001f", markersize=22, mew=3)
    for k, cell in enumerate(info_cells):
        r, c = divmod(cell, cols)
        mark, _ = _INFO_MARK.get(k, ("?", ""))
        ax.text(c, r - 0.05, mark, ha="center", va="center", fontsize=15, weight="bold", color="#08306b",
                bbox={"boxstyle": "circle", "fc": "white", "ec": "#08306b"})
    sr, sc = divmod(start, cols)
    ax.plot(sc, sr, marker="*", color="#fdb863", markersize=20, mec="black")
    if len(path) > 1:
        pts = np.array([divmod(p, cols) for p in path], dtype=float)
        jitter = np.linspace(-0.12, 0.12, len(pts))
        xs, ys = pts[:, 1] + jitter, pts[:, 0] + jitter
        ax.plot(xs, ys, color="#2166ac", lw=2, alpha=0.9)
        for i in range(len(pts) - 1):
            ax.annotate("", xy=(xs[i + 1], ys[i + 1]), xytext=(xs[i], ys[i]),
                        arrowprops={"arrowstyle": "->", "color": "#2166ac", "lw": 1.5})
    ax.set_xticks(range(cols))
    ax.set_yticks(range(rows))
    ax.set_xlim(-0.5, cols - 0.5)
    ax.set_ylim(rows - 0.5, -0.5)
    ax.set_title(title or "one episode", fontsize=10)
    handles = [
        plt.Line2D([], [], marker="x", color="#67001f", ls="", mew=3, label="hazard (hidden from the client)"),
        plt.Rectangle((0, 0), 1, 1, fill=False, hatch="///", edgecolor="#b2182b", label="X_u from reports"),
        plt.Line2D([], [], color="#b2182b", lw=2.2, label="move outside U'(x)"),
        plt.Line2D([], [], color="#2166ac", lw=2, label="path taken"),
        plt.Line2D([], [], marker="*", color="#fdb863", mec="black", ls="", markersize=12, label="start"),
    ]
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.06), ncol=2, fontsize=7, frameon=False)
    return _save(fig, path_png)


def plot_ablation(path_png: str | Path, result: Mapping[str, Any], title: str | None = None) -> Path:
    """Grouped bars of MSR / CSR / SMS (mean ± std) for the four configurations."""
    import numpy as np

    plt = _plt()
    configs = list(result["configs"])
    metrics = [("msr", "MSR"), ("csr", "CSR"), ("sms", "SMS")]
    colours = ["#9e9e9e", "#4daf4a", "#377eb8", "#984ea3"]
    fig, ax = plt.subplots(figsize=(7.2, 3.8), dpi=120)
    x = np.arange(len(metrics))
    w = 0.8 / len(configs)
    for i, cfg in enumerate(configs):
        means = [result["configs"][cfg][m][0] for m, _ in metrics]
        stds = [result["configs"][cfg][m][1] for m, _ in metrics]
        bars = ax.bar(x + (i - (len(configs) - 1) / 2) * w, means, w, yerr=stds, capsize=3,
                      label=cfg, color=colours[i % len(colours)])
        for b, v in zip(bars, means, strict=True):
            ax.text(b.get_x() + b.get_width() / 2, v + 1.5, f"{v:.0f}", ha="center", va="bottom", fontsize=7)
    ax.set_xticks(x, [label for _, label in metrics])
    ax.set_ylim(0, 112)
    ax.set_ylabel("percent (mean ± std over runs)")
    ax.set_title(title or f"{result['client']}: {result['runs']} runs × {result['episodes']} episodes", fontsize=10)
    ax.legend(ncol=4, fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.08), frameon=False)
    return _save(fig, path_png)


def plot_curves(path_png: str | Path, curves: Mapping[str, Sequence[float]], title: str, window: int = 50) -> Path:
    """Learning curves: mission success per ``window`` episodes, one line per configuration."""
    import numpy as np

    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.4, 3.4), dpi=120)
    for name, ys in curves.items():
        a = np.asarray(ys, dtype=float)
        n = len(a) // window
        if n == 0:
            continue
        ax.plot(np.arange(1, n + 1) * window, 100 * a[: n * window].reshape(n, window).mean(1), label=name)
    ax.set_xlabel("episode")
    ax.set_ylabel(f"success, % per {window} episodes")
    ax.set_ylim(0, 102)
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8)
    return _save(fig, path_png)

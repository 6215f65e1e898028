"""The plot of a solve over drive types (``axisopt solve --plot`` when a rack-and-pinion or
linear-motor design answers): each shown design's check and limit margins as horizontal bars against
the line at 1 (a bar short of it fails), and the designs' objective against their cost."""

from __future__ import annotations

from ..fileio import save_figure, tidy_layout
from .drivetype import LABELS, MARGIN_LABELS


def plot_drive_designs(res, path: str | None = None, top: int = 5):
    """Margins of the best design (and the runners-up shown, ``top`` in all) of a drive types'
    answer (:class:`axisopt.search.drivedesigns.DriveTypeResult`), or of the closest designs when
    none meets every check, and each design's objective against its cost.  Returns the Figure;
    written to ``path`` if given."""
    from ..figure import Figure

    designs = (
        ([res.best] + list(res.runners_up))[:top] if res.best is not None else list(res.closest)
    )
    fig = Figure(figsize=(12, 6))
    ax1, ax2 = fig.subplots(1, 2, width_ratios=(3, 2))
    keys = sorted({k for d in designs for k in d.margins})
    n = max(len(designs), 1)
    height = 0.8 / n
    for i, d in enumerate(designs):
        ys = [j + i * height for j in range(len(keys))]
        vals = [d.margins.get(k, float("nan")) for k in keys]
        ax1.barh(
            ys,
            vals,
            height=height,
            label=f"#{i + 1} {LABELS[d.drive_type]}",
            gid=f"margins-{i + 1}",
        )
    ax1.axvline(1.0, color="k", linestyle="--", linewidth=1.0, label="met at 1")
    ax1.set_yticks([j + 0.4 - height / 2 for j in range(len(keys))])
    ax1.set_yticklabels([MARGIN_LABELS.get(k, k) for k in keys])
    ax1.set_xscale("log")
    ax1.set_xlabel("margin (available / needed; log scale)")
    ax1.set_title(
        "checks and limits" if res.best is not None else "closest designs (no design fits)"
    )
    ax1.legend(loc="lower right", fontsize="small")
    for i, d in enumerate(designs):
        ax2.plot(
            [d.cost],
            [d.objective],
            "o",
            label=f"#{i + 1} {LABELS[d.drive_type]}",
            gid=f"design-{i + 1}",
        )
    ax2.set_xlabel("cost [EUR]")
    ax2.set_ylabel(f"{res.objective_label.split(' ', 1)[-1]} [{res.objective_unit}]")
    ax2.set_title(res.objective_label)
    ax2.legend(fontsize="small")
    tidy_layout(fig)
    if path:
        save_figure(fig, path)
    return fig

"""Line profiles of a run folder (pd, dbm: profiles/index.csv and profiles/profile_<k>.csv, read
through shockfield.run.Run): one panel per column against x at up to six of the run's profile
times, with reference levels from the run beside them. Used by pd_plots and dbm_plots.

    panels = [Panel("p", "pressure p", levels=[("exact p*", 0.303)])]
    draw_profiles(run, panels, "x", "x", out)
"""
from dataclasses import dataclass, field

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MAX_TIMES = 6


@dataclass
class Panel:
    """A column of the profiles drawn against x: its label, a factor to the drawn unit, and
    reference levels (name, value in the drawn unit) drawn as dashed lines."""
    column: str
    label: str
    scale: float = 1.0
    levels: list = field(default_factory=list)


def chosen_frames(run, kind="profiles"):
    """Up to MAX_TIMES frames of `kind` of `run` evenly spread over its times (the first and the
    last included)."""
    frames = list(run.frames(kind=kind))
    picks = np.linspace(0, len(frames) - 1, min(MAX_TIMES, len(frames))).round().astype(int)
    return [frames[k] for k in np.unique(picks)]


def time_label(t, unit):
    """`t = ...` in the run's time unit: ns for SI runs (unit "s"), else the model's own."""
    return f"t = {t * 1e9:.3g} ns" if unit == "s" else f"t = {t:.3g}"


def draw_profiles(run, panels, x_column, x_label, out, x_scale=1.0, time_unit="", title_what="profiles",
                  extra_axes=0, columns=2, frames=None):
    """The profiles of `panels` against `x_column` into `out` (of `frames`, default
    chosen_frames(run)); returns (figure, the axes left free for the caller when `extra_axes` >
    0) and leaves the saving to the caller then. Points of a 2D or 3D body (several rows per x)
    are drawn as dots."""
    frames = frames or chosen_frames(run)
    count = len(panels) + extra_axes
    cols = min(columns, count)
    rows = (count + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 3.0 * rows), squeeze=False)
    cmap = plt.get_cmap("viridis")
    flat = list(axes.flat)
    for n, frame in enumerate(frames):
        p = frame.data
        x = p[x_column] * x_scale
        scattered = len(np.unique(x)) < len(x)
        colour = cmap(n / max(len(frames) - 1, 1))
        for ax, panel in zip(flat, panels):
            y = p[panel.column] * panel.scale
            if scattered:
                ax.plot(x, y, ".", ms=1.5, color=colour, label=time_label(frame.time, time_unit))
            else:
                ax.plot(x, y, color=colour, label=time_label(frame.time, time_unit))
    for ax, panel in zip(flat, panels):
        for name, value in panel.levels:
            ax.axhline(value, color="grey", ls="--", lw=0.8)
            ax.annotate(f"{name} {value:.4g}", (0.01, value), xycoords=("axes fraction", "data"),
                        fontsize="x-small", va="bottom", color="0.3")
        ax.set_xlabel(x_label)
        ax.set_ylabel(panel.label)
    flat[0].legend(fontsize="x-small")
    for ax in flat[count:]:
        ax.remove()
    fig.suptitle(run.title(title_what))
    if extra_axes:
        return fig, flat[len(panels):count]
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return fig, []

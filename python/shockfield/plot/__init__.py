"""Figures of run folders: ``python -m shockfield.plot KIND RUN [--out PNG]``.

Each kind names the methods whose runs it draws; a run of another method is refused with the
kinds its method has. The generic kinds (thermo, series) read the run through ``shockfield.Run``
and take their titles from the run (method, case file); the method kinds are drawn by the
helpers in ``shockfield_plot`` (installed beside this package).
"""

import pathlib

from ..errors import InputError
from ..run import Run

# kind -> (methods it draws, what it shows)
KINDS = {
    "thermo": (None, "every thermo.csv column against the step"),
    "series": (None, "every series.csv column against time"),
    "profiles": ({"md"}, "binned shock profiles at six times (profiles.csv)"),
    "porous": ({"mpm"}, "bottom-window means against time beside Xu et al. (2015)'s values"),
    "cavity": ({"mpm"}, "particles around the cavity, its area and collapsibility"),
    "bar": ({"pd"}, "axial stress and velocity profiles of a bar"),
}


def kinds_for(method):
    """The kinds that draw runs of ``method``."""
    return [k for k, (methods, _) in KINDS.items() if methods is None or method in methods]


MAX_PANELS = 12


def _columns_figure(run, table, x_name, title_what, out, columns=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = [n for n in table.dtype.names if n != x_name and table.dtype[n].kind == "f"]
    if columns:
        unknown = [c for c in columns if c not in names]
        if unknown:
            raise InputError(f"{run.folder}: {title_what} has no column {', '.join(unknown)}; "
                             f"its columns: {', '.join(names)}")
        names = list(columns)
    if not names:
        raise InputError(f"{run.folder}: {title_what} has no numeric column besides {x_name}")
    names = names[:MAX_PANELS]
    cols = min(4, len(names))
    rows = (len(names) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(3.6 * cols, 2.6 * rows), squeeze=False)
    for ax, name in zip(axes.flat, names):
        ax.plot(table[x_name], table[name])
        ax.set(xlabel=x_name, title=name)
    for ax in list(axes.flat)[len(names):]:
        ax.axis("off")
    case = pathlib.Path(run.summary["case"]).name if run.summary else run.folder.name
    fig.suptitle(f"{run.method} run {run.folder.name} ({case}): {title_what}")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def plot(kind, folder, out=None, columns=None):
    """Draws ``kind`` of the run in ``folder`` to ``out`` (default FOLDER/KIND.png); returns the
    PNG's path. ``columns``: for thermo and series, the columns to draw (default the first
    MAX_PANELS numeric ones). InputError for an unknown kind, an unknown column or a run of a
    method the kind does not draw."""
    if kind not in KINDS:
        raise InputError(f"plot: unknown kind '{kind}'; expected one of {', '.join(KINDS)}")
    run = Run.open(folder)
    methods, _ = KINDS[kind]
    if methods is not None and run.method not in methods:
        raise InputError(f"{run.folder}: a {run.method} run; '{kind}' draws {'/'.join(sorted(methods))} runs. "
                         f"Kinds for this run: {', '.join(kinds_for(run.method))}")
    out = str(out or run.folder / f"{kind}.png")
    if kind == "thermo":
        table = run.thermo
        _columns_figure(run, table, table.dtype.names[0], "thermo.csv", out, columns)
    elif kind == "series":
        table = run.series
        x = "time_s" if "time_s" in table.dtype.names else table.dtype.names[0]
        _columns_figure(run, table, x, "series.csv", out, columns)
    elif kind == "profiles":
        from shockfield_plot import md_plots
        md_plots.plot_profiles(str(run.folder), out, run.config.get("output", {}).get("profile_axis", "z"))
    elif kind in ("porous", "cavity"):
        from shockfield_plot import mpm_plots
        mpm_plots.porous(str(run.folder), out) if kind == "porous" else mpm_plots.cavity([str(run.folder)], out)
    else:
        from shockfield_plot import pd_plots
        pd_plots.bar([str(run.folder)], [run.folder.name], out)
    return out

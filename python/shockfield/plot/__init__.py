"""Figures of run folders: ``python -m shockfield.plot KIND RUN [--out PNG]`` (``shockfield plot``
runs exactly this).

Each kind names the runs it draws; a run of another method is refused with the kinds that run
has. The generic kinds (thermo, series) are drawn here from ``shockfield.Run``; the method kinds
by the helpers in ``shockfield_plot`` (installed beside this package), which read every file
through ``shockfield.run`` too. Titles and reference levels come from the run (its method, case
file, config.resolved.toml).
"""

import pathlib
from dataclasses import dataclass

from ..errors import InputError
from ..run import Run


@dataclass(frozen=True)
class Kind:
    """A kind of figure: ``methods`` the run methods it draws (None: any run); ``what`` one line
    of help; ``target`` "run" (a run folder), "folder" (another output folder) or "file";
    ``only`` an extra condition on the run (a predicate) and its words for the refusal."""
    methods: frozenset
    what: str
    target: str = "run"
    only: tuple = None

    def draws(self, run):
        """True when this kind draws ``run`` (a Run): its method and the extra condition."""
        return (self.methods is None or run.method in self.methods) and (self.only is None or self.only[0](run))

    def runs_text(self):
        """The runs it draws, in words, for a refusal ("pd runs", "dbm runs of ...")."""
        runs = f"{'/'.join(sorted(self.methods))} runs"
        return f"{runs} {self.only[1]}" if self.only else runs


def _gls(run):
    return run.config.get("model", {}).get("kind") == "gls"


def _homogeneous(run):
    return "homogeneous" in run.config


def _cavity(run):
    return run.value("cavity_radius") is not None


KINDS = {
    "thermo": Kind(None, "any run: every thermo.csv column against the step"),
    "series": Kind(None, "any run: every series.csv column against time"),
    "profiles": Kind(frozenset({"md", "pd", "dbm"}),
                     "md, pd, dbm: profiles along x at up to six times (dbm: with its [derived] levels)"),
    "porous": Kind(frozenset({"mpm"}), "mpm: bottom-window means against time, beside Xu et al. (2015) for their case"),
    "cavity": Kind(frozenset({"mpm"}), "mpm: particles around the cavity, its collapsibility against time",
                   only=(_cavity, "with a cavity ([[body]] cavity_radius)")),
    "bar": Kind(frozenset({"pd"}), "pd: axial stress and plastic strain along a bar, the derived HEL and impact stress"),
    "crystal": Kind(frozenset({"pd"}), "pd: axial compression and accumulated slip at the last profile"),
    "compression": Kind(frozenset({"pd"}), "pd: every grain's axial compression against strain, the Taylor average",
                        only=(_homogeneous, "with a [homogeneous] block")),
    "orientations": Kind(frozenset({"pd"}), "pd: the grains' loading axis before and after, inverse pole figure",
                         only=(_homogeneous, "with a [homogeneous] block")),
    "damage": Kind(frozenset({"pd"}), "pd: damage of a 2D body and the angle of the cracks grown from its notches"),
    "tne": Kind(frozenset({"dbm"}), "dbm: mean TNE strength against time, Δ*_2xx and Δ*_(3,1)x along x"),
    "phase-separation": Kind(frozenset({"dbm"}), "dbm (GLS): density frames, boundary length, TNE, domain size",
                             only=(_gls, 'of [model] kind = "gls"')),
    "chain": Kind(frozenset({"granular"}), "granular: space-time contact force, signal depth, energies"),
    "stress-strain": Kind(frozenset({"macroparticle"}), "macroparticle: |stress| against |strain| of the rod"),
    "phasefield": Kind(frozenset({"phasefield"}), "phasefield: domain radius and growth speed, the last ξ frame"),
    "hugoniot": Kind(None, "the folder of `shockfield hugoniot`: Us against Up, the fit and the experiment",
                     target="folder"),
    "structures": Kind(None, "the folder of `analyze atoms` or an md run with [analysis]: structure fractions",
                       target="folder"),
    "slice": Kind(None, "an annotated dump of `analyze atoms`: a slice of atoms by structure type",
                  target="file"),
    "voids": Kind(None, "the folder of `analyze atoms --voids`: total and largest void volume and area",
                  target="folder"),
    "domains": Kind(None, "the folder of `analyze atoms --domains`: total and largest domain volume and area",
                    target="folder"),
}


def kinds_for(run):
    """The kinds that draw ``run`` (a Run)."""
    return [name for name, kind in KINDS.items() if kind.target == "run" and kind.draws(run)]


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
        ax.remove()
    fig.suptitle(run.title(title_what))
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def _draw_run(kind, run, out, options):
    """Draws a kind of a run folder (the run checked to be of the kind's methods)."""
    folder = str(run.folder)
    if kind == "thermo":
        table = run.thermo
        _columns_figure(run, table, table.dtype.names[0], "thermo.csv", out, options.get("columns"))
    elif kind == "series":
        table = run.series
        x = next((n for n in ("time_s", "time") if n in table.dtype.names), table.dtype.names[0])
        _columns_figure(run, table, x, "series.csv", out, options.get("columns"))
    elif kind == "profiles" and run.method == "md":
        from shockfield_plot import md_plots
        md_plots.plot_profiles(folder, out, options.get("axis"))
    elif run.method == "mpm":
        from shockfield_plot import mpm_plots
        mpm_plots.porous(folder, out) if kind == "porous" else mpm_plots.cavity([folder], out)
    elif run.method == "pd":
        from shockfield_plot import pd_plots
        if kind == "damage":
            pd_plots.damage([folder], [run.folder.name], out, [])
        else:
            getattr(pd_plots, kind)([folder], [run.folder.name], out)
    elif run.method == "dbm":
        from shockfield_plot import dbm_plots
        dbm_plots.KINDS[kind](folder, out)
    elif run.method == "granular":
        from shockfield_plot import granular_plots
        granular_plots.chain(folder, out)
    elif run.method == "macroparticle":
        from shockfield_plot import macroparticle_plots
        macroparticle_plots.stress_strain([folder], out, title=run.title("stress against strain"))
    else:
        from shockfield_plot import phasefield_plots
        phasefield_plots.phasefield(folder, out)


def _draw_other(kind, target, out, options):
    """Draws a kind whose target is not a run folder (hugoniot, structures, voids, domains: folders;
    slice: a dump)."""
    path = pathlib.Path(target)
    if kind == "slice":
        if not path.is_file():
            raise InputError(f"'{target}' is not a file: plot slice draws an annotated dump of analyze atoms")
        thickness = options.get("thickness") or 3.0
        if not thickness > 0:
            raise InputError(f"--thickness {thickness}: expected a number > 0 (Å)")
        from shockfield_plot import atoms_plots
        atoms_plots.slice_plot(str(path), out or str(path.with_suffix("")) + "_slice.png", options.get("axis") or "z",
                               options.get("at"), thickness, options.get("column"), options.get("frame", -1))
        return out or str(path.with_suffix("")) + "_slice.png"
    if not path.is_dir():
        raise InputError(f"'{target}' is not a folder: plot {kind} draws {KINDS[kind].what.split(':')[0]}")
    out = str(out or path / f"{kind}.png")
    if kind == "hugoniot":
        from shockfield_plot import md_plots
        md_plots.plot_hugoniot(str(path), out, options.get("compare"))
    elif kind in ("voids", "domains"):  # the figure `analyze atoms` draws itself (OUTPUT/voids.png)
        table = path / f"{kind}.csv"
        if not table.is_file():
            raise InputError(f"{path}: no {kind}.csv (the folder of `shockfield analyze atoms --{kind}`)")
        from shockfield_plot.__main__ import surfaces
        surfaces(str(table), out)
    else:
        from shockfield_plot import atoms_plots
        atoms_plots.structures(str(path), out)
    return out


def plot(kind, target, out=None, columns=None, **options):
    """Draws ``kind`` of ``target`` (a run folder; for hugoniot, structures, voids and domains an
    output folder, for slice a dump file) to ``out`` (default TARGET/KIND.png); returns the PNG's path.
    ``columns``: for thermo and series, the columns to draw (default the first MAX_PANELS numeric
    ones); ``options``: axis (md profiles, slice), at, thickness, column, frame (slice), compare
    (hugoniot). InputError for an unknown kind, an unknown column or a run the kind does not draw."""
    if kind not in KINDS:
        raise InputError(f"plot: unknown kind '{kind}'; expected one of {', '.join(KINDS)}")
    options["columns"] = columns
    if KINDS[kind].target != "run":
        return _draw_other(kind, target, out, options)
    run = Run.open(target)
    if not KINDS[kind].draws(run):
        raise InputError(f"{run.folder}: a {run.method} run; '{kind}' draws {KINDS[kind].runs_text()}. "
                         f"Kinds for this run: {', '.join(kinds_for(run))}")
    out = str(out or run.folder / f"{kind}.png")
    _draw_run(kind, run, out, options)
    return out

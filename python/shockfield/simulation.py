"""A case run in-process and stepped from Python, with numpy views of its particles.

    sim = shockfield.Simulation("tests/cli/cases/tiny_cu.toml", output="runs/cu", threads=2)
    sim.step(10)
    v = sim["velocities"]          # (n, 3) float64 over the simulation's own memory
    v[:] = 0.0                     # the next step starts from rest
    sim.step(sim.steps_left)
    sim.finish()                   # final outputs, summary.json

The method is built by the same registry and run by the same driver as ``shockfield run``, so
the run folder holds the same files (thermo.csv, series.csv, dumps, checkpoints, summary.json);
docs/python.md says what each method offers and what happens to a view across steps.
"""

import pathlib

import numpy as np

from .analysis import _require_core
from .box import Box
from .case import Case


class Simulation:
    """``Simulation(case, output, threads=0, overwrite=False, quiet=True, resume=False)``: opens
    the run folder ``output`` and starts the case (a ``Case`` or the path of a case file) in this
    process.

    ``threads``: OpenMP threads for every step (0: OMP_NUM_THREADS, else all cores); ``quiet``:
    no progress line; ``resume``: continue the run in ``output`` from its last checkpoint, as
    ``shockfield run CASE --output OUTPUT --resume`` (the same case and values; a run stopped by
    ``stop()``, Ctrl-C or ``--stop-after`` continues as if never stopped). Bad input raises
    ``InputError`` with the command line's message, a failed step ``RunError`` (the run folder
    keeps what was written)."""

    def __init__(self, case, output, threads=0, overwrite=False, quiet=True, resume=False):
        if not isinstance(case, Case):
            case = Case.load(case)
        with case._case_file() as case_file:
            self._core = _require_core().Simulation(str(case_file), list(case.overrides), str(output), int(threads),
                                                    bool(overwrite), bool(quiet), bool(resume))
        self.folder = pathlib.Path(self._core.folder)

    method = property(lambda self: self._core.method, doc='The method\'s name ("md", "mpm", "pd", ...).')
    step_number = property(lambda self: self._core.step_number, doc="The step counter.")
    time = property(lambda self: self._core.time, doc="Simulated time, in time_unit.")
    time_unit = property(lambda self: self._core.time_unit, doc='"ps", "s" or "1" (lattice units).')
    steps_left = property(lambda self: self._core.steps_left, doc="Steps left (an estimate for adaptive steps).")
    finished = property(lambda self: self._core.finished, doc="True when no step is left.")
    closed = property(lambda self: self._core.closed, doc="True after finish() or stop().")

    def step(self, n=1):
        """Advances ``n`` steps (fewer if the run ends first) with the scheduled outputs; returns
        the number made. Raises ``ValueError`` when no step is left or after ``finish()``."""
        return self._core.step(int(n))

    def finish(self):
        """Writes the end of the run (final outputs, last checkpoint, summary.json); every step
        must have been made."""
        self._core.finish()

    def stop(self):
        """Stops the run here as Ctrl-C does: the method's stop state, a checkpoint, summary.json
        with status "stopped". ``Simulation(case, output, resume=True)`` continues it. Returns the
        message saying how (the command line's)."""
        return self._core.stop()

    def thermo(self):
        """The thermo columns at the current step, as a dict (the values of a thermo.csv row)."""
        return self._core.thermo()

    def arrays(self):
        """Every state array (per particle, or a grid's field) as a numpy view (no copy) of the
        simulation's memory, by name: md ``positions``, ``velocities``, ``forces`` (n, 3),
        ``types`` (0-based), ``ids``, ``images`` and, when computed, ``energies``; mpm
        ``positions``, ``velocities``, ``masses``, ``volumes0``, ``materials`` and each particle's
        material state as strided views: ``pressures`` (EOS), ``viscous_pressures``, ``energies``,
        ``temperatures``, ``plastic_works``, ``plastic_strains``, ``damages`` (n,), ``deviators``
        and ``deformations`` (n, 3, 3); pd ``positions``,
        ``velocities``, ``force_densities``; granular ``displacements``, ``velocities``,
        ``forces`` (n,); phasefield ``xi`` shaped as the grid ((ny, nx) in 2D, x last); dbm ``f``
        (Q, ny + 4, nx + 4), ghosts included; macroparticle md's arrays in the engine's reduced
        units (each unit text is one unit in SI). Writing into a view changes the simulation."""
        return self._core.arrays()

    def fields(self):
        """The fields the method computes from its state, by name, as numpy arrays that are
        copies made at this call (writing into them changes nothing; call again after a step):
        dbm ``rho`` (ny, nx), ``velocity`` (ny, nx, 2) (vx, vy) and ``T`` (ny, nx), the moments
        of f in lattice units — the values the run's field frames hold for this step; pd
        ``damage`` (n,), the share of each point's bonds broken, and for models with them
        ``stress`` (n, 3, 3) and ``plastic`` (n,) (its profiles' columns); md the box:
        ``box_lo``, ``box_hi``, ``box_tilt`` (3,) and ``cell`` (3, 3) (see ``box``). Other
        methods (and decomposed DBM runs) raise ``ValueError``."""
        return self._core.fields()

    @property
    def box(self):
        """The md box at this step as a ``shockfield.Box`` (a copy; take it again after a step that
        moves it): ``lo``, ``hi`` (LAMMPS's boxlo/boxhi), ``tilt`` (xy, xz, yz; zero for an
        orthogonal box), ``cell`` (3, 3) with the edge vectors a, b, c as rows, ``volume``,
        ``bounds``. Methods without a box raise ``ValueError``."""
        fields = self.fields()
        if "box_lo" not in fields:
            raise ValueError(f"the {self.method} method has no box")
        return Box.of(fields["box_lo"], fields["box_hi"], fields["box_tilt"])

    def units(self):
        """The unit of each array, by name ("" for indices)."""
        return self._core.units()

    def __getitem__(self, name):
        views = self.arrays()
        if name not in views:
            raise KeyError(f"{self.method} simulation has no array {name!r}; it has: {', '.join(views)}")
        return views[name]

    def __setitem__(self, name, values):
        """Copies ``values`` into the array ``name``: the same dtype and shape, nothing cast or
        broadcast (``TypeError`` / ``ValueError`` otherwise)."""
        view = self[name]
        if not isinstance(values, np.ndarray):
            raise TypeError(f"{name}: expected a numpy array of dtype {view.dtype} and shape {view.shape}, "
                            f"got {type(values).__name__}")
        if values.dtype != view.dtype:
            raise TypeError(f"{name}: expected dtype {view.dtype}, got {values.dtype} "
                            f"(convert with values.astype(numpy.{view.dtype}))")
        if values.shape != view.shape:
            raise ValueError(f"{name}: expected shape {view.shape}, got {values.shape}")
        view[...] = values

    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        """A with block that ends without an exception on a run with no step left finishes it."""
        if kind is None and self.finished and not self.closed:
            self.finish()
        return False

    def __repr__(self):
        return f"Simulation({self.method}, step {self.step_number}, folder {str(self.folder)!r})"


__all__ = ["Simulation"]

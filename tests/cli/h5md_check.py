#!/usr/bin/python3
"""md_h5md.sh's checks of trajectory.h5md: usage h5md_check.py STRAIGHT SPLIT (two run folders).

1. STRAIGHT's frames equal its full-precision LAMMPS dumps of the same steps (positions, velocities,
   ids, types, box lengths: exactly, since both are the same doubles printed or stored), with times
   step × timestep and the H5MD 1.1 attributes MDAnalysis and VMD read.
2. SPLIT (stopped at step 130, resumed) holds the same frames, bit for bit.
3. MDAnalysis (Debian python3-mdanalysis) reads the frames, box and times (skipped with a message
   when it is not installed), from a copy without the forces: MDAnalysis 2.4 knows no eV/Å and
   refuses a file whose forces carry it."""
import pathlib
import shutil
import sys
import warnings

import h5py
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "python"))
from shockfield.run import read_lammps_dump  # noqa: E402  (the package's dump reader)


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


straight, split = (pathlib.Path(a) for a in sys.argv[1:3])
f = h5py.File(straight / "trajectory.h5md", "r")
if list(f["h5md"].attrs["version"]) != [1, 1] or f["h5md/creator"].attrs["name"] != "shockfield":
    fail("h5md group: version or creator")
box = f["particles/all/box"]
if box.attrs["dimension"] != 3 or list(box.attrs["boundary"]) != ["periodic"] * 3:
    fail(f"box attributes {dict(box.attrs)}")
steps = f["particles/all/position/step"][:]
if list(steps) != [0, 50, 100, 150, 200, 250, 300]:
    fail(f"frame steps {steps}")
if not np.array_equal(f["particles/all/position/time"][:], steps * 0.002):
    fail("times are not step × 0.002 ps")
units = {g: f[f"particles/all/{g}/value"].attrs["unit"] for g in ("position", "velocity", "force")}
if units != {"position": "Angstrom", "velocity": "Angstrom ps-1", "force": "eV Angstrom-1"}:
    fail(f"units {units}")
ids, species = f["particles/all/id"][:], f["particles/all/species"][:]
for k, step in enumerate(steps):
    [(dump_step, _, dump_box, atoms)] = read_lammps_dump(straight / "dumps" / f"dump.{step:03d}.lammpstrj")
    atoms = np.sort(atoms, order="id")
    if not np.array_equal(atoms["id"], ids) or not np.array_equal(atoms["type"], species):
        fail(f"step {step}: ids or types differ from the dump")
    for group, columns in (("position", ("x", "y", "z")), ("velocity", ("vx", "vy", "vz")), ("force", ("fx", "fy", "fz"))):
        dumped = np.column_stack([atoms[c] for c in columns])
        if not np.array_equal(f[f"particles/all/{group}/value"][k], dumped):
            fail(f"step {step}: {group} differs from the dump by {np.abs(f[f'particles/all/{group}/value'][k] - dumped).max()}")
    if not np.array_equal(np.diag(f["particles/all/box/edges/value"][k]), dump_box.lengths):
        fail(f"step {step}: box edges differ from the dump's box")
g = h5py.File(split / "trajectory.h5md", "r")
for name in ("position", "velocity", "force", "box/edges"):
    for part in ("step", "time", "value"):
        a, b = f[f"particles/all/{name}/{part}"][:], g[f"particles/all/{name}/{part}"][:]
        if a.shape != b.shape or not np.array_equal(a, b):
            fail(f"the resumed run's {name}/{part} differs from the uninterrupted run's")
print(f"ok: {len(steps)} frames equal the dumps; the resumed trajectory equals the uninterrupted one")
try:
    warnings.simplefilter("ignore")
    import MDAnalysis
except ImportError:
    print("skipped: MDAnalysis is not installed (apt-get install python3-mdanalysis)")
    sys.exit(0)
copy = split / "without_forces.h5md"
shutil.copy(straight / "trajectory.h5md", copy)
with h5py.File(copy, "r+") as h:
    del h["particles/all/force"]
u = MDAnalysis.Universe.empty(len(ids), trajectory=True)
u.load_new(str(copy), format="H5MD")
ts = u.trajectory[3]
if len(u.trajectory) != 7 or not np.isclose(ts.time, 0.3) or not np.allclose(ts.dimensions[:3], np.diag(f["particles/all/box/edges/value"][3])):
    fail(f"MDAnalysis reads {len(u.trajectory)} frames, time {ts.time}, box {ts.dimensions}")
if not np.allclose(ts.positions, f["particles/all/position/value"][3], atol=1e-5):  # MDAnalysis holds float32
    fail("MDAnalysis positions differ")
print(f"ok: MDAnalysis {MDAnalysis.__version__} reads the trajectory")

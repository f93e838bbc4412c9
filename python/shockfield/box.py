"""LAMMPS boxes as the dump and data readers return them and the atom analyses take them.

    box = Box.of(lo, hi, tilt)       # or any (lo, hi) / (lo, hi, tilt) sequence
    box.lo, box.hi, box.tilt, box.cell, box.volume, box.bounds, box.triclinic

A restricted triclinic cell (LAMMPS's, https://docs.lammps.org/Howto_triclinic.html) has the edge
vectors a = (lx, 0, 0), b = (xy, ly, 0), c = (xz, yz, lz) from the corner ``lo``, with
lx = hi.x − lo.x etc.: ``lo`` and ``hi`` are LAMMPS's boxlo/boxhi, not the bounding box, which
a dump's ``ITEM: BOX BOUNDS xy xz yz`` lines give (``Box.from_bounds`` converts, as LAMMPS's
read_dump does). An orthogonal box has tilt (0, 0, 0).
"""

from typing import NamedTuple

import numpy as np


def _bounding_pads(tilt):
    """How far a tilted cell's bounding box reaches below lo and above hi on each axis (LAMMPS
    Domain): x by min/max(0, xy, xz, xy + xz), y by min/max(0, yz), z not at all."""
    xy, xz, yz = (float(t) for t in tilt)
    return (np.array([min(0.0, xy, xz, xy + xz), min(0.0, yz), 0.0]),
            np.array([max(0.0, xy, xz, xy + xz), max(0.0, yz), 0.0]))


class Box(NamedTuple):
    """``lo``, ``hi``: the cell's corners (Å, arrays of 3); ``tilt``: (xy, xz, yz) (Å)."""
    lo: np.ndarray
    hi: np.ndarray
    tilt: np.ndarray

    @classmethod
    def of(cls, lo, hi, tilt=(0.0, 0.0, 0.0)):
        """A Box of three float64 arrays of 3 values each (ValueError otherwise)."""
        parts = [np.array(v, dtype=np.float64).reshape(-1) for v in (lo, hi, tilt)]
        for name, v in zip(("lo", "hi", "tilt"), parts):
            if v.shape != (3,):
                raise ValueError(f"box {name}: expected 3 values, got {v.size}")
        return cls(*parts)

    @classmethod
    def coerce(cls, box):
        """A Box from a Box, (lo, hi) or (lo, hi, tilt) (ValueError for anything else)."""
        if isinstance(box, Box):
            return box
        try:
            parts = list(box)
        except TypeError:
            raise ValueError(f"box: expected (lo, hi) or (lo, hi, tilt), got {type(box).__name__}") from None
        if len(parts) not in (2, 3):
            raise ValueError(f"box: expected (lo, hi) or (lo, hi, tilt), got {len(parts)} entries")
        return cls.of(*parts)

    @classmethod
    def from_bounds(cls, bounds, tilt=(0.0, 0.0, 0.0)):
        """The cell of a LAMMPS dump's BOX BOUNDS: ``bounds`` (3, 2) rows ``xlo_bound xhi_bound``
        etc. and the tilts (LAMMPS Domain: xlo = xlo_bound − min(0, xy, xz, xy + xz),
        xhi = xhi_bound − max(0, xy, xz, xy + xz), ylo = ylo_bound − min(0, yz), yhi likewise)."""
        bounds = np.asarray(bounds, dtype=np.float64)
        pad_lo, pad_hi = _bounding_pads(tilt)
        return cls.of(bounds[:, 0] - pad_lo, bounds[:, 1] - pad_hi, tilt)

    @property
    def triclinic(self):
        """True when a tilt factor is not zero."""
        return bool(np.any(self.tilt != 0))

    @property
    def lengths(self):
        """lx, ly, lz (Å)."""
        return self.hi - self.lo

    @property
    def cell(self):
        """The edge vectors as the rows of a (3, 3) array: a, b, c (Å)."""
        (lx, ly, lz), (xy, xz, yz) = self.lengths, self.tilt
        return np.array([[lx, 0.0, 0.0], [xy, ly, 0.0], [xz, yz, lz]])

    @property
    def volume(self):
        """lx·ly·lz = det(cell) (Å³)."""
        return float(np.prod(self.lengths))

    @property
    def bounds(self):
        """The axis-aligned bounding box as (3, 2) rows ``lo hi`` (a LAMMPS dump's BOX BOUNDS)."""
        pad_lo, pad_hi = _bounding_pads(self.tilt)
        return np.column_stack([self.lo + pad_lo, self.hi + pad_hi])

    def fractional(self, positions):
        """Fractional (LAMMPS "lamda") coordinates s of positions x = lo + s·cell, (n, 3)."""
        return np.linalg.solve(self.cell.T, (np.asarray(positions, dtype=np.float64) - self.lo).T).T

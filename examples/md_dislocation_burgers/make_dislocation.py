#!/usr/bin/env python3
"""Writes dislocation.data: a Cu cylinder (axis z) holding a perfect edge dislocation a/2[1-10]
along z = [-1-12] with glide plane y = (111), displaced by the isotropic Volterra field
(Hirth & Lothe 1982, eq 3-45). Box axes x = [1-10], y = [111], z = [-1-12]; z periodic.

usage: make_dislocation.py [--radius R] [--repeat-z N] [--output FILE]"""
import argparse

import numpy as np

A = 3.615  # Å, Cu_u3 lattice constant
ORIENT = np.array([[1, -1, 0], [1, 1, 1], [-1, -1, 2]], dtype=float)
ROT = ORIENT / np.linalg.norm(ORIENT, axis=1)[:, None]  # rows: box axes in crystal coordinates
BASIS = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
NU = 0.34  # Poisson's ratio of Cu (only the starting field: the minimiser relaxes it)


def crystal(radius, repeat_z):
    lz = repeat_z * A * np.sqrt(6) / 2  # periodic repeat along [-1-12] is a·√6/2
    span = int(np.ceil((radius + lz) / A)) + 2
    n = np.arange(-span, span + 1)
    cells = np.stack(np.meshgrid(n, n, n, indexing="ij"), -1).reshape(-1, 3)
    sites = (cells[:, None, :] + BASIS[None, :, :]).reshape(-1, 3) * A
    x = sites @ ROT.T
    eps = 1e-6
    keep = (x[:, 2] >= -eps) & (x[:, 2] < lz - eps) & (np.hypot(x[:, 0], x[:, 1]) < radius)
    x = x[keep]
    x[:, 2] = np.where(x[:, 2] < 0, 0.0, x[:, 2])
    return x, lz


def add_edge(x, x0, y0, b):
    dx, dy = x[:, 0] - x0, x[:, 1] - y0
    r2, theta = dx * dx + dy * dy, np.arctan2(dy, dx)
    ux = b / (2 * np.pi) * (theta + dx * dy / (2 * (1 - NU) * r2))
    uy = -b / (2 * np.pi) * ((1 - 2 * NU) / (4 * (1 - NU)) * np.log(r2) + (dx * dx - dy * dy) / (4 * (1 - NU) * r2))
    out = x.copy()
    out[:, 0] += ux
    out[:, 1] += uy
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--radius", type=float, default=45.0, help="cylinder radius, Å")
    p.add_argument("--repeat-z", type=int, default=4, help="periodic repeats a·√6/2 along the line")
    p.add_argument("--output", default="dislocation.data")
    a = p.parse_args()
    x, lz = crystal(a.radius, a.repeat_z)
    # The line between two (111) layers (spacing a/√3) and off every atomic column.
    x0, y0 = 0.37, A / np.sqrt(3) / 2
    x = add_edge(x, x0, y0, A / np.sqrt(2))
    lo, hi = x.min(axis=0) - 1.0, x.max(axis=0) + 1.0
    with open(a.output, "w") as f:
        f.write(f"Cu edge dislocation a/2[1-10] at x = {x0}, y = {y0:.6f} (Volterra field, nu = {NU})\n\n")
        f.write(f"{len(x)} atoms\n1 atom types\n\n")
        f.write(f"{lo[0]:.6f} {hi[0]:.6f} xlo xhi\n{lo[1]:.6f} {hi[1]:.6f} ylo yhi\n0 {lz:.12f} zlo zhi\n\n")
        f.write("Masses\n\n1 63.546 # Cu\n\nAtoms # atomic\n\n")
        for i, p_ in enumerate(x, 1):
            f.write(f"{i} 1 {p_[0]:.8f} {p_[1]:.8f} {p_[2]:.8f}\n")
    print(f"wrote {a.output}: {len(x)} atoms, cylinder radius {a.radius} Å, line length {lz:.3f} Å, core at ({x0}, {y0:.4f})")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Writes sheared_<gamma>.data: fcc Cu (a0 = 3.615 Å, 6 x 6 x 6 cubic cells, [100] axes) under the
simple shear x' = x + gamma·y, in the triclinic cell whose tilt xy = gamma·ly carries that shear
across the periodic faces. Usage: make_sheared.py OUT_DIR GAMMA..."""
import pathlib
import sys

A0, N = 3.615, 6
BASIS = [(0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)]


def write(path, gamma):
    length = N * A0
    rows = []
    for i in range(N):
        for j in range(N):
            for k in range(N):
                for b in BASIS:
                    x, y, z = ((i + b[0]) * A0, (j + b[1]) * A0, (k + b[2]) * A0)
                    rows.append((x + gamma * y, y, z))
    lines = ["fcc Cu under simple shear gamma = %r (examples/md_triclinic_shear)" % gamma, "",
             "%d atoms" % len(rows), "1 atom types", "",
             "0 %r xlo xhi" % length, "0 %r ylo yhi" % length, "0 %r zlo zhi" % length,
             "%r 0 0 xy xz yz" % (gamma * length), "", "Masses", "", "1 63.55", "", "Atoms # atomic", ""]
    lines += ["%d 1 %r %r %r" % (n + 1, *r) for n, r in enumerate(rows)]
    path.write_text("\n".join(lines) + "\n")


out = pathlib.Path(sys.argv[1])
for g in sys.argv[2:]:
    write(out / ("sheared_%s.data" % g), float(g))

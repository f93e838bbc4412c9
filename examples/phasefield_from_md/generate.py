"""Synthetic MD frames of a growing hcp domain (no potential, no dynamics): a periodic fcc crystal
(lattice constant 3.615 Å) with its close-packed (111) planes normal to z, in which the atoms
within a sphere of radius R(t) + OFFSET about the box centre take the hcp stacking ABAB instead of
fcc's ABCABC (each atom moves within its own (111) plane, as a Shockley partial moves it).

R(t) is the equivalent radius the adaptive CNA measures: the outermost ~2.25 Å of switched atoms
(their neighbour shells are mixed) are not hcp, so the stacking is switched within R(t) + OFFSET,
OFFSET = 2.25 Å (measured: the a-CNA hcp volume of a switched sphere of radius 8 ... 24 Å is the
sphere of radius R_switched − 2.16 ... 2.46 Å).

  law = allen-cahn: dR/dt = c0 − 2D/R from R0 at t = 0 (RK4), the well-posed phase-field law;
  law = power:      R = R0 (t/t_ref)^0.465 (t_ref the first frame time), the decelerating growth
                    of Xu et al. (2015)'s MD hcp domains (L ~ t^0.465).

usage: generate.py OUTDIR LAW [--c0 1.0] [--D 4.0] [--R0 10] [--times 0,1.5,...] [--cells 24,14,10]
Frames: OUTDIR/grow.<timestep>.dump, timestep = t/0.001 ps (1 fs steps); columns id type x y z.
"""
import argparse
import numpy as np

A, OFFSET = 3.615, 2.25


def radius(law, times, c0, D, R0):
    if law == "power":
        t_ref = times[0] if times[0] > 0 else times[1]
        return R0 * (np.maximum(times, 1e-12) / t_ref) ** 0.465
    out, R, t = [], R0, 0.0
    f = lambda r: c0 - 2.0 * D / r
    for target in times:
        steps = max(1, int(np.ceil((target - t) / 0.01)))
        h = (target - t) / steps
        for _ in range(steps):
            k1 = f(R); k2 = f(R + h / 2 * k1); k3 = f(R + h / 2 * k2); k4 = f(R + h * k3)
            R += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t = target
        out.append(R)
    return np.array(out)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out"); p.add_argument("law", choices=["allen-cahn", "power"])
    p.add_argument("--c0", type=float, default=1.0); p.add_argument("--D", type=float, default=4.0)
    p.add_argument("--R0", type=float, default=10.0)
    p.add_argument("--times", default=",".join(f"{1.5 * k:g}" for k in range(19)))
    p.add_argument("--cells", default="24,14,10")
    a = p.parse_args()
    nx, ny, nz = map(int, a.cells.split(","))
    dnn = A / np.sqrt(2)
    L = np.array([nx * dnn, ny * dnn * np.sqrt(3), nz * 3 * A / np.sqrt(3)])
    layer = A / np.sqrt(3)
    ix, iy = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    base = np.concatenate([np.stack([ix * dnn, iy * dnn * np.sqrt(3)], -1).reshape(-1, 2),
                           np.stack([(ix + 0.5) * dnn, (iy + 0.5) * dnn * np.sqrt(3)], -1).reshape(-1, 2)])
    shift = np.array([[0, 0], [dnn / 2, dnn * np.sqrt(3) / 6], [dnn, dnn * np.sqrt(3) / 3]])  # A, B, C
    times = np.array([float(t) for t in a.times.split(",")])
    for t, R in zip(times, radius(a.law, times, a.c0, a.D, a.R0)):
        rows = []
        for k in range(3 * nz):
            z = (k + 0.5) * layer
            fcc, hcp = base + shift[k % 3], base + shift[k % 2]
            inside = np.linalg.norm(np.column_stack([fcc, np.full(len(fcc), z)]) - L / 2, axis=1) < R + OFFSET
            rows.append(np.column_stack([np.where(inside[:, None], hcp, fcc) % L[:2], np.full(len(fcc), z)]))
        x = np.concatenate(rows)
        step = int(round(t / 0.001))
        with open(f"{a.out}/grow.{step}.dump", "w") as f:
            f.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{len(x)}\nITEM: BOX BOUNDS pp pp pp\n")
            f.write("".join(f"0 {l:.8f}\n" for l in L) + "ITEM: ATOMS id type x y z\n")
            np.savetxt(f, np.column_stack([np.arange(1, len(x) + 1), np.ones(len(x)), x]), fmt="%d %d %.5f %.5f %.5f")
        print(f"t = {t:g} ps  R = {R:.4f} A  ({len(x)} atoms)")


if __name__ == "__main__":
    main()

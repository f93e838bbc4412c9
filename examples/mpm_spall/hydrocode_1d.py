#!/usr/bin/env python3
"""Reference 1D Lagrangian hydrocode for the spall pull-back (no MPM involved).

The flyer-plate set-up of tests/unit/mpm/test_spall.cpp (flyer d = 4 mm at v = 200 m/s onto a
3d target, the paper's aluminium made hydrodynamic) solved with the classical staggered von
Neumann-Richtmyer scheme (Wilkins, "Computer Simulation of Dynamic Phenomena", 1999, ch. 2): node
velocities, cell densities and energies, the same Mie-Grüneisen EOS (Xu et al. 2015, eqs. 5-6, tension
branch included), the same bulk artificial viscosity q = ρℓ(C_Q·ℓ·(∂u/∂x)² − C_L·c·∂u/∂x) in
compression only (c the bulk speed, or the longitudinal one with --shear as in the MPM's
PointState::sound_speed), the same trapezoidal energy update, and the same instantaneous spall criterion
(materials/spall.hpp: P + q < −σ_sp ⇒ P ≥ 0 thereafter). The free-surface velocity is the last
node's, so no particle sampling is involved; the pull-back is read as in the unit test.

    /usr/bin/python3 hydrocode_1d.py --cell 1e-4 --linear 0.3 --quadratic 2 --spall 1e9
    /usr/bin/python3 hydrocode_1d.py --figure pullback_1d.png --mpm RUN   (RUN: hydrodynamic.toml's output)

The two options --no-q-in-tension and --single-plane are experiments that remove, one at a time,
the two numerical effects that make the pull-back read low (README, "Against the spall relation").
"""
import argparse

import numpy as np

RHO0, C0, LAM, GAMMA0 = 2700.0, 5350.0, 1.34, 1.96   # aluminium_seed000 (materials/library.cpp)
K0, B = RHO0 * C0 * C0, RHO0 * GAMMA0


def eos(rho, e):
    """P(ρ, e), a = P − B·e (P is linear in e at fixed ρ) and the bulk sound speed
    (materials/eos/mie_gruneisen.hpp)."""
    eta = 1.0 - RHO0 / rho
    d = np.where(eta > 0, 1.0 - LAM * eta, 1.0)
    ph = np.where(eta > 0, K0 * eta / d**2, K0 * eta)
    dph = np.where(eta > 0, K0 * (1 + LAM * eta) / d**3, K0)
    eh = 0.5 * ph * eta / RHO0
    p = ph + B * (e - eh)
    deh = (ph + eta * dph) / (2 * RHO0)
    c2 = (dph - B * deh) * RHO0 / rho**2 + p * B / rho**2
    return p, ph - B * eh, np.sqrt(np.maximum(c2, 1e-6 * C0 * C0))


def run(cell, linear, quadratic, spall, speed=200.0, flyer=4e-3, courant=0.3, shear=0.0, q_in_tension=True,
        single_plane=False, end=None):
    n_flyer = int(round(flyer / cell))
    n = 4 * n_flyer                                    # flyer + 3d target, one Lagrangian mesh
    x = np.arange(n + 1) * cell
    m = RHO0 * cell * np.ones(n)                       # cell masses
    u = np.zeros(n + 1)
    u[:n_flyer] = speed                                # interface node: the momentum average
    u[n_flyer] = 0.5 * speed
    e = np.zeros(n)
    rho = RHO0 * np.ones(n)
    p, _, c = eos(rho, e)
    c = np.sqrt(c**2 + 4 * shear / (3 * rho))         # longitudinal speed (as PointState::sound_speed)
    q = np.zeros(n)
    damage = np.zeros(n, bool)
    mnode = np.zeros(n + 1)
    mnode[:-1] += 0.5 * m
    mnode[1:] += 0.5 * m
    end = end if end is not None else 7.0 * flyer / C0
    t, ts, us = 0.0, [], []
    while t < end:
        dt = courant * cell / (c.max() + np.abs(u).max())
        sig = -(p + q)
        f = np.zeros(n + 1)
        f[:-1] += sig                                  # node i: σ of cell i minus σ of cell i − 1,
        f[1:] -= sig                                   # σ = 0 beyond both free faces
        u += dt * f / mnode
        x += dt * u
        dx = np.diff(x)
        rho_new = m / dx
        dv = 1.0 / rho_new - 1.0 / rho
        div = np.diff(u) / dx
        q = np.where(div < 0, rho_new * cell * (quadratic * cell * div**2 - linear * c * div), 0.0)
        if not q_in_tension:                           # experiment: no q where the EOS is in tension
            q = np.where(p > 0, q, 0.0)
        _, a, _ = eos(rho_new, e)                      # P = a + B·e at the new density
        e = (e - 0.5 * (p + a + 2 * q) * dv) / (1 + 0.5 * B * dv)
        rho = rho_new
        p, _, c = eos(rho, e)
        c = np.sqrt(c**2 + 4 * shear / (3 * rho))
        if spall > 0:
            new = (p + q < -spall) & ~damage
            if single_plane:                           # experiment: only the first failing cell fails
                new = new & (np.arange(n) == np.argmax(new)) & (not damage.any())
            damage |= new
            cut = damage & (p < 0)
            e = np.where(cut, e + 0.5 * p * dv, e)
            p = np.where(cut, 0.0, p)
        t += dt
        ts.append(t)
        us.append(u[-1])
    return np.array(ts), np.array(us), damage, x


def pullback(t, u, speed=200.0):
    """Plateau median over 0.5 µs after u first reaches 95 % of v; first minimum after it falls
    5 % of v below (tests/unit/mpm/test_spall.cpp)."""
    k = np.argmax(u >= 0.95 * speed)
    peak = np.median(u[k:][t[k:] < t[k] + 0.5e-6])
    mm = k
    while mm + 1 < len(u) and u[mm] > peak - 0.05 * speed:
        mm += 1
    while mm + 1 < len(u) and u[mm + 1] <= u[mm]:
        mm += 1
    return peak, peak - u[mm], t[mm]


def figure(out, mpm_run, shear):
    """u_fs(t): the MPM run of hydrodynamic.toml, this code at its cell size and at 10 µm with and
    without the two experiments, and without the spall model."""
    import os
    import sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
    from shockfield.run import Run  # the shared run-folder reader
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    if mpm_run:
        series = Run.open(mpm_run).series
        t, u = series["time_s"], series["top_h25um_vy_mean_m_s"]
        _, dufs, _ = pullback(t, u)
        ax.plot(t * 1e9, u, "k", lw=2, label=f"MPM, 0.1 mm cells: {0.5 * RHO0 * C0 * dufs / 1e9:.2f} GPa")
    cases = [(1e-4, True, False, 1e9, "1D, 0.1 mm"), (1e-5, True, False, 1e9, "1D, 10 µm"),
             (1e-5, False, False, 1e9, "1D, 10 µm, no q where P < 0"),
             (1e-5, False, True, 1e9, "1D, 10 µm, no q where P < 0, one failed cell"),
             (1e-5, True, False, 0.0, "1D, 10 µm, no spall model")]
    for cell, qt, single, spall, label in cases:
        t, u, _, _ = run(cell, 0.3, 2.0, spall, shear=shear, q_in_tension=qt, single_plane=single)
        _, dufs, _ = pullback(t, u)
        est = f": {0.5 * RHO0 * C0 * dufs / 1e9:.2f} GPa" if spall else ""
        ax.plot(t * 1e9, u, "--" if cell > 5e-5 else "-", label=label + est)
    ax.axhline(200.0 - 2e9 / (RHO0 * C0), color="0.6", ls=":", lw=1)
    ax.text(3310, 200.0 - 2e9 / (RHO0 * C0) + 3, "v − 2σ_sp/(ρ0c0): the acoustic minimum for 1 GPa",
            fontsize="small", color="0.4")
    ax.set_xlim(3300, 4100)
    ax.set_xlabel("t (ns)")
    ax.set_ylabel("free-surface velocity (m/s)")
    ax.set_title("hydrodynamic Al, 200 m/s, σ_sp = 1 GPa: ½ρ0c0Δu_fs", fontsize="medium")
    ax.legend(fontsize="small", loc="lower right")
    fig.tight_layout()
    fig.savefig(out, dpi=90)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cell", type=float, default=1e-4)
    ap.add_argument("--linear", type=float, default=0.3)
    ap.add_argument("--quadratic", type=float, default=2.0)
    ap.add_argument("--spall", type=float, default=1e9)
    ap.add_argument("--courant", type=float, default=0.3)
    ap.add_argument("--shear", type=float, default=0.0,
                    help="shear modulus G [Pa] in the speed of q and of the step only (no deviatoric stress); "
                    "the unit test's material keeps G = 25.9 GPa")
    ap.add_argument("--no-q-in-tension", action="store_true", help="experiment: q = 0 where P < 0")
    ap.add_argument("--single-plane", action="store_true", help="experiment: only the first failing cell fails")
    ap.add_argument("--save", default="")
    ap.add_argument("--figure", default="", help="write the comparison figure to this PNG and stop")
    ap.add_argument("--mpm", default="", help="with --figure: the output folder of hydrodynamic.toml")
    a = ap.parse_args()
    if a.figure:
        figure(a.figure, a.mpm, a.shear)
        return
    t, u, dmg, x = run(a.cell, a.linear, a.quadratic, a.spall, courant=a.courant, shear=a.shear,
                     q_in_tension=not a.no_q_in_tension, single_plane=a.single_plane)
    peak, dufs, tmin = pullback(t, u)
    est = 0.5 * RHO0 * C0 * dufs
    failed = x[:-1][dmg]
    span = (x[-1] - failed.max(), x[-1] - failed.min()) if failed.size else (0, 0)
    print(f"cell {a.cell:.2e} C_L {a.linear} C_Q {a.quadratic} sigma {a.spall:.2e}: plateau {peak:.1f} m/s, "
          f"pull-back {dufs:.1f} m/s at {tmin*1e9:.0f} ns, estimate {est/1e9:.3f} GPa "
          f"({est/a.spall if a.spall else 0:.3f} sigma), failed {failed.size} cells "
          f"{span[0]*1e3:.2f}-{span[1]*1e3:.2f} mm below the face")
    if a.save:
        np.savetxt(a.save, np.c_[t, u], header="t_s u_fs_m_per_s")


if __name__ == "__main__":
    main()

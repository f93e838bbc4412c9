#!/usr/bin/env python3
"""The compressive instability as {111} slip (Saitoh et al., Fig 6(b)). Usage: slip.py OUT HERE.

OUT holds the runs of run.sh: slip (compression, sliding ends, imperfect; n_phi = 4, n_h = 8),
slip_fine (the same at n_phi = 8, n_h = 16), slip_perfect, slip_clamped and slip_tension. Prints and draws (HERE/slip.png):
- the onset predicted for the infinite packing: the uniaxial-stress path of the nearest-neighbour
  fcc network with the plastic bond law, and the smallest eigenvalue of its acoustic tensor
  Q_ik(N) = ½ Σ_b (R_b·N)² [k_t n_i n_k + (T/r)(δ_ik − n_i n_k)] over band normals N (loss of
  ellipticity: a band of normal N may form; theory §8);
- the slip between neighbouring layers of the planes {111}, {100}, {110} in the dumps of `slip`:
  the start's bonds (r < 1.2 r0) between adjacent layers, their relative displacement less the
  rod's best affine map, in-plane part averaged over the layer pair (the measure of the test
  MacroparticleSlip.OneBondLawYieldsNearOnePercentInTensionAndSlipsOnA111PlaneInCompression);
- stress-strain of the five runs, the particles of slip_fine viewed edge-on to its slip plane
  coloured by their slip, and the largest layer-pair slip of each family against strain.
"""
import itertools
import os
import sys

import numpy as np
from scipy.optimize import brentq
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)

A = np.sqrt(2.0)  # cubic cell of the packing, r0 = 1
FAMILIES = {"111": ([[1, 1, 1], [1, 1, -1], [1, -1, 1], [-1, 1, 1]], A / np.sqrt(3)),
            "100": ([[1, 0, 0], [0, 1, 0], [0, 0, 1]], A / 2),
            "110": ([[1, 1, 0], [1, -1, 0], [1, 0, 1], [1, 0, -1], [0, 1, 1], [0, 1, -1]], A / (2 * A))}


def resolved(run):
    """r0 and the bond law of a run: p, q and the route (ε_y, h, ε_s, ε_c as in [plasticity])."""
    config = Run.open(run)
    get = lambda key, default=None: (lambda v: default if v is None else v)(config.value(key))
    hardening = [float(v) for v in config.config["plasticity"]["hardening"]]
    route = dict(eps_y=get("yield_strain"), h=hardening, sat=get("saturation_strain", np.inf),
                 eps_c=get("compression_yield_strain", get("yield_strain")))
    return get("r0"), route, get("p"), get("q")


def thermo(run):
    table = Run.open(run).thermo
    return tuple(np.abs(table[c]) for c in ("Strain", "Stress", "Step"))


def frames(run):
    """The run's dump frames in step order."""
    return list(Run.open(run).frames(kind="dumps"))


def positions(frame, r0):
    """The particles' positions of a dump frame in id order, in units of r0."""
    data = frame.data[np.argsort(frame.data["id"])]
    return np.c_[data["x"], data["y"], data["z"]] / r0


# --- the infinite packing (engine units: r0 = D = 1, k = pq) ---
def bond_law(p, q, eps_y, h, sat, eps_c):
    k = p * q
    te = lambda s: k / (q - p) * (s ** -p - s ** -q) / s
    ke = lambda s: k / (q - p) * ((q + 1) * s ** -q - (p + 1) * s ** -p) / s ** 2

    def law(r):  # monotonic loading: the route's tension and tangent, or the elastic ones
        u = r - (1 + eps_y) if r >= 1 + eps_y else (1 - eps_c) - r if r <= 1 - eps_c else None
        if u is None:
            return te(r), ke(r)
        sign = 1 if r > 1 else -1
        saturated, u = u >= sat, min(u, sat)  # past ε_s the route's tension is constant
        return (te(1 + eps_y if sign > 0 else 1 - eps_c) + sign * k * sum(c * u ** (n + 1) for n, c in enumerate(h)),
                0.0 if saturated else k * sum((n + 1) * c * u ** n for n, c in enumerate(h)))
    return law, k


BONDS = np.array([v for v in itertools.product([-1, 0, 1], repeat=3) if sum(map(abs, v)) == 2], float) / A


def onset(p, q, route, strains):
    """First strain of uniaxial [001] compression where the acoustic tensor has a negative eigenvalue."""
    law, k = bond_law(p, q, **route)

    def sums(lx, lz, normal=None):
        F = np.diag([lx, lx, lz])
        out = np.zeros((3, 3))
        for R in BONDS:
            r = F @ R
            rr = np.linalg.norm(r)
            n = r / rr
            t, kt = law(rr)
            out += 0.5 * (t * np.outer(r, n) if normal is None else
                          (R @ normal) ** 2 * (kt * np.outer(n, n) + t / rr * (np.eye(3) - np.outer(n, n))))
        return out
    th, ph = np.meshgrid(np.linspace(0, np.pi / 2, 31), np.linspace(0, 2 * np.pi, 120, endpoint=False))
    normals = np.c_[(np.sin(th) * np.cos(ph)).ravel(), (np.sin(th) * np.sin(ph)).ravel(), np.cos(th).ravel()]
    lx = 1.0
    for e in strains:
        lx = brentq(lambda L: sums(L, 1 - e)[0, 0], lx - 0.002, lx + 0.004)  # σ_xx = 0 along the path
        w = [np.linalg.eigh(sums(lx, 1 - e, N)) for N in normals]
        i = int(np.argmin([v[0][0] for v in w]))
        if w[i][0][0] < 0:
            return e, normals[i], w[i][0][0] / k
    return None, None, None


# --- slip between neighbouring layers ---
def layer_slip(X, x, bonds):
    B0, B = X[bonds[:, 1]] - X[bonds[:, 0]], x[bonds[:, 1]] - x[bonds[:, 0]]
    D = B - B0 @ np.linalg.lstsq(B0, B, rcond=None)[0]  # less the best affine map
    out = {}
    for name, (normals, spacing) in FAMILIES.items():
        for n in np.array(normals, float) / np.linalg.norm(normals[0]):
            L = np.round(X @ n / spacing).astype(int)
            dl = L[bonds[:, 1]] - L[bonds[:, 0]]
            d = D * np.sign(dl)[:, None]
            d -= np.outer(d @ n, n)
            low = np.minimum(L[bonds[:, 0]], L[bonds[:, 1]])
            pairs = {k: np.linalg.norm(d[(abs(dl) == 1) & (low == k)].mean(0))
                     for k in np.unique(low) if ((abs(dl) == 1) & (low == k)).sum() >= 6}
            if pairs and max(pairs.values()) > out.get(name, (0,))[0]:
                out[name] = (max(pairs.values()), n, pairs, L, d, dl)
    return out


def main(out, here):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    run = f"{out}/slip"
    r0, route, p, q = resolved(run)
    law_text = (f"eps_y = {route['eps_y']}, h = {route['h']}, eps_s = {route['sat']}, eps_c = {route['eps_c']}")
    r0s = {name: resolved(f"{out}/{name}")[0] for name in ("slip", "slip_fine")}
    e_c, normal, qmin = onset(p, q, route, np.arange(0.001, 0.06, 0.001))
    if e_c is not None:
        angle = np.degrees(np.arccos(min(1.0, np.max(np.abs(np.array(FAMILIES["111"][0]) @ normal)) / np.sqrt(3))))
        print(f"infinite packing ({law_text}): acoustic tensor loses positivity at {100 * e_c:.1f} % "
              f"strain, band normal {np.round(normal, 2)} ({angle:.1f} deg from <111>), Q_min/k = {qmin:.4f}")
    else:
        print(f"infinite packing ({law_text}): acoustic tensor positive to 6 %")
    histories = {}
    for name in ("slip", "slip_fine"):
        files = frames(f"{out}/{name}")
        X = positions(files[0], r0s[name])
        bonds = np.array(sorted(cKDTree(X).query_pairs(1.2)))
        strain, stress, step = thermo(f"{out}/{name}")
        at = np.interp([f.step for f in files], step, strain)
        histories[name] = (at, [{k: v[0] for k, v in layer_slip(X, positions(f, r0s[name]), bonds).items()} for f in files])
        final = layer_slip(X, positions(files[-1], r0s[name]), bonds)
        s111, n111, pairs, L, d, dl = final["111"]
        print(f"{name} at {100 * at[-1]:.1f} %: largest {{111}} layer pair {s111:.3f} r0 on "
              f"({' '.join(f'{v:+.0f}' for v in n111 * np.sqrt(3))}) (median of its set {np.median(list(pairs.values())):.3f}), "
              f"{{100}} {final['100'][0]:.3f}, {{110}} {final['110'][0]:.3f}; layer pairs above 0.1 r0: "
              f"{sorted(k for k, v in pairs.items() if v > 0.1)}")
        view_data = (X, bonds, positions(files[-1], r0s[name]), n111, d, dl, at[-1])  # the finest run drawn
    for name in ("slip_perfect", "slip_clamped", "slip_tension"):  # the controls' last frames
        files = frames(f"{out}/{name}")
        r0c = resolved(f"{out}/{name}")[0]
        X = positions(files[0], r0c)
        final = layer_slip(X, positions(files[-1], r0c), np.array(sorted(cKDTree(X).query_pairs(1.2))))
        print(f"{name}: largest {{111}} layer pair {final['111'][0]:.3f} r0 (median of its set "
              f"{np.median(list(final['111'][2].values())):.3f}), {{100}} {final['100'][0]:.3f}, {{110}} {final['110'][0]:.3f}")
    fig, ax = plt.subplots(1, 3, figsize=(15, 5.2))
    for name, colour, label in [("slip_fine", "k", "the same, n_phi = 8, n_h = 16 (slips)"),
                                ("slip", "C3", "compression, sliding ends, imperfect 1e-3 r0 (slips)"),
                                ("slip_perfect", "C2", "compression, perfect (slips later)"),
                                ("slip_clamped", "C1", "compression, clamped ends (slips)"),
                                ("slip_tension", "C0", "tension")]:
        e, sgm, _ = thermo(f"{out}/{name}")
        ax[0].plot(100 * e, sgm / 1e9, colour, label=label)
        j = int(np.argmax(sgm))
        print(f"{name}: peak {sgm[j] / 1e9:.2f} GPa at {100 * e[j]:.2f} %, end {sgm[-1] / 1e9:.2f} GPa")
    ax[0].set(xlabel="|strain| (%)", ylabel="|stress| (GPa)",
              title=f"bonds: tension yield {100 * route['eps_y']:.2f} %, h_1 = {route['h'][0]},\n"
                    f"saturation {100 * route['sat']:.1f} % past it, compression yield {100 * route['eps_c']:.1f} %")
    ax[0].set_ylim(bottom=0)
    ax[0].legend(fontsize=8)
    # Particles edge-on to the slip plane: view along the horizontal direction in the plane.
    X, bonds, x, n111, d, dl, drawn_at = view_data
    view = np.cross(n111, [0, 0, 1.0])
    view /= np.linalg.norm(view)
    across = np.cross([0, 0, 1.0], view)
    per_particle = np.zeros(len(X))
    count = np.zeros(len(X))
    cross = abs(dl) == 1
    mag = np.linalg.norm(d, axis=1)
    for c in (0, 1):
        np.add.at(per_particle, bonds[cross, c], mag[cross])
        np.add.at(count, bonds[cross, c], 1)
    per_particle /= np.maximum(count, 1)
    order = np.argsort(x @ view)
    sc = ax[1].scatter((x @ across)[order], x[order, 2], c=per_particle[order], s=9, cmap="magma_r", vmin=0, vmax=0.3)
    ax[1].set_aspect("equal")
    ax[1].set(xlabel="r0 (horizontal, normal to the view)", ylabel="z (r0)",
              title=f"n_phi = 8 at {100 * drawn_at:.1f} %:\nview along [{' '.join(f'{v:.2f}' for v in view)}]")
    fig.colorbar(sc, ax=ax[1], label="slip of the particle's bonds across its layers (r0)")
    for run_name, ls in (("slip", "-"), ("slip_fine", "--")):
        at, history = histories[run_name]
        for name, style in [("111", "C3"), ("100", "C0"), ("110", "C2")]:
            ax[2].plot(100 * at, [hh.get(name, 0) for hh in history], style, ls=ls, marker="o", ms=3,
                       label=f"largest {{{name}}} layer pair, n_phi = {4 if run_name == 'slip' else 8}")
    ax[2].axvline(100 * e_c if e_c else 0, color="grey", ls=":", label="infinite packing loses ellipticity")
    ax[2].set(xlabel="|strain| (%)", ylabel="slip between neighbouring layers (r0)",
              title="slip concentrates on one {111} layer pair")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{here}/slip.png", dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

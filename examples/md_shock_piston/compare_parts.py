#!/usr/bin/python3
"""Compares the piston shock run in one part with the same shock run in two parts chained through
final.data (run.sh): the Hugoniot states, the final thermo row and the final profiles binned from
both final.data files on the same bins (7.23 Å from the piston face).

    compare_parts.py ONE_PART_RUN PART2_RUN

final.data is read by the compiled module: the package of the build tree (build/release/python)
must be on PYTHONPATH, as run.sh sets it.
"""
import sys

import numpy as np

from shockfield.run import Run, read_lammps_data  # noqa: E402  (the shared readers; PYTHONPATH: the build tree's package)

KB = 8.617333262e-5            # eV/K
MVV2E = 1.0364269e-4           # amu Å²/ps² → eV
AMU_A3_TO_G_CC = 1.66053906660  # amu/Å³ → g/cm³


def read_data(run):
    """The run's final.data (the library's reader, with the run's boundary codes: atoms mapped into
    the periodic x and y only): box (a shockfield.box.Box), and in id order the atoms' masses,
    positions (n, 3) and velocities (n, 3)."""
    system = Run.open(run).config["system"]
    data = read_lammps_data(f"{run}/final.data", system.get("boundary") or system["lattice"]["boundary"])
    order = np.argsort(data["ids"])
    return data["box"], data["masses"][data["types"][order] - 1], data["positions"][order], data["velocities"][order]


def profile(run, origin, width, nbins):
    """Per bin along z: count, density (g/cm³), mean vz (km/s), temperature (K, c.o.m. removed)."""
    box, m, x, v = read_data(run)
    area = (box.hi[0] - box.lo[0]) * (box.hi[1] - box.lo[1])
    k = np.floor((x[:, 2] - origin) / width).astype(int)
    out = np.full((nbins, 4), np.nan)
    for b in range(nbins):
        sel = k == b
        n = sel.sum()
        if n < 2:
            continue
        vc = (m[sel, None] * v[sel]).sum(0) / m[sel].sum()
        ke2 = (m[sel, None] * (v[sel] - vc) ** 2).sum() * MVV2E
        out[b] = [n, m[sel].sum() / (area * width) * AMU_A3_TO_G_CC, vc[2] / 10.0, ke2 / ((3 * n - 3) * KB)]
    return out


def last_thermo(run):
    """The last row of the run's thermo table as {column: value}."""
    thermo = Run.open(run).thermo
    return dict(zip(thermo.dtype.names, thermo[-1]))


def main(one, part2):
    width = 7.23
    # Common bins: from the lower face of the one-part run's final box (the piston side).
    origin = read_data(one)[0].lo[2]
    top = max(read_data(r)[0].hi[2] for r in (one, part2))
    nbins = int(np.ceil((top - origin) / width))
    a, b = profile(one, origin, width, nbins), profile(part2, origin, width, nbins)
    both = ~np.isnan(a[:, 0]) & ~np.isnan(b[:, 0])
    print(f"final profiles on {both.sum()} common bins of {width} Å (one part | two parts):")
    for name, col, unit in (("density", 1, "g/cc"), ("vz", 2, "km/s"), ("temperature", 3, "K")):
        d = b[both, col] - a[both, col]
        print(f"  {name:11s}: mean |diff| {np.abs(d).mean():.4g} {unit}, largest {np.abs(d).max():.4g} {unit} "
              f"(values {np.nanmin(a[both, col]):.4g}..{np.nanmax(a[both, col]):.4g})")
    for label, p in (("one part", a), ("two parts", b)):  # front: first bin from the free end above up/2
        shocked = np.where(p[:, 2] > 0.5)[0]
        print(f"  front bin ({label}): {shocked.max() if shocked.size else 'none'} (z = {origin + width * (shocked.max() + 0.5):.1f} Å)")
    ta, tb = last_thermo(one), last_thermo(part2)
    print(f"final thermo: T {ta['temperature_K']:.2f} | {tb['temperature_K']:.2f} K, PE {ta['pe_eV']:.3f} | {tb['pe_eV']:.3f} eV, "
          f"KE {ta['ke_eV']:.3f} | {tb['ke_eV']:.3f} eV, Pzz {ta['pzz_bar']:.1f} | {tb['pzz_bar']:.1f} bar, "
          f"rebuilds {ta['neighbor_rebuilds']:.0f} | {tb['neighbor_rebuilds']:.0f}")
    ha, hb = Run.open(one).toml("hugoniot_shock"), Run.open(part2).toml("hugoniot_shock")
    print("Hugoniot (one part over 2.5 ps | part 2 alone over its 1.2 ps):")
    for key in ("us_km_s", "up_km_s", "pressure_GPa", "density_g_cc", "temperature_K"):
        if key in ha and key in hb:
            print(f"  {key:20s} {ha[key]:.4g} | {hb[key]:.4g}  ({100 * (hb[key] - ha[key]) / ha[key]:+.2f} %)")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

#!/usr/bin/python3
"""The scatter of a piston run's Hugoniot state (examples/md_shock_piston at 1.5 km/s): per profile
of the fit window (the last 70% of the piston stage, as md/diagnostics/hugoniot.cpp), the
count-weighted means of U_p, P_zz, density and T over the bins between piston and front (3 bins
kept from each), and over frames their mean and standard deviation; the bins ahead of the front
give rho0. Prints TOML. Usage: /usr/bin/python3 piston_scatter.py PISTON_RUN_DIR
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)

MARGIN = 3


def main():
    run = Run.open(sys.argv[1])
    fronts = {}
    for r in run.table("shock_front_shock"):
        fronts[int(r["step"])] = (float(r["front_A"]), float(r["piston_A"]), float(r["time_ps"]))
    frames = {}
    for r in run.profiles:
        frames.setdefault(int(r["step"]), []).append(r)
    steps = sorted(fronts)  # the profiles of the piston stage
    t0, t1 = fronts[steps[0]][2], fronts[steps[-1]][2]
    steps = [s for s in steps if fronts[s][2] >= t0 + 0.3 * (t1 - t0) - 1e-9 and fronts[s][0] == fronts[s][0]]
    series = {"up_km_s": [], "pressure_GPa": [], "density_g_cc": [], "temperature_K": [], "density0_g_cc": []}
    for s in steps:
        front, wall, _ = fronts[s]
        bins = frames[s]
        width = float(bins[1]["position_A"]) - float(bins[0]["position_A"])
        w = up = p = rho = t = w0 = rho0 = 0.0
        top = max(float(b["position_A"]) for b in bins if int(b["count"]) > 0)
        if top - front <= MARGIN * width:  # the front reached the free end: the window ends
            break
        for b in bins:
            n = int(b["count"])
            if n == 0:
                continue
            z = float(b["position_A"])
            if z - wall > MARGIN * width and front - z > MARGIN * width:
                w += n; up += n * float(b["vz_A_ps"]) * 0.1; p += n * float(b["pzz_GPa"])
                rho += n * float(b["density_g_cc"]); t += n * float(b["temperature_K"])
            elif z - front > MARGIN * width and top - z > MARGIN * width:
                w0 += n; rho0 += n * float(b["density_g_cc"])
        if w > 0:
            for key, v in (("up_km_s", up / w), ("pressure_GPa", p / w), ("density_g_cc", rho / w),
                           ("temperature_K", t / w)):
                series[key].append(v)
        if w0 > 0:
            series["density0_g_cc"].append(rho0 / w0)
    print(f"frames = {len(series['up_km_s'])}")
    for key, v in series.items():
        print(f"{key} = [{statistics.fmean(v):.5g}, {statistics.stdev(v):.3g}]  # mean, standard deviation over frames")


if __name__ == "__main__":
    main()

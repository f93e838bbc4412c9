"""bridge_cu.png of the bridge example, and the table of its README: the MD Us-Up points, the
bridged linear fit, the MPM shocked states on the bridged EOS and the experimental copper Hugoniot
(Marsh 1980: Us = 3.940 + 1.489 Up km/s); the PD elastic front speeds on the bridged cubic
constants against sqrt(C_L/rho); the MD tension and [111] compression with the bridged spall
strength and yield, and the MPM flyer-plate free-surface velocity with and without the bridged
spall strength; the share of the wall time each scale took.
Usage: plot.py OUT PNG [--check] (OUT: the folder run.sh wrote). With --check, exits 1 unless the
issue's round-trip bounds hold: MPM Us, P and rho (P and rho against the MD Rankine-Hugoniot values)
within 2% of every MD point, PD front speeds within 1% of sqrt(C_L/rho)."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "mpm_spall"))
import spall as mpm_spall  # noqa: E402  the pull-back and last-frame readers of examples/mpm_spall
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run, read_csv, read_toml  # noqa: E402  (the shared run-folder readers)

out, png = sys.argv[1], sys.argv[2]
check = "--check" in sys.argv[3:]
worst = {"mpm": 0.0, "pd": 0.0}
md = read_csv(f"{out}/md_sweep/hugoniot_sweep.csv")  # shockfield hugoniot's table
md_up, md_us, md_err = md["up_km_s"], md["us_km_s"], md["us_stderr_km_s"]
md_p, md_prh, md_rho = md["pressure_GPa"], md["pressure_rankine_hugoniot_GPa"], md["density_g_cc"] * 1e3
mpm = np.loadtxt(f"{out}/mpm_states.txt", ndmin=2)  # up us P P_RH rho
material = read_toml(f"{out}/cu_md.toml")
eos, el = material["eos"], material["elasticity"]
fit = material["provenance"]["hugoniot_to_eos"]["fit"]
c0, s = eos["c0"] / 1e3, eos["s"]
# The density a Us-Up EOS represents (as P_RH for the pressure): rho0 Us / (Us - Up), rho0 the MD
# crystal ahead of the shock; the profile density behind a short, unsteady MD front can differ by 2-3%.
md_rho_rh = eos["rho0"] * md_us / (md_us - md_up)
pd = {line.split()[0]: float(line.split()[1]) for line in open(f"{out}/pd_speeds.txt")}
c11, c12, c44, rho = el["c11"], el["c12"], el["c44"], el["density"]
cl = {"100": c11, "110": (c11 + c12 + 2 * c44) / 2, "111": (c11 + 2 * c12 + 4 * c44) / 3}
times = {line.split()[0]: float(line.split()[1]) for line in open(f"{out}/timings.txt")}
total = sum(times.values())

print(f"bridged EOS: c0 = {c0:.3f} +- {fit['c0_stderr_m_s'] / 1e3:.3f} km/s, s = {s:.3f} +- {fit['s_stderr']:.3f}"
      f" (Marsh 1980 copper: 3.940, 1.489); rho0 = {eos['rho0']:.0f} kg/m^3")
print("| Up (km/s) | MD Us | MPM Us | dUs | MD P_RH | MD P (virial) | MPM P | dP (vs P_RH) | MD rho_RH | MD rho (profiles) | MPM rho | drho (vs rho_RH) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for k in range(len(md_up)):
    u, us_m, p_m, _, rho_m = mpm[k]
    worst["mpm"] = max(worst["mpm"], abs(us_m / md_us[k] - 1), abs(p_m / md_prh[k] - 1), abs(rho_m / md_rho_rh[k] - 1))
    print(f"| {md_up[k]:.3f} | {md_us[k]:.3f} | {us_m:.3f} | {100 * (us_m / md_us[k] - 1):+.2f}% | {md_prh[k]:.2f} | "
          f"{md_p[k]:.2f} | {p_m:.2f} | {100 * (p_m / md_prh[k] - 1):+.2f}% | {md_rho_rh[k]:.0f} | {md_rho[k]:.0f} | "
          f"{rho_m:.0f} | {100 * (rho_m / md_rho_rh[k] - 1):+.2f}% |")
for d in ("100", "110", "111"):
    ref = np.sqrt(cl[d] / rho)
    worst["pd"] = max(worst["pd"], abs(pd[d] / ref - 1))
    print(f"PD [{d}]: front {pd[d]:.1f} m/s, sqrt(C_L/rho) = {ref:.1f} m/s ({100 * (pd[d] / ref - 1):+.2f}%)")
strength, sp = material["strength"], material["spall"]
yfit, sfit = material["provenance"]["yield"]["fit"], material["provenance"]["spall"]["fit"]
print(f"bridged spall: {sp['strength'] / 1e9:.2f} +- {sfit['strength_stderr_Pa'] / 1e9:.2f} GPa at "
      f"{sp['strain_rate']:.3g} /s; yield along {yfit['direction']}: HEL {yfit['hel_Pa'] / 1e9:.1f} +- "
      f"{yfit['hel_stderr_Pa'] / 1e9:.1f} GPa, Y {strength['yield_stress'] / 1e9:.1f} GPa (nu {yfit['poisson']:.3f}), "
      f"g0 {strength['g0'] / 1e9:.2f} GPa (Schmid {yfit['schmid_factor']:.3f}) at {strength['strain_rate']:.3g} /s")
fs = {}
for name in ("bridged", "none"):
    run = f"{out}/mpm_spall_{name}"
    ser = Run.open(run).series
    t_fs, u_fs = ser["time_s"], ser["top_h10um_vy_mean_m_s"]
    plateau, low, t_low = mpm_spall.pullback(t_fs, u_fs)
    frame = mpm_spall.last_frame(run)[1]
    failed = frame["damage"] > 0
    fs[name] = (t_fs, u_fs, plateau - low, int(failed.sum()), frame["points"][failed, 1])
    zone = fs[name][4]
    print(f"MPM spall ({name}): free-surface plateau {plateau:.0f} m/s, pull-back {plateau - low:.0f} m/s "
          f"(1/2 rho0 c0 du = {0.5 * eos['rho0'] * eos['c0'] * (plateau - low) / 1e9:.2f} GPa); "
          f"{failed.sum()} failed particles"
          + (f", y in [{zone.min() * 1e3:.3f}, {zone.max() * 1e3:.3f}] mm" if failed.any() else ""))
print("wall time: " + ", ".join(f"{k} {v:.0f} s ({100 * v / total:.0f}%)" for k, v in times.items()))

fig, ((a, b), (c, e)) = plt.subplots(2, 2, figsize=(11, 8.2), gridspec_kw={"width_ratios": [1.6, 1]})
up = np.linspace(0.0, 1.1 * md_up.max(), 50)
a.plot(up, 3.940 + 1.489 * up, "k--", label="experiment, Cu (Marsh 1980)")
a.plot(up, c0 + s * up, "C0-", label=f"bridged fit: c0 = {c0:.2f} km/s, s = {s:.2f}")
a.errorbar(md_up, md_us, yerr=md_err, fmt="o", color="C0", label="MD, Cu_u3.eam [100]")
a.plot(mpm[:, 0], mpm[:, 1], "s", mfc="none", color="C3", ms=9, label="MPM impact on the bridged EOS")
a.set_xlabel("particle velocity Up (km/s)")
a.set_ylabel("shock speed Us (km/s)")
a.legend(fontsize=8)
a.set_title("Hugoniot: atoms -> EOS -> plate impact", fontsize=10)
dirs = ["100", "110", "111"]
x = np.arange(3)
b.bar(x - 0.18, [np.sqrt(cl[d] / rho) / 1e3 for d in dirs], 0.36, label="sqrt(C_L/rho), MD constants")
b.bar(x + 0.18, [pd[d] / 1e3 for d in dirs], 0.36, label="PD crystal bar, front")
b.set_xticks(x, [f"[{d}]" for d in dirs])
b.set_ylim(3.5, 5.6)
b.set_ylabel("longitudinal speed (km/s)")
b.legend(fontsize=8, loc="upper left")
b.set_title("elastic waves: atoms -> cubic C_ij -> PD", fontsize=10)
for run, series, key, label, color in (("md_tension", "tension", "spall", "MD tension: -P", "C0"),
                                       ("md_compression_111", "diff", "yield", "MD [111]: sigma_L - sigma_T", "C3")):
    th = Run.open(f"{out}/{run}").thermo
    t_md = th["time_ps"]
    if series == "tension":
        y_md = -th["press_bar"] / 1e4
        bridged = sp["strength"] / 1e9
        text = f"[spall] strength {bridged:.1f} GPa at {sp['strain_rate']:.2g}/s"
    else:
        y_md = (th["pzz_bar"] - 0.5 * (th["pxx_bar"] + th["pyy_bar"])) / 1e4
        bridged = yfit["stress_difference_Pa"] / 1e9
        text = (f"break {bridged:.1f} GPa -> [strength] Y {strength['yield_stress'] / 1e9:.1f} GPa, "
                f"g0 {strength['g0'] / 1e9:.1f} GPa")
    c.plot(t_md, y_md, "-", color=color, lw=0.8, label=label)
    c.axhline(bridged, color=color, ls=":", lw=1, label=text)
c.set_xlabel("MD time (ps), loading at 1e10/s from 1 ps")
c.set_ylabel("stress (GPa)")
c.legend(fontsize=8, loc="upper left")
c.set_title("strength: MD tension and compression -> [spall], [strength]", fontsize=10)
for name, style in (("bridged", "-"), ("none", "--")):
    t_fs, u_fs, pull, failed, _ = fs[name]
    lab = f"MD spall strength {sp['strength'] / 1e9:.1f} GPa" if name == "bridged" else "no failure"
    e.plot(t_fs * 1e9, u_fs, style, label=f"{lab}: pull-back {pull:.0f} m/s, {failed} failed")
e.set_xlabel("t (ns)")
e.set_ylabel("free-surface velocity (m/s)")
e.set_ylim(-50, 1400)
e.legend(fontsize=7.5, loc="upper left")
e.set_title("MPM: Cu flyer 0.5 mm at 1 km/s on 1.5 mm Cu", fontsize=10)
fig.suptitle("wall time: " + ", ".join(f"{k} {100 * v / total:.0f}%" for k, v in times.items())
             + f" of {total:.0f} s", fontsize=9)
fig.tight_layout()
fig.savefig(png, dpi=110)
if check and (worst["mpm"] > 0.02 or worst["pd"] > 0.01):
    sys.exit(f"round trip outside the bounds: MPM {100 * worst['mpm']:.2f}% (2%), PD {100 * worst['pd']:.2f}% (1%)")
if check and (fs["bridged"][3] == 0 or fs["none"][3] != 0 or not fs["bridged"][2] < 0.8 * fs["none"][2]):
    sys.exit("MPM spall: expected failed points with the bridged spall strength (and a pull-back smaller than "
             "without failure), none without")

"""a-CNA fractions along z at the last dump of the Fe piston shock (analyze atoms --profile) and the
Hugoniot state of the run. Usage: plot_piston.py PROFILES_CSV RUN OUT.png [STEP=4000]
(step 4000: 3 ps into the shock, the front at ~200 Å, before it reaches the free end)"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run, read_csv  # noqa: E402  (the shared run-folder readers)

prof, run, out = sys.argv[1:4]
rows = read_csv(prof)  # analyze atoms --profile
last = int(sys.argv[4]) if len(sys.argv) > 4 else 4000
rr = [r for r in rows if int(r["timestep"]) == last and int(r["atoms"]) > 0]
z = [float(r["centre_A"]) for r in rr]
fig, ax = plt.subplots(figsize=(7, 4))
for s, c in (("bcc", "tab:blue"), ("hcp", "tab:green"), ("fcc", "tab:orange"), ("other", "tab:red")):
    ax.plot(z, [float(r[f"acna_{s}_fraction"]) for r in rr], color=c, label=f"a-CNA {s}")
ax.set_xlabel("z (Å), [001]; piston at the left")
ax.set_ylabel("fraction of atoms in the bin")
ax.set_ylim(-0.02, 1.02)
hug = os.path.join(run, "hugoniot_shock.toml")
title = f"bcc Fe (Fe_mm), 1.2 km/s piston, step {last}"
if os.path.exists(hug):
    kv = Run.open(run).toml("hugoniot_shock")
    p = next((kv[k] for k in kv if k.startswith("pressure")), None)
    title += f"; P = {float(p):.1f} GPa" if p is not None else ""
ax.set_title(title, fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"step {last}: bins {len(rr)}")
for r in rr:
    print(f"z {float(r['centre_A']):7.1f}  atoms {int(r['atoms']):>4}  bcc {float(r['acna_bcc_fraction']):.3f}  hcp {float(r['acna_hcp_fraction']):.3f}  "
          f"fcc {float(r['acna_fcc_fraction']):.3f}  other {float(r['acna_other_fraction']):.3f}")
if os.path.exists(hug):
    print(open(hug).read())

#!/usr/bin/env bash
# The aluminium rod of Saitoh et al.: E and ν against division (Figs 4, 5) and the plastic
# stress–strain curves in tension and compression (Fig 6). Usage: run.sh [SHOCKFIELD] [OUT]
# (defaults: build/release/shockfield of the repository, runs/macroparticle_rod). About 16 min on
# one core; FINEST=8 skips the n_phi = 16 rods (about 4 min).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
sf="${1:-$root/build/release/shockfield}"
out="${2:-$root/runs/macroparticle_rod}"
finest="${FINEST:-16}"
mkdir -p "$out"
divisions="2 4 8"
[ "$finest" -ge 16 ] && divisions="$divisions 16"
# Figs 4 and 5: n_h/n_phi = 1/2, 1, 2, 4 (n_h >= 1), 0.1 % strain at T = 0 in 4000 steps.
for ratio in 0.5 1 2 4; do
  /usr/bin/python3 "$here/study.py" "$sf" "$out/elastic" "$ratio" $divisions
done
# Fig 6: tension and compression to 5 % with one plastic pair law (rod_fig6.toml: n_phi = 4,
# n_h = 8; tension yields near 1 %, compression slips on a {111} plane after 3.3 %).
"$sf" run "$here/rod_fig6.toml" -q --overwrite --output "$out/tension"
"$sf" run "$here/rod_fig6.toml" -q --overwrite --output "$out/compression" --set 'loading.mode="compression"'
# Buckling of a longer rod with the hardening law of rod_plastic.toml (symmetric, no saturation):
# the rod of L/D = 3.5 (n_h = 16, the paper's 3.9) in compression, imperfect by
# 1e-3 r0 with sliding ends (it buckles), the same clamped (it does not), and perfect (no drop).
buckle=(--set 'loading.mode="compression"' --set specimen.n_h=16 --set loading.strain_rate=140 --set output.vtk_every=0)
"$sf" run "$here/rod_plastic.toml" -q --overwrite --output "$out/buckling" "${buckle[@]}" \
  --set specimen.perturbation=0.001 --set output.dump_every=1024
"$sf" run "$here/rod_plastic.toml" -q --overwrite --output "$out/buckling_clamped" "${buckle[@]}" \
  --set specimen.perturbation=0.001 --set 'loading.ends="clamped"' --set output.dump_every=0
"$sf" run "$here/rod_plastic.toml" -q --overwrite --output "$out/buckling_perfect" "${buckle[@]}" --set output.dump_every=0
# Slip on {111} would leave hcp stacking faults in the packing: adaptive CNA of the particle dumps.
"$sf" analyze atoms "$out/buckling" -o "$out/buckling/analysis" > /dev/null
# Fig 6(b)'s slip with the law of rod_fig6.toml: the n_phi = 4, n_h = 8 rod (L/D = 1.7: too short
# to buckle) in compression to 6 %, imperfect with sliding ends (one {111} layer pair slides; also
# at n_phi = 8, n_h = 16, about 2 min), perfect, clamped, and in tension; slip.py measures the
# slip between neighbouring layers and draws slip.png.
slip=(--set 'loading.mode="compression"' --set loading.final_strain=0.06 --set output.vtk_every=0)
"$sf" run "$here/rod_fig6.toml" -q --overwrite --output "$out/slip" "${slip[@]}" --set output.dump_every=1025
"$sf" run "$here/rod_fig6.toml" -q --overwrite --output "$out/slip_fine" "${slip[@]}" \
  --set specimen.n_phi=8 --set specimen.n_h=16 --set output.dump_every=2050
"$sf" run "$here/rod_fig6.toml" -q --overwrite --output "$out/slip_perfect" "${slip[@]}" \
  --set specimen.perturbation=0.0 --set output.dump_every=1025
"$sf" run "$here/rod_fig6.toml" -q --overwrite --output "$out/slip_clamped" "${slip[@]}" \
  --set 'loading.ends="clamped"' --set output.dump_every=1025
"$sf" run "$here/rod_fig6.toml" -q --overwrite --output "$out/slip_tension" "${slip[@]}" \
  --set 'loading.mode="tension"' --set output.dump_every=1025
"$sf" analyze atoms "$out/slip" -o "$out/slip/analysis" > /dev/null
/usr/bin/python3 "$here/slip.py" "$out" "$here"
/usr/bin/python3 "$here/plot.py" "$out" "$here"

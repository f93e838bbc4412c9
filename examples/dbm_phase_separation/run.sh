#!/usr/bin/env bash
# The phase-separation study of Xu et al. (2015), §4.3 (Figs. 63-64, eqs. 34-37): `shockfield sweep` of
# case.toml over K, the convergence and sensitivity sweeps, then plot.py (table.md, fig63.png, fig64.png).
# usage: run.sh [RUNS] [PART ...], PART in study, conv, sensitivity, box (default: the first three; box is
# optional: the two largest K in a box 2 x 2).
# Wall times measured on this machine (load average 6-9, one thread per run): 64² runs 2-5 min each,
# K = 1e-5 on 128² to t = 4 38 min
# (493 s of CPU), the convergence runs 2.4 (96²) to 26 min (96², K = 1e-5, to t = 4) each, K = 1e-5 on 160²
# 27 min on a nearly free core.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exe=${SHOCKFIELD:-$here/../../build/release/shockfield}
out=${1:-runs/$(basename "$here")}   # beside the other examples' runs, not in the source tree
shift || true
parts=${*:-study conv sensitivity}
# A sweep exits 3 when a run stopped; its folder and row are kept, so carry on.
sweep() { "$exe" sweep "$here/case.toml" -j 2 --threads 1 --overwrite "$@" || [ $? -eq 3 ]; }
# Δt about 0.7 of the GLS limit on the finer grids (diffusion, ∝ Δx²: 8.6e-4 on 96², 4.8e-4 on 128²).
g96="--set grid.nx=96 --set grid.ny=96 --set grid.dx=0.010416666666666666 --set run.dt=6e-4"
g128="--set grid.nx=128 --set grid.ny=128 --set grid.dx=0.0078125 --set run.dt=3.5e-4"
g160="--set grid.nx=160 --set grid.ny=160 --set grid.dx=0.00625 --set run.dt=2.2e-4"
for part in $parts; do
  case $part in
    study)
      sweep -o "$out/study64" --set model.K=2e-5,3e-5,6e-5,1e-4,1.8e-4,3e-4
      # K = 1e-5: interface 1 cell wide on 64², so the study's grid for it is 128² (to t = 4 like the rest)
      sweep -o "$out/study128" --set model.K=1e-5 $g128 ;;
    conv)  # the same band-limited noise on 64² (study64), 96² and 128²; t_SD ≈ 0.46, 0.54 and 1.58 on 64²; end times: past the last peak
      for K_end in 2e-5:1.0 3e-5:1.2 1.8e-4:2.0; do
        K=${K_end%:*} end=${K_end#*:}
        sweep -o "$out/conv96_K$K" --set model.K=$K --set run.end_time=$end $g96
        sweep -o "$out/conv128_K$K" --set model.K=$K --set run.end_time=$end $g128
      done
      # K = 1e-5 (study on 128²) on the coarser grids and on 160², to t = 4
      sweep -o "$out/conv64_K1e-5" --set model.K=1e-5
      sweep -o "$out/conv96_K1e-5" --set model.K=1e-5 $g96
      sweep -o "$out/conv160_K1e-5" --set model.K=1e-5 $g160 ;;
    sensitivity)  # assumptions the paper does not give: noise amplitude, quench depth (ρ_th: extra_thresholds)
      # the study's K on 64² (K = 1e-5 needs 128², 40 min: left out), enough for the eq. 34 cubic
      sensitivity_K=2e-5,3e-5,6e-5,1e-4,1.8e-4,3e-4
      sweep -o "$out/noise0.02" --set model.K=$sensitivity_K --set initial.noise=0.02
      sweep -o "$out/quench0.80" --set model.K=$sensitivity_K --set initial.T=0.80 ;;
    box)  # R_SD is 0.27-0.35 of the box 1 for K >= 1.8e-4: the same Δx and noise wavelength in a box 2 x 2
      # (128², 12 min each at load average 8-10), and box 1 with another noise seed: the realisations' spread
      sweep -o "$out/box2" --set model.K=1.8e-4,3e-4 --set grid.nx=128 --set grid.ny=128
      sweep -o "$out/box1_seed8" --set model.K=1.8e-4,3e-4 --set initial.seed=8 ;;
    *) echo "unknown part '$part' (study, conv, sensitivity, box)" >&2; exit 2 ;;
  esac
done
/usr/bin/python3 "$here/plot.py" "$out"

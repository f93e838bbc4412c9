#!/usr/bin/env bash
# MD domains -> phase field, on synthetic MD frames (no Fe potential shockfield reads transforms
# bcc -> hcp: examples/md_fe_alpha_epsilon). generate.py writes 19 frames (t = 0 ... 27 ps) of an
# fcc crystal with an hcp domain growing by dR/dt = c0 - 2D/R (c0 = 1 Å/ps, D = 4 Å²/ps);
# analyze atoms tracks it; bridge domain-growth fits c0 and D on t <= 15 ps and writes the
# material file; analyze atoms --voxel makes the hcp-fraction field of the 15 ps frame; the
# phase-field model runs from it to 27 ps and plot.py compares its R(t) with the MD's
# (compare.png). Then the decelerating growth R ~ t^0.465 of Xu et al. (2015), which the bridge
# refuses for the well-posed model, and which --law paper fits and the sharp-front option runs
# (paper_law.png). About 20 s of CPU. CHECK=1: exit 1 when the numbers leave the bounds of README.md.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exe=${SHOCKFIELD:-$here/../../build/release/shockfield}
out=${1:-runs/$(basename "$here")}
fit=15 width=2 dx=${DX:-0.6667}
export OMP_WAIT_POLICY=passive
rm -rf "$out" && mkdir -p "$out/frames" "$out/decelerating"
py=/usr/bin/python3
$py "$here/generate.py" "$out/frames" allen-cahn > "$out/frames/law.txt"
frames() { ls "$1"/grow.*.dump | sort -V; }
"$exe" analyze atoms $(frames "$out/frames") --clusters 3.0 --cluster-select acna:hcp --cluster-min-size 20 --track \
  --timestep-size 0.001 -o "$out/analysis" | tail -n 1
"$exe" bridge domain-growth "$out/analysis" --interface-width $width --until $fit -o "$out/fe_pf.toml" | tee "$out/bridge.txt"
"$exe" analyze atoms "$out/frames/grow.$((fit * 1000)).dump" --voxel "$dx" --voxel-smooth 1.5 -o "$out/voxels" \
  | tee "$out/voxels.txt" | tail -n 1
nodes=$(sed -n 's/.* \([0-9]*\) x \([0-9]*\) x \([0-9]*\) nodes.*/[\1, \2, \3]/p' "$out/voxels.txt")
tau_ps=$($py -c "import tomllib,sys; print(tomllib.load(open(sys.argv[1],'rb'))['phasefield']['relaxation_time']*1e12)" "$out/fe_pf.toml")
end=$($py -c "print((27 - $fit) / $tau_ps)")
dt=$($py -c "print(0.85 * $dx**2 / (6 * $width**2 / 2))")
"$exe" run "$here/case.toml" -o "$out/pf" --overwrite -q --set "grid.nodes=$nodes" --set "grid.spacing=$dx" \
  --set "model.file='$(realpath "$out/fe_pf.toml")'" --set "initial.file='$(realpath "$out/voxels/voxels_$((fit * 1000)).vti")'" \
  --set "time.end_time=$end" --set "time.dt=$dt"
$py "$here/plot.py" "$out" $fit "$tau_ps"
# The decelerating growth: R = 8 Å (t/2 ps)^0.465, t = 2 ... 16 ps.
$py "$here/generate.py" "$out/decelerating" power --R0 8 --times 2,4,6,8,10,12,14,16 > /dev/null
"$exe" analyze atoms $(frames "$out/decelerating") --clusters 3.0 --cluster-select acna:hcp --cluster-min-size 20 --track \
  --timestep-size 0.001 -o "$out/decelerating/analysis" | head -n 1
set +e
"$exe" bridge domain-growth "$out/decelerating/analysis" --interface-width $width -o "$out/decelerating.toml" 2> "$out/refused.txt"
code=$?
set -e
echo "decelerating growth: exit $code: $(cat "$out/refused.txt")"
[ "${CHECK:-0}" != 1 ] || { [ $code -eq 2 ] && [ ! -e "$out/decelerating.toml" ] && grep -q "is not positive" "$out/refused.txt"; }
# The same series under the paper's law (--law paper: dR/dt = c0 + 2D/R, D > 0 accepted), run by the
# sharp-front option ([model] kind = "sharp_front") from the fitted radius at 2 ps to 16 ps.
"$exe" bridge domain-growth "$out/decelerating/analysis" --law paper -o "$out/paper.toml" | tee "$out/paper.txt"
R0=$($py -c "import tomllib,sys; print(tomllib.load(open(sys.argv[1],'rb'))['provenance']['domain_growth']['fit']['R0_m']*1e10)" "$out/paper.toml")
"$exe" run "$here/sharp_front.toml" -o "$out/sharp" --overwrite -q --set "model.file='$(realpath "$out/paper.toml")'" \
  --set "initial.sphere[0].radius=$R0"
$py "$here/plot_paper.py" "$out"

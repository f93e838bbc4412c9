#!/bin/sh
# A sheared Cu crystal relaxed by npt's tilt degrees of freedom (couple = "tri", LAMMPS `fix npt
# ... tri`): sheared to gamma = 0.02 in 2 ps, then 8 ps of npt tri at 300 K, 0 bar; relax.png.
# About 5 s on one core.   examples/md_npt_tri_relax/run.sh [RUNS_DIR]   (from the repository root)
set -eu
. "$(dirname "$0")/../run_common.sh"
export OMP_WAIT_POLICY=passive
rm -rf "$runs/relax"
"$bin" run "$here/case.toml" -o "$runs/relax" -q
/usr/bin/python3 "$here/plot.py" "$runs/relax" "$here/relax.png" "$(cd "$here/../.." && pwd)"

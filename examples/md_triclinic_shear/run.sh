#!/bin/sh
# Simple shear of fcc Cu in a triclinic cell (issue 18): strains gamma = -0.02 .. 0.02 carried by
# the tilt xy = gamma·ly, one force evaluation each, the shear stress against gamma and the
# slope C44 beside LAMMPS's C44 of the same potential (tests/fixtures/lammps_elastic): shear.png.
# A few seconds.   examples/md_triclinic_shear/run.sh [RUNS_DIR]   (from the repository root)
set -eu
. "$(dirname "$0")/../run_common.sh"
strains="-0.02 -0.01 -0.005 0 0.005 0.01 0.02"
/usr/bin/python3 "$here/make_sheared.py" "$runs" $strains
export OMP_WAIT_POLICY=passive
for g in $strains; do
  rm -rf "$runs/run_$g"
  "$bin" run "$here/case.toml" -o "$runs/run_$g" -q --set "system.data_file=\"$(cd "$runs" && pwd)/sheared_$g.data\""
done
/usr/bin/python3 "$here/plot.py" "$runs" "$here/shear.png" $strains

#!/bin/sh
# The Hugoniostat scan of bcc Fe along [001]: every Fe potential of /usr/share/lammps/potentials
# that shockfield reads (eam/fs; FeCr.cdeam is eam/cd, not supported) at 15, 20, 30, 40 and 60 GPa,
# two runs at a time on one thread each, then adaptive CNA of every dump (one per ps).
#   examples/md_fe_alpha_epsilon/scan.sh [RUNS_DIR]   (from the repository root)
set -eu
. "$(dirname "$0")/../run_common.sh"
pressures="150000 200000 300000 400000 600000"   # bar
potentials="Fe_mm FeP_mm AlFe_mm VFe_mm"
one() {  # potential pressure
  d="$runs/nphug/$1/p$2"
  rm -rf "$d"
  OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive "$bin" run "$here/nphug.toml" -o "$d" -j1 -q \
    --set "potential.file=\"$1.eam.fs\"" --set 'potential.elements=["Fe"]' \
    --set "stage[1].nphug.pressure=$2" > /dev/null
  "$bin" analyze atoms "$d" -o "$d/analysis" -j1 > /dev/null
}
for pot in $potentials; do
  set -- $pressures
  while [ $# -gt 0 ]; do
    one "$pot" "$1" &
    if [ $# -gt 1 ]; then one "$pot" "$2" & shift; fi
    shift; wait
  done
done
/usr/bin/python3 "$here/plot_nphug_scan.py" "$runs/nphug" "$here"

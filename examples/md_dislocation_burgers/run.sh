#!/usr/bin/env bash
# Builds a Cu edge dislocation (Volterra field), relaxes it with the MD minimiser (it dissociates
# into two Shockley partials), finds the Burgers vectors by the Frank scheme and draws them.
# About 10 s on one core. Usage: bash run.sh [BUILD_DIR] (default ../../build/release).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
SF="${1:-$here/../../build/release}/shockfield"
PY=/usr/bin/python3
out="$here/../../runs/md_dislocation_burgers"
rm -rf "$out"
mkdir -p "$out"
cd "$here"
sh prepare.sh
"$SF" run case.toml -o "$out/relax" -j 1 > "$out/run.log"
"$SF" analyze atoms "$out/relax" --clusters 3.0 --cluster-select 'acna:!fcc,hcp' --cluster-min-size 10 \
  --burgers-orient '1 -1 0,1 1 1,-1 -1 2' --burgers-lattice 3.615 \
  --burgers-line 0.37,1.04,8.85:0,0,1:25 --burgers-clusters -o "$out/analysis"
cut -d, -f3,4,13,14 "$out/analysis/burgers.csv" | column -t -s,
$PY plot.py "$out/analysis" "$here/burgers.png"

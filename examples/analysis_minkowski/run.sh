#!/usr/bin/env bash
# Generates the example's fields (make_fields.py, numpy) and runs the three analyses of README.md.
#   examples/analysis_minkowski/run.sh [SHOCKFIELD_BINARY [OUTPUT_FOLDER]]
# Defaults: `shockfield` on the PATH, output in runs/analysis_minkowski.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
sf=${1:-shockfield}
out=${2:-runs/analysis_minkowski}
/usr/bin/python3 "$here/make_fields.py"
T=0,0.2,0.4,0.6,0.8,1.0
"$sf" analyze minkowski "$here"/fields/ref_t{0..5}.csv --times $T -t 310,330,350,370,390,410 \
  -o "$out/minkowski"
"$sf" analyze similarity -r "$here"/fields/ref_t{0..5}.csv --reference-threshold 350 \
  "$here"/fields/hot_t{0..5}.csv --times $T -n 60 -o "$out/similarity"
"$sf" analyze stats "$here"/fields/ref_t{0..5}.csv --times $T -o "$out/stats"

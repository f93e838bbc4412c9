#!/usr/bin/env bash
# Generates the example's fields (make_fields.py, numpy) into the output folder, runs the three
# analyses of README.md and copies their pictures beside this script.
#   examples/analysis_minkowski/run.sh [SHOCKFIELD_BINARY [OUTPUT_FOLDER]]
# Defaults: `shockfield` on the PATH, output in runs/analysis_minkowski.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
sf=${1:-shockfield}
out=${2:-runs/analysis_minkowski}
fields="$out/fields"
/usr/bin/python3 "$here/make_fields.py" "$fields"
T=0,0.2,0.4,0.6,0.8,1.0  # a dimensionless time: the tables' time_1 column
"$sf" analyze minkowski "$fields"/ref_t{0..5}.csv --times $T --time-units 1 -t 310,330,350,370,390,410 \
  -o "$out/minkowski"
"$sf" analyze similarity -r "$fields"/ref_t{0..5}.csv --reference-threshold 350 \
  "$fields"/hot_t{0..5}.csv --times $T --time-units 1 -n 60 -o "$out/similarity"
"$sf" analyze stats "$fields"/ref_t{0..5}.csv --times $T --time-units 1 -o "$out/stats"
for picture in minkowski/minkowski.png similarity/similarity.png; do
  [ -f "$out/$picture" ] && cp "$out/$picture" "$here/"
done

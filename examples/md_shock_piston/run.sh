#!/bin/sh
# Piston shock at 1 km/s in EAM copper: the run, its Hugoniot state (hugoniot_shock.toml) and profiles.png,
# then the same shock in two runs chained through final.data (case.toml cut after 1300 shock steps, then
# case_part2.toml), compared with the one-part run by compare_parts.py (a few minutes on two cores).
#   examples/md_shock_piston/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run" "$runs/part1" "$runs/part2"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -3
"$bin" plot profiles "$runs/run" -o "$here/profiles.png"
cat "$runs/run/hugoniot_shock.toml"
# Part 1: the same case with its shock stage cut to 1300 of its 2500 steps. Part 2 reads part 1's
# final.data (positions, velocities) and puts the piston where part 1 left it (the last piston_A).
"$bin" run "$here/case.toml" -o "$runs/part1" -j2 --set 'stage[1].steps=1300' | tail -1
piston=$(tail -1 "$runs/part1/shock_front_shock.csv" | cut -d, -f4)
data="$(cd "$runs/part1" && pwd)/final.data"
"$bin" run "$here/case_part2.toml" -o "$runs/part2" -j2 --set "system.data_file=\"$data\"" \
  --set "stage[0].piston.position=$piston" | tail -1
PYTHONPATH="${PYTHONPATH:-$(cd "$here/../.." && pwd)/build/release/python}" /usr/bin/python3 "$here/compare_parts.py" "$runs/run" "$runs/part2"

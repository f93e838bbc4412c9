#!/bin/sh
# Sod shock tube with the discrete Boltzmann model: the run; the plateau of profiles/profile_4.csv beside the exact star state of config.resolved.toml; profiles.png and tne.png (`shockfield plot`).
#   examples/dbm_sod/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run"
"$bin" run "$here/case.toml" -o "$runs/run" | tail -1
awk -F, 'NR > 1 && $1 > 0.55 && $1 < 0.82 { p += $5; u += $3; n++ } END { printf "DBM plateau: p* = %.5f, u* = %.5f\n", p / n, u / n }' "$runs/run/profiles/profile_4.csv"
grep -E "exact_(p|u)_star" "$runs/run/config.resolved.toml"
"$bin" plot profiles "$runs/run" -o "$here/profiles.png"
"$bin" plot tne "$runs/run" -o "$here/tne.png"

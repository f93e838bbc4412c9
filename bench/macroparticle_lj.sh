#!/usr/bin/env bash
# Macroparticle pair law against the MD engine's LJ on about 10^6 particles (issue 20's
# performance goal), alternated in the same minutes: ROUNDS rounds of, for 1 and 2 threads,
# LJ (bench/cases/lj.toml at 63^3 cells: 1 000 188 atoms, in.lj's work, 100 steps) then the
# macroparticle box (bench/cases/macroparticle_box.toml at 62^3 cells: 976 563 particles, 100
# steps) with each binary given. Prints one line per run: label threads rate (per particle-step)
# and the force time per step; the load average before each round.
# Usage: bench/macroparticle_lj.sh [SHOCKFIELD [OTHER_SHOCKFIELD]]   (ROUNDS=3)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
sf="${1:-$root/build/release/shockfield}"
other="${2:-}"
rounds="${ROUNDS:-3}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
export OMP_WAIT_POLICY=passive
rate() { grep -o '[0-9.e+]* [a-z]*-steps/s' "$1/log.txt" | tail -1 | cut -d' ' -f1; }
force() { grep -o 'of which force [0-9.e+-]* s' "$1/log.txt" | tail -1 | awk '{print $4}'; }
for r in $(seq "$rounds"); do
  echo "# round $r, load $(cut -d' ' -f1-3 /proc/loadavg)"
  for j in 1 2; do
    "$sf" run "$root/bench/cases/lj.toml" -q --overwrite -o "$out/lj" -j "$j" --set 'system.lattice.repeat=[63,63,63]'
    echo "lj $j $(rate "$out/lj") force_s $(force "$out/lj")"
    for b in "$sf" $other; do
      "$b" run "$root/bench/cases/macroparticle_box.toml" -q --overwrite -o "$out/mp" -j "$j" --set 'specimen.cells=[62,62,62]'
      echo "macroparticle:$b $j $(rate "$out/mp") force_s $(force "$out/mp")"
    done
  done
done

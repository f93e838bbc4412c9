#!/bin/bash
# User cycles per particle-step of one mpm_bench configuration, less sensitive to a loaded machine
# than wall time: perf stat cycles of `BIN STEPS CASE THREADS` minus those of `BIN 0 CASE THREADS`
# (set-up and warm-up step), divided by STEPS × points; cycles are summed over the threads.
#   bench/mpm_cycles.sh BIN 2d|3d 1|2 STEPS
set -euo pipefail
bin=$1 case=$2 threads=$3 steps=$4
export OMP_WAIT_POLICY=passive
cycles() { perf stat -x, -e cycles:u "$bin" "$1" "$case" "$threads" 2>&1 >/dev/null | grep cycles | cut -d, -f1; }
c0=$(cycles 0)
out=$(perf stat -x, -e cycles:u "$bin" "$steps" "$case" "$threads" 2>&1)
c1=$(echo "$out" | grep cycles | cut -d, -f1)
points=$(echo "$out" | grep particle-steps | sed 's/.*: *\([0-9]*\) particles.*/\1/')
rate=$(echo "$out" | grep particle-steps | sed 's/.*steps, \([0-9.e+]*\) particle.*/\1/')
echo "$(( (c1 - c0) / (steps * points) )) cycles/particle-step ($rate particle-steps/s wall)"

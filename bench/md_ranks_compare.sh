#!/usr/bin/env bash
# MD on MPI ranks against LAMMPS on the same work in the same minutes (docs/parallel.md,
# bench/RESULTS.md "## MD on MPI ranks"): LAMMPS's bench/lammps/in.eam (32,000 Cu atoms, EAM,
# 100 NVE steps) as shockfield's decomposed Simulation (bench/md_ranks_bench.cpp) on 1 and 2 ranks
# and as LAMMPS (Debian's, MPI-built) on 1 and 2 ranks, alternated RUNS times, one thread per rank.
# Prints each run's loop seconds and the medians.
# Usage: bench/md_ranks_compare.sh [RUNS=3]    (repository root; MPI Release build in build/release)
set -euo pipefail
runs=${1:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
bench=$root/build/release/bench/md_ranks_bench
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-/usr/share/lammps/potentials}
cd "$work"
sf() { mpirun --oversubscribe -np "$1" "$bench" 20 100 | sed -n 's/.*loop \([0-9.]*\) s.*exchange \([0-9.]*\) ms.*/\1 \2/p'; }
lmp_loop() {
  mpirun --oversubscribe -np "$1" lmp -nocite -screen none -log log.lmp -in "$root/bench/lammps/in.eam" > /dev/null
  awk '/^Loop time of/ {print $4}' log.lmp
}
for ((r = 1; r <= runs; ++r)); do
  for np in 1 2; do
    read -r loop halo <<< "$(sf $np)"
    echo "shockfield np$np $loop $halo" | tee -a results.txt
    echo "lammps np$np $(lmp_loop $np) -" | tee -a results.txt
  done
done
echo "median loop seconds (exchange ms/step for shockfield):"
for who in shockfield lammps; do
  for np in 1 2; do
    awk -v w=$who -v n=np$np '$1 == w && $2 == n {print $3, $4}' results.txt | sort -n |
      awk -v w=$who -v n=$np '{a[NR] = $1; h[NR] = $2} END {m = int((NR + 1) / 2); printf "%s np%d: %s s (exchange %s)\n", w, n, a[m], h[m]}'
  done
done

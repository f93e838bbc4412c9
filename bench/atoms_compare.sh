#!/bin/sh
# CNA + CSP + coordination on ~10⁶ Cu atoms: shockfield (atoms_bench, 1 and 2 threads, analysis
# only) alternated run by run with LAMMPS (`run 0` with cna/atom + centro/atom + coord/atom, minus
# the same run without them), the load average before each run, then the peak RSS of
# `shockfield analyze atoms` (the command-line tool, 1 thread) on the same atoms. Medians by
# bench/atoms_compare_summary.py. The machine is shared: read the load averages beside the times.
#   sh bench/atoms_compare.sh [BUILD_DIR] [ROUNDS] [CELLS]     (from the repository root)
set -eu
build=${1:-build/release}
rounds=${2:-5}
cells=${3:-63}
out=${OUT:-runs/bench_atoms}
mkdir -p "$out"
bench="$build/bench/atoms_bench"
data="$out/cu_${cells}.data"
log="$out/rounds.txt"
export OMP_WAIT_POLICY=passive LAMMPS_POTENTIALS=/usr/share/lammps/potentials
"$bench" --cells "$cells" --write-data "$data"
rc=3.0858
lmp_in() {  # with|without
  {
    printf 'units metal\natom_style atomic\nboundary p p p\nread_data %s\npair_style eam\npair_coeff * * Cu_u3.eam\n' "$data"
    if [ "$1" = with ]; then
      printf 'compute cna all cna/atom %s\ncompute csp all centro/atom fcc\ncompute coord all coord/atom cutoff %s\n' $rc $rc
      printf 'variable isfcc atom c_cna==1\ncompute nfcc all reduce sum v_isfcc\ncompute sumcsp all reduce sum c_csp\n'
      printf 'compute sumcoord all reduce sum c_coord\nthermo_style custom step c_nfcc c_sumcsp c_sumcoord\n'
    fi
    printf 'run 0\n'
  } > "$out/in.$1"
}
lmp_in with; lmp_in without
: > "$log"
for r in $(seq 1 "$rounds"); do
  echo "round $r load $(cut -d' ' -f1-3 /proc/loadavg)" >> "$log"
  "$bench" --cells "$cells" --repeats 1 --no-lammps | sed "s/^/round $r ours: /" >> "$log"
  for w in without with; do
    echo "round $r load $(cut -d' ' -f1-3 /proc/loadavg)" >> "$log"
    OMP_NUM_THREADS=1 /usr/bin/time -f "%e %U %S %M" -o "$out/time.$w" lmp -nocite -screen none -log "$out/log.$w" -in "$out/in.$w" > /dev/null
    echo "round $r lammps $w: $(cat "$out/time.$w")" >> "$log"
  done
  tail -n 7 "$log"
done
grep -A1 "c_nfcc" "$out/log.with" | tail -1 | sed 's/^/lammps fcc count line: /' >> "$log"
# Peak RSS of the command-line tool on the same atoms (reads the data file, writes the annotated dump).
for j in 1 2; do
  echo "load $(cut -d' ' -f1-3 /proc/loadavg)" >> "$log"
  /usr/bin/time -v "$build/shockfield" analyze atoms "$data" --cna $rc --csp fcc --coordination $rc -j $j -o "$out/cli$j" \
    2> "$out/cli$j.time" | tail -1
  echo "cli -j $j: $(grep -E 'Elapsed|Maximum resident' "$out/cli$j.time" | tr -s ' ' | tr '\n' ';')" >> "$log"
done
rm -f "$out/cli1/"*.dump "$out/cli2/"*.dump
/usr/bin/python3 "$(dirname "$0")/atoms_compare_summary.py" "$log"

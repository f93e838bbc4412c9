# Shared by the MD bench scripts (run_md_bench.sh, md_table_bench.sh), sourced with the script's
# arguments: strict mode; runs = the first argument (default 5); root = the repository; sf = the
# shockfield binary ($SHOCKFIELD, else build/release/shockfield); work = a temporary folder
# /tmp/<bench_name>.XXXXXX removed on exit; the work of LAMMPS's in.lj/in.eam (32,000 atoms,
# 100 steps); median of the numbers on stdin.
set -euo pipefail
runs=${1:-5}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
sf=${SHOCKFIELD:-$root/build/release/shockfield}
work=$(mktemp -d "/tmp/${bench_name}.XXXXXX")
trap 'rm -rf "$work"' EXIT
atoms=32000
steps=100
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

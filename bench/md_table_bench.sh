#!/usr/bin/env bash
# pair_style table against lj/cut on LAMMPS's in.lj work (issue 18): 32,000 LJ atoms, 100 NVE
# steps, one thread. shockfield: bench/cases/lj.toml (lj/cut) and the same case on an LJ table
# of the same ε, σ, cutoff (N 1000 RSQ from 0.6σ to 2.5σ; `linear 1000`, which takes the file as
# its inner table, and `spline 1000`). LAMMPS: bench/lammps/in.lj and the same input on the same
# table in reduced units. The six runs alternate, RUNS times each; medians of the loop time
# (shockfield's run-stage rate, LAMMPS's "Loop time") per atom-step.
# Usage: bench/md_table_bench.sh [RUNS=5]   (repository root; Release build in build/release)
bench_name=md_table_bench
source "$(dirname "$0")/md_bench_lib.bash" "$@"

# table FILE EPSILON SIGMA: section LJ, N 1000 RSQ 0.6σ 2.5σ, energy and force of LJ.
table() {
  python3 - "$@" <<'PY'
import math, sys
path, eps, sigma = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
n, rlo, rhi = 1000, 0.6 * sigma, 2.5 * sigma
with open(path, "w") as out:
    out.write(f"LJ\nN {n} RSQ {rlo!r} {rhi!r}\n\n")
    for i in range(n):
        r = math.sqrt(rlo * rlo + (rhi * rhi - rlo * rlo) * i / (n - 1))
        sr6 = (sigma / r) ** 6
        out.write(f"{i + 1} {r!r} {4 * eps * (sr6 * sr6 - sr6)!r} {24 * eps * (2 * sr6 * sr6 - sr6) / r!r}\n")
PY
}
table "$work/lj_metal.table" 0.0104 3.405
table "$work/lj_reduced.table" 1.0 1.0

# shockfield cases: lj.toml with its [potential] replaced by the table.
for style in linear spline; do
  awk -v style="$style" -v file="$work/lj_metal.table" '
    /^\[potential\]/ {print; print "style = \"table\""; print "interpolation = \"" style "\"";
                      print "points = 1000"; print "file = \"" file "\""; print "keyword = \"LJ\""; skip = 1; next}
    /^\[/ {skip = 0}
    !skip {print}' "$root/bench/cases/lj.toml" > "$work/table_$style.toml"
  sed "s|^pair_style.*|pair_style table $style 1000|; s|^pair_coeff.*|pair_coeff 1 1 $work/lj_reduced.table LJ|" \
    "$root/bench/lammps/in.lj" > "$work/in.table_$style"
done
cp "$root/bench/cases/lj.toml" "$work/lj.toml"
cp "$root/bench/lammps/in.lj" "$work/in.lj"

alternate lj table_linear table_spline
ratio_table lj lj table_linear table_spline

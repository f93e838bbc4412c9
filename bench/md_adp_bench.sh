#!/usr/bin/env bash
# pair_style adp beside eam/alloy on one Ni cell (issue 18): 32,000 atoms (fcc a0 = 3.52 Å,
# 20x20x20 cells, periodic), 300 K, dt 2 fs, skin 1 Å, 100 NVE steps, one thread. ADP: Ni.adp;
# eam/alloy: NiAlH_jea.eam.alloy (Ni). shockfield: bench/cases/eam.toml with this cell and
# potential; LAMMPS: bench/lammps/in.eam likewise. The four runs alternate, RUNS times each;
# medians of the loop time (shockfield's run-stage rate, LAMMPS's "Loop time") per atom-step.
# Usage: bench/md_adp_bench.sh [RUNS=5]   (repository root; Release build in build/release)
bench_name=md_adp_bench
source "$(dirname "$0")/md_bench_lib.bash" "$@"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"

# case STYLE FILE: eam.toml on the Ni cell with this potential.
case_file() {
  awk -v style="$1" -v file="$2" '
    /^\[potential\]/ {print; print "style = \"" style "\""; print "file = \"" file "\""; print "elements = [\"Ni\"]"; skip = 1; next}
    /^\[/ {skip = 0}
    /^a0 =/ {print "a0 = 3.52"; next}
    /^elements =/ && !skip {print "elements = [\"Ni\"]"; next}
    /^timestep =/ {print "timestep = 0.002"; next}
    /^temperature =/ {print "temperature = 300.0"; next}
    !skip {print}' "$root/bench/cases/eam.toml"
}
lammps_input() {  # STYLE FILE
  sed "s|^lattice.*|lattice fcc 3.52|; s|^pair_style.*|pair_style $1|; s|^pair_coeff.*|pair_coeff * * $2 Ni|;
       s|^velocity.*|velocity all create 300.0 376847 loop geom|; s|^timestep.*|timestep 0.002|" \
    "$root/bench/lammps/in.eam"
}
case_file adp Ni.adp > "$work/adp.toml"
case_file eam/alloy NiAlH_jea.eam.alloy > "$work/eam_alloy.toml"
lammps_input adp Ni.adp > "$work/in.adp"
lammps_input eam/alloy NiAlH_jea.eam.alloy > "$work/in.eam_alloy"

alternate eam_alloy adp
ratio_table eam_alloy eam_alloy adp

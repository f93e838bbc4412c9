#!/usr/bin/env bash
# Bad MPM case files: one clear message naming file, key and line, exit code 2, nothing left
# behind (porosity that cannot be packed, a cavity outside its body, a body outside the grid, a
# fixed time step beyond the CFL limit, unknown keys and materials, a negative conductivity, a
# heat_conduction switch that is not a boolean).
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/mpm_tiny.toml")

expect_error "${base/void_radius = 40e-6/void_raduis = 40e-6}" "case.toml" "body[0].void_radius" "missing required value"
expect_error "${base/porosity = 0.05/porosity = 0.05
colour = 1}" "unknown key" "body[0].colour"
expect_error "${base/porosity = 0.05/porosity = 0.6}" "body[0].porosity" "random-packing limit"
expect_error "${base/void_radius = 40e-6/void_radius = 300e-6}" "body[0].porosity" "do not fit the body"
expect_error "${base/porosity = 0.05
void_radius = 40e-6/cavity_depth = 480e-6
cavity_radius = 50e-6}" "body[0].cavity_depth" "does not lie inside the body"
expect_error "${base/hi = \[0.4e-3, 0.5e-3\]/hi = [0.4e-3, 0.7e-3]}" "body[0].hi" "outside the grid"
expect_error "${base/lo = \[0.0, 0.0\]
hi = \[0.4e-3, 0.5e-3\]/lo = [0.0, 0.1e-3]
hi = [0.4e-3, 0.5e-3]}" "body[0].lo" "within one cell of the wall"
expect_error "${base/hi = \[0.4e-3, 0.6e-3\]/hi = [0.41e-3, 0.6e-3]}" "grid.hi" "whole number"
expect_error "${base/end_time = 40e-9/end_time = 40e-9
time_step = 1e-8}" "solver.time_step" "beyond the CFL limit"
expect_error "${base/library = \"aluminium_seed000\"/library = \"unobtainium\"}" "material[0].library" "expected one of"
expect_error "${base/library = \"aluminium_seed000\"/library = \"aluminium_seed000\"
yield_stress = -1.0}" "material[0].yield_stress"
expect_error "${base/library = \"aluminium_seed000\"/library = \"aluminium_seed000\"
spall_strength = -1e9}" "material[0].spall_strength"
expect_error "${base/library = \"aluminium_seed000\"/library = \"aluminium_seed000\"
conductivity = -1.0}" "material[0].conductivity"
expect_error "${base/end_time = 40e-9/end_time = 40e-9
heat_conduction = \"yes\"}" "solver.heat_conduction"
expect_error "${base/material = \"al\"/material = \"steel\"}" "body[0].material" "no [[material]] named"
expect_error "${base/speed = 1000.0/}" "loading.speed" "missing required value"
expect_error "$base
[contact]
enabled = true
friction = -0.5" "contact.friction"
expect_error "$base
[contact]
friction = 0.5" "contact.friction" "set enabled = true"
expect_error "${base/type = \"wall\"/type = \"wall\"
wall = \"free\"}" "loading.wall" "stick"
# Sizes counted before anything is made (issue 14): a body spacing giving 2e13 particles is
# refused by key; a grid of 6e8 nodes (a box from -1 m on 1 µm cells, as fuzz_slow.case_check
# seed 2 found) is within the 1e9 bound and `--check` validates it without allocating the grid:
# in 2 GB of address space, where the grid's fields alone need 60 GB (it stopped with exit 3,
# "out of memory", before).
expect_error "${base/porosity = 0.05/spacing = 1e-10
porosity = 0.05}" "body[0].spacing" "2e+13 particles" "at most 1e+08"
big="${base/cell_size = 25e-6/cell_size = 1e-6}"
big="${big/end_time = 40e-9/end_time = 40e-9
shape = \"linear\"}"
big="${big/porosity = 0.05/spacing = 12.5e-6
porosity = 0.05}"
big="${big/lo = \[0.0, 0.0\]
hi = \[0.4e-3, 0.6e-3\]/lo = [-1.0, 0.0]
hi = [0.4e-3, 0.6e-3]}"
printf '%s\n' "$big" > "$WORK/big.toml"
set +e
(ulimit -v 2000000; "$SF" run "$WORK/big.toml" --check > "$WORK/stdout" 2> "$WORK/stderr")
code=$?
set -e
[ $code -eq 0 ] || fail "--check of a 6e8-node grid: exit $code (expected 0): $(cat "$WORK/stderr")"
grep -qF "601240400 grid nodes" "$WORK/stdout" || fail "--check does not report the 601240400 grid nodes: $(cat "$WORK/stdout")"
echo "ok: $(cat "$WORK/stdout")"
echo "mpm_bad_input: all cases rejected cleanly"

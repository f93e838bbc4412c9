#!/usr/bin/env bash
# Bad case files: each gives one clear message naming file, key and line, exit code 2, and
# leaves nothing behind.
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/tiny_cu.toml")

expect_error "${base/skin = 1.0/skni = 1.0}" "case.toml" "unknown key" "'md.skni' (line"
expect_error "${base/timestep = 0.002/timestep = \"fast\"}" "case.toml:" "md.timestep" "expected a number"
expect_error "${base/timestep = 0.002/timestep = -0.002}" "md.timestep" "expected a number in (0, 0.1]"
expect_error "${base/ensemble = \"nvt\"/ensemble = \"npe\"}" "stage[0].ensemble" "expected one of"
expect_error "${base/steps = 100/}" "stage[0].steps" "missing required value"
expect_error "${base/file = \"Cu_u3.eam\"/file = \"Nope.eam\"}" "potential.file" "Nope.eam"
expect_error "${base/style = \"fcc\"/style = \"fcx\"}" "system.lattice.style" "expected one of"
expect_error "${base/method = \"md\"/method = \"xyz\"}" "key 'method'" "expected one of"
expect_error "method = \"md\"
[system.lattice]
style = \"fcc\"
a0 = 3.615
repeat = [2, 2, 2]
elements = [\"Cu\"]
[potential]
style = \"eam\"
file = \"Cu_u3.eam\"
[md]
timestep = 0.001" "key 'stage'" "at least one [[stage]]"
expect_error "${base} = broken" "case.toml:" "TOML syntax error"
# Two atoms on top of each other (a data file with an overlap).
cat > "$WORK/overlap.data" <<'DATA'
overlap test

2 atoms
1 atom types

0 10 xlo xhi
0 10 ylo yhi
0 10 zlo zhi

Masses

1 63.55

Atoms # atomic

1 1 5.0 5.0 5.0
2 1 5.0 5.0 5.01
DATA
expect_error "method = \"md\"
[system]
data_file = \"overlap.data\"
[potential]
style = \"eam\"
file = \"Cu_u3.eam\"
[md]
timestep = 0.001
[[stage]]
steps = 10" "closer than"
echo "bad_input: all cases rejected cleanly"

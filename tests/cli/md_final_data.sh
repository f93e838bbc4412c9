#!/usr/bin/env bash
# final.data of every MD example (examples/md_*/case.toml, each stage cut to STEPS steps with
# --set) is read back, every atom assigned, by LAMMPS read_data (skipped with a message when `lmp`
# is not installed) and by shockfield's own data-file reader (`run --check` on a case reading it).
# Before the fix, a shrink-wrapped dimension was written with the box of the last neighbour
# rebuild: atoms that had moved past it since were refused ("Did not assign all atoms correctly").
# Then part 2 of the chained piston example (examples/md_shock_piston/case_part2.toml) continues
# part 1's shock from its final.data for a few steps.
source "$(dirname "$0")/lib.bash"
set -e
STEPS=${STEPS:-20}
have_lmp=1
command -v lmp > /dev/null || { have_lmp=0; echo "SKIP (LAMMPS part): lmp is not installed (Debian package lammps)"; }

# The --set arguments that cut every stage of a case to $STEPS steps (a minimisation to 50 iterations),
# then the boundary codes of its [system].
case_facts() {
  /usr/bin/python3 - "$1" "$STEPS" <<'PY'
import sys, tomllib
case = tomllib.load(open(sys.argv[1], "rb"))
args = []
for k, stage in enumerate(case["stage"]):
    if stage.get("ensemble") == "minimize":
        args.append(f"stage[{k}].max_iterations=50")
    else:
        args.append(f"stage[{k}].steps={sys.argv[2]}")
system = case["system"]
print(" ".join(args))
print(system.get("boundary") or system.get("lattice", {}).get("boundary", "ppp"))
PY
}

# check_data FILE BOUNDARY: every atom of FILE is assigned by LAMMPS and by shockfield.
check_data() {
  local data="$1" boundary="$2" natoms
  natoms=$(awk '$2 == "atoms" { print $1; exit }' "$data")
  [ -n "$natoms" ] && [ "$natoms" -gt 0 ] || fail "$data: no atom count in the header"
  if [ $have_lmp -eq 1 ]; then
    lammps_reads_data "$data" "$natoms" "$boundary"
  fi
  cat > "$WORK/read.toml" <<EOF
method = "md"
[system]
data_file = "$data"
boundary = "$boundary"
[potential]
style = "eam"
file = "Cu_u3.eam"
[md]
timestep = 0.001
[[stage]]
steps = 1
EOF
  "$SF" run "$WORK/read.toml" --check > "$WORK/check.out" 2>&1 || fail "$data: shockfield refuses it: $(cat "$WORK/check.out")"
  grep -q "($natoms atoms" "$WORK/check.out" || fail "$data: shockfield did not read $natoms atoms: $(cat "$WORK/check.out")"
  echo "ok: $data: $natoms atoms read by$([ $have_lmp -eq 1 ] && echo " LAMMPS and") shockfield"
}

count=0
for case_file in "$ROOT"/examples/md_*/case.toml; do
  example=$(basename "$(dirname "$case_file")")
  if [ -f "$(dirname "$case_file")/prepare.sh" ]; then  # generated inputs: prepare a copy
    mkdir -p "$WORK/prepared/$example" && cp -r "$(dirname "$case_file")"/. "$WORK/prepared/$example"/
    sh "$WORK/prepared/$example/prepare.sh" > /dev/null || fail "$example/prepare.sh failed"
    case_file="$WORK/prepared/$example/case.toml"
  fi
  facts=$(case_facts "$case_file")
  sets=()
  for s in $(echo "$facts" | head -1); do sets+=(--set "$s"); done
  sets+=(--set "output.profile_every=$STEPS")  # the piston's last position is in the last profile row
  out="$WORK/$example"
  OMP_WAIT_POLICY=passive "$SF" run "$case_file" -o "$out" -q -j 2 "${sets[@]}" > /dev/null 2> "$WORK/stderr" \
    || fail "$example: run failed: $(tail -c 400 "$WORK/stderr")"
  check_data "$out/final.data" "$(echo "$facts" | tail -1)"
  count=$((count + 1))
done
[ $count -ge 4 ] || fail "only $count MD examples found"

# A slab drifting at 5 Å/ps along its shrink-wrapped z with skin 1 Å: the list is rebuilt every
# 100 steps, so after 150 steps every atom is 0.25 Å beyond the box of the last rebuild, which the
# old final.data carried (LAMMPS then assigned none of the top layer).
cat > "$WORK/drift.toml" <<'EOF'
method = "md"
[system.lattice]
style = "fcc"
a0 = 3.615
repeat = [3, 3, 6]
boundary = "pps"
elements = ["Cu"]
[potential]
style = "eam"
file = "Cu_u3.eam"
[md]
skin = 1.0
[[velocity.add]]
group = "all"
velocity = [0.0, 0.0, 5.0]
[[stage]]
steps = 150
EOF
"$SF" run "$WORK/drift.toml" -o "$WORK/drift" -q > /dev/null 2> "$WORK/stderr" || fail "drifting slab: $(cat "$WORK/stderr")"
check_data "$WORK/drift/final.data" pps

# The chained shock: part 2 reads part 1's final.data (velocities included) and the piston
# continues from where part 1 left it (the last piston_A of shock_front_shock.csv).
part1="$WORK/md_shock_piston"
piston=$(tail -1 "$part1/shock_front_shock.csv" | cut -d, -f4)
OMP_WAIT_POLICY=passive "$SF" run "$ROOT/examples/md_shock_piston/case_part2.toml" -o "$WORK/part2" -q -j 2 \
  --set "system.data_file=\"$part1/final.data\"" --set "stage[0].piston.position=$piston" \
  --set "stage[0].steps=20" > /dev/null 2> "$WORK/stderr" || fail "part 2 of the chained shock failed: $(tail -c 400 "$WORK/stderr")"
check_data "$WORK/part2/final.data" pps
echo "md_final_data: $count MD examples' final.data and the chained shock's read back"

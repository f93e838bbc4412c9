#!/usr/bin/env bash
# [output] h5md_every: the MD trajectory as H5MD (io/h5md_writer). Its positions, velocities, ids,
# types, box and times equal the full-precision LAMMPS dumps of the same steps; a run stopped and
# resumed writes the same frames as an uninterrupted one; MDAnalysis reads it (when installed);
# a damaged trajectory is refused on --resume by name (exit 2).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
# tiny_cu (256 atoms, 300 steps) with dumps and H5MD frames every 50 steps.
sed 's/^dump_every = 100$/dump_every = 50\nh5md_every = 50\nh5md_forces = true/; s/^dump_fields = .*/dump_fields = ["id", "type", "x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz"]/' \
  "$ROOT/tests/cli/cases/tiny_cu.toml" > "$WORK/case.toml"
grep -q '^h5md_every = 50$' "$WORK/case.toml" || fail "the test case did not get h5md_every"
"$SF" run "$WORK/case.toml" --output "$WORK/straight" -q > /dev/null
stop_then_resume "$WORK/case.toml" "$WORK/split" 130
/usr/bin/python3 "$ROOT/tests/cli/h5md_check.py" "$WORK/straight" "$WORK/split" || fail "H5MD check"

# A trajectory cut short (as by a kill in the middle of writing a frame) is refused on --resume.
set +e
"$SF" run "$WORK/case.toml" --output "$WORK/damaged" -q --stop-after 70 > /dev/null 2>&1
truncate -s 600 "$WORK/damaged/trajectory.h5md"
"$SF" run "$WORK/case.toml" --output "$WORK/damaged" -q --resume > /dev/null 2> "$WORK/err.txt"
code=$?
set -e
[ $code -eq 2 ] || fail "resume with a damaged trajectory exited $code, expected 2: $(cat "$WORK/err.txt")"
grep -q "trajectory.h5md: cannot open the H5MD trajectory to resume it" "$WORK/err.txt" ||
  fail "no message naming the damaged trajectory: $(cat "$WORK/err.txt")"
echo "ok: H5MD trajectory equals the dumps, resumes frame for frame, a damaged one is refused"

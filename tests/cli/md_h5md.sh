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

# A tilted cell (cases/tilted_fcc.toml, tilts 2.1 -3.3 1.7 Å): the box rows are its edge
# vectors (lx, 0, 0), (xy, ly, 0), (xz, yz, lz), as final.data's header gives them.
"$SF" run "$ROOT/tests/cli/cases/tilted_fcc.toml" --set output.h5md_every=5 --output "$WORK/tilted" -q > /dev/null
/usr/bin/python3 - "$WORK/tilted" <<'PY' || fail "tilted H5MD box"
import sys, h5py, numpy as np
folder = sys.argv[1]
lines = open(f"{folder}/final.data").read().splitlines()
lo_hi = [[float(w) for w in l.split()[:2]] for l in lines if l.split()[2:3] and l.split()[2] in ("xlo", "ylo", "zlo")]
xy, xz, yz = next([float(w) for w in l.split()[:3]] for l in lines if l.endswith("xy xz yz"))
(lx, ly, lz) = [hi - lo for lo, hi in lo_hi]
expected = np.array([[lx, 0, 0], [xy, ly, 0], [xz, yz, lz]])
got = h5py.File(f"{folder}/trajectory.h5md", "r")["particles/all/box/edges/value"][-1]
if not np.allclose(got, expected, rtol=0, atol=1e-12):
    print("FAIL: box rows", got.tolist(), "expected", expected.tolist())
    sys.exit(1)
print("ok: tilted box rows", got.tolist())
PY

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

#!/usr/bin/env bash
# Particle frames as LAMMPS text dumps ([output] dump = true, granular and pd; dump_every,
# macroparticle; docs/conventions.md): read back by shockfield's own dump reader (`analyze atoms <run folder>`:
# every frame, the chain's and the bar's neighbours counted) and by LAMMPS `read_dump` and
# `rerun` (Debian lammps; that part is skipped with a message when `lmp` is absent): every
# particle, positions and velocities equal to the file's to the last bit (extremes compared, as
# they do not depend on the order of a sum).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
PY=/usr/bin/python3
cases="$ROOT/tests/cli/cases"
"$SF" run "$cases/granular_tiny.toml" --output "$WORK/granular" -q > /dev/null
"$SF" run "$cases/pd_tiny.toml" --output "$WORK/pd" -q > /dev/null
"$SF" run "$cases/macroparticle_tiny.toml" --output "$WORK/macroparticle" -q > /dev/null
[ "$(ls "$WORK/granular/dumps")" = "$(printf 'dump.000.lammpstrj\ndump.309.lammpstrj\ndump.617.lammpstrj')" ] ||
  fail "granular dumps are not one per particle frame, named by the padded step: $(ls "$WORK/granular/dumps")"
# The macroscopic particles' dumps (MD's writer, dump_every) are named and labelled alike: the step
# padded to the digits of the last (250), ITEM: UNITS si (metres, m/s).
[ "$(ls "$WORK/macroparticle/dumps")" = "$(printf 'dump.000.lammpstrj\ndump.125.lammpstrj\ndump.250.lammpstrj')" ] ||
  fail "macroparticle dumps are not named by the padded step: $(ls "$WORK/macroparticle/dumps")"
for f in "$WORK"/{granular,pd,macroparticle}/dumps/*; do
  [ "$(sed -n '/^ITEM: UNITS$/{n;p;q}' "$f")" = si ] || fail "$f does not say ITEM: UNITS si"
done
# Every particle of every frame inside its box: the shrink-wrapped box is reset to the particles
# (as write_data does), not the box of the last neighbour rebuild, which they had left.
"$PY" - "$WORK"/macroparticle/dumps/* <<'PYEOF' || fail "a macroparticle lies outside its dump's box"
import sys
for name in sys.argv[1:]:
    lines = open(name).read().splitlines()
    b = lines.index(next(l for l in lines if l.startswith("ITEM: BOX BOUNDS")))
    box = [tuple(map(float, lines[b + 1 + d].split())) for d in range(3)]
    at = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS")))
    columns = lines[at].split()[2:]
    for row in lines[at + 1:]:
        v = row.split()
        for d, c in enumerate("xyz"):
            x = float(v[columns.index(c)])
            assert box[d][0] <= x <= box[d][1], (name, v[0], c, x, box[d])
print(f"ok: every macroparticle inside its frame's box ({len(sys.argv) - 1} frames)")
PYEOF

# analyze atoms reads the run folders. Grains 4 mm apart (touching) and PD points 10 µm apart
# have two neighbours within 1.025 spacings, the two ends one.
coordination() {  # coordination RUN CUTOFF ATOMS: every frame has ATOMS - 2 twos and 2 ones
  "$SF" analyze atoms "$1" --coordination "$2" -o "$1/analysis" > /dev/null
  "$PY" - "$1/analysis" "$3" <<'PYEOF' || fail "analyze atoms on $1: wrong neighbours"
import collections, pathlib, sys
folder, atoms = pathlib.Path(sys.argv[1]), int(sys.argv[2])
dumps = sorted(folder.glob("dump.*.lammpstrj"))
assert len(dumps) >= 3, dumps
for dump in dumps:
    lines = dump.read_text().splitlines()
    columns = next(l for l in lines if l.startswith("ITEM: ATOMS")).split()[2:]
    rows = lines[-atoms:]
    counts = collections.Counter(int(r.split()[columns.index("coord")]) for r in rows)
    assert counts == {2: atoms - 2, 1: 2}, (dump.name, counts)
print(f"ok: analyze atoms read {len(dumps)} frames of {atoms} particles from {folder.parent.name}")
PYEOF
}
coordination "$WORK/granular" 0.0041 200
coordination "$WORK/pd" 1.025e-5 400

if ! command -v lmp > /dev/null; then
  echo "SKIP (LAMMPS part): lmp is not installed (Debian package lammps)"
  exit 0
fi
# extremes FILE...: "atoms min(x) max(x) min(z) max(z) min(vx) max(vx) min(vz) max(vz)" of each dump file.
extremes() {
  "$PY" - "$@" <<'PYEOF'
import sys
for name in sys.argv[1:]:
    lines = open(name).read().splitlines()
    at = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    columns = lines[at].split()[2:]
    rows = [list(map(float, l.split())) for l in lines[at + 1:]]
    col = lambda c: [r[columns.index(c)] for r in rows]
    print(len(rows), *(repr(f(col(c))) for c in ("x", "z", "vx", "vz") for f in (min, max)))
PYEOF
}
# lammps_extremes RUN TYPES: the same numbers from LAMMPS, one line per frame of `rerun` over the
# run's dumps after a read_dump of the first (which creates the atoms with the dump's ids, `add keep`:
# a macroparticle rod cut from a lattice has ids with gaps, which `add yes` would renumber, and rerun
# matches atoms by id).
lammps_extremes() {
  local files
  files=$(ls "$1"/dumps/dump.*.lammpstrj | tr '\n' ' ')
  cat > "$1/in.rerun" <<EOF
units si
atom_style atomic
boundary s s s
region box block -1 1 -1 1 -1 1
create_box $2 box
mass * 1.0
read_dump $(ls "$1"/dumps/dump.*.lammpstrj | head -1) 0 x y z vx vy vz box yes add keep
compute xlo all reduce min x
compute xhi all reduce max x
compute zlo all reduce min z
compute zhi all reduce max z
compute vxlo all reduce min vx
compute vxhi all reduce max vx
compute vzlo all reduce min vz
compute vzhi all reduce max vz
thermo 1
thermo_style custom step atoms c_xlo c_xhi c_zlo c_zhi c_vxlo c_vxhi c_vzlo c_vzhi
thermo_modify format float %.17g
rerun $files dump x y z vx vy vz box yes
EOF
  (cd "$1" && lmp -nocite -log none -in in.rerun > lmp.out 2>&1) || fail "LAMMPS rerun of $1: $(grep -m1 ERROR "$1/lmp.out")"
  awk '/^ *Step /{on = 1; next} /^Loop time/{on = 0} on && $1 ~ /^[0-9]+$/ {$1 = ""; print substr($0, 2)}' "$1/lmp.out"
}
for run in granular:2 pd:1 macroparticle:1; do
  name=${run%:*}
  ours=$(extremes "$WORK/$name"/dumps/dump.*.lammpstrj)
  theirs=$(lammps_extremes "$WORK/$name" "${run#*:}")
  "$PY" - "$ours" "$theirs" <<'PYEOF' || fail "$name: LAMMPS read other values than the dumps hold"
import sys
ours, theirs = ([list(map(float, l.split())) for l in s.strip().splitlines()] for s in sys.argv[1:])
assert len(ours) == len(theirs) >= 3, (ours, theirs)
assert ours == theirs, (ours, theirs)
PYEOF
  echo "ok: LAMMPS rerun read $(echo "$ours" | wc -l) $name frames, every particle, the same extremes of x, z, vx, vz"
done
echo "particle_dumps: granular, pd and macroparticle dumps read by analyze atoms and by LAMMPS read_dump/rerun"

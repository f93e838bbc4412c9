#!/usr/bin/env bash
# `shockfield convert` (docs/checkpoints.md) on the checkpoint of every method's test case
# (tests/cli/cases): `--format list` names every dataset with its units; the default conversion
# writes the method's ordinary output, which convert_check.py reads with VTK and compares with the
# checkpoint read by h5py (DBM's rho, u, T recomputed from f independently). The MD checkpoint
# becomes a LAMMPS data file that LAMMPS read_data assigns completely (skipped with a message
# when `lmp` is absent) and that starts a new shockfield run as its [system] data_file, whose
# step-0 thermo row is the original run's last one. Bad input exits 2 naming the file.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
check() { /usr/bin/python3 "$ROOT/tests/cli/convert_check.py" "$@"; }
for name in tiny_cu mpm_tiny pd_tiny granular_tiny macroparticle_tiny dbm_sod phasefield_tiny \
            phasefield_sharp_front_tiny; do
  "$SF" run "$ROOT/tests/cli/cases/$name.toml" --output "$WORK/$name" -q > /dev/null
  "$SF" convert "$WORK/$name/checkpoint.h5" --format list > "$WORK/$name.list"
  grep -qE "^  position +float64 .* (Angstrom|m|1)$|^  (xi|f|domain_centre|displacement) +float64 " "$WORK/$name.list" ||
    fail "$name: the listing lacks the positions or the field: $(cat "$WORK/$name.list")"
  [ "$(grep -c '^  ' "$WORK/$name.list")" -ge 1 ] || fail "$name: no dataset listed"
  "$SF" convert "$WORK/$name/checkpoint.h5" > "$WORK/$name.out"
  converted=$(sed 's/.* -> //' "$WORK/$name.out")
  [ -s "$converted" ] || fail "$name: convert wrote nothing: $(cat "$WORK/$name.out")"
  case "$converted" in
    *.vtp|*.vti) check "$WORK/$name/checkpoint.h5" "$converted" || fail "$name: $converted differs from the checkpoint" ;;
  esac
  echo "ok: $name -> $(basename "$converted")"
done

# The checker can fail: a PD checkpoint against the MPM particle file.
set +e
check "$WORK/pd_tiny/checkpoint.h5" "$WORK/mpm_tiny/checkpoint.vtp" > "$WORK/mismatch.txt"
code=$?
set -e
[ $code -eq 1 ] || fail "convert_check.py passed a file converted from another checkpoint"

# MD: the data file, read by LAMMPS and as the data_file of a new run.
data="$WORK/tiny_cu/checkpoint.data"
grep -qE "^256 atoms$" "$data" || fail "the data file does not hold 256 atoms"
if command -v lmp > /dev/null; then
  lammps_reads_data "$data" 256
  echo "ok: LAMMPS read_data assigns the 256 atoms"
else
  echo "SKIP (LAMMPS part): lmp is not installed (Debian package lammps)"
fi
cat > "$WORK/continue.toml" <<CASE
# tiny_cu continued from its converted checkpoint.
method = "md"
[system]
data_file = "$data"
boundary = "ppp"
[potential]
style = "eam"
file = "Cu_u3.eam"
[md]
timestep = 0.002
skin = 1.0
[output]
thermo_every = 10
[[stage]]
name = "more"
steps = 10
CASE
"$SF" run "$WORK/continue.toml" --output "$WORK/continue" -q > /dev/null
# The step-0 row of the new run against the last row of the first: the same atoms, velocities
# and box, so the same energies and pressure. Tolerance 1e-9 relative: positions wrapped into the
# box (x - L) can differ in their last bit, which moves the tenth significant digit at most.
/usr/bin/python3 - "$WORK/tiny_cu/thermo.csv" "$WORK/continue/thermo.csv" <<'PY' || fail "the continued run does not start where the first ended"
import csv, sys
last = list(csv.DictReader(open(sys.argv[1])))[-1]
first = list(csv.DictReader(open(sys.argv[2])))[0]
for key in ("temperature_K", "pe_eV", "ke_eV", "press_bar", "volume_A3"):
    a, b = float(last[key]), float(first[key])
    if abs(a - b) > 1e-9 * max(abs(a), 1.0):
        sys.exit(f"{key}: {a} at the end of the first run, {b} at the start of the second")
print(f"ok: the run from the converted checkpoint starts at T {first['temperature_K']} K, pe {first['pe_eV']} eV, "
      f"P {first['press_bar']} bar, as the first ended")
PY

# Bad input: exit 2, the file named.
expect_exit2() {
  set +e
  "$SF" convert "$@" > /dev/null 2> "$WORK/stderr"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "convert $* exited $code, expected 2: $(cat "$WORK/stderr")"
  grep -qF "$1" "$WORK/stderr" || [ ! -e "$1" ] || fail "convert $*: the message does not name $1: $(cat "$WORK/stderr")"
  echo "ok: $(head -c 200 "$WORK/stderr")"
}
expect_exit2 "$WORK/tiny_cu/config.resolved.toml"
cp "$WORK/mpm_tiny/checkpoint.h5" "$WORK/damaged.h5"
printf '\x5a' | dd of="$WORK/damaged.h5" bs=1 seek=3000 conv=notrunc status=none
expect_exit2 "$WORK/damaged.h5"
expect_exit2 "$WORK/tiny_cu/checkpoint.h5" --format vti
expect_exit2 "$WORK/no_such_file.h5"
"$SF" convert --help | grep -q -- "--format" || fail "convert --help does not describe --format"
echo "convert: every method's checkpoint converts to its outputs; the MD state continues in a new run"

#!/usr/bin/env bash
# Fault: a run of every method into a small full filesystem (a tmpfs of 150 kB to 1.5 MB; CI runs as root, and
# the test is skipped with the reason printed where the mount is refused). Each run must stop
# with exit 3 and a message naming the file it could not write, leave no half-written
# checkpoint, and keep its previous checkpoint whole: after space is freed (the tmpfs remounted
# larger), --resume finishes the run and its outputs are byte for byte those of an
# uninterrupted run on a roomy disk. `analyze`, `analyze atoms`, `analyze geometry` and a PD
# [homogeneous] run on a full disk stop with exit 3 naming the file too.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
DISK="$WORK/disk"
mkdir -p "$DISK"
if ! mount -t tmpfs -o size=300k tmpfs "$DISK" 2> "$WORK/mount.txt"; then
  echo "skip: cannot mount a tmpfs here ($(cat "$WORK/mount.txt")); the full-disk fault test needs root"
  exit 0
fi
trap 'umount "$DISK" 2>/dev/null; rm -rf "$WORK"' EXIT

# full_disk_then_resume NAME SIZE CASE FILE...: NAME's run into a SIZE tmpfs stops cleanly; resumed
# after remounting larger, FILE... equal those of the uninterrupted run.
full_disk_then_resume() {
  local name="$1" size="$2" case_file="$3"
  shift 3
  "$SF" run "$case_file" --output "$WORK/$name.straight" -q > /dev/null
  mount -o remount,size="$size" "$DISK"
  set +e
  "$SF" run "$case_file" --output "$DISK/$name" -q > /dev/null 2> "$WORK/$name.err"
  local code=$?
  set -e
  [ $code -eq 3 ] || fail "$name: exit $code on a full disk, expected 3: $(cat "$WORK/$name.err")"
  grep -q "No space left on device" "$WORK/$name.err" || fail "$name: the message gives no reason: $(cat "$WORK/$name.err")"
  grep -qF "$DISK/$name/" "$WORK/$name.err" || fail "$name: the message names no file: $(cat "$WORK/$name.err")"
  # The error that stopped the run comes first, not a later one of reporting it (summary.json,
  # log.txt, failure.vtp: written after the stop, on the same full disk).
  ! grep -Eq "^run stopped: [^ ]*(summary.json|log.txt|failure.vtp)" "$WORK/$name.err" ||
    fail "$name: the failure report hid the error that stopped the run: $(cat "$WORK/$name.err")"
  [ ! -e "$DISK/$name/checkpoint.h5.tmp" ] || fail "$name: a partial checkpoint.h5.tmp was left behind"
  [ -s "$DISK/$name/checkpoint.h5" ] || fail "$name: no checkpoint before the disk filled (make the case write one earlier)"
  echo "ok: $name stopped on the full disk: $(head -c 200 "$WORK/$name.err")"
  mount -o remount,size=64m "$DISK"
  "$SF" run "$case_file" --output "$DISK/$name" -q --resume > /dev/null 2> "$WORK/$name.resume" ||
    fail "$name: resume after freeing space failed: $(cat "$WORK/$name.resume")"
  same_files "$WORK/$name.straight" "$DISK/$name" "$@"
  echo "ok: $name resumed from its previous checkpoint, bitwise"
  rm -rf "${DISK:?}/$name"
}

# MD: a dump every 10 steps (31 of 40 kB each) overflows 300 kB.
sed -e 's/^dump_every = 100/dump_every = 10/' -e 's/^checkpoint_every = 50/checkpoint_every = 20/' \
  "$ROOT/tests/cli/cases/tiny_cu.toml" > "$WORK/md.toml"
full_disk_then_resume md 300k "$WORK/md.toml" thermo.csv final.data dumps/dump.300.lammpstrj dumps/dump.150.lammpstrj

# MPM: a field frame every 2 ns (about 150 kB each) and a 510 kB checkpoint, into 1500 kB.
sed -e 's/^field_interval = 10e-9/field_interval = 2e-9/' -e 's/^checkpoint_every = 20/checkpoint_every = 2/' \
  "$ROOT/tests/cli/cases/mpm_tiny.toml" > "$WORK/mpm.toml"
full_disk_then_resume mpm 1500k "$WORK/mpm.toml" series.csv grid.pvd particles.pvd histograms/hist_0.csv

# PD: a profile (25 kB) every 3 ns and a 150 kB checkpoint, into 500 kB.
sed -e 's/^profile_interval = 5e-8/profile_interval = 3e-9/' -e 's/^checkpoint_every = 50/checkpoint_every = 2/' \
  "$ROOT/tests/cli/cases/pd_tiny.toml" > "$WORK/pd.toml"
full_disk_then_resume pd 500k "$WORK/pd.toml" series.csv profiles/index.csv profiles/profile_60.csv

# DBM: the Sod example cut to t = 0.05 (200 steps), writing a field frame (17 kB) every other
# step and a 260 kB checkpoint, into 800 kB.
sed -e 's/^end_time = 0.2/end_time = 0.05/' -e 's/^series_interval = 0.01/series_interval = 0.001/' \
  -e 's/^profile_interval = 0.05/field_interval = 0.0005\ncheckpoint_every = 10/' \
  "$ROOT/examples/dbm_sod/case.toml" > "$WORK/dbm.toml"
full_disk_then_resume dbm 800k "$WORK/dbm.toml" series.csv grid.pvd
# Granular: the space-time rows of every grain every microsecond (about 4 kB each, two files) and
# a 11 kB checkpoint every 50 steps, into 200 kB.
sed -e 's/^field_interval = 1e-5/field_interval = 1e-6/' -e 's/^spacetime_stride = 10/spacetime_stride = 1\ncheckpoint_every = 50/' \
  "$ROOT/tests/cli/cases/granular_tiny.toml" > "$WORK/granular.toml"
full_disk_then_resume granular 200k "$WORK/granular.toml" series.csv probes.csv spacetime_velocity.csv \
  spacetime_force.csv signal.csv

# Phase field: a 21 kB frame every 5 steps and a 17 kB checkpoint every 5 steps, into 150 kB.
sed -e 's/^field_interval = 2.0/field_interval = 0.5\ncheckpoint_every = 5/' \
  "$ROOT/tests/cli/cases/phasefield_tiny.toml" > "$WORK/phasefield.toml"
full_disk_then_resume phasefield 150k "$WORK/phasefield.toml" series.csv fields.pvd fields/xi_12.vti

# Writers outside the time-stepping runs, on a disk with no space left: `analyze` and a PD
# [homogeneous] compression used to exit 0 with truncated files.
mount -o remount,size=300k "$DISK"
dd if=/dev/zero of="$DISK/filler" bs=1k count=400 2> /dev/null || true
expect_full_disk() {
  local what="$1"
  shift
  set +e
  "$@" > /dev/null 2> "$WORK/err"
  local code=$?
  set -e
  [ $code -eq 3 ] || fail "$what: exit $code on a full disk, expected 3: $(cat "$WORK/err")"
  grep -qF "$DISK/" "$WORK/err" && grep -q "No space left on device" "$WORK/err" ||
    fail "$what: the message names no file or reason: $(cat "$WORK/err")"
  echo "ok: $what stopped on the full disk: $(head -c 160 "$WORK/err")"
}
expect_full_disk "analyze" "$SF" analyze minkowski "$ROOT/tests/fixtures/analysis/fields/series.pvd" -t 50 --no-plot \
  -o "$DISK/analyze"
expect_full_disk "analyze atoms" "$SF" analyze atoms "$ROOT/tests/fixtures/lammps_structure/cu_fcc_perfect.dump" \
  -o "$DISK/atoms"
expect_full_disk "analyze geometry" "$SF" analyze geometry "$ROOT/tests/fixtures/lammps_structure/fe_bcc_perfect.dump" \
  -o "$DISK/geometry"
expect_full_disk "pd [homogeneous]" "$SF" run "$ROOT/examples/pd_ofhc_compression/ofhc_compression.toml" \
  --output "$DISK/homogeneous" -q
echo "fault_full_disk: every method stops with exit 3 naming the file and resumes bitwise"

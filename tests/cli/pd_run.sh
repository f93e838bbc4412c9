#!/usr/bin/env bash
# A PD run writes its folder (log, resolved config with derived values, series, profiles,
# checkpoint; stop and resume of this case: stop_resume.sh); --check validates without a folder;
# the bond models stopped after bonds broke and resumed write the same output, bitwise.
source "$(dirname "$0")/lib.bash"
set -e
case="$ROOT/tests/cli/cases/pd_tiny.toml"
export OMP_NUM_THREADS=2
"$SF" run "$case" --check | grep -q "valid pd case (400 points" || fail "--check does not report the case"
"$SF" run "$case" --output "$WORK/straight" -q > /dev/null
for f in log.txt config.resolved.toml series.csv checkpoint.h5 profiles/index.csv profiles/profile_4.csv; do
  [ -s "$WORK/straight/$f" ] || fail "run folder lacks $f"
done
grep -q "hel_Pa = 541626506" "$WORK/straight/config.resolved.toml" || fail "derived HEL missing"
grep -q "time_step_s" "$WORK/straight/config.resolved.toml" || fail "derived time step missing"

# The bond models on the same bar, with bonds breaking before the stop: a run stopped after the
# first break and resumed (intact flags and critical stretches go through the checkpoint) writes
# the same output as an uninterrupted one, bitwise; PMB profiles have a damage column.
base=$(cat "$case")
j2='model = "j2"
density = 2703.0
young = 77.11e9
poisson = 0.334
yield_stress = 270e6'
# has_damage FILE: some point of the profile has broken bonds (last column > 0).
has_damage() { awk -F, 'NR > 1 && $NF > 0 { found = 1 } END { exit !found }' "$1"; }
# stop_and_resume NAME STOP PROFILE: straight and split runs of $WORK/NAME.toml, split stopped
# after STOP steps; PROFILE (written before the stop) must already show damage.
stop_and_resume() {
  local name="$1" stop="$2" profile="$3"
  "$SF" run "$WORK/$name.toml" --output "$WORK/${name}_straight" -q > /dev/null
  has_damage "$WORK/${name}_straight/profiles/profile_$profile.csv" || fail "$name: no bond broken by profile $profile"
  awk -F, -v p="$profile" -v s="$stop" '$1 == p && $3 >= s { exit 1 }' "$WORK/${name}_straight/profiles/index.csv" ||
    fail "$name: profile $profile is not written before step $stop"
  stop_then_resume "$WORK/$name.toml" "$WORK/${name}_split" "$stop"
  same_files "$WORK/${name}_straight" "$WORK/${name}_split" series.csv profiles/index.csv profiles/points.pvd \
    $(cd "$WORK/${name}_straight" && ls profiles/profile_*.csv profiles/points_*.vtp)
  echo "ok: $name resumed after bonds broke (stop at step $stop), bitwise"
}
pmb="${base/"$j2"/model = \"pmb\"
density = 2703.0
micromodulus = 4e21
critical_stretch = 0.004}"
echo "${pmb/profile_interval = 5e-8/profile_interval = 2.5e-8}" > "$WORK/pmb.toml"
stop_and_resume pmb 560 7
head -1 "$WORK/pmb_straight/profiles/profile_4.csv" | grep -q ",grain,damage$" || fail "PMB profile lacks the damage column"
echo "${base/"$j2"/model = \"lps\"
density = 2703.0
bulk = 70e9
shear = 26e9
critical_stretch = 0.002}" > "$WORK/lps.toml"
stop_and_resume lps 120 1
# The issue-17 block, PMB and LPS with short-range contact acting (from about step 150): stopped at
# step 250 and resumed, bitwise (the contact force has no state; its candidate list is rebuilt).
cp "$ROOT/tests/cli/cases/pd_block_contact.toml" "$WORK/block_pmb.toml"
stop_and_resume block_pmb 250 1
block=$(cat "$ROOT/tests/cli/cases/pd_block_contact.toml")
block="${block/model = \"pmb\"/model = \"lps\"}"
echo "${block/micromodulus = 2.989065910664636e22/bulk = 14.9e9
shear = 8.94e9}" > "$WORK/block_lps.toml"
stop_and_resume block_lps 250 1
# The crystal law on a Taylor aggregate of 2 random grains per point, stopped while it flows: its
# state goes through the checkpoint as one dataset per quantity, per point and grain
# (docs/checkpoints.md). 48 steps (the crystal law costs ~0.05 s a step here).
crystal="${base/"$j2"/model = \"crystal\"
density = 8960.0
orientation = \"random\"
taylor_grains = 2}"
echo "${crystal/end_time = 2e-7/end_time = 1e-7}" > "$WORK/crystal.toml"
"$SF" run "$WORK/crystal.toml" --output "$WORK/crystal_straight" -q > /dev/null
stop_then_resume "$WORK/crystal.toml" "$WORK/crystal_split" 30
same_files "$WORK/crystal_straight" "$WORK/crystal_split" series.csv profiles/index.csv \
  $(cd "$WORK/crystal_straight" && ls profiles/profile_*.csv)
/usr/bin/python3 - "$WORK/crystal_split/checkpoint.h5" <<'PY' || fail "crystal checkpoint layout"
import sys, h5py, numpy
with h5py.File(sys.argv[1]) as f:
    expected = {"deformation_gradient": ((400, 9), "1"), "orientation": ((400, 2, 9), "1"),
                "slip_resistance": ((400, 2, 12), "Pa"), "slip": ((400, 2, 12), "1"),
                "accumulated_slip": ((400, 2), "1"), "substeps": ((400, 2), "1")}
    for name, (shape, units) in expected.items():
        d = f[name]
        assert d.shape == shape and d.attrs["units"].decode() == units, (name, d.shape, d.attrs["units"])
    assert numpy.issubdtype(f["substeps"].dtype, numpy.integer), f["substeps"].dtype
    assert f["accumulated_slip"][...].max() > 0, "no slip: the test would not exercise the plastic state"
    assert "model_state" not in f
PY
echo "ok: crystal (2 Taylor grains) resumed while flowing, bitwise; its state as named datasets"
echo "pd_run: run folder, derived values and bitwise resume (J2; PMB and LPS after bonds broke; the block with contact; a crystal aggregate)"

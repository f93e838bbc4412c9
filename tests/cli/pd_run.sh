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
echo "pd_run: run folder, derived values and bitwise resume (J2; PMB and LPS after bonds broke; the block with contact)"

#!/usr/bin/env bash
# A PD run writes its folder (log, resolved config with derived values, series, profiles,
# checkpoint); a run stopped (as by Ctrl-C) and resumed writes the same output as an
# uninterrupted one, bitwise (same thread count); --check validates without a folder.
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
set +e
"$SF" run "$case" --output "$WORK/split" -q --stop-after 77 > /dev/null 2> "$WORK/stop.txt"
code=$?
set -e
[ $code -eq 130 ] || fail "stopped run exit code $code, expected 130: $(cat "$WORK/stop.txt")"
grep -q -- "--resume" "$WORK/stop.txt" || fail "the stop message does not say how to resume"
"$SF" run "$case" --output "$WORK/split" -q --resume > /dev/null
for f in series.csv profiles/index.csv profiles/profile_2.csv profiles/profile_4.csv; do
  cmp "$WORK/straight/$f" "$WORK/split/$f" || fail "resumed $f differs"
done
echo "ok: resumed run is bitwise identical"

# The bond models on the same bar: a PMB run finishes with a damage column; an LPS run resumes bitwise.
base=$(cat "$case")
j2='model = "j2"
density = 2703.0
young = 77.11e9
poisson = 0.334
yield_stress = 270e6'
echo "${base/"$j2"/model = \"pmb\"
density = 2703.0
micromodulus = 4e21
critical_stretch = 0.01}" > "$WORK/pmb.toml"
"$SF" run "$WORK/pmb.toml" --output "$WORK/pmb" -q > /dev/null
head -1 "$WORK/pmb/profiles/profile_4.csv" | grep -q ",grain,damage$" || fail "PMB profile lacks the damage column"
echo "${base/"$j2"/model = \"lps\"
density = 2703.0
bulk = 70e9
shear = 26e9
critical_stretch = 0.01}" > "$WORK/lps.toml"
"$SF" run "$WORK/lps.toml" --output "$WORK/lps_straight" -q > /dev/null
set +e
"$SF" run "$WORK/lps.toml" --output "$WORK/lps_split" -q --stop-after 77 > /dev/null 2> "$WORK/stop.txt"
code=$?
set -e
[ $code -eq 130 ] || fail "stopped LPS run exit code $code, expected 130: $(cat "$WORK/stop.txt")"
"$SF" run "$WORK/lps.toml" --output "$WORK/lps_split" -q --resume > /dev/null
for f in series.csv profiles/index.csv profiles/profile_2.csv profiles/profile_4.csv; do
  cmp "$WORK/lps_straight/$f" "$WORK/lps_split/$f" || fail "resumed LPS $f differs"
done
echo "pd_run: run folder, derived values and bitwise resume (J2, LPS); PMB run"

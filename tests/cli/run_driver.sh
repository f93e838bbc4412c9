#!/usr/bin/env bash
# What the run driver does for every method: --set is the same as editing the case file (the
# outputs byte-identical), a wrong key or type given with --set is refused like the file's; the
# resolved configuration of a run fed back as the case gives the identical run; --resume after an
# unsafe edit is refused listing the changed keys, after a safe edit (a later end) accepted,
# logged and config.resolved.toml rewritten, and a finished run resumed has nothing to do unless
# the edit extended it; summary.json is present and valid for each method's tiny case, finished,
# stopped or failed; log.txt carries the provenance and the performance summary.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=2
cases="$ROOT/tests/cli/cases"
CHECK="/usr/bin/python3 $ROOT/tests/cli/check_summary.py"
run() { "$SF" run "$@" -q > /dev/null; }

# summary.json of every method's tiny case, and the log's provenance and performance lines.
for m in md:tiny_cu mpm:mpm_tiny pd:pd_tiny dbm:dbm_sod; do
  method=${m%%:*} name=${m#*:}
  run "$cases/$name.toml" --output "$WORK/$name"
  $CHECK "$WORK/$name/summary.json" --method "$method" --status finished > /dev/null ||
    fail "$name: $($CHECK "$WORK/$name/summary.json")"
  grep -q "^provenance: command line: .*$name.toml" "$WORK/$name/log.txt" || fail "$name: no provenance in log.txt"
  grep -q "^performance: .* steps/s" "$WORK/$name/log.txt" || fail "$name: no performance summary"
  grep -q "^\[provenance\]" "$WORK/$name/config.resolved.toml" || fail "$name: no [provenance] in config.resolved.toml"
done
grep -q '"hugoniot"' "$WORK/tiny_cu/summary.json" && grep -q "ns/day" "$WORK/tiny_cu/log.txt" || fail "md summary"
grep -q "Step .*Temp .*PotEng .*KinEng .*TotEng .*Press" "$WORK/tiny_cu/log.txt" || fail "md thermo table header"
grep -q "sha256 [0-9a-f]\{64\}" "$WORK/tiny_cu/log.txt" || fail "the potential file's checksum is not logged"
# MD times its step phases: force and neighbour-rebuild seconds are positive (the run rebuilds).
grep -qE "^wall time: step .* \(of which force [0-9.e+-]+ s, neighbour (0\.0*[1-9]|[1-9])[0-9.e+-]* s, ghosts" "$WORK/tiny_cu/log.txt" \
  || fail "md phase times (force, neighbour, ghosts) missing from the performance summary"
echo "ok: summary.json valid, provenance and performance logged for md, mpm, pd, dbm"

# [md] is optional (every key has a default): without it the run uses and echoes the defaults,
# and --set reaches its keys; with the table's values given by --set the run equals the case's.
awk '/^\[md\]/ { skip = 1; next } /^\[/ { skip = 0 } !skip' "$cases/tiny_cu.toml" > "$WORK/no_md.toml"
grep -q '^\[md\]' "$WORK/no_md.toml" && fail "the [md] table was not removed"
run "$WORK/no_md.toml" --output "$WORK/no_md" --set md.timestep=0.002 --set md.skin=1.0
grep -A8 '^\[md\]' "$WORK/no_md/config.resolved.toml" | grep -q '^neighbor_every = 1$' ||
  fail "[md] defaults not echoed without the table"
same_files "$WORK/tiny_cu" "$WORK/no_md" thermo.csv
# thermo_full_precision: the same run's thermo.csv in shortest round-trip text; every value rounded
# to 10 significant digits is the default file's, and some need more than 10 digits.
run "$cases/tiny_cu.toml" --output "$WORK/full_thermo" --set output.thermo_full_precision=true
/usr/bin/python3 - "$WORK/tiny_cu/thermo.csv" "$WORK/full_thermo/thermo.csv" <<'PY' || fail "thermo_full_precision"
import sys
short, full = (open(f).read().splitlines() for f in sys.argv[1:])
assert short[0] == full[0] and len(short) == len(full), "different header or rows"
longer = 0
for a, b in zip(short[1:], full[1:]):
    for x, y in zip(a.split(","), b.split(",")):
        assert f"{float(y):.10g}" == x, (x, y)
        longer += len(y.replace("-", "").replace(".", "").split("e")[0].lstrip("0")) > 10
assert longer > 0, "no value needed more than 10 digits"
PY

# --set equals editing the file, bitwise.
sed 's/^end_time = 2e-7/end_time = 1.5e-7/' "$cases/pd_tiny.toml" > "$WORK/pd_edited.toml"
grep -q "^end_time = 1.5e-7" "$WORK/pd_edited.toml" || fail "the edit did not apply"
run "$WORK/pd_edited.toml" --output "$WORK/edited"
run "$cases/pd_tiny.toml" --output "$WORK/set" --set solver.end_time=1.5e-7
same_files "$WORK/edited" "$WORK/set" series.csv thermo.csv profiles/index.csv profiles/profile_3.csv
grep -q "^end_time = 1.5e-07$" "$WORK/set/config.resolved.toml" || fail "--set value not in config.resolved.toml"
echo "ok: --set is the same run as the edited file"
# A wrong key or type given with --set is refused (exit 2, no run folder), naming --set.
set +e
"$SF" run "$cases/pd_tiny.toml" --output "$WORK/bad" -q --set solver.end_tim=1e-7 2> "$WORK/err1"; c1=$?
"$SF" run "$cases/pd_tiny.toml" --output "$WORK/bad" -q --set 'solver.end_time="soon"' 2> "$WORK/err2"; c2=$?
set -e
[ $c1 -eq 2 ] && grep -q "end_tim" "$WORK/err1" && grep -q -- "--set" "$WORK/err1" || fail "unknown --set key: $c1 $(cat "$WORK/err1")"
[ $c2 -eq 2 ] && grep -q "end_time" "$WORK/err2" && grep -q -- "--set" "$WORK/err2" || fail "wrong --set type: $c2 $(cat "$WORK/err2")"
[ ! -e "$WORK/bad" ] || fail "a refused --set left a run folder"
echo "ok: a wrong key or type with --set is refused"

# The resolved configuration replayed gives the identical run (md and dbm).
run "$WORK/tiny_cu/config.resolved.toml" --output "$WORK/md_replay"
same_files "$WORK/tiny_cu" "$WORK/md_replay" thermo.csv dumps/dump.300.lammpstrj final.data
run "$WORK/dbm_sod/config.resolved.toml" --output "$WORK/dbm_replay"
same_files "$WORK/dbm_sod" "$WORK/dbm_replay" series.csv thermo.csv profiles/profile_2.csv
# A case with open block-region bounds (LAMMPS's INF) replays too: the infinite defaults are not
# written (they were written as -inf, which a case file refuses).
run "$ROOT/examples/md_flyer_impact/case.toml" --set 'stage[0].steps=5' --output "$WORK/open_region"
run "$WORK/open_region/config.resolved.toml" --output "$WORK/open_region_replay"
same_files "$WORK/open_region" "$WORK/open_region_replay" thermo.csv
# ... and a [derived] value that does not match the fresh derivation is refused.
sed 's/^steps = 50$/steps = 51/' "$WORK/dbm_sod/config.resolved.toml" > "$WORK/wrong_derived.toml"
grep -q "^steps = 51" "$WORK/wrong_derived.toml" || fail "the [derived] edit did not apply"
set +e
"$SF" run "$WORK/wrong_derived.toml" --output "$WORK/bad" -q 2> "$WORK/err"; code=$?
set -e
[ $code -eq 2 ] && grep -q "steps" "$WORK/err" || fail "a wrong [derived] value was accepted: $code $(cat "$WORK/err")"
echo "ok: the resolved configuration replays the identical run"

# --resume: an unsafe edit refused with every changed key listed; a safe one accepted.
set +e
"$SF" run "$cases/pd_tiny.toml" --output "$WORK/pds" -q --stop-after 50 2> /dev/null
"$SF" run "$cases/pd_tiny.toml" --output "$WORK/pds" -q --resume --set body.horizon_factor=3.5 \
  --set solver.end_time=3e-7 2> "$WORK/err"; code=$?
set -e
[ $code -eq 2 ] || fail "an unsafe edit was resumed (exit $code)"
grep -q "body.horizon_factor: 3.0 -> 3.5" "$WORK/err" && grep -q "solver.end_time: .* (safe)" "$WORK/err" ||
  fail "the refusal does not list the changed keys: $(cat "$WORK/err")"
$CHECK "$WORK/pds/summary.json" --method pd --status stopped > /dev/null || fail "no valid stopped summary"
run "$cases/pd_tiny.toml" --output "$WORK/pds" --resume --set solver.end_time=3e-7
grep -q "resume: solver.end_time changed" "$WORK/pds/log.txt" || fail "the safe change is not logged"
grep -q "^end_time = 3e-07$" "$WORK/pds/config.resolved.toml" || fail "config.resolved.toml not rewritten"
grep -q "finished: t = 3e-07 s" "$WORK/pds/log.txt" || fail "the resumed run did not run to the new end time"
"$SF" run "$cases/pd_tiny.toml" --output "$WORK/pds" --resume --set solver.end_time=3e-7 | grep -q "nothing to do" ||
  fail "a finished run resumed again did not say nothing to do"
echo "ok: --resume refuses an unsafe edit, accepts a safe one"

# A finished MD run resumed with a longer last stage continues, bitwise as a longer run.
sed 's/^steps = 200$/steps = 260/' "$cases/tiny_cu.toml" > "$WORK/md_longer.toml"
run "$WORK/md_longer.toml" --output "$WORK/md_long"
cp -r "$WORK/tiny_cu" "$WORK/md_ext"
run "$cases/tiny_cu.toml" --output "$WORK/md_ext" --resume --set 'stage[1].steps=260'
same_files "$WORK/md_long" "$WORK/md_ext" thermo.csv final.data
echo "ok: a finished md run extended by --resume"

# A failed run writes a summary too.
base=$(sed -n '/^method/,$p' "$cases/tiny_cu.toml")
hot=${base/temperature = 600.0/temperature = 20000.0}
run_expecting 3 "${hot/timestep = 0.002/timestep = 0.05}" "too large"
$CHECK "$WORK/out/summary.json" --method md --status failed > /dev/null || fail "no valid failed summary"
echo "run_driver: --set, replay, resume checks, summary.json for every method"

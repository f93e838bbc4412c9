#!/usr/bin/env bash
# A short DBM Sod tube writes its folder (log, resolved config with the exact star state, series,
# profiles); an unknown key, an unstable tau and --resume are refused (exit 2, file and key
# named, no run folder); a blow-up stops with the cell named (exit 3) and keeps the output.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=2
sod='method = "dbm"
[grid]
nx = 100
dx = 0.01
[model]
tau = 1e-3
[initial]
left = { rho = 1.0, p = 1.0 }
right = { rho = 0.125, p = 0.1 }
[run]
end_time = 0.05
courant = 0.4
[output]
series_interval = 0.01
profile_interval = 0.025'
printf '%s\n' "$sod" > "$WORK/sod.toml"
"$SF" run "$WORK/sod.toml" --check | grep -q "valid dbm case (100 x 1 cells, 50 steps" || fail "--check does not report the case"
"$SF" run "$WORK/sod.toml" --output "$WORK/sod" -q > /dev/null
for f in log.txt config.resolved.toml series.csv profiles/index.csv profiles/profile_0.csv profiles/profile_2.csv; do
  [ -s "$WORK/sod/$f" ] || fail "run folder lacks $f"
done
grep -q "exact_p_star = 0.30313" "$WORK/sod/config.resolved.toml" || fail "derived exact p* missing"
[ "$(wc -l < "$WORK/sod/series.csv")" -eq 7 ] || fail "series.csv should have a header and 6 rows"
head -1 "$WORK/sod/profiles/profile_2.csv" | grep -q "x,rho,ux,uy,p,T,D2xx,D31x" || fail "profile columns"
[ "$(wc -l < "$WORK/sod/profiles/profile_2.csv")" -eq 101 ] || fail "profile should have 100 cells"

expect_error "${sod/courant = 0.4/courant = 0.4
colour = 1}" "case.toml" "run.colour"
expect_error "${sod/tau = 1e-3/tau = 1e-5}" "case.toml" "model.tau" "dt/tau"
expect_error "$sod
[boundary]
x_low = \"periodic\"" "boundary.x_low" "periodic"
set +e
"$SF" run "$WORK/sod.toml" --output "$WORK/sod" -q --resume > /dev/null 2> "$WORK/resume.txt"
code=$?
set -e
[ $code -eq 2 ] || fail "--resume exit code $code, expected 2"
grep -q "cannot be resumed" "$WORK/resume.txt" || fail "--resume message: $(cat "$WORK/resume.txt")"
run_expecting 3 "${sod/p = 0.1 \}/p = 1e-4 \}}" "broke down" "in cell ("
[ -s "$WORK/out/series.csv" ] && [ -s "$WORK/out/profiles/profile_1.csv" ] || fail "a blown-up run lost its output"
echo "dbm_run: run folder, derived exact star state, refused keys, tau and --resume, blow-up"

#!/usr/bin/env bash
# A short GLS quench ([model] kind = "gls", [initial] type = "quench") writes series.csv with the
# phase-separation columns, summary.csv (t_SD, D_max, peak of L, u_DG), field frames with D and D^F and
# the derived time-step limit; a stopped and resumed run writes the same series and summary, a finished
# one resumed writes its summary again;
# bad GLS input is refused (exit 2, key named): dt above the stable limit with its cause, rho0
# outside the EOS domain, q >= tau, gamma != 2, NND convection, the state filter with NND, a
# non-periodic side; a blow-up
# (a deep quench of a dense liquid) stops with exit 3 and keeps series and summary.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
gls='method = "dbm"
[grid]
nx = 16
ny = 16
dx = 0.0625
[model]
kind = "gls"
K = 1e-3
tau = 1e-3
q = -0.019
[initial]
type = "quench"
rho0 = 1.0
T = 0.85
noise = 0.05
[run]
end_time = 0.02
dt = 1e-3
[output]
series_interval = 0.005
field_interval = 0.01
checkpoint_every = 5'
printf '%s\n' "$gls" > "$WORK/gls.toml"
"$SF" run "$WORK/gls.toml" --output "$WORK/gls" -q > /dev/null
for f in series.csv summary.csv grid.pvd fields/grid_000000010.vti checkpoint.h5; do
  [ -s "$WORK/gls/$f" ] || fail "run folder lacks $f"
done
head -1 "$WORK/gls/series.csv" | grep -q "step,time,D,D_force,D_gradient,L,R,density_variance,rho_min,rho_max,T_mean,v_max,mass_per_length,energy_per_length" \
  || fail "series columns: $(head -1 "$WORK/gls/series.csv")"
[ "$(wc -l < "$WORK/gls/series.csv")" -eq 6 ] || fail "series.csv should have a header and 5 rows"
head -1 "$WORK/gls/summary.csv" | grep -q "t_SD,D_max" || fail "summary columns"
grep -q 'Name="D_force"' "$WORK/gls/fields/grid_000000010.vti" || fail "field frame lacks D_force"
grep -q "gls_time_step_limited_by = 'collision'" "$WORK/gls/config.resolved.toml" || fail "derived time-step limit missing"
grep -q "phase separation: t_SD" "$WORK/gls/log.txt" || fail "log lacks the t_SD line"
grep -q "\"u_DG\"" "$WORK/gls/summary.json" || fail "summary.json results lack phase_separation.u_DG"
stop_then_resume "$WORK/gls.toml" "$WORK/split" 7
same_files "$WORK/gls" "$WORK/split" series.csv summary.csv fields/grid_000000020.vti
# A finished run resumed steps nothing and writes summary.csv again from series.csv (u_DG with its window).
head -1 "$WORK/gls/summary.csv" | grep -q ",u_DG,t_DG_begin,t_DG_end$" || fail "summary lacks u_DG: $(head -1 "$WORK/gls/summary.csv")"
mv "$WORK/gls/summary.csv" "$WORK/summary.before"
"$SF" run "$WORK/gls.toml" --output "$WORK/gls" --resume -q > /dev/null
cmp -s "$WORK/summary.before" "$WORK/gls/summary.csv" || fail "a finished run resumed did not write the same summary.csv"
expect_error "${gls/checkpoint_every = 5/checkpoint_every = 5
growth_window = 0}" "output.growth_window"
expect_error "${gls/q = -0.019/q = -0.019
zeta = 1.0}" "run.dt" "stable limit" "diffusion"
expect_error "${gls/K = 1e-3/K = 5.0}" "run.dt" "capillary waves"
expect_error "${gls/rho0 = 1.0/rho0 = 3.2}" "initial.rho0"
expect_error "${gls/q = -0.019/q = 2e-3}" "model.q" "tau"
expect_error "${gls/kind = \"gls\"/kind = \"gls\"
gamma = 1.4}" "model.gamma" "2"
expect_error "${gls/kind = \"gls\"/kind = \"gls\"
convection = \"nnd\"}" "model.convection" "spectral"
expect_error "${gls/kind = \"gls\"/kind = \"bgk\"
filter_state = true}" "model.filter_state" "spectral"
expect_error "$gls
[boundary]
x_low = \"outflow\"" "boundary.x_low" "periodic"
# (without the state filter: with it, this quench no longer breaks down within t = 0.02)
deep="${gls/rho0 = 1.0/rho0 = 2.6}"; deep="${deep/noise = 0.05/noise = 0.15}"; deep="${deep/q = -0.019/q = -0.019
filter_state = false}"
run_expecting 3 "${deep/T = 0.85/T = 0.2}" "broke down"
[ -s "$WORK/out/series.csv" ] && [ -s "$WORK/out/summary.csv" ] || fail "a blown-up GLS run lost its output"
# [output] extra_thresholds: L at the default threshold (rho0 = 1) again as column L_rho1 equals column L;
# [initial] noise_wavelength: band-limited noise runs, one shorter than two cells is refused.
run_expecting 0 "${gls/checkpoint_every = 5/checkpoint_every = 5
extra_thresholds = [1.0, 1.3]}"
/usr/bin/python3 - "$WORK/out/series.csv" <<'PY' || fail "L_rho1 differs from L"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert "L_rho1.3" in rows[0], rows[0].keys()
assert all(r["L_rho1"] == r["L"] for r in rows) and float(rows[1]["L"]) > 0, [(r["L"], r["L_rho1"]) for r in rows]
PY
run_expecting 0 "${gls/noise = 0.05/noise = 0.05
noise_wavelength = 0.25}"
expect_error "${gls/noise = 0.05/noise = 0.05
noise_wavelength = 0.1}" "initial.noise_wavelength" "two cells"
echo "dbm_gls_run: series, summary, fields, derived dt limit, bitwise resume, summary of a finished run resumed, refused GLS input, blow-up, extra L thresholds, band-limited noise"

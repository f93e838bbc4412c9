#!/usr/bin/env bash
# The linear stability check of a dbm case ([model] stability_check, docs/dbm.md): a detonation
# whose CJ state is too hot for speeds 1..4 is refused naming the state, the growth rate and the
# remedy (exit 2, no run folder); "warn" runs it with the warning on stderr; a 2D time step beyond
# the analysed limit is refused with the largest stable one; a stable case records the result
# under [derived]; the von Neumann state of the detonation example held by an inflow at dx = 0.0025,
# stable with first-order upwind but whose smooth modes grow (the run breaks down at t = 1.2), is
# refused, while dx = 0.005 or tau = 1e-3 (runs that finish) pass, and so does a detonation at
# dx = 0.0025 whose von Neumann state is only the peak of the front (structure.toml refined: it
# finishes).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
det='method = "dbm"
[grid]
nx = 60
dx = 0.01
[model]
tau = 2e-3
[initial]
type = "uniform"
state = { rho = 1.0, p = 1.0 }
[reaction]
kind = "arrhenius"
heat_release = 1.0
rate = 20.0
[boundary]
x_low = "reflecting"
[run]
end_time = 0.01
courant = 0.4'
expect_error "$det" "model.stability_check" "Chapman-Jouguet state" "T = 1.579" "grow as exp(26.8 t)" \
  "for every time step" "speeds = [3, 2, 5, 10]"
run_expecting 0 "${det/tau = 2e-3/tau = 2e-3
stability_check = \"warn\"}" "warning: the Chapman-Jouguet state"
grep -q "linear_stability = 'unstable'" "$WORK/out/config.resolved.toml" || fail "warned run lacks the derived verdict"
expect_error "${det/tau = 2e-3/tau = 2e-3
stability_check = \"maybe\"}" "model.stability_check" "error"
square='method = "dbm"
[grid]
nx = 16
ny = 16
dx = 0.01
[model]
tau = 2e-3
[initial]
type = "uniform"
state = { rho = 1.0, p = 1.0 }
[boundary]
x_low = "periodic"
x_high = "periodic"
[run]
end_time = 0.01
courant = 0.8'
expect_error "$square" "model.stability_check" "with dt = 0.002" "largest stable time step here is 0.001446"
run_expecting 0 "${square/courant = 0.8/courant = 0.5}"
grep -q "linear_stability = 'stable'" "$WORK/out/config.resolved.toml" || fail "stable run lacks the derived verdict"
grep -q "linear_stability_stable_time_step = 0.00144" "$WORK/out/config.resolved.toml" || fail "derived stable time step"
inert='method = "dbm"
[grid]
nx = 100
dx = 0.0025
[model]
tau = 2e-3
[initial]
type = "uniform"
state = { rho = 1.0, p = 0.6 }
[boundary]
x_low = "inflow"
x_low_state = { rho = 2.269952, vx = 0.894427, p = 2.029951 }
[run]
end_time = 3.0
courant = 0.4'
expect_error "$inert" "model.stability_check" "boundary.x_low_state (rho = 2.27, v = (0.8944, 0), T = 0.8943)" \
  "smooth waves" "grows as exp(10.4 t)" "coarser grid or a smaller model.tau"
peak="${inert/x_low = \"inflow\"/x_low = \"reflecting\"}"
peak="${peak/x_low_state*p = 2.029951 \}/[reaction]
kind = \"arrhenius\"
heat_release = 0.6
rate = 1.0
ignition_temperature = 0.7}"
for ok in "${inert/dx = 0.0025/dx = 0.005}" "${inert/tau = 2e-3/tau = 1e-3}" "$peak"; do
  printf '%s\n' "$ok" > "$WORK/ok.toml"
  "$SF" run --check "$WORK/ok.toml" > /dev/null || fail "refused: $ok"
done
echo "dbm_stability: hot CJ state refused and warned, bad key value, 2D time step refused, derived verdict, smooth modes of a held von Neumann state"

#!/usr/bin/env bash
# Round trip through a material file (docs/bridges.md): the MD elastic constants of Cu_u3.eam
# (the LAMMPS fixture, via `bridge elastic --constants`) in a PD crystal bar loaded along [100],
# [110] and [111] give elastic fronts at √(C_L/ρ) of the same constants, C_L = C11,
# (C11 + C12 + 2C44)/2, (C11 + 2C12 + 4C44)/3 (Nye 1957). Tolerance 1%: the front position is
# read to a fraction of the 10 µm spacing over ~1.5 mm of travel, and PD's dispersion at this
# horizon shifts the half-height point by less than that (we see 0.04%).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
PY=/usr/bin/python3
"$SF" bridge elastic --constants "$ROOT/tests/fixtures/lammps_elastic/results.toml" --mass 63.546 \
  -o "$WORK/cu.toml" > /dev/null
for dir in "1, 0, 0" "1, 1, 0" "1, 1, 1"; do
  name=$(echo "$dir" | tr -d ' ,')
  cat > "$WORK/pd_$name.toml" <<CASE
method = "pd"
[body]
dim = 1
counts = [800]
spacing = 10e-6
[material]
model = "crystal"
file = "cu.toml"
orientation = "direction"
direction = [$dir]
[solver]
end_time = 0.5e-6
[loading]
type = "impact"
speed = 2.0
[output]
series_interval = 1e-7
profile_interval = 0.5e-7
CASE
  "$SF" run "$WORK/pd_$name.toml" --output "$WORK/pd_$name" -q > /dev/null
  measured=$($PY "$ROOT/tests/cli/bridge/pd_front_speed.py" "$WORK/pd_$name" 2.0)
  expected=$($PY - "$WORK/cu.toml" "$name" <<'PY'
import sys, tomllib
e = tomllib.load(open(sys.argv[1], "rb"))["elasticity"]
c11, c12, c44, rho = e["c11"], e["c12"], e["c44"], e["density"]
cl = {"100": c11, "110": (c11 + c12 + 2 * c44) / 2, "111": (c11 + 2 * c12 + 4 * c44) / 3}[sys.argv[2]]
print((cl / rho) ** 0.5)
PY
)
  echo "[$name]: front $measured m/s, sqrt(C_L/rho) = $expected m/s"
  $PY -c "import sys; m, e = map(float, sys.argv[1:]); sys.exit(0 if abs(m - e) <= 0.01 * e else 1)" "$measured" "$expected" \
    || fail "[$name] front speed $measured m/s is not within 1% of $expected m/s"
done
echo "bridge_round_trip: ok"

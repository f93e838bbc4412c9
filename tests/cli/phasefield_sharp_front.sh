#!/usr/bin/env bash
# The sharp-front option ([model] kind = "sharp_front") and bridge domain-growth --law paper, end to
# end on tracks.csv files written here (the format of analyze atoms --track):
# 1. an exact paper-law R(t) (dR/dt = 0.4 + 2*3/R, RK4 at 1e-3 ps) -> --law paper gives c0 = 40 m/s,
#    D = 3e-8 m^2/s to 1e-4 relative (the RK4 error of the writer's and the fit's steps);
# 2. Xu et al. (2015)'s decelerating growth R = 8 A (t/2 ps)^0.465 (t = 2 ... 16 ps) -> --law paper
#    (D > 0 accepted) -> a sharp-front run from the fitted R0 reading the material file reproduces
#    the series within 3x the fit's rms residual at every point, and its own tracks.csv fitted again
#    gives the same c0 and D to 1e-6 relative (the round trip closes);
# 3. refusals: an accelerating series under --law paper, --interface-width with --law paper, none
#    with the default law; every case key the option cannot represent, named;
# 4. (run before 3) the allen_cahn law against the field model's disc (a peer run).
source "$(dirname "$0")/lib.bash"
source "$(dirname "$0")/bridge_lib.bash"
set -e
/usr/bin/python3 - "$WORK" <<'PY'
import math, sys
w = sys.argv[1]
head = "track,frame,timestep,time,cluster,size,x,y,z,a,b,c,L,area,volume,atomic_volume\n"
def rows(times, radii):
    return "".join(f"1,{i},{int(round(t * 1000))},{t},1,{int(4 / 3 * math.pi * r**3 / 11.8)},0,0,0,{r},{r},{r},{r},0,0,"
                   f"{4 / 3 * math.pi * r**3!r}\n" for i, (t, r) in enumerate(zip(times, radii)))
def law(times, R, c0, s):  # dR/dt = c0 + s/R by RK4
    out, t = [], times[0]
    for target in times:
        n = max(1, round((target - t) / 0.001)); h = (target - t) / n
        f = lambda r: c0 + s / r
        for _ in range(n):
            k1 = f(R); k2 = f(R + h/2*k1); k3 = f(R + h/2*k2); k4 = f(R + h*k3); R += h/6*(k1 + 2*k2 + 2*k3 + k4)
        t = target; out.append(R)
    return out
times = [1.5 * k for k in range(12)]
open(f"{w}/paper.csv", "w").write(head + rows(times, law(times, 6.0, 0.4, 6.0)))
open(f"{w}/accel.csv", "w").write(head + rows(times, law(times, 9.0, 1.2, -6.0)))
pt = [2.0 * k for k in range(1, 9)]
open(f"{w}/power.csv", "w").write(head + rows(pt, [8 * (x / 2) ** 0.465 for x in pt]))
PY
# 1. The exact paper law.
"$SF" bridge domain-growth "$WORK/paper.csv" --law paper -o "$WORK/paper.toml"
within "$(value "$WORK/paper.toml" phasefield.front_speed)" 40 0.004 1 || fail "c0: $(cat "$WORK/paper.toml")"
within "$(value "$WORK/paper.toml" phasefield.curvature_coefficient)" 3e-8 3e-12 1 || fail "D: $(cat "$WORK/paper.toml")"
[ "$(value "$WORK/paper.toml" phasefield.kind)" = sharp_front ] && [ "$(value "$WORK/paper.toml" phasefield.law)" = paper ] \
  || fail "kind/law not written: $(cat "$WORK/paper.toml")"
# 2. t^0.465 -> the paper law -> a sharp-front run.
"$SF" bridge domain-growth "$WORK/power.csv" --law paper -o "$WORK/power.toml"
R0=$(/usr/bin/python3 -c "import sys; print(float(sys.argv[1]) * 1e10)" "$(value "$WORK/power.toml" provenance.domain_growth.fit.R0_m)")
cat > "$WORK/run.toml" <<EOF
method = "phasefield"
[grid]
dimensions = 3
nodes = [64, 64, 64]
spacing = 1.0
[model]
kind = "sharp_front"
file = "power.toml"
length_unit = 1e-10
time_unit = 1e-12
[time]
dt = 0.01
end_time = 14.0
[[initial.sphere]]
center = [32.0, 32.0, 32.0]
radius = $R0
[output]
series_interval = 2.0
EOF
"$SF" run "$WORK/run.toml" -o "$WORK/run" -q
"$SF" plot phasefield "$WORK/run" > /dev/null
[ -s "$WORK/run/phasefield.png" ] || fail "shockfield plot phasefield wrote no PNG for a sharp-front run"
/usr/bin/python3 - "$WORK" <<'PY' || fail "the sharp-front run does not reproduce t^0.465"
import csv, sys, tomllib
w = sys.argv[1]
rms = tomllib.load(open(f"{w}/power.toml", "rb"))["provenance"]["domain_growth"]["fit"]["residual_rms_m"] * 1e10
rows = list(csv.DictReader(open(f"{w}/run/tracks.csv")))
assert len(rows) == 8, len(rows)
worst = max(abs(float(r["L"]) - 8 * ((float(r["time"]) + 2) / 2) ** 0.465) for r in rows)
print(f"ok: sharp-front R(t) within {worst:.4f} A of 8 (t/2)^0.465 (bound 3 x rms {rms:.4f} A)")
sys.exit(0 if worst <= 3 * rms else 1)
PY
"$SF" bridge domain-growth "$WORK/run" --law paper -o "$WORK/back.toml" > /dev/null
for k in front_speed curvature_coefficient; do
  a=$(value "$WORK/power.toml" phasefield.$k); b=$(value "$WORK/back.toml" phasefield.$k)
  within "$b" "$a" "$(/usr/bin/python3 -c "print(abs($a) * 1e-6)")" 1 || fail "round trip $k: $a -> $b"
done
echo "ok: the run's tracks.csv gives the same c0 and D back"
# 4. Peer run: the allen_cahn sharp front against the field model it is the limit of (2D disc,
# a = 0.4, D = 1: c0 = sqrt(1/2)(1 - 2a), R* = 7.07; R = 10 -> 12 over t = 40). The radius of the
# field's xi > 1/2 area must be within 1% of the sharp front's at every row (measured 0.46%: the
# node count of a 20-node disc at t = 0, then <= 0.27%), the paper's law ends 30% away.
base='method = "phasefield"
[grid]
dimensions = 2
nodes = [128, 128]
spacing = 0.5
[time]
dt = 0.05
end_time = 40.0'
field="$base
[[initial.sphere]]
center = [32.0, 32.0]
radius = 10.0
[output]
series_interval = 10.0"
printf '%s\n[model]\na = 0.4\nD = 1.0\n' "$field" > "$WORK/field.toml"
for law in allen_cahn paper; do
  printf '%s\n[model]\nkind = "sharp_front"\nlaw = "%s"\nc0 = %s\nD = 1.0\n' "$field" $law \
    "$(/usr/bin/python3 -c 'print(0.5 ** 0.5 * 0.2)')" > "$WORK/sf_$law.toml"
  "$SF" run "$WORK/sf_$law.toml" -o "$WORK/sf_$law" -q
done
"$SF" run "$WORK/field.toml" -o "$WORK/field" -q
/usr/bin/python3 - "$WORK" <<'PY' || fail "the allen_cahn sharp front is not the field model's limit"
import csv, math, sys
w = sys.argv[1]
field, ac, paper = (list(csv.DictReader(open(f"{w}/{n}/series.csv"))) for n in ("field", "sf_allen_cahn", "sf_paper"))
dev = [math.sqrt(float(f["volume_fraction"]) * 64 * 64 / math.pi) / float(s["max_radius"]) - 1 for f, s in zip(field, ac)]
end = float(paper[-1]["max_radius"]) / float(ac[-1]["max_radius"]) - 1
print(f"ok: field vs allen_cahn sharp front: largest |R_field/R_sharp - 1| {max(map(abs, dev)):.4f} over {len(dev)} rows; "
      f"paper's law {end:+.2f} at the end")
sys.exit(0 if len(dev) == 5 and max(map(abs, dev)) <= 0.01 and end > 0.3 else 1)
PY
# 3. Refusals of the bridge.
bad "of the paper's law" "is not positive" "--law allen_cahn" "Nothing written" -- domain-growth "$WORK/accel.csv" --law paper -o "$WORK/x.toml"
[ ! -e "$WORK/x.toml" ] || fail "a material was written for an accelerating series"
bad "no front width" -- domain-growth "$WORK/paper.csv" --law paper --interface-width 2 -o "$WORK/x.toml"
bad "--interface-width W is required" -- domain-growth "$WORK/paper.csv" -o "$WORK/x.toml"
bad "--law paper fits" -- domain-growth "$WORK/power.csv" --interface-width 2 -o "$WORK/x.toml"
# ... and of the case reader: what the sharp front cannot represent, each key named.
law='[model]
kind = "sharp_front"
law = "paper"
c0 = 0.1
D = 1.0'
sphere='[[initial.sphere]]
center = [16.0, 16.0]
radius = 4.0'
expect_error "$base
$law
[[initial.ellipsoid]]
center = [16.0, 16.0]
semi_axes = [4.0, 2.0]" "initial.ellipsoid" "spheres only"
expect_error "$base
$law
[[initial.slab]]
center = [16.0, 16.0]
normal = [1.0, 0.0]
half_width = 3.0" "initial.slab" "spheres only"
expect_error "$base
$law
[initial]
file = \"xi.vti\"" "initial.file" "spheres only"
expect_error "$base
$law
[grid.boundary]
x = \"neumann\"
$sphere" "grid.boundary" "periodic box"
expect_error "$(echo "$base" | sed 's/^dt = 0.05/scheme = "spectral"\ndt = 0.05/')
$law
$sphere" "time.scheme" "RK4"
expect_error "$base
$law
a = 0.4
$sphere" "model.a" "field model"
expect_error "$base
$(echo "$law" | grep -v '^law')
$sphere" "model.law"
expect_error "$base
$(echo "$law" | sed 's/^D = 1.0/D = 0.0/')
$sphere" "model.D"
expect_error "$base
$law" "initial" "at least one"
expect_error "$base
$(echo "$law" | sed 's/sharp_front/sharp/')
$sphere" "model.kind"
# Material files: a sharp-front file needs time_unit; a field-model file has no front speed; the
# field model refuses a sharp-front file.
expect_error "$base
[model]
kind = \"sharp_front\"
file = \"$WORK/paper.toml\"
length_unit = 1e-10
$sphere" "model.time_unit"
printf 'name = "f"\n[phasefield]\na = 0.3\ninterface_width = 2e-10\nrelaxation_time = 1e-12\n' > "$WORK/field.toml"
expect_error "$base
[model]
kind = \"sharp_front\"
law = \"paper\"
file = \"$WORK/field.toml\"
length_unit = 1e-10
time_unit = 1e-12
$sphere" "phasefield.front_speed" "sharp-front model"
expect_error "$base
[model]
file = \"$WORK/paper.toml\"
length_unit = 1e-10
$sphere" "model.file" "kind = \"sharp_front\""
echo "phasefield_sharp_front: all checks passed"

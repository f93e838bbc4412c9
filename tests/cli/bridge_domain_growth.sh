#!/usr/bin/env bash
# `shockfield bridge domain-growth` on tracks.csv files written here (the format of analyze atoms
# --track): R(t) of dR/dt = c0 - 2D/R (c0 = 1.2 Å/ps, D = 3 Å²/ps, exact to RK4 round-off) must
# give c0 and D to 1e-4 relative (the fit integrates the same law; the bound is the RK4 error of
# the writer's and the fit's steps) and a = (1 - c0 W/D)/2, tau = W²/(2D) exactly from them; then
# the refusals: R = 8 (t/2)^0.465 (D < 0: nothing written), one frame, no rows (no hcp atoms), a
# missing file, a front too wide for a, a missing track, a non-numeric cell; analyze atoms --voxel
# refusals; a phase-field case with [model] file needs length_unit.
source "$(dirname "$0")/lib.bash"
source "$(dirname "$0")/bridge_lib.bash"
set -e
/usr/bin/python3 - "$WORK" <<'PY'
import math, sys
w = sys.argv[1]
def rows(times, radii, track=1):
    return "".join(f"{track},{i},{int(t*1000)},{t},1,{int(4/3*math.pi*r**3/11.8)},0,0,0,{r},{r},{r},{r},0,0,{4/3*math.pi*r**3}\n"
                   for i, (t, r) in enumerate(zip(times, radii)))
head = ("track,frame,timestep,time_ps,cluster,size,x_A,y_A,z_A,a_A,b_A,c_A,L_A,ellipsoid_surface_A2,ellipsoid_volume_A3,"
        "atomic_volume_A3\n")
times = [1.5 * k for k in range(12)]
R, out, t = 9.0, [], 0.0
for target in times:
    n = max(1, round((target - t) / 0.001)); h = (target - t) / n
    for _ in range(n):
        f = lambda r: 1.2 - 6.0 / r
        k1 = f(R); k2 = f(R + h/2*k1); k3 = f(R + h/2*k2); k4 = f(R + h*k3); R += h/6*(k1+2*k2+2*k3+k4)
    t = target; out.append(R)
open(f"{w}/law.csv", "w").write(head + rows(times, out) + rows(times[:3], [5, 5.5, 6], track=2))
# The same track under the model-unit names of a phasefield run's tracks.csv (time, L, atomic_volume).
model_head = "track,frame,timestep,time,cluster,size,x,y,z,a,b,c,L,area,volume,atomic_volume\n"
open(f"{w}/law_model.csv", "w").write(model_head + rows(times, out))
pt = [2 * k for k in range(1, 9)]
open(f"{w}/power.csv", "w").write(head + rows(pt, [8 * (x / 2) ** 0.465 for x in pt]))
open(f"{w}/one.csv", "w").write(head + rows([3.0], [10.0]))
open(f"{w}/empty.csv", "w").write(head)
lines = rows(times, out).splitlines(True)
lines[3] = lines[3].rsplit(",", 1)[0] + ",many\n"  # file line 5
open(f"{w}/text.csv", "w").write(head + "".join(lines))
PY
"$SF" bridge domain-growth "$WORK/law.csv" --interface-width 2 -o "$WORK/pf.toml" > "$WORK/stdout"
cat "$WORK/stdout"
c0=$(value "$WORK/pf.toml" provenance.domain_growth.fit.c0_m_s); D=$(value "$WORK/pf.toml" provenance.domain_growth.fit.D_m2_s)
within "$c0" 120 0.012 1 || fail "c0 $c0 m/s, expected 120"
within "$D" 3e-8 3e-12 1 || fail "D $D m^2/s, expected 3e-8"
a=$(value "$WORK/pf.toml" phasefield.a); tau=$(value "$WORK/pf.toml" phasefield.relaxation_time)
within "$a" 0.1 1e-5 1 || fail "a = $a, expected (1 - 1.2*2/3)/2 = 0.1"
within "$tau" 6.6667e-13 1e-16 1 || fail "tau = $tau, expected 4/6 ps"
[ "$(value "$WORK/pf.toml" provenance.domain_growth.inputs | grep -c sha256)" -ge 1 ] || fail "no input hash"
echo "ok: c0 $c0 m/s, D $D m^2/s, a $a, tau $tau s"
"$SF" bridge domain-growth "$WORK/law_model.csv" --interface-width 2 -o "$WORK/pf_model.toml" > /dev/null
[ "$(value "$WORK/pf_model.toml" provenance.domain_growth.fit.c0_m_s)" = "$c0" ] \
  || fail "a phasefield run's tracks.csv (model-unit names) gives another c0: $(value "$WORK/pf_model.toml" provenance.domain_growth.fit.c0_m_s)"
# --update keeps another bridge's section.
printf 'name = "x"\n[spall]\nstrength = 1e9\nstrain_rate = 1e9\n' > "$WORK/both.toml"
"$SF" bridge domain-growth "$WORK/law.csv" --interface-width 2 -o "$WORK/both.toml" --update > /dev/null
within "$(value "$WORK/both.toml" spall.strength)" 1e9 1 1 && value "$WORK/both.toml" phasefield.a > /dev/null \
  || fail "--update lost a section: $(cat "$WORK/both.toml")"
bad "is not positive" "L ~ t^0.465" "Nothing written" -- domain-growth "$WORK/power.csv" --interface-width 2 -o "$WORK/p.toml"
[ ! -e "$WORK/p.toml" ] || fail "a material was written for D < 0"
bad "1 point(s)" "at least 4" -- domain-growth "$WORK/one.csv" --interface-width 2 -o "$WORK/p.toml"
bad "no tracked domain" "hcp atoms" -- domain-growth "$WORK/empty.csv" --interface-width 2 -o "$WORK/p.toml"
bad "no such file" -- domain-growth "$WORK/none.csv" --interface-width 2 -o "$WORK/p.toml"
bad "wider than D/|c0|" -- domain-growth "$WORK/law.csv" --interface-width 4 -o "$WORK/p.toml"
bad "no track 7" -- domain-growth "$WORK/law.csv" --track 7 --interface-width 2 -o "$WORK/p.toml"
bad "text.csv: line 5" "'atomic_volume_A3'" -- domain-growth "$WORK/text.csv" --interface-width 2 -o "$WORK/p.toml"
bad "at least 4" -- domain-growth "$WORK/law.csv" --until 4 --interface-width 2 -o "$WORK/p.toml"
# analyze atoms --voxel: a spacing longer than the box, a bad selection, a missing dump.
/usr/bin/python3 - "$WORK" "$ROOT/tests/cli" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from fcc_frames import fcc_sites, write_dump
write_dump(f"{sys.argv[1]}/fcc.dump", fcc_sites(3.615, 3), 3 * 3.615, 0)
PY
"$SF" analyze atoms "$WORK/fcc.dump" --voxel 1.0 -o "$WORK/vox" > "$WORK/stdout"
grep -q "voxel fields of 'acna:hcp': 1 frames, 11 x 11 x 11 nodes" "$WORK/stdout" || fail "voxel summary: $(cat "$WORK/stdout")"
[ -s "$WORK/vox/voxels_0.vti" ] || fail "no voxels_0.vti"
analyze_rejected "longer than the box" -- atoms "$WORK/fcc.dump" --voxel 30
analyze_rejected "--voxel-select 'acna:foo'" -- atoms "$WORK/fcc.dump" --voxel 1 --voxel-select acna:foo
set +e
"$SF" analyze atoms "$WORK/missing.dump" --voxel 1 -o "$WORK/bad" > /dev/null 2> "$WORK/stderr"; code=$?
set -e
[ $code -ne 0 ] && [ $code -ne 1 ] && grep -q "missing.dump" "$WORK/stderr" || fail "missing dump: exit $code $(cat "$WORK/stderr")"
echo "ok: missing dump refused (exit $code)"
# A phase-field case reading the material file: length_unit is required with it.
expect_error "method = \"phasefield\"
[grid]
dimensions = 2
nodes = [16, 16]
spacing = 0.5
[model]
file = \"$WORK/pf.toml\"
[time]
dt = 0.05
end_time = 1.0
[[initial.sphere]]
center = [4.0, 4.0]
radius = 2.0" "length_unit"

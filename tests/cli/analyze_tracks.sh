#!/usr/bin/env bash
# `shockfield analyze atoms --track`: a dump series of a Cu crystal in which a disordered sphere
# (atoms displaced at random by up to 0.45 Å, adaptive CNA "other") grows as R = 0.5 t^0.5 Å
# (t in timesteps) must be one track whose fitted growth laws are L ~ t^0.5, A ~ t, V ~ t^1.5
# (Xu et al. (2015) Fig 72). Tolerances: the random displacements decide which atoms at the
# sphere's edge are "other" (a fraction of a shell either way); measured L 0.493, A 0.980,
# V 1.479 with 6 frames; the bounds are ±0.04 on L, ±0.08 on A and ±0.12 on V (about five times
# the measured deviation, for other random draws). Then bad options.
source "$(dirname "$0")/lib.bash"
set -e
/usr/bin/python3 - "$WORK" "$ROOT/tests/cli" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[2])
from fcc_frames import fcc_sites, write_dump
a, n = 3.615, 12
x, L = fcc_sites(a, n), n * a
rng = np.random.default_rng(5)
for t in (100, 200, 300, 500, 700, 1000):
    inside = np.linalg.norm(x - L / 2, axis=1) < 0.5 * np.sqrt(t)
    write_dump(f"{sys.argv[1]}/grow.{t}.dump", x + inside[:, None] * rng.uniform(-0.45, 0.45, x.shape), L, t)
PY
files=()
for t in 100 200 300 500 700 1000; do files+=("$WORK/grow.$t.dump"); done
"$SF" analyze atoms "${files[@]}" --clusters 3.0 --cluster-select acna:other --cluster-min-size 20 --track \
  --timestep-size 0.002 -o "$WORK/an" > "$WORK/stdout"
grep -q "^track 1 (6 frames" "$WORK/stdout" || fail "track summary: $(cat "$WORK/stdout")"
[ "$(awk -F, 'NR > 1 { print $1 }' "$WORK/an/tracks.csv" | sort -u)" = "1" ] || fail "more than one track: $(cat "$WORK/an/tracks.csv")"
[ "$(wc -l < "$WORK/an/tracks.csv")" -eq 7 ] || fail "tracks.csv rows: $(cat "$WORK/an/tracks.csv")"
awk -F, 'NR == 2 && ($4 < 0.19 || $4 > 0.21) { exit 1 }' "$WORK/an/tracks.csv" || fail "time column (100 × 0.002): $(sed -n 2p "$WORK/an/tracks.csv")"
k() { awk -F, -v q="$1" '$2 == q { print $3 }' "$WORK/an/growth.csv"; }
head -1 "$WORK/an/tracks.csv" | grep -qx "track,frame,timestep,time_ps,cluster,size,x_A,y_A,z_A,a_A,b_A,c_A,L_A,ellipsoid_surface_A2,ellipsoid_volume_A3,atomic_volume_A3" \
  || fail "tracks.csv columns (units in the names, docs/conventions.md): $(head -1 "$WORK/an/tracks.csv")"
awk -v l="$(k L_A)" -v v="$(k ellipsoid_volume_A3)" -v s="$(k ellipsoid_surface_A2)" 'BEGIN { exit !(l > 0.46 && l < 0.54 && s > 0.92 && s < 1.08 && v > 1.38 && v < 1.62) }' \
  || fail "growth exponents L $(k L_A) A $(k ellipsoid_surface_A2) V $(k ellipsoid_volume_A3)"
grep -q " track" "$WORK/an/grow.1000.dump" || fail "no track column"
echo "ok: one track, L ~ t^$(k L_A), A ~ t^$(k ellipsoid_surface_A2), V ~ t^$(k ellipsoid_volume_A3)"
# Without --timestep-size the growth time is in timesteps and named so.
"$SF" analyze atoms "${files[@]}" --clusters 3.0 --cluster-select acna:other --cluster-min-size 20 --track \
  --no-plot -o "$WORK/steps" > /dev/null
[ "$(head -1 "$WORK/steps/tracks.csv" | cut -d, -f4)" = elapsed_timesteps ] || fail "time column without --timestep-size: $(head -1 "$WORK/steps/tracks.csv")"
awk -F, 'NR == 2 && $4 != 100 { exit 1 }' "$WORK/steps/tracks.csv" || fail "elapsed timesteps: $(sed -n 2p "$WORK/steps/tracks.csv")"

set +e
"$SF" analyze atoms "$WORK/grow.100.dump" --track -o "$WORK/bad" > /dev/null 2> "$WORK/stderr"
code=$?
set -e
[ $code -eq 2 ] && grep -q "needs --clusters" "$WORK/stderr" && [ ! -e "$WORK/bad" ] || fail "--track without --clusters: exit $code, $(cat "$WORK/stderr")"
echo "ok: $(cat "$WORK/stderr")"

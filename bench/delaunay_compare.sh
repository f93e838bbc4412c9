#!/usr/bin/env bash
# Delaunay division of the same uniform random points by shockfield, CGAL (cgal_delaunay_peer)
# and SciPy/Qhull, alternating the three on each data set, then SHT vs nanoflann query rates.
#   bash bench/delaunay_compare.sh BUILD_DIR [N3D] [N2D] [ROUNDS]
# (defaults 1000000 1000000 1). Times are of the division only (files read first).
set -eu
B="$1"; N3="${2:-1000000}"; N2="${3:-1000000}"; ROUNDS="${4:-1}"
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
"$B/bench/delaunay_bench" generate 3 "$N3" "$W/p3.csv"
"$B/bench/delaunay_bench" generate 2 "$N2" "$W/p2.csv"
scipy() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys, time, numpy as np
from scipy.spatial import Delaunay
d, f = int(sys.argv[1]), sys.argv[2]
p = np.loadtxt(f, delimiter=",", skiprows=1)
t = time.perf_counter(); tri = Delaunay(p); t = time.perf_counter() - t
print(f"scipy {d}d points {len(p)} simplices {len(tri.simplices)} seconds {t:.3f}")
PY
}
for r in $(seq "$ROUNDS"); do
  for d in 3 2; do
    "$B/bench/delaunay_bench" delaunay "$d" "$W/p$d.csv"
    [ -x "$B/bench/cgal_delaunay_peer" ] && "$B/bench/cgal_delaunay_peer" "$d" "$W/p$d.csv"
    scipy "$d" "$W/p$d.csv"
  done
done
"$B/bench/delaunay_bench" queries 1000000 1000000

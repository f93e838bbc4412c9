#!/usr/bin/env bash
# GISO benchmark (bench/RESULTS.md "## GISO"): the Delaunay division of the same points by
# shockfield, CGAL (cgal_delaunay_peer) and SciPy/Qhull, then SHT vs nanoflann (and SciPy's
# cKDTree) query rates.
#   bash bench/delaunay_compare.sh BUILD_DIR [N3D] [N2D] [ROUNDS] [QUERIES] [BEFORE_BENCH]
# (defaults 1000000 1000000 3 200000). Data sets: N3D uniform random points in the unit cube,
# an fcc crystal of about N3D atoms with thermal displacements (delaunay_bench generate-fcc),
# N2D uniform points in the unit square. Each round runs, per data set, BEFORE_BENCH (an older
# delaunay_bench, optional), ours and CGAL one after the other; SciPy/Qhull (minutes per 10^6
# points) runs once per data set, after all rounds. Each line is followed by the process's CPU
# time (`cpu USER SYS`, /usr/bin/time, file reading included); the printed `seconds` and
# `cpu_seconds` are the wall and CPU times of the division only (an older BEFORE_BENCH may print
# only the wall time). `uptime` is printed before and after: report medians and the load.
# QHULL=0 in the environment leaves SciPy/Qhull out (a rerun of ours against CGAL). SETS (default
# "uniform3 fcc3 uniform2") chooses the data sets; sc3 and fcclat3 are the exact simple cubic and
# fcc lattices of about N3D points (generate-lattice, lattice constant 1: every in-sphere test
# degenerate), fcccu3 the fcc lattice of copper's a = 3.615 (coordinates rounded, near-degenerate). QUERIES=0
# leaves the query rates out.
set -eu
B="$1"; N3="${2:-1000000}"; N2="${3:-1000000}"; ROUNDS="${4:-3}"; Q="${5:-200000}"
BEFORE="${6:-}"
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
cpu() { /usr/bin/time -f "  cpu %U %S" "$@"; }
SETS="${SETS:-uniform3 fcc3 uniform2}"
for set in $SETS; do
  case "$set" in
    uniform3) "$B/bench/delaunay_bench" generate 3 "$N3" "$W/$set.csv" ;;
    fcc3) "$B/bench/delaunay_bench" generate-fcc "$N3" "$W/$set.csv" ;;
    uniform2) "$B/bench/delaunay_bench" generate 2 "$N2" "$W/$set.csv" ;;
    sc3) "$B/bench/delaunay_bench" generate-lattice sc "$N3" "$W/$set.csv" ;;
    fcclat3) "$B/bench/delaunay_bench" generate-lattice fcc "$N3" "$W/$set.csv" ;;
    fcccu3) "$B/bench/delaunay_bench" generate-lattice fcc "$N3" "$W/$set.csv" 3.615 ;;
    *) echo "unknown data set $set" >&2; exit 2 ;;
  esac
done
scipy_delaunay() {
  cpu /usr/bin/python3 - "$1" "$2" <<'PY'
import sys, time, numpy as np
from scipy.spatial import Delaunay
d, f = int(sys.argv[1]), sys.argv[2]
p = np.loadtxt(f, delimiter=",", skiprows=1)
t, c = time.perf_counter(), time.process_time()
tri = Delaunay(p)
t, c = time.perf_counter() - t, time.process_time() - c
print(f"scipy {d}d points {len(p)} simplices {len(tri.simplices)} seconds {t:.3f} cpu_seconds {c:.3f}")
PY
}
dim_of() { [ "$1" = uniform2 ] && echo 2 || echo 3; }
echo "load: $(uptime)"
for r in $(seq "$ROUNDS"); do
  for set in $SETS; do
    d=$(dim_of "$set")
    echo "round $r $set"
    [ -n "$BEFORE" ] && { echo -n "before "; cpu "$BEFORE" delaunay "$d" "$W/$set.csv"; }
    cpu "$B/bench/delaunay_bench" delaunay "$d" "$W/$set.csv"
    [ -x "$B/bench/cgal_delaunay_peer" ] && cpu "$B/bench/cgal_delaunay_peer" "$d" "$W/$set.csv"
  done
done
[ "${QUERIES:-1}" = 0 ] && ROUNDS_Q=0 || ROUNDS_Q="$ROUNDS"
for r in $(seq "$ROUNDS_Q"); do
  echo "queries round $r"
  [ -n "$BEFORE" ] && { echo "before:"; "$BEFORE" queries "$N3" "$Q"; }
  "$B/bench/delaunay_bench" queries "$N3" "$Q"
done
[ "$ROUNDS_Q" = 0 ] || echo "scipy cKDTree (its own uniform points, same counts and radius, one thread):"
[ "$ROUNDS_Q" = 0 ] || /usr/bin/python3 - "$N3" "$Q" <<'PY'
import sys, time, numpy as np
from scipy.spatial import cKDTree
n, q = int(sys.argv[1]), int(sys.argv[2])
rng = np.random.default_rng(1)
p, qs = rng.random((n, 3)), rng.random((q, 3))
r = (30.0 / (4.18879 * n)) ** (1 / 3)
t = time.perf_counter(); tree = cKDTree(p, leafsize=10); build = time.perf_counter() - t
t = time.perf_counter(); tree.query(qs, k=1, workers=1); nearest = time.perf_counter() - t
t = time.perf_counter(); hits = tree.query_ball_point(qs, r, workers=1); radius = time.perf_counter() - t
print(f"ckdtree build {build:.3f} s, nearest {q / nearest:.3g} /s, radius {q / radius:.3g} /s, "
      f"found {sum(len(h) for h in hits)}")
PY
if [ "${QHULL:-1}" != 0 ]; then
  for set in $SETS; do
    scipy_delaunay "$(dim_of "$set")" "$W/$set.csv"
  done
fi
echo "load: $(uptime)"

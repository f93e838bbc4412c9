#!/usr/bin/env bash
# `shockfield analyze geometry` on a run's particle frames (analysis/point_frame_reader): the last
# MPM particle frame as a .vtp, through its .pvd (--frame -1), and as a .pvtp of three pieces gives
# the Delaunay division (2D: the particles' x, y) that the same points give as a CSV file written by
# the Python reader (shockfield.vtk_arrays, numpy only: a peer reader of the same file); the
# outputs carry the frame's position unit (units="m"); a .pvd of grid frames and a frame beyond the
# series are refused (exit 2).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
CASE="$ROOT/tests/cli/cases/mpm_tiny.toml"
"$SF" run "$CASE" --output "$WORK/one" -q > /dev/null
sed "s/^\[output\]/[output]\nvtk_pieces = 3/" "$CASE" > "$WORK/pieces.toml"
"$SF" run "$WORK/pieces.toml" --output "$WORK/three" -q > /dev/null
last=$(ls "$WORK/one/fields" | grep '^particles_.*\.vtp$' | tail -1)
# The peer: the same frame's points through the Python reader, as x,y CSV (repr: every double exact;
# the file's Float32 coordinates are doubles exactly).
PYTHONPATH="$ROOT/python" /usr/bin/python3 - "$WORK/one/fields/$last" "$WORK/points.csv" <<'PY'
import sys
from shockfield.vtk_arrays import read_vtk_arrays
xyz = read_vtk_arrays(sys.argv[1])["points"]
with open(sys.argv[2], "w") as f:
    f.write("x,y\n" + "".join(f"{float(x)!r},{float(y)!r}\n" for x, y, _ in xyz))
PY
"$SF" analyze geometry "$WORK/points.csv" --dimension 2 -d 3e-5 -o "$WORK/csv" > /dev/null
for input in "one/fields/$last" "one/particles.pvd" "three/particles.pvd"; do
  out="$WORK/out_$(echo "$input" | tr / _)"
  "$SF" analyze geometry "$WORK/$input" --dimension 2 --frame -1 -d 3e-5 -o "$out" > /dev/null
  cmp -s "$WORK/csv/summary.txt" "$out/summary.txt" ||
    fail "$input: another division than the CSV of its points: $(diff "$WORK/csv/summary.txt" "$out/summary.txt")"
  cmp -s <(cut -d, -f2- "$WORK/csv/clusters.csv") <(cut -d, -f2- "$out/clusters.csv") || fail "$input: other clusters"
  grep -aq 'Name="points"[^>]* units="m"' "$out/delaunay.vtu" ||
    fail "$input: delaunay.vtu's points do not say units=\"m\""
done
grep -aq 'Name="points"[^>]* units="1"' "$WORK/csv/delaunay.vtu" || fail "a CSV's points are not units=\"1\""
echo "ok: .vtp, .pvd and .pvtp frames divide as the CSV of their points ($(grep '^points' "$WORK/csv/summary.txt"), $(grep '^simplices' "$WORK/csv/summary.txt"))"
analyze_rejected "its frames are .vti files; expected particle frames" -- geometry "$WORK/one/grid.pvd" --dimension 2
analyze_rejected "--frame 5; the series has 5 frames" -- geometry "$WORK/one/particles.pvd" --frame 5 --dimension 2
printf '<VTKFile type="PolyData"><PolyData><Piece NumberOfPoints="1000000000"><Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0</DataArray></Points></Piece></PolyData></VTKFile>\n' > "$WORK/huge.vtp"
analyze_rejected "1000000000 points cannot fit in a file of" -- geometry "$WORK/huge.vtp"
echo "analyze_geometry_frames: ok"

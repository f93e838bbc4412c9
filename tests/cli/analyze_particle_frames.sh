#!/usr/bin/env bash
# `shockfield analyze` on a run's particle frames (analysis/point_frame_reader). Geometry: the last
# MPM particle frame as a .vtp, through its .pvd (--frame -1), and as a .pvtp of three pieces gives
# the Delaunay division (2D: the particles' x, y) that the same points give as a CSV file written by
# the Python reader (shockfield.vtk_arrays, numpy only: a peer reader of the same file, given
# --length-units m); the outputs carry the frame's position unit (units="m", x_m, total_area_m2), a
# CSV's is unknown without --length-units, and a --length-units other than the frame's is refused; a .pvd of grid frames and a frame beyond the
# series are refused (exit 2). Fields: `analyze stats --bin-size` bins the frames' pressure on one
# grid and gets per frame the void cells, mean and std that numpy gets binning the same points
# (read by shockfield.vtk_arrays) by the same rule, in the frames' units (mean_Pa, time_s); the
# 3-piece frames give the same table; wrong combinations are refused (exit 2). MD's LAMMPS dumps
# (one frame per file) bin to their known cell means; a dump of two frames or without the column
# is refused.
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
"$SF" analyze geometry "$WORK/points.csv" --dimension 2 -d 3e-5 --length-units m -o "$WORK/csv" > /dev/null
for input in "one/fields/$last" "one/particles.pvd" "three/particles.pvd"; do
  out="$WORK/out_$(echo "$input" | tr / _)"
  "$SF" analyze geometry "$WORK/$input" --dimension 2 --frame -1 -d 3e-5 -o "$out" > /dev/null
  cmp -s "$WORK/csv/summary.txt" "$out/summary.txt" ||
    fail "$input: another division than the CSV of its points: $(diff "$WORK/csv/summary.txt" "$out/summary.txt")"
  cmp -s <(cut -d, -f2- "$WORK/csv/clusters.csv") <(cut -d, -f2- "$out/clusters.csv") || fail "$input: other clusters"
  grep -aq 'Name="points"[^>]* units="m"' "$out/delaunay.vtu" ||
    fail "$input: delaunay.vtu's points do not say units=\"m\""
  [ "$(head -1 "$out/clusters.csv")" = "index,x_m,y_m,seed_rule,single_linkage" ] || fail "$input: clusters.csv header $(head -1 "$out/clusters.csv")"
  grep -q '^total_area_m2 ' "$out/summary.txt" || fail "$input: summary.txt names no m2: $(cat "$out/summary.txt")"
done
# Without --length-units a CSV's unit is unknown, and the outputs say so.
"$SF" analyze geometry "$WORK/points.csv" --dimension 2 -o "$WORK/csv_unknown" > /dev/null
grep -aq 'Name="points"[^>]* units="unknown"' "$WORK/csv_unknown/delaunay.vtu" || fail "a CSV's points are not units=\"unknown\""
grep -q '^total_area_unknown ' "$WORK/csv_unknown/summary.txt" || fail "summary.txt of a CSV: $(cat "$WORK/csv_unknown/summary.txt")"
analyze_rejected "its coordinates are in 'm'; --length-units says 'A'" -- geometry "$WORK/one/particles.pvd" --dimension 2 --length-units A
echo "ok: .vtp, .pvd and .pvtp frames divide as the CSV of their points ($(grep '^points' "$WORK/csv/summary.txt"), $(grep '^simplices' "$WORK/csv/summary.txt"))"
analyze_rejected "its frames are .vti files; expected particle frames" -- geometry "$WORK/one/grid.pvd" --dimension 2
analyze_rejected "--frame 5; the series has 5 frames" -- geometry "$WORK/one/particles.pvd" --frame 5 --dimension 2
printf '<VTKFile type="PolyData"><PolyData><Piece NumberOfPoints="1000000000"><Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0</DataArray></Points></Piece></PolyData></VTKFile>\n' > "$WORK/huge.vtp"
analyze_rejected "1000000000 points cannot fit in a file of" -- geometry "$WORK/huge.vtp"
"$SF" analyze stats "$WORK/one/particles.pvd" --array pressure --bin-size 2e-5 -o "$WORK/binned" > /dev/null
"$SF" analyze stats "$WORK/three/particles.pvd" --array pressure --bin-size 2e-5 -o "$WORK/binned3" > /dev/null
cmp -s <(cut -d, -f2- "$WORK/binned/stats.csv") <(cut -d, -f2- "$WORK/binned3/stats.csv") ||
  fail "the 3-piece frames binned to other statistics"
PYTHONPATH="$ROOT/python" /usr/bin/python3 - "$WORK/one" "$WORK/binned/stats.csv" <<'PY' || fail "binned statistics differ from numpy's"
import csv, pathlib, re, sys
import numpy as np
from shockfield.vtk_arrays import read_vtk_arrays
run = pathlib.Path(sys.argv[1])
files = re.findall(r'file="([^"]+)"', (run / "particles.pvd").read_text())
frames = [read_vtk_arrays(run / f) for f in files]
h = 2e-5
lo = np.min([f["points"].min(axis=0) for f in frames], axis=0)
hi = np.max([f["points"].max(axis=0) for f in frames], axis=0)
n = np.floor((hi - lo) / h).astype(int) + 1
rows = list(csv.DictReader(open(sys.argv[2])))
assert list(rows[0])[:6] == ["file", "time_s", "cells", "void_cells", "mean_Pa", "std_Pa"], list(rows[0])
for frame, row in zip(frames, rows):
    cell = np.floor((frame["points"][:, :2] - lo[:2]) / h).astype(int)
    flat = cell[:, 0] + n[0] * cell[:, 1]
    count = np.bincount(flat, minlength=n[0] * n[1])
    total = np.bincount(flat, weights=frame["pressure"].astype(float), minlength=n[0] * n[1])
    means = total[count > 0] / count[count > 0]
    assert int(row["cells"]) == n[0] * n[1] and int(row["void_cells"]) == (count == 0).sum(), (row, n)
    for key, value in (("mean_Pa", means.mean()), ("std_Pa", means.std())):
        # %.10g in the CSV; the sums run in another order: 1e-9 of the field's scale
        assert abs(float(row[key]) - value) <= 1e-9 * max(abs(means).max(), 1.0), (key, row[key], value)
print(f"ok: {len(rows)} binned frames as numpy bins them ({n[0]} x {n[1]} cells of 20 um)")
PY
analyze_rejected "give --bin-size H" -- stats "$WORK/one/particles.pvd" --array pressure
analyze_rejected "--bin-size bins particle frames" -- stats "$WORK/one/grid.pvd" --bin-size 1e-5
analyze_rejected "no point array named 'nope'" -- stats "$WORK/one/particles.pvd" --array nope --bin-size 1e-5
analyze_rejected "expected at most 1e8" -- stats "$WORK/one/particles.pvd" --array pressure --bin-size 1e-12
# MD's LAMMPS dumps binned the same way (one frame per file): 4 atoms, two per 1 A cell along x at
# one y and z (a 2D grid of 2 x 1 cells), vx 1, 3 | V, 7: cell means 2 and (V + 7)/2, so stats.csv's
# mean over the cells is 4 (V = 5) and 5 (V = 9) exactly; positions in A (no ITEM: UNITS), vx of
# no named unit (mean_unknown), times from --times.
dump_frame() {  # dump_frame STEP V FILE
  printf 'ITEM: TIMESTEP\n%s\nITEM: NUMBER OF ATOMS\n4\nITEM: BOX BOUNDS ss pp pp\n0 2\n0 1\n0 1\nITEM: ATOMS id type x y z vx\n1 1 0 0.5 0.5 1\n2 1 0.5 0.5 0.5 3\n3 1 1.5 0.5 0.5 %s\n4 1 1.6 0.5 0.5 7\n' "$1" "$2" > "$3"
}
mkdir -p "$WORK/md_dumps"
dump_frame 0 5 "$WORK/md_dumps/dump.0.lammpstrj"
dump_frame 100 9 "$WORK/md_dumps/dump.100.lammpstrj"
"$SF" analyze stats "$WORK/md_dumps/dump.0.lammpstrj" "$WORK/md_dumps/dump.100.lammpstrj" --array vx --bin-size 1 \
  --times 0,0.1 --time-units ps -o "$WORK/md_binned" > /dev/null
/usr/bin/python3 - "$WORK/md_binned/stats.csv" <<'PY' || fail "MD dumps binned to other cell means"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [(r["time_ps"], r["cells"], r["void_cells"], float(r["mean_unknown"])) for r in rows] == \
    [("0", "2", "0", 4.0), ("0.1", "2", "0", 5.0)], rows
print("ok: two MD dumps binned to their known cell means (4 and 5)")
PY
cat "$WORK/md_dumps/dump.0.lammpstrj" "$WORK/md_dumps/dump.100.lammpstrj" > "$WORK/md_dumps/two_frames.lammpstrj"
analyze_rejected "2 frames; expected one frame per file" -- stats "$WORK/md_dumps/two_frames.lammpstrj" --array vx --bin-size 1
analyze_rejected "vy" -- stats "$WORK/md_dumps/dump.0.lammpstrj" --array vy --bin-size 1
echo "analyze_particle_frames: ok"

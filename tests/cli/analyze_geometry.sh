#!/usr/bin/env bash
# `shockfield analyze geometry`: the Delaunay division of the 8 corners of a unit cube plus its
# centre (total volume 1 exactly, every tetrahedron checked), clusters of two separated pairs
# (seed rule 1 cluster, single linkage 2), the rolling-ball surface of the cube (its hull: 12
# triangles, area 6, volume 1, χ = 2; the same by the pivoting ball and by packing-sculpting), a LAMMPS dump and an .xyz file as input,
# the outputs' length unit (summary.txt and clusters.csv names, VTK units: `unknown` for a CSV or XYZ
# file, --length-units when given, Å for a dump, m for a dump with ITEM: UNITS si), and bad input
# (NaN coordinate, fewer points than a simplex, coplanar points in 3D, collinear in 2D, a ball
# radius or sculpting depth too small to find a surface, a depth without packing or packing without
# a depth, a unit no column name can spell, a --length-units against the dump's, a dump's unknown unit style): one clear
# message, exit code 2, no output folder.
source "$(dirname "$0")/lib.bash"
set -e
printf 'x,y,z\n0,0,0\n1,0,0\n0,1,0\n1,1,0\n0,0,1\n1,0,1\n0,1,1\n1,1,1\n0.5,0.5,0.5\n' > "$WORK/cube.csv"
"$SF" analyze geometry "$WORK/cube.csv" --check -o "$WORK/cube" > "$WORK/stdout"
grep -q "^total_volume_unknown 1$" "$WORK/cube/summary.txt" || fail "cube volume: $(cat "$WORK/cube/summary.txt")"
grep -q "^check passed$" "$WORK/cube/summary.txt" || fail "no check line"
grep -q "^simplices 12$" "$WORK/cube/summary.txt" || fail "cube + centre is 12 tetrahedra: $(cat "$WORK/cube/summary.txt")"
grep -q 'NumberOfCells="12"' "$WORK/cube/delaunay.vtu" || fail "vtu cell count"
# The .vtu (zlib binary through io/vtk_xml) as VTK reads it: 9 points, 12 tetrahedra whose
# "volume" cell data sums to the cube's 1 (to Float64 round-off).
/usr/bin/python3 - "$WORK/cube/delaunay.vtu" <<'PY' || fail "delaunay.vtu as VTK reads it"
import sys
try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("python3-vtk9 missing: VTK read of delaunay.vtu skipped"); sys.exit(0)
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()
g = r.GetOutput()
assert g.GetNumberOfPoints() == 9 and g.GetNumberOfCells() == 12, (g.GetNumberOfPoints(), g.GetNumberOfCells())
assert all(g.GetCellType(c) == vtk.VTK_TETRA for c in range(12))
v = vtk_to_numpy(g.GetCellData().GetArray("volume"))
assert abs(v.sum() - 1.0) < 1e-14 and (v > 0).all(), v
PY
echo "ok: cube"
"$SF" analyze geometry "$WORK/cube.csv" -r 5 --no-mesh -o "$WORK/ball" > /dev/null
for want in "surface_triangles 12" "surface_area_unknown 6" "surface_volume_unknown 1" "surface_euler_characteristic 2" "surface_manifold yes"; do
  grep -qx "$want" "$WORK/ball/summary.txt" || fail "rolling ball: no '$want' in $(cat "$WORK/ball/summary.txt")"
done
grep -q 'NumberOfPolys="12"' "$WORK/ball/surface.vtp" || fail "surface.vtp polygon count"
echo "ok: rolling-ball surface of the cube"
"$SF" analyze geometry "$WORK/cube.csv" -r 5 --surface-method pivot --no-mesh -o "$WORK/pivot" > /dev/null
for want in "surface_triangles 12" "surface_area_unknown 6" "surface_volume_unknown 1" "surface_euler_characteristic 2" "surface_manifold yes"; do
  grep -qx "$want" "$WORK/pivot/summary.txt" || fail "pivoting ball: no '$want' in $(cat "$WORK/pivot/summary.txt")"
done
echo "ok: pivoting-ball surface of the cube (cocircular faces)"
"$SF" analyze geometry "$WORK/cube.csv" --surface-method packing --sculpt-depth 5 --no-mesh --length-units um -o "$WORK/packing" > /dev/null
for want in "surface_triangles 12" "surface_area_um2 6" "surface_volume_um3 1" "surface_euler_characteristic 2" "surface_manifold yes"; do
  grep -qx "$want" "$WORK/packing/summary.txt" || fail "packing-sculpting: no '$want' in $(cat "$WORK/packing/summary.txt")"
done
echo "ok: packing-sculpting surface of the cube (the convex hull: nothing deeper than 5)"
printf '0 0\n0.1 0\n5 0.05\n5.1 0.05\n' > "$WORK/pairs.txt"
"$SF" analyze geometry "$WORK/pairs.txt" --dimension 2 -d 1 -o "$WORK/pairs" > /dev/null
grep -q "^seed_rule_clusters 1$" "$WORK/pairs/summary.txt" || fail "seed rule: $(cat "$WORK/pairs/summary.txt")"
grep -q "^single_linkage_clusters 2$" "$WORK/pairs/summary.txt" || fail "single linkage"
[ "$(sed -n 4p "$WORK/pairs/clusters.csv")" = "2,5,0.05,0,1" ] || fail "clusters.csv row: $(sed -n 4p "$WORK/pairs/clusters.csv")"
[ "$(head -1 "$WORK/pairs/clusters.csv")" = "index,x_unknown,y_unknown,seed_rule,single_linkage" ] || fail "clusters.csv header: $(head -1 "$WORK/pairs/clusters.csv")"
echo "ok: clusters"
cat > "$WORK/atoms.dump" <<'DUMP'
ITEM: TIMESTEP
0
ITEM: NUMBER OF ATOMS
5
ITEM: BOX BOUNDS pp pp pp
0 2
0 2
0 2
ITEM: ATOMS id type x y z
1 1 0 0 0
2 1 1 0 0
3 1 0 1 0
4 1 0 0 1
5 1 1 1 1
DUMP
"$SF" analyze geometry "$WORK/atoms.dump" -o "$WORK/dump" --no-mesh > /dev/null
grep -q "^points 5$" "$WORK/dump/summary.txt" || fail "dump points"
grep -q "^total_volume_A3 " "$WORK/dump/summary.txt" || fail "a dump without ITEM: UNITS is in A (metal): $(cat "$WORK/dump/summary.txt")"
sed "s/^ITEM: NUMBER OF ATOMS/ITEM: UNITS\nsi\nITEM: NUMBER OF ATOMS/" "$WORK/atoms.dump" > "$WORK/si.dump"
"$SF" analyze geometry "$WORK/si.dump" -d 5 -o "$WORK/si" > /dev/null
grep -q "^total_volume_m3 " "$WORK/si/summary.txt" || fail "ITEM: UNITS si: $(cat "$WORK/si/summary.txt")"
[ "$(head -1 "$WORK/si/clusters.csv")" = "index,x_m,y_m,z_m,seed_rule,single_linkage" ] || fail "si clusters.csv: $(head -1 "$WORK/si/clusters.csv")"
grep -aq 'Name="volume"[^>]* units="m3"' "$WORK/si/delaunay.vtu" || fail "delaunay.vtu volume of an si dump is not m3"
[ ! -e "$WORK/dump/delaunay.vtu" ] || fail "--no-mesh wrote a mesh"
printf '4\ncomment\nCu 0 0 0\nCu 1 0 0\nCu 0 1 0\nCu 0 0 1\n' > "$WORK/tet.xyz"
"$SF" analyze geometry "$WORK/tet.xyz" -o "$WORK/xyz" > /dev/null
grep -q "^total_volume_unknown 0.166666666667$" "$WORK/xyz/summary.txt" || fail "xyz volume: $(cat "$WORK/xyz/summary.txt")"
echo "ok: dump and xyz input"
# bad FILE PATTERN [OPTIONS...]: analyze geometry FILE exits 2 naming PATTERN, writes nothing.
bad() { local file="$WORK/$1" pattern="$2"; shift 2; analyze_rejected "$pattern" -- geometry "$file" "$@"; }
printf 'x,y,z\n0,0,0\n1,0,nan\n0,1,0\n0,0,1\n' > "$WORK/nan.csv"
bad nan.csv "nan.csv:3: expected coordinate z (a finite number), got 'nan'"
printf '0,0,0\n1,0,0\n0,1,0\n' > "$WORK/three.csv"
bad three.csv "3 distinct points; a 3D Delaunay division needs at least 4"
printf '0,0,0\n1,0,0\n0,1,0\n1,1,0\n2,3,0\n' > "$WORK/flat.csv"
bad flat.csv "all 5 distinct points lie on one plane"
printf '0,0\n1,1\n2,2\n' > "$WORK/line.csv"
bad line.csv "all 3 distinct points lie on one line" --dimension 2
printf '0,0,0\n1,0\n' > "$WORK/short.csv"
bad short.csv "short.csv:2: expected at least 3 values per line, got 2"
bad cube.csv "a ball of radius 0.001 passes between the points everywhere" -r 0.001
bad cube.csv "pivoting ball of radius 0.001: no second point met turning about z" -r 0.001 --surface-method pivot
bad pairs.txt "--ball-radius/--sculpt-depth: surfaces need --dimension 3" --dimension 2 -r 1
bad cube.csv "sculpting to depth 0.001 removes every tetrahedron" --surface-method packing -s 0.001
bad cube.csv "--surface-method packing needs --sculpt-depth S" --surface-method packing
bad cube.csv "--surface-method packing takes --sculpt-depth, not --ball-radius" --surface-method packing -s 1 -r 1
bad cube.csv "--sculpt-depth is the depth of --surface-method packing" -s 1
bad cube.csv "unit 'm-1': cannot spell 'm-1' in a column name" --length-units m-1
bad si.dump "its coordinates are in 'm'; --length-units says 'A'" --length-units A
sed "s/^si$/furlongs/" "$WORK/si.dump" > "$WORK/furlongs.dump"
bad furlongs.dump "ITEM: UNITS 'furlongs' is not a LAMMPS unit style"

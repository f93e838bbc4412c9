#!/usr/bin/env bash
# Parallel VTK pieces ([output] vtk_pieces, io/vtk_pieces): each method's tiny case run once with
# single files and once in pieces; VTK's parallel readers (python3-vtk9) read the .pvti/.pvtp of
# the pieces run as its serial readers read the single files (tests/cli/vtk_pieces.py): MPM's 2D
# grid (point data, vtkGhostType) and particles in 3 pieces, DBM's cell data in 2, the 3D
# phase-field grid (sharp front, 40³) in 3, PD points and macroparticles in 2, granular grains in
# 201 for 200 grains (an empty piece). vtk_pieces = 1 writes the same bytes as no key. Skips the VTK part with a
# message when python3-vtk9 is absent (scripts/install-deps.sh installs it).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
PY=/usr/bin/python3
# pieces NAME CASE_FILE N PVD...: runs the case without vtk_pieces and with vtk_pieces = N, then
# compares the two runs' frames (exit 77 of the script is a skip).
pieces() {
  local name="$1" case_file="$2" n="$3"
  shift 3
  "$SF" run "$case_file" --output "$WORK/${name}_1" -q > /dev/null
  sed "s/^\[output\]/[output]\nvtk_pieces = $n/" "$case_file" > "$WORK/$name.toml"
  "$SF" run "$WORK/$name.toml" --output "$WORK/${name}_$n" -q > /dev/null
  set +e
  "$PY" "$ROOT/tests/cli/vtk_pieces.py" "$WORK/${name}_1" "$WORK/${name}_$n" "$n" "$@" > "$WORK/check.txt" 2>&1
  local code=$?
  set -e
  [ $code -eq 0 ] || [ $code -eq 77 ] || fail "$name: $(cat "$WORK/check.txt")"
  cat "$WORK/check.txt"
}
CASES="$ROOT/tests/cli/cases"
pieces mpm "$CASES/mpm_tiny.toml" 3 grid.pvd particles.pvd
pieces dbm "$CASES/dbm_sod.toml" 2 grid.pvd
pieces phasefield "$CASES/phasefield_sharp_front_tiny.toml" 3 fields.pvd  # 40³ points: cut along z
pieces pd "$CASES/pd_tiny.toml" 2 profiles/points.pvd
pieces granular "$CASES/granular_tiny.toml" 201 profiles/grains.pvd
grep -q "(3 empty)" "$WORK/check.txt" || grep -q "^skip" "$WORK/check.txt" || fail "201 pieces of 200 grains left no empty piece"
pieces macroparticle "$CASES/macroparticle_tiny.toml" 2 particles.pvd
# shockfield analyze reads the .pvti frames as the single files: the same statistics per frame.
for run in mpm_1 mpm_3; do
  "$SF" analyze stats "$WORK/$run/grid.pvd" --array pressure -o "$WORK/stats_$run" --no-plot > /dev/null
done
[ "$(cut -d, -f2- "$WORK/stats_mpm_1/stats.csv")" = "$(cut -d, -f2- "$WORK/stats_mpm_3/stats.csv")" ] ||
  fail "analyze stats of the .pvti frames differ from the single files'"
echo "ok: analyze stats of the 3-piece MPM grids equal the single files'"

# One piece is today's single file: the same bytes with vtk_pieces = 1 as without the key.
sed "s/^\[output\]/[output]\nvtk_pieces = 1/" "$CASES/mpm_tiny.toml" > "$WORK/mpm_one.toml"
"$SF" run "$WORK/mpm_one.toml" --output "$WORK/mpm_one" -q > /dev/null
for f in grid.pvd particles.pvd fields/grid_000000066.vti fields/particles_000000066.vtp; do
  cmp "$WORK/mpm_1/$f" "$WORK/mpm_one/$f" || fail "vtk_pieces = 1 changed $f"
done
[ -z "$(find "$WORK/mpm_one" -name '*.pvt?')" ] || fail "vtk_pieces = 1 wrote a .pvti/.pvtp"

# Bad input: a clear message naming the key, exit 2.
expect_error "$(sed "s/^\[output\]/[output]\nvtk_pieces = 0/" "$CASES/mpm_tiny.toml")" "vtk_pieces"
echo "vtk_pieces: every method's frames in pieces read by VTK as its single files"

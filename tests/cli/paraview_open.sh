#!/usr/bin/env bash
# ParaView itself (Debian's paraview 5.11, pvbatch under Xvfb) opens the VTK output of every method
# with VTK frames — MPM grid and particles, DBM cells, phase field (field and sharp front), PD
# points, granular grains, macroparticles, and MPM and PD as parallel pieces (.pvti, .pvtp) — as a
# user would (the .pvd): the .pvd's times, every array of the last frame with its centring and
# components, no NaN among the values ParaView shows (void MPM nodes are blanked by vtkGhostType),
# a picture of one array per method that is drawn and has no NaN-coloured pixel
# (tests/cli/paraview_open.py). Skips (exit 77, CTest SKIP_RETURN_CODE) with a message when pvbatch
# or Xvfb is absent: ParaView is about 800 MB installed, so .ci/run does not install it
# (`apt-get install paraview python3-paraview xvfb` does).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
for tool in pvbatch Xvfb; do  # (and pvbatch's Python package: checked on its first run below)
  command -v $tool > /dev/null || { echo "SKIP: $tool not installed (apt-get install paraview python3-paraview xvfb)"; exit 77; }
done
series=()
run() {  # run NAME CASE_FILE [--set ...]
  local name=$1 case_file=$2; shift 2
  "$SF" run "$case_file" --output "$WORK/$name" -q "$@" > /dev/null
}
C="$ROOT/tests/cli/cases"
run mpm "$C/mpm_tiny.toml"
run mpm_pieces "$C/mpm_tiny.toml" --set output.vtk_pieces=2
run dbm "$C/dbm_sod.toml"
run phasefield "$C/phasefield_tiny.toml"
run sharp_front "$C/phasefield_sharp_front_tiny.toml"
run pd "$C/pd_tiny.toml"
run pd_pieces "$C/pd_tiny.toml" --set output.vtk_pieces=2
run granular "$C/granular_tiny.toml"
run macroparticle "$C/macroparticle_tiny.toml"
ls "$WORK"/mpm_pieces/fields/*.pvti > /dev/null && ls "$WORK"/pd_pieces/profiles/*.pvtp > /dev/null || fail "no pieces written"
series=(mpm_grid:"$WORK/mpm/grid.pvd":pressure mpm_particles:"$WORK/mpm/particles.pvd":pressure
        mpm_pieces:"$WORK/mpm_pieces/grid.pvd":pressure dbm:"$WORK/dbm/grid.pvd":rho
        phasefield:"$WORK/phasefield/fields.pvd":xi sharp_front:"$WORK/sharp_front/fields.pvd":xi
        pd:"$WORK/pd/profiles/points.pvd":damage pd_pieces:"$WORK/pd_pieces/profiles/points.pvd":damage
        granular:"$WORK/granular/profiles/grains.pvd":velocity macroparticle:"$WORK/macroparticle/particles.pvd":velocity)
# A private X server; its first free display from :90. An X connection fails now and then under
# Xvfb here ("bad X server connection", about 1 in 20 xdpyinfo calls): pvbatch is retried then.
display=90
while [ -e "/tmp/.X$display-lock" ]; do display=$((display + 1)); done
Xvfb ":$display" -screen 0 1024x768x24 -nolisten tcp > "$WORK/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2> /dev/null; rm -rf "$WORK"' EXIT
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$display" ] && break; sleep 0.1; done
mkdir -p "$WORK/pictures"
for attempt in 1 2 3; do
  code=0
  DISPLAY=":$display" pvbatch "$ROOT/tests/cli/paraview_open.py" "$WORK/pictures" "${series[@]}" > "$WORK/pv.txt" 2>&1 || code=$?
  grep -q "bad X server connection" "$WORK/pv.txt" || break
done
if grep -q "No module named 'paraview'" "$WORK/pv.txt"; then  # pvbatch without its Python package
  echo "SKIP: pvbatch cannot import paraview (apt-get install python3-paraview)"; exit 77
fi
grep -v "^\s*[0-9]* *0x\|^\[" "$WORK/pv.txt" | grep -v "^$" || true
[ $code -eq 0 ] || fail "ParaView shows the outputs otherwise than they are written (above; exit $code)"
[ -n "${PARAVIEW_PICTURES:-}" ] && cp "$WORK"/pictures/*.png "$PARAVIEW_PICTURES/"
echo "ok: ParaView 5.11 opened $(grep -c "times (last" "$WORK/pv.txt") series of every method with VTK frames as written"

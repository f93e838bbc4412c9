#!/bin/sh
# Growth shapes of one hcp domain in the phase-field model: isotropic from a sphere (stays a
# sphere) and from an elongated ellipsoid (rounds up), and with anisotropic gradient energies
# D_d = D w_d that grow a disc (w = 1, 1, 1/4) and a column (w = 1/4, 1/4, 1); then plot.py draws
# shapes.png (the final domains' middle slices and the axis ratios against time). About a minute
# on one core (four 80^3 spectral runs of 240 steps).
#   examples/phasefield_shapes/run.sh [RUNS_DIR]   (from the repository root; SHOCKFIELD=path/to/shockfield)
set -eu
. "$(dirname "$0")/../run_common.sh"
"$bin" run "$here/case.toml" -o "$runs/sphere" --overwrite -q
"$bin" run "$here/ellipsoid.toml" -o "$runs/ellipsoid" --overwrite -q
"$bin" run "$here/case.toml" -o "$runs/disc" --overwrite -q --set 'model.anisotropy=[1.0, 1.0, 0.25]'
"$bin" run "$here/case.toml" -o "$runs/column" --overwrite -q --set 'model.anisotropy=[0.25, 0.25, 1.0]'
PYTHONPATH="${PYTHONPATH:-$(cd "$here/../.." && pwd)/build/release/python}" /usr/bin/python3 "$here/plot.py" "$here/shapes.png" "$runs/sphere" "$runs/ellipsoid" "$runs/disc" "$runs/column"

#!/usr/bin/env bash
# Sweeps MPM and PD impact speeds from Python and draws sweep.png (about 30 s; --small: 5 s).
# Uses the build tree's package (build/release/python) unless PYTHONPATH already names one.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
export PYTHONPATH="${PYTHONPATH:-$ROOT/build/release/python}"
export OMP_WAIT_POLICY=passive
/usr/bin/python3 "$ROOT/examples/python_sweep/sweep.py" -o "${OUT:-$ROOT/runs/python_sweep}" "$@"

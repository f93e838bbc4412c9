#!/bin/sh
# Writes the input the case reads (dislocation.data, from make_dislocation.py) next to case.toml.
# run.sh calls it; so does the test that runs every example case (tests/cli/examples_summary.sh).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
/usr/bin/python3 "$here/make_dislocation.py" --output "$here/dislocation.data"

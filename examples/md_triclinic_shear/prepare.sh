#!/bin/sh
# Writes the input case.toml reads (sheared_0.01.data, fcc Cu at shear strain 0.01, from
# make_sheared.py) next to it. The test that runs every MD example case (tests/cli/md_final_data.sh)
# calls it; run.sh writes its own strains into the runs folder.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
/usr/bin/python3 "$here/make_sheared.py" "$here" 0.01

#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the installed tree moved elsewhere and, where
# unshare allows it, the build tree and python/ hidden as if deleted (so nothing in it can lean on
# the build tree's or the install-time paths): its `shockfield --version`
# names the moved tree's Python helpers, it runs a case copied out of the source tree and plots
# it (Python found by the documented rule, with a python3 first on PATH that lacks numpy), a bad
# SHOCKFIELD_PYTHON is refused, `import shockfield` works from the moved tree and finds the
# moved command, examples/python_sweep runs from it (its runs by the moved command), and a program
# outside the tree builds against the library with find_package(shockfield) and with pkg-config.
# About 25 s (two small compiles, the example's 5 s).
set -euo pipefail
source "$(dirname "$0")/lib.bash"
BUILD=$(dirname "$SF")
cmake --install "$BUILD" --prefix "$WORK/prefix" > "$WORK/install.log" || fail "cmake --install: $(tail -5 "$WORK/install.log")"
mv "$WORK/prefix" "$WORK/moved"
P="$WORK/moved"
BIN="$P/bin/shockfield"
# hidden CMD...: CMD with the build tree and the source tree's python/ (the helpers' build-time
# fallback) replaced by empty directories, as if deleted (a private mount namespace: unshare -rm,
# nothing outside the command sees it). Where unshare is refused, CMD runs with them in place:
# the moved tree is then still the only one on any path.
if unshare -rm true 2> /dev/null; then
  hidden() { unshare -rm bash -c 'mount -t tmpfs none "$1" && mount -t tmpfs none "$2" && shift 2 && exec "$@"' _ "$BUILD" "$ROOT/python" "$@"; }
  echo "ok: the build tree and python/ are hidden (empty mounts) from the installed tree's commands"
else
  hidden() { "$@"; }
  echo "note: unshare refused here: the build tree stays in place (the installed tree is still the only one on any path)"
fi
[ -x "$BIN" ] || fail "no bin/shockfield in the install tree"
for f in lib/libshockfield.a include/shockfield/analysis/minkowski.hpp lib/cmake/shockfield/shockfieldConfig.cmake \
         lib/cmake/shockfield/shockfieldTargets.cmake lib/pkgconfig/shockfield.pc; do
  [ -f "$P/$f" ] || fail "the install tree lacks $f"
done
[ ! -e "$P/include/shockfield/app" ] || fail "the command's private headers were installed"
PYDIR=$(dirname "$(find "$P" -type d -name shockfield_plot | head -1)")
[ -f "$PYDIR/shockfield/__init__.py" ] || fail "the Python package is not installed beside shockfield_plot ($PYDIR)"

# --version: version, commit, compiler, libraries; the helpers found in the moved tree.
hidden "$BIN" --version > "$WORK/version.txt"
for p in "shockfield 0." "git commit:" "build:" "OpenMP:" "FFTW: fftw-3" "HDF5: 1." "MPI:" "Python helpers: $PYDIR"; do
  grep -qF -- "$p" "$WORK/version.txt" || fail "--version lacks '$p': $(cat "$WORK/version.txt")"
done
echo "ok: $(head -1 "$WORK/version.txt"), helpers in the moved tree"

# A case outside the source tree, run and plotted by the installed command. python3 first on
# PATH is a stub without numpy: the helpers must fall back to /usr/bin/python3.
mkdir -p "$WORK/stub"
printf '#!/bin/sh\necho "stub python3: no numpy" >&2\nexit 1\n' > "$WORK/stub/python3"
chmod +x "$WORK/stub/python3"
cp "$ROOT/tests/cli/cases/tiny_cu.toml" "$WORK/case.toml"
(cd "$WORK" && hidden env -u SHOCKFIELD_PYTHON PATH="$WORK/stub:/usr/bin:/bin" "$BIN" run case.toml -o run -q -j 1 --set 'stage[0].steps=20' > /dev/null) \
  || fail "the installed command could not run a case"
[ -s "$WORK/run/summary.json" ] || fail "the installed run wrote no summary.json"
(cd "$WORK" && hidden env -u SHOCKFIELD_PYTHON PATH="$WORK/stub:/usr/bin:/bin" "$BIN" plot thermo run > "$WORK/plot.txt" 2>&1) \
  || fail "plot from the install tree failed: $(cat "$WORK/plot.txt")"
[ -s "$WORK/run/thermo.png" ] || fail "plot thermo wrote no PNG"
echo "ok: the installed command ran and plotted a case (python3 on PATH without numpy skipped)"
set +e
SHOCKFIELD_PYTHON="$WORK/stub/python3" "$BIN" plot thermo "$WORK/run" > /dev/null 2> "$WORK/bad_python.txt"
code=$?
set -e
[ $code -eq 2 ] || fail "a SHOCKFIELD_PYTHON without numpy: exit $code, expected 2"
grep -qF "SHOCKFIELD_PYTHON=$WORK/stub/python3 cannot import numpy and matplotlib" "$WORK/bad_python.txt" \
  || fail "bad SHOCKFIELD_PYTHON message: $(cat "$WORK/bad_python.txt")"
echo "ok: $(cat "$WORK/bad_python.txt")"

# import shockfield from the moved tree: it finds the moved command and runs a case with it.
(cd "$WORK" && hidden env PYTHONPATH="$PYDIR" /usr/bin/python3 - "$BIN" <<'PY'
import pathlib, sys
import shockfield
assert pathlib.Path(shockfield.__file__).resolve().is_relative_to(pathlib.Path(sys.argv[1]).resolve().parents[1]), shockfield.__file__
assert shockfield.shockfield_command() == sys.argv[1], (shockfield.shockfield_command(), sys.argv[1])
run = shockfield.Run.open("run")
assert run.method == "md" and run.summary["status"] == "finished", run
assert len(run.thermo) > 0
print("ok: import shockfield from", pathlib.Path(shockfield.__file__).parent, "->", shockfield.shockfield_command())
PY
) || fail "import shockfield from the install tree failed"
if grep -q "Python module: built" "$WORK/version.txt"; then
  hidden env PYTHONPATH="$PYDIR" /usr/bin/python3 -c "
import numpy as np, shockfield
f = np.zeros((16, 16)); f[4:12, 4:12] = 1.0
m = shockfield.analysis.minkowski(f, thresholds=[0.5])
assert m['chi'][0] == 1 and m['A'][0] == 0.25, m
print('ok: shockfield.analysis.minkowski from the install tree')" || fail "the installed module failed"
fi

# An example from the moved tree: examples/python_sweep (--small, ~5 s) with the installed package
# and no build tree on any path; every run it starts must be the moved command's.
if grep -q "Python module: built" "$WORK/version.txt"; then
  (cd "$WORK" && hidden env -u SHOCKFIELD_BIN PYTHONPATH="$PYDIR" OUT="$WORK/sweep" PATH="$P/bin:/usr/bin:/bin" \
    bash "$ROOT/examples/python_sweep/run.sh" --small > "$WORK/sweep.txt" 2>&1) \
    || fail "examples/python_sweep from the install tree failed: $(tail -20 "$WORK/sweep.txt")"
  [ "$(grep -cE '^(mpm|pd) ' "$WORK/sweep.txt")" -eq 4 ] || fail "python_sweep printed no 4 states: $(cat "$WORK/sweep.txt")"
  [ -s "$WORK/sweep/sweep.png" ] || fail "python_sweep drew no sweep.png"
  logs=$(find "$WORK/sweep" -name log.txt | wc -l)
  moved=$(grep -l "command line: $BIN run " $(find "$WORK/sweep" -name log.txt) | wc -l)
  [ "$logs" -eq 4 ] && [ "$moved" -eq 4 ] || fail "python_sweep: $moved of $logs runs by the moved command $BIN"
  echo "ok: examples/python_sweep from the install tree (4 runs by $BIN, sweep.png)"
fi

# A consumer project: find_package(shockfield), then pkg-config, against the moved tree.
cmake -S "$ROOT/tests/install/consumer" -B "$WORK/consumer" -DCMAKE_PREFIX_PATH="$P" -DCMAKE_BUILD_TYPE=Release \
  > "$WORK/consumer.log" 2>&1 || fail "find_package(shockfield) failed: $(tail -20 "$WORK/consumer.log")"
cmake --build "$WORK/consumer" > "$WORK/consumer_build.log" 2>&1 || fail "the consumer did not build: $(tail -20 "$WORK/consumer_build.log")"
out=$("$WORK/consumer/consumer") || fail "the consumer failed: $out"
echo "ok: find_package consumer: $out"
flags=$(PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --cflags --libs shockfield) || fail "pkg-config shockfield failed"
# shellcheck disable=SC2086
c++ -O1 "$ROOT/tests/install/consumer/main.cpp" -o "$WORK/consumer_pc" $flags || fail "the pkg-config build failed ($flags)"
out=$("$WORK/consumer_pc") || fail "the pkg-config consumer failed: $out"
echo "ok: pkg-config consumer: $out"

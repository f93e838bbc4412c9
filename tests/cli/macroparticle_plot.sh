#!/usr/bin/env bash
# `shockfield plot stress-strain` on a macroparticle run (the tiny rod of
# tests/cli/cases/macroparticle_tiny.toml, 250 steps): writes RUN/stress-strain.png.
# Skipped (saying so) when no Python with numpy and
# matplotlib is found.
source "$(dirname "$0")/lib.bash"
set -e
"$SF" run "$ROOT/tests/cli/cases/macroparticle_tiny.toml" -q -o "$WORK/rod" > /dev/null
if ! "$SF" plot stress-strain "$WORK/rod" > "$WORK/out" 2>&1; then
  if grep -q "SHOCKFIELD_PYTHON" "$WORK/out"; then echo "skip: no Python with numpy and matplotlib"; exit 0; fi
  fail "plot stress-strain: $(cat "$WORK/out")"
fi
png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$1 is not a PNG"; }
png "$WORK/rod/stress-strain.png"
echo "ok: stress-strain.png"

# Sourced by examples/<name>/run.sh (from the repository root): sets `here` (the example folder),
# `runs` (the script's first argument, else runs/<name>; created) and `bin` (the shockfield binary,
# $SHOCKFIELD or ./build/release/shockfield).
here=$(dirname "$0")
runs=${1:-runs/$(basename "$here")}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"

#!/bin/sh
# Burgers circuits around the defect clusters, frame by frame (analyze atoms --burgers-clusters:
# one circuit about a straight cluster, circuits at stations along a curved one; a cluster without
# a closed circuit is skipped and counted); a frame that fails for another reason is reported and
# skipped. Writes DIR/burgers.csv (all
# frames) and DIR/failed.txt.   Usage: burgers_frames.sh SHOCKFIELD DIR DUMP...
set -u
bin=$1; dir=$2; shift 2
mkdir -p "$dir"
: > "$dir/failed.txt"
rm -f "$dir/burgers.csv"
for dump in "$@"; do
  tmp="$dir/frame"
  rm -rf "$tmp"
  if "$bin" analyze atoms "$dump" --clusters 3.0 --cluster-select 'acna:!fcc,hcp' --cluster-min-size 10 \
       --burgers-clusters --burgers-orient '1 1 0,-1 1 0,0 0 1' -o "$tmp" -j1 > "$tmp.log" 2>&1; then
    if [ -f "$dir/burgers.csv" ]; then tail -n +2 "$tmp/burgers.csv" >> "$dir/burgers.csv"
    else cp "$tmp/burgers.csv" "$dir/burgers.csv"; fi
  else
    echo "$(basename "$dump"): $(tail -1 "$tmp.log")" >> "$dir/failed.txt"
  fi
done
rm -rf "$dir/frame" "$dir/frame.log"

#!/usr/bin/env bash
# Bad input to `shockfield analyze`: each gives one clear message, exit code 2, and no output
# folder.
source "$(dirname "$0")/lib.bash"
set -e
F="$ROOT/tests/fixtures/analysis/fields"
printf '# no values\n' > "$WORK/empty.csv"
printf '1,2\n3,nan\n' > "$WORK/nan.csv"
printf '1,2\n3,4\n' > "$WORK/small.csv"
for sub in minkowski stats; do
  analyze_rejected "empty field" -- $sub "$WORK/empty.csv"
  analyze_rejected "nan.csv:2: NaN value; write \`void\`" -- $sub "$WORK/nan.csv"
  analyze_rejected "mismatched grids" -- $sub "$F/two_disks.csv" "$WORK/small.csv"
  analyze_rejected "times out of order: 0 at position 2 follows 1" -- $sub "$WORK/small.csv" "$WORK/small.csv" --times 1,0
  analyze_rejected "--times: 1 times for 2 input fields" -- $sub "$WORK/small.csv" "$WORK/small.csv" --times 1
  analyze_rejected "--times: value inf at position 2 is not finite" -- $sub "$WORK/small.csv" "$WORK/small.csv" --times 0,inf
  analyze_rejected "--dimension 2 needs a single layer" -- $sub "$F/grid.csv" --dimension 2
  analyze_rejected "is compressed with vtkLZ4DataCompressor" -- $sub "$F/compressed_lz4.vti"
  analyze_rejected "the compressed data ends in its header" -- $sub "$F/compressed.vti"
done
analyze_rejected "thresholds out of order: 1 at position 2 follows 3" -- minkowski "$WORK/small.csv" -t 3,1
analyze_rejected "thresholds out of order" -- minkowski "$WORK/small.csv" -t 1,1
analyze_rejected "give either --thresholds or --count" -- minkowski "$WORK/small.csv" -t 1 -n 4
printf '5,5\n5,5\n' > "$WORK/constant.csv"
analyze_rejected "cannot spread 4 thresholds" -- minkowski "$WORK/constant.csv" -n 4
analyze_rejected "name the .pvd file" -- minkowski "$ROOT/tests/fixtures/analysis"
# similarity: the same checks on both processes, and the same times for both.
analyze_rejected "thresholds out of order" -- similarity -r "$WORK/small.csv" --reference-threshold 2 "$WORK/small.csv" -t 3,2
analyze_rejected "times out of order" -- similarity -r "$WORK/small.csv" "$WORK/small.csv" --reference-threshold 2 "$WORK/small.csv" "$WORK/small.csv" --times 2,2
analyze_rejected "sampled at the same times" -- similarity -r "$WORK/small.csv" "$WORK/small.csv" --reference-threshold 2 "$WORK/small.csv"
analyze_rejected "mismatched grids: reference fields" -- similarity -r "$F/two_disks.csv" --reference-threshold 2 "$WORK/small.csv"
analyze_rejected "NaN value" -- similarity -r "$WORK/nan.csv" --reference-threshold 2 "$WORK/small.csv"
echo "analyze_bad_input: all cases analyze_rejected cleanly"

#!/usr/bin/env bash
# `shockfield analyze similarity` finds the threshold at which a shifted process looks exactly
# like the reference (d_P = 0), with CSV and PNG; `analyze stats` gives the known moments.
source "$(dirname "$0")/lib.bash"
set -e
F="$ROOT/tests/fixtures/analysis/fields"
# ramp SHIFT FILE: a 32 x 8 field T = x + SHIFT.
ramp() { awk -v s="$1" 'BEGIN { for (y = 0; y < 8; ++y) { line = s; for (x = 1; x < 32; ++x)
  line = line "," x + s; print line } }' > "$2"; }
ramp 0 "$WORK/ref0.csv"; ramp 2 "$WORK/ref1.csv"; ramp 5 "$WORK/cand0.csv"; ramp 7 "$WORK/cand1.csv"
"$SF" analyze similarity -r "$WORK/ref0.csv" "$WORK/ref1.csv" --reference-threshold 10.5 \
  "$WORK/cand0.csv" "$WORK/cand1.csv" --times 0,0.5 -t 12.5,13.5,14.5,15.5,16.5,17.5 \
  -o "$WORK/sim" > "$WORK/out.txt" 2>&1
grep -q "best candidate threshold 15.5: process distance d_P = 0" "$WORK/out.txt" ||
  fail "similarity: $(cat "$WORK/out.txt")"
csv="$WORK/sim/similarity.csv"
grep -q "^# reference threshold 10.5, interval \[0, 0.5\], best candidate threshold 15.5" "$csv" ||
  fail "similarity.csv header: $(head -1 "$csv")"
[ "$(grep -c '^c,' "$csv")" -eq 6 ] || fail "one row per candidate threshold: $(cat "$csv")"
awk -F, '$1 == "c" && $2 != 15.5 && !($3 > 0) { exit 1 }' "$csv" || fail "d_P > 0 elsewhere"
[ "$(sed -n 2p "$csv")" = "candidate,threshold_unknown,d_P,S_D" ] || fail "similarity.csv columns: $(sed -n 2p "$csv")"
[ "$(head -c 4 "$WORK/sim/similarity.png" | tail -c 3)" = "PNG" ] || fail "no similarity.png"
grep -q "warning: the best threshold" "$WORK/out.txt" && fail "a warning for a minimum inside the range"
# A best threshold on the edge of the candidates: the minimum may lie outside, the command says so.
"$SF" analyze similarity -r "$WORK/ref0.csv" "$WORK/ref1.csv" --reference-threshold 10.5 \
  "$WORK/cand0.csv" "$WORK/cand1.csv" --times 0,0.5 -t 11.5,12.5,13.5 --no-plot \
  -o "$WORK/edge" > /dev/null 2> "$WORK/edge.txt"
grep -q "warning: the best threshold 13.5 is at the edge of the candidate range \[11.5, 13.5\]" "$WORK/edge.txt" ||
  fail "no edge warning: $(cat "$WORK/edge.txt")"

# stats: two disks of 69 cells at 400 K in 768 cells at 300 K.
"$SF" analyze stats "$F/two_disks.csv" "$F/two_disks.csv" --times 1,2 --bins 4 -o "$WORK/stats" > /dev/null
line=$(awk -F, 'NR == 2 { print $3 "," $4 "," $5 }' "$WORK/stats/stats.csv")
[ "$line" = "768,0,317.96875" ] || fail "stats (cells, void, mean): $line"
[ "$(grep -c "two_disks.csv,2," "$WORK/stats/histogram.csv")" -eq 4 ] || fail "4 bins per field"
awk -F, 'NR > 1 && $2 == 1 { n += $5 } END { exit n != 768 }' "$WORK/stats/histogram.csv" ||
  fail "histogram counts do not add up to 768"
for f in structure_factor correlation; do
  [ "$(wc -l < "$WORK/stats/$f.csv")" -gt 5 ] || fail "$f.csv is nearly empty"
done
"$SF" analyze stats "$F/grid.csv" --no-plot -o "$WORK/grid" > /dev/null
[ "$(awk -F, 'NR == 2 { print $3 "," $4 }' "$WORK/grid/stats.csv")" = "24,1" ] ||
  fail "void cells: $(cat "$WORK/grid/stats.csv")"
# The tables name the field's units (`# units`, `# length_units`, --time-units): docs/conventions.md.
{ echo "# units = kg/m3"; echo "# length_units = m"; cat "$F/two_disks.csv"; } > "$WORK/disks_si.csv"
"$SF" analyze stats "$WORK/disks_si.csv" --times 1e-6 --time-units s -o "$WORK/stats_si" > /dev/null
for pair in "stats:file,time_s,cells,void_cells,mean_kg_m3,std_kg_m3,skewness,kurtosis,domain_size_R_m" \
  "histogram:file,time_s,lo_kg_m3,hi_kg_m3,count" "structure_factor:file,time_s,k_per_m,S_kg2_m6,shell_points" \
  "correlation:file,time_s,r_m,C,shell_points"; do
  [ "$(head -1 "$WORK/stats_si/${pair%%:*}.csv")" = "${pair#*:}" ] ||
    fail "${pair%%:*}.csv header: $(head -1 "$WORK/stats_si/${pair%%:*}.csv")"
done
[ "$(cut -d, -f2- "$WORK/stats_si/stats.csv" | tail -1)" = "$(cut -d, -f2- "$WORK/stats/stats.csv" | sed -n 2p | sed 's/^1,/1e-06,/')" ] ||
  fail "the units changed the values: $(cat "$WORK/stats_si/stats.csv")"
echo "analyze_similarity_stats: ok"

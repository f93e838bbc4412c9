#!/usr/bin/env bash
# The in-run [analysis] table of an MD case (tests/cli/cases/tiny_cu_analysis.toml: 4x4x4 Cu at
# 1400 K, a-CNA, CNA, CSP, coordination, diamond, the clusters of non-fcc atoms and the excess energy
# every 25 steps, their columns in the dumps every 50): structures.csv has a row per analysis step,
# and at the dump steps its counts and fractions, the excess energy's reference and mean, and
# clusters.csv's rows, are exactly those `shockfield analyze atoms --excess-energy auto` finds on
# the run's own dumps (full precision: the same atoms and per-atom pe), and the dumps' per-atom
# columns are exactly what analyze atoms appends (the annotated dump is byte-identical to the
# run's). At step 0 (the perfect 0 K crystal) the reference is Cu_u3's cohesive energy and the
# excess zero. Clusters picked by excess> equal analyze atoms' too. Then bad [analysis] tables,
# refused by key.
source "$(dirname "$0")/lib.bash"
set -e
case_file="$ROOT/tests/cli/cases/tiny_cu_analysis.toml"
"$SF" run "$case_file" --output "$WORK/run" -q > /dev/null
s="$WORK/run/structures.csv"
[ "$(wc -l < "$s")" -eq 14 ] || fail "structures.csv: $(wc -l < "$s") lines, expected a header and 13 rows (steps 0, 25, ..., 300)"
head -1 "$s" | grep -q "^step,time_ps,atoms,cna_fcc_count,.*,acna_other_fraction,dia_cubic_count,.*,dia_other_fraction,excess_reference_eV,excess_mean_eV$" || fail "header: $(head -1 "$s")"
# Step 0, the perfect lattice at 0 K: every atom has e0 = -3.54 eV (Cu_u3's cohesive energy; the
# file's tabulation gives it to ~1e-9 eV) and no excess (round-off of the median's subtraction).
awk -F, 'NR == 2 && ($(NF-1) + 3.54 > 1e-8 || $(NF-1) + 3.54 < -1e-8 || $NF > 1e-12 || $NF < -1e-12) { exit 1 }' "$s" \
  || fail "step 0 excess reference/mean: $(sed -n 2p "$s" | awk -F, '{ print $(NF-1), $NF }'), expected -3.54 and 0"
# At 1400 K the fcc atoms' median pe lies above -3.54 eV by about 3/2 k_B T (equipartition of the
# harmonic potential energy, 0.18 eV) less anharmonic terms: between 0.05 and 0.2 eV above it.
awk -F, 'NR > 2 && ($(NF-1) < -3.49 || $(NF-1) > -3.34) { exit 1 }' "$s" \
  || fail "hot excess references outside (-3.49, -3.34) eV: $(awk -F, 'NR > 2 { printf "%s ", $(NF-1) }' "$s")"
awk -F, 'NR > 1 && ($1 != (NR - 2) * 25 || $3 != 256) { exit 1 }' "$s" || fail "steps: $(cut -d, -f1-3 "$s")"
awk -F, 'NR > 1 && $4 < 256 { hot++ } END { exit !hot }' "$s" || fail "no frame with non-fcc CNA atoms at 1400 K: the test would not see a difference"

"$SF" analyze atoms "$WORK/run" --cna 3.0858 --adaptive-cna --csp 12 --coordination 3.0858 --diamond \
  --clusters 3.0 --cluster-select 'acna:!fcc' --excess-energy auto -o "$WORK/a" > /dev/null
awk -F, 'NR > 1 && $1 % 50 == 0' "$s" | cut -d, -f3- > "$WORK/inrun"
awk -F, 'NR > 1' "$WORK/a/structures.csv" | cut -d, -f3- > "$WORK/post"
[ "$(wc -l < "$WORK/post")" -eq 7 ] || fail "analyze atoms read $(wc -l < "$WORK/post") frames, expected 7"
cmp "$WORK/inrun" "$WORK/post" || fail "in-run fractions differ from analyze atoms on the dumps: $(diff "$WORK/inrun" "$WORK/post" | head -5)"
echo "ok: in-run structures.csv = analyze atoms on the run's 7 dumps ($(awk -F, 'NR > 1 { printf "%s ", $4 }' "$WORK/a/structures.csv")fcc by CNA; excess references $(awk -F, 'NR > 1 { printf "%s ", $(NF-1) }' "$WORK/a/structures.csv")eV)"
c="$WORK/run/clusters.csv"
head -1 "$c" | grep -q "^step,time_ps,cluster,size,x_A,y_A,z_A,a_A,b_A,c_A,axis1_x,.*,atomic_volume_A3$" || fail "clusters.csv header: $(head -1 "$c")"
awk -F, 'NR > 1 && $1 % 50 == 0' "$c" | cut -d, -f3- > "$WORK/inrun_clusters"
awk -F, 'NR > 1' "$WORK/a/clusters.csv" | cut -d, -f3- > "$WORK/post_clusters"
[ "$(wc -l < "$WORK/post_clusters")" -gt 7 ] || fail "fewer than one cluster per dump: the comparison would be empty"
cmp "$WORK/inrun_clusters" "$WORK/post_clusters" || fail "in-run clusters differ from analyze atoms': $(diff "$WORK/inrun_clusters" "$WORK/post_clusters" | head -5)"
[ "$(awk -F, 'NR > 1 { print $1 }' "$c" | sort -un | tr "\n" " ")" = "25 50 75 100 125 150 175 200 225 250 275 300 " ] \
  || fail "clusters.csv steps: every analysis step but 0 (the perfect start has no non-fcc atom)"
echo "ok: in-run clusters.csv = analyze atoms' on the dumps ($(wc -l < "$WORK/post_clusters") cluster rows in 7 frames)"
for f in "$WORK"/run/dumps/*.lammpstrj; do
  grep -q "^ITEM: ATOMS id type x y z vx vy vz pe coord cna acna csp dia cluster excess$" "$f" || fail "$f columns: $(sed -n 9p "$f")"
  cmp "$f" "$WORK/a/$(basename "$f")" || fail "$(basename "$f"): the run's columns differ from analyze atoms'"
done
echo "ok: the dumps' coord cna acna csp dia cluster excess columns = analyze atoms', byte for byte"

# Clusters of the atoms with an excess energy above 0.15 eV (the hot crystal's tail: a few per cent of the atoms), in the run and
# by analyze atoms on its dumps.
base=$(cat "$case_file")
printf '%s\n' "${base/cluster_select = \"acna:!fcc\"/cluster_select = \"excess>0.15\"}" > "$WORK/excess.toml"
"$SF" run "$WORK/excess.toml" --output "$WORK/run_e" -q --set 'stage[1].steps=50' > /dev/null
"$SF" analyze atoms "$WORK/run_e" --cna 3.0858 --adaptive-cna --csp 12 --coordination 3.0858 --diamond \
  --clusters 3.0 --cluster-select 'excess>0.15' --excess-energy auto -o "$WORK/ae" > /dev/null
awk -F, 'NR > 1 && $1 % 50 == 0' "$WORK/run_e/clusters.csv" | cut -d, -f3- > "$WORK/inrun_e"
awk -F, 'NR > 1' "$WORK/ae/clusters.csv" | cut -d, -f3- > "$WORK/post_e"
[ "$(wc -l < "$WORK/post_e")" -gt 9 ] || fail "fewer than 10 excess clusters in 4 frames: the comparison would be empty"
cmp "$WORK/inrun_e" "$WORK/post_e" || fail "in-run excess> clusters differ from analyze atoms': $(diff "$WORK/inrun_e" "$WORK/post_e" | head -5)"
echo "ok: in-run clusters of excess > 0.15 eV = analyze atoms' ($(wc -l < "$WORK/post_e") rows)"

# Bad tables: exit 2 before anything runs, the key named.
expect_error "${base/methods = \[\"acna\", \"cna\", \"csp\", \"coordination\", \"diamond\"\]/methods = [\"acna\", \"wurtzite\"]}" "analysis.methods" 'got "wurtzite"'
expect_error "${base/cutoff = 3.0858/}" "analysis.cutoff"
expect_error "${base/every = 25/every = 0}" "analysis.every"
expect_error "${base/dump_every = 50/dump_every = 0}" "analysis.dump_columns" "dump_every > 0"
expect_error "${base/dump_columns = true/csp_neighbors = 7}" "analysis.csp_neighbors" "even"
expect_error "${base/dump_columns = true/dump_columns = true
coordinates = 1}" "analysis.coordinates"
expect_error "${base/clusters = 3.0 /}" "analysis.clusters" "go together"
expect_error "${base/cluster_select = \"acna:!fcc\"/cluster_select = \"cna:hcp,bogus\"}" "analysis.cluster_select" "expected cna|acna|bpa"
no_excess="${base/excess_energy = true/}"
expect_error "${no_excess/cluster_select = \"acna:!fcc\"/cluster_select = \"excess>0.1\"}" "analysis.cluster_select" "needs excess_energy = true"
expect_error "${base/excess_energy = true/excess_energy = true
excess_crystal = \"diamond\"}" "analysis.excess_crystal"
expect_error "${no_excess/dump_columns = true/dump_columns = true
excess_reference = -3.54}" "analysis.excess_reference" "excess_energy = true"
only_csp="${base/methods = \[\"acna\", \"cna\", \"csp\", \"coordination\", \"diamond\"\]/methods = [\"csp\"]}"
expect_error "${only_csp/cluster_select = \"acna:!fcc\"/cluster_select = \"csp>1\"}" "analysis.excess_energy" "excess_reference"
no_cna="${base/methods = \[\"acna\", \"cna\", \"csp\", \"coordination\", \"diamond\"\]/methods = [\"acna\", \"csp\"]}"
expect_error "${no_cna/cluster_select = \"acna:!fcc\"/cluster_select = \"cna:hcp\"}" "analysis.cluster_select" 'selecting by cna needs "cna" in methods'
echo "all md analysis checks passed"

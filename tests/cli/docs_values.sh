#!/usr/bin/env bash
# The numbers the docs quote from an example's run are what the example prints (docs_values.py, the
# fifth check of docs_current.py): each example below is copied to $WORK (its run.sh draws its
# pictures beside itself) and run, its stdout kept as printed/<example>.txt; then every marker
# `<!-- value: EXAMPLE LABEL -->` of those examples in docs/ and examples/*/README.md is compared with
# it. The check must fail on a planted wrong number (0.3042 where dbm_sod prints p* = 0.30323), on a
# label the run does not print and on an example whose output no page quotes.
# Default suite: dbm_sod, md_npt_tri_relax, analysis_minkowski, python_sweep and md_triclinic_shear
# (about 14 s of CPU). SLOW=1 (test slow.docs_values) adds md_shock_piston (the Hugoniot state and
# the two-part comparison quoted by docs/md.md) and the examples of 4-30 s of CPU each: about 4 min
# of CPU in all, 7.5 min wall on a loaded 2-core machine. (MD on the same thread count repeats itself
# bit for bit on one machine, so its values are compared to their digits; two runs of each MD example
# printed the same; python_sweep, run twice, printed the same too.)
source "$(dirname "$0")/lib.bash"
set -e
export OMP_WAIT_POLICY=passive SHOCKFIELD="$SF" PYTHONPATH="$(cd "$(dirname "$SF")" && pwd)/python"
examples=(dbm_sod md_npt_tri_relax analysis_minkowski python_sweep md_triclinic_shear)
[ "${SLOW:-0}" = 1 ] && examples+=(md_shock_piston dbm_detonation phasefield_domain phasefield_shapes
  phasefield_from_md pd_crack_branching pd_kalthoff_winkler pd_single_crystal pd_polycrystal pd_ofhc_compression
  granular_chain mpm_tensile_cavity mpm_spall)
mkdir -p "$WORK/examples" "$WORK/printed"
cp "$ROOT/examples/run_common.sh" "$WORK/examples/"
# The copies' repository root is $WORK: their scripts find python/ and tests/fixtures/ there.
ln -s "$ROOT/python" "$ROOT/tests" "$WORK/"
# run.sh's arguments: the run folder, except where the script takes the binary first or reads the
# folder from $OUT.
arguments() {
  case "$1" in
    analysis_minkowski) echo "$SF" "$WORK/runs/$1" ;;
    python_sweep) ;;
    *) echo "$WORK/runs/$1" ;;
  esac
}
for example in "${examples[@]}"; do cp -r "$ROOT/examples/$example" "$WORK/examples/"; done
# The other examples linked, for the case files one example reads from another (python_sweep's PD bar).
for folder in "$ROOT"/examples/*/; do
  [ -e "$WORK/examples/$(basename "$folder")" ] || ln -s "$folder" "$WORK/examples/$(basename "$folder")"
done
for example in "${examples[@]}"; do
  # from $WORK, the copies' repository root (dbm_detonation's plot finds python/ from there)
  (cd "$WORK" && OUT="$WORK/runs/$example" bash "examples/$example/run.sh" $(arguments "$example")) > "$WORK/printed/$example.txt" \
    || fail "examples/$example/run.sh failed: $(tail -5 "$WORK/printed/$example.txt")"
done
check() { /usr/bin/python3 "$ROOT/tests/cli/docs_current.py" "$SF" "$ROOT" --printed "$@"; }
check "$WORK/printed" || fail "a quoted value disagrees with what its example printed (above)"
# Planted: a wrong number, a label dbm_sod does not print, and the output of an example no page quotes.
cat > "$WORK/planted.md" <<'DOC'
The plateau pressure is 0.3042<!-- value: dbm_sod p* -->, its velocity 0.9276<!-- value: dbm_sod u* -->
and its density 0.4263<!-- value: dbm_sod rho* -->.
DOC
mkdir -p "$WORK/planted_printed"
cp "$WORK/printed/dbm_sod.txt" "$WORK/planted_printed/"
echo "nothing quoted = 1" > "$WORK/planted_printed/granular_chain.txt"
if check "$WORK/planted_printed" "$WORK/planted.md" > "$WORK/report.txt"; then fail "the check passed planted wrong values: $(cat "$WORK/report.txt")"; fi
reports_planted "$WORK/report.txt" 3 \
  "planted.md:1: value of dbm_sod \`p*\`: quoted 0.3042, the run printed 0.30323" \
  "planted.md:2: value of dbm_sod \`rho*\`: its run.sh printed no number 1 after \`rho*\`" \
  "granular_chain: its run.sh output was given, but no page quotes a value of it"
echo "docs_values: ok (${examples[*]})"

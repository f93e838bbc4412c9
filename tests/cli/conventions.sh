#!/usr/bin/env bash
# The output conventions (docs/conventions.md) hold for the run folder of every method's test case
# (tests/cli/cases): units on every VTK array, one time column per file named for the method's unit
# system, units in the series.csv column names of the methods that have them, self-describing
# checkpoints (docs/checkpoints.md). The checker itself fails on a folder that breaks them (a second
# time column, a time column of another unit system, an array without units, a granular series
# column without its unit, a checkpoint dataset without units or a case that is not the run's).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
check() { /usr/bin/python3 "$ROOT/tests/cli/conventions.py" "$@"; }
runs=()
for case_file in "$ROOT"/tests/cli/cases/*.toml; do
  name=$(basename "$case_file" .toml)
  "$SF" run "$case_file" --output "$WORK/$name" -q > /dev/null
  runs+=("$WORK/$name")
done
check "${runs[@]}" || fail "a run folder breaks the output conventions (above)"

# A deliberately broken folder: the checker must name each violation.
mkdir -p "$WORK/broken/fields"
printf "method = 'mpm'\n" > "$WORK/broken/config.resolved.toml"
printf "step,time_s,time\n0,0,0\n" > "$WORK/broken/series.csv"
printf "step,time_ps\n0,0\n" > "$WORK/broken/profile.csv"
cp "$WORK/mpm_tiny/fields/grid_000000000.vti" "$WORK/broken/fields/"
sed -i '0,/ units="K"/s/ units="K"//' "$WORK/broken/fields/grid_000000000.vti"
cp "$WORK/mpm_tiny/checkpoint.h5" "$WORK/broken/"
/usr/bin/python3 -c 'import h5py, sys
with h5py.File(sys.argv[1], "r+") as f:
    del f["pressure"].attrs["units"]
    f["mass"].attrs["units"] = "mixed"
    f.attrs["step"] = 66.0' "$WORK/broken/checkpoint.h5"
mkdir -p "$WORK/broken_granular"
cp "$WORK/granular_tiny/config.resolved.toml" "$WORK/broken_granular/"
sed '1s/,kinetic_J,/,kinetic,/' "$WORK/granular_tiny/series.csv" > "$WORK/broken_granular/series.csv"
set +e
check "$WORK/broken_granular" > "$WORK/broken_granular.txt"
[ $? -eq 1 ] || fail "the checker passed a granular series column without its unit"
grep -qF "series.csv: column 'kinetic' has no unit suffix" "$WORK/broken_granular.txt" ||
  fail "the checker did not name the column without a unit: $(cat "$WORK/broken_granular.txt")"
mkdir -p "$WORK/broken_pd"
cp "$WORK/pd_tiny/config.resolved.toml" "$WORK/broken_pd/"
printf "step,time_s,kinetic_energy,momentum_x_kg_m_s\n0,0,0,0\n" > "$WORK/broken_pd/series.csv"
check "$WORK/broken_pd" > "$WORK/broken_pd.txt"
[ $? -eq 1 ] || fail "the checker passed a 1D PD series without units or per-area labels"
for p in "column 'kinetic_energy' has no unit suffix" \
         "column 'momentum_x_kg_m_s' is a total of a 1D run; name it 'momentum_x_kg_m_s_per_m2'"; do
  grep -qF "$p" "$WORK/broken_pd.txt" || fail "the checker did not report: $p ($(cat "$WORK/broken_pd.txt"))"
done
check "$WORK/broken" > "$WORK/broken.txt"
code=$?
set -e
[ $code -eq 1 ] || fail "the checker passed a broken folder (exit $code)"
for p in "series.csv: 2 time columns" "profile.csv: time column 'time_ps'; a mpm run names it 'time_s'" \
         "DataArray 'temperature' has no units attribute" "checkpoint.h5: dataset 'pressure' has no units attribute" \
         "checkpoint.h5: attribute 'step' is not stored as an integer" \
         "checkpoint.h5: dataset 'mass' is an opaque mix" \
         "checkpoint.h5: attribute 'case' is not the run's config.resolved.toml"; do
  grep -qF "$p" "$WORK/broken.txt" || fail "the checker did not report: $p ($(cat "$WORK/broken.txt"))"
done
echo "conventions: every method's run folder follows docs/conventions.md; a broken folder is caught"

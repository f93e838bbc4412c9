#!/usr/bin/env bash
# The output conventions (docs/conventions.md) hold for the run folder of every method's test case
# (tests/cli/cases, plus MPM runs with a cavity and contact in 2D and 3D): units on every VTK array, one time
# column per file named for the method's unit system, units in every CSV column name (SI and metal
# units) and summary.json result key, velocities never named u, totals of 1D/2D runs labelled per length or area
# (model units too), self-describing checkpoints (docs/checkpoints.md), and the same for the tables and surfaces
# of `analyze atoms` (metal units) and the outputs of `analyze geometry` (the length unit of its input). The checker
# itself fails on a folder that breaks them (a second time column, a time column of another unit
# system, an array without units, an image without its length_units and a .pvd without or with
# another time_units, granular, PD and MPM columns without their units, PD summary keys
# without their unit or per-area label, MD analysis tables without units, an MPM velocity and a DBM
# (model-unit) velocity named u, DBM and phase-field totals without their per-length label, analyze
# atoms' tables under their old names (tracks.csv, growth.csv, profiles.csv) and a surface without
# units, analyze geometry's summary.txt, clusters.csv and mesh without units, a method without a unit system, a checkpoint dataset without units or a case that is not
# the run's).
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
# The MPM columns the tiny case leaves out, in cases/mpm_cavity_contact.toml (run above): a cavity
# (its tracker's columns) and two bodies in contact (contact_node_count, contact_force_N_per_m).
for c in cavity_size_m2 collapsibility v_up_above_m_s contact_node_count contact_force_N_per_m ejecta_mass_kg_per_m; do
  head -1 "$WORK/mpm_cavity_contact/series.csv" | grep -q "\b$c\b" || fail "the cavity and contact run lacks $c"
done
# The same in 3D (cavity_size_m3, totals without a per-length label, vz), 50 µm cells, 2 rows.
cat > "$WORK/mpm_3d.toml" <<'CASE'
method = "mpm"
[grid]
dim = 3
cell_size = 50e-6
lo = [0.0, 0.0, 0.0]
hi = [0.4e-3, 0.4e-3, 1.1e-3]
[solver]
end_time = 4e-9
[[material]]
name = "al"
library = "aluminium_seed000"
[[body]]
material = "al"
lo = [0.0, 0.0, 0.0]
hi = [0.4e-3, 0.4e-3, 0.5e-3]
cavity_radius = 100e-6
cavity_depth = 250e-6
[loading]
type = "symmetric"
speed = 1000.0
[diagnostics]
window_bottom = 25e-6
window_heights = [200e-6]
histogram_times = [2e-9]
[output]
series_interval = 2e-9
[contact]
enabled = true
CASE
"$SF" run "$WORK/mpm_3d.toml" --output "$WORK/mpm_3d" -q > /dev/null
for c in cavity_size_m3 momentum_z_kg_m_s bottom_h200um_vz_mean_m_s contact_force_N ejecta_mass_kg; do
  head -1 "$WORK/mpm_3d/series.csv" | grep -q "\b$c\b" || fail "the 3D cavity and contact run lacks $c"
done
grep -q "^vz_m_s," "$WORK/mpm_3d/histograms/hist_0.csv" || fail "the 3D histogram lacks vz_m_s"
runs+=("$WORK/mpm_3d")
# The tables of `analyze atoms` (LAMMPS metal units, checked with --analysis) on the dumps of the MD
# analysis case: structures, clusters, tracks and growth, profiles, Burgers circuits, domains and
# voids with their surfaces (.vtp).
"$SF" analyze atoms "$WORK/tiny_cu_analysis" --adaptive-cna --clusters 3.0 --cluster-select acna:other --track \
  --timestep-size 0.002 --profile z:3.6 --excess-energy auto --voids 2.0 --domains 3.0 --burgers-clusters \
  --burgers-lattice 3.615 --no-plot -o "$WORK/atoms" > /dev/null 2>&1
for f in structures clusters tracks growth profiles burgers domains voids; do
  [ "$(wc -l < "$WORK/atoms/$f.csv")" -ge 1 ] || fail "analyze atoms wrote no $f.csv"
done
[ "$(wc -l < "$WORK/atoms/growth.csv")" -gt 1 ] && ls "$WORK"/atoms/domains_*.vtp > /dev/null || fail "no growth laws or domain surfaces to check"
# The tables of the field analyses in the units of the fields they read: an MPM grid (SI, the
# .pvd's time_units and the grid's length_units) and a phase-field grid (model units: _1).
"$SF" analyze minkowski "$WORK/mpm_tiny" --array pressure -n 3 --no-plot -o "$WORK/fields_mpm" > /dev/null
"$SF" analyze stats "$WORK/mpm_tiny" --array pressure --bins 4 -o "$WORK/fields_mpm" > /dev/null
"$SF" analyze minkowski "$WORK/phasefield_tiny" -n 3 --no-plot -o "$WORK/fields_phasefield" > /dev/null
[ "$(head -1 "$WORK/fields_mpm/minkowski.csv")" = "file,time_s,threshold_Pa,A,L_m,chi,chi_per_black" ] ||
  fail "MPM minkowski.csv columns: $(head -1 "$WORK/fields_mpm/minkowski.csv")"
[ "$(head -1 "$WORK/fields_mpm/structure_factor.csv")" = "file,time_s,k_per_m,S_Pa2,shell_points" ] ||
  fail "MPM structure_factor.csv columns: $(head -1 "$WORK/fields_mpm/structure_factor.csv")"
[ "$(head -1 "$WORK/fields_phasefield/minkowski.csv")" = "file,time_1,threshold_1,A,L_1,chi,chi_per_black" ] ||
  fail "phase-field minkowski.csv columns: $(head -1 "$WORK/fields_phasefield/minkowski.csv")"
# `analyze geometry` in the length unit of its points: an MPM particle frame (m), the MD analysis
# case's last dump (A), a CSV without --length-units (unknown).
last_frame=$(ls "$WORK"/mpm_tiny/fields/particles_*.vtp | tail -1)
"$SF" analyze geometry "$last_frame" --dimension 2 -d 3e-5 -o "$WORK/geometry_mpm" > /dev/null
"$SF" analyze geometry "$(ls "$WORK"/tiny_cu_analysis/dumps/* | tail -1)" -d 3.0 -r 3.0 -o "$WORK/geometry_md" > /dev/null
printf 'x,y,z\n0,0,0\n1,0,0\n0,1,0\n0,0,1\n' > "$WORK/tetrahedron.csv"
"$SF" analyze geometry "$WORK/tetrahedron.csv" -d 2 -o "$WORK/geometry_csv" > /dev/null
grep -q '^total_area_m2 ' "$WORK/geometry_mpm/summary.txt" && grep -q '^surface_area_A2 ' "$WORK/geometry_md/summary.txt" &&
  grep -q '^total_volume_unknown ' "$WORK/geometry_csv/summary.txt" || fail "analyze geometry's summaries name no units"
runs+=("$WORK/geometry_mpm" "$WORK/geometry_md" "$WORK/geometry_csv")
check "${runs[@]}" --analysis "$WORK/atoms" "$WORK/fields_mpm" "$WORK/fields_phasefield" ||
  fail "a run or analysis folder breaks the output conventions (above)"

# The checker on a deliberately broken folder: it must exit 1 and report each message given.
expect_reported() {
  local folder=$1 what=$2 code=0 p
  shift 2
  check ${AS_ANALYSIS:+--analysis} "$folder" > "$folder.txt" || code=$?
  [ $code -eq 1 ] || fail "the checker passed $what (exit $code)"
  for p in "$@"; do
    grep -qF "$p" "$folder.txt" || fail "the checker did not report: $p ($(cat "$folder.txt"))"
  done
}

# A second time column, a time column of another unit system, an array without units, a
# checkpoint that does not describe itself.
mkdir -p "$WORK/broken/fields"
printf "method = 'mpm'\n" > "$WORK/broken/config.resolved.toml"
printf "step,time_s,time\n0,0,0\n" > "$WORK/broken/series.csv"
printf "step,time_ps\n0,0\n" > "$WORK/broken/profile.csv"
cp "$WORK/mpm_tiny/fields/grid_000000000.vti" "$WORK/broken/fields/"
sed -i -e '0,/ units="K"/s/ units="K"//' -e 's/ length_units="m"//' "$WORK/broken/fields/grid_000000000.vti"
sed 's/ time_units="s"//' "$WORK/mpm_tiny/grid.pvd" > "$WORK/broken/grid.pvd"
sed 's/ time_units="s"/ time_units="ps"/' "$WORK/mpm_tiny/particles.pvd" > "$WORK/broken/particles.pvd"
cp "$WORK/mpm_tiny/checkpoint.h5" "$WORK/broken/"
/usr/bin/python3 -c 'import h5py, sys
with h5py.File(sys.argv[1], "r+") as f:
    del f["pressure"].attrs["units"]
    f["mass"].attrs["units"] = "mixed"
    f.attrs["step"] = 66.0' "$WORK/broken/checkpoint.h5"
expect_reported "$WORK/broken" "a broken folder" \
  "series.csv: 2 time columns" "profile.csv: time column 'time_ps'; a mpm run names it 'time_s'" \
  "DataArray 'temperature' has no units attribute" "checkpoint.h5: dataset 'pressure' has no units attribute" \
  "checkpoint.h5: attribute 'step' is not stored as an integer" "checkpoint.h5: dataset 'mass' is an opaque mix" \
  "checkpoint.h5: attribute 'case' is not the run's config.resolved.toml" \
  "grid_000000000.vti: <ImageData> names no length_units" \
  "grid.pvd: <Collection> names no time_units; a mpm run's times are in 's'" \
  "particles.pvd: time_units 'ps'; a mpm run's times are in 's'"
# A granular series column without its unit.
mkdir -p "$WORK/broken_granular"
cp "$WORK/granular_tiny/config.resolved.toml" "$WORK/broken_granular/"
sed '1s/,kinetic_J,/,kinetic,/' "$WORK/granular_tiny/series.csv" > "$WORK/broken_granular/series.csv"
expect_reported "$WORK/broken_granular" "a granular series column without its unit" \
  "series.csv: column 'kinetic' has no unit suffix"
# A 1D PD series and summary.json without units or per-area labels: the series' kinetic energy
# and momentum, the summary under its old keys (momentum without its unit, the kinetic energy
# without its per-area label).
mkdir -p "$WORK/broken_pd"
cp "$WORK/pd_tiny/config.resolved.toml" "$WORK/broken_pd/"
printf "step,time_s,kinetic_energy,momentum_x_kg_m_s\n0,0,0,0\n" > "$WORK/broken_pd/series.csv"
sed 's/"kinetic_energy_J_per_m2"/"kinetic_energy_J"/; s/"momentum_kg_m_s_per_m2"/"momentum"/' \
    "$WORK/pd_tiny/summary.json" > "$WORK/broken_pd/summary.json"
grep -q '"momentum":' "$WORK/broken_pd/summary.json" || fail "the PD summary has no momentum key to break"
expect_reported "$WORK/broken_pd" "a 1D PD series and summary without units or per-area labels" \
  "column 'kinetic_energy' has no unit suffix" \
  "column 'momentum_x_kg_m_s' is a total of a 1D run; name it 'momentum_x_kg_m_s_per_m2'" \
  "summary.json: results key 'momentum' has no unit suffix" \
  "summary.json: results key 'kinetic_energy_J' is a total of a 1D run; name it 'kinetic_energy_J_per_m2'"
# MD's in-run analysis tables under their old names: lengths and volumes without Å, counts
# without _count.
mkdir -p "$WORK/broken_md"
cp "$WORK/tiny_cu_analysis/config.resolved.toml" "$WORK/broken_md/"
sed '1s/,x_A,y_A,z_A,a_A,/,x,y,z,a,/; 1s/,ellipsoid_volume_A3,ellipsoid_surface_A2,/,ellipsoid_volume,ellipsoid_surface,/' \
    "$WORK/tiny_cu_analysis/clusters.csv" > "$WORK/broken_md/clusters.csv"
sed '1s/,cna_fcc_count,/,cna_fcc,/' "$WORK/tiny_cu_analysis/structures.csv" > "$WORK/broken_md/structures.csv"
expect_reported "$WORK/broken_md" "MD analysis tables without units" \
  "clusters.csv: column 'x' has no unit suffix" "clusters.csv: column 'a' has no unit suffix" \
  "clusters.csv: column 'ellipsoid_surface' has no unit suffix" "structures.csv: column 'cna_fcc' has no unit suffix"
# DBM (model units) with a velocity named u: series and profile columns ux, uy and a field array ux.
mkdir -p "$WORK/broken_dbm/profiles" "$WORK/broken_dbm/fields"
cp "$WORK/dbm_sod/config.resolved.toml" "$WORK/broken_dbm/"
sed '1s/,vx,vy,/,ux,uy,/' "$WORK/dbm_sod/series.csv" > "$WORK/broken_dbm/series.csv"
sed '1s/,vx,vy,/,ux,uy,/' "$WORK/dbm_sod/profiles/profile_1.csv" > "$WORK/broken_dbm/profiles/profile_1.csv"
sed 's/Name="velocity"/Name="ux"/' "$WORK/dbm_sod/fields/grid_000000000.vti" > "$WORK/broken_dbm/fields/grid_000000000.vti"
expect_reported "$WORK/broken_dbm" "a DBM velocity named u" \
  "series.csv: column 'ux' is a velocity in model units" "series.csv: column 'uy' is a velocity in model units" \
  "profile_1.csv: column 'ux' is a velocity in model units" "grid_000000000.vti: DataArray 'ux' is a velocity in model units"
# MPM columns and arrays under their old names: a window mean without its unit, a gradient
# without 1/s², the highest particle without metres, a velocity named u (series and grid frame),
# a summary.json mean without its unit.
mkdir -p "$WORK/broken_mpm/fields"
cp "$WORK/mpm_tiny/config.resolved.toml" "$WORK/broken_mpm/"
sed '1s/,top_m,rot2_per_s2,/,top,rot2,/; 1s/_pressure_mean_Pa,/_pressure_mean,/; 1s/_vy_mean_m_s,/_uy_mean_m_s,/' \
    "$WORK/mpm_tiny/series.csv" > "$WORK/broken_mpm/series.csv"
sed 's/Name="vy"/Name="uy"/' "$WORK/mpm_tiny/fields/grid_000000000.vti" > "$WORK/broken_mpm/fields/grid_000000000.vti"
sed 's/"pressure_Pa"/"pressure"/' "$WORK/mpm_tiny/summary.json" > "$WORK/broken_mpm/summary.json"
expect_reported "$WORK/broken_mpm" "MPM columns without units" \
  "column 'top' has no unit suffix" "column 'rot2' has no unit suffix" \
  "column 'bottom_h200um_pressure_mean' has no unit suffix" \
  "column 'bottom_h200um_uy_mean_m_s' names a velocity u" "DataArray 'uy' is a velocity" \
  "summary.json: results key 'pressure' has no unit suffix"
# analyze atoms' tables under their names before issue 15 (tracks.csv: time, x, a, L, area; growth.csv's
# quantity L; profiles.csv: lo, hi, centre) and a surface whose points have no unit.
mkdir -p "$WORK/broken_atoms"
sed '1s/.*/track,frame,timestep,time,cluster,size,x,y,z,a,b,c,L,area,volume,atomic_volume/' "$WORK/atoms/tracks.csv" \
  > "$WORK/broken_atoms/tracks.csv"
sed 's/,L_A,/,L,/' "$WORK/atoms/growth.csv" > "$WORK/broken_atoms/growth.csv"
sed '1s/,lo_A,hi_A,centre_A,/,lo,hi,centre,/' "$WORK/atoms/profiles.csv" > "$WORK/broken_atoms/profiles.csv"
sed 's/ units="A"//' "$(ls "$WORK"/atoms/domains_*.vtp | head -1)" > "$WORK/broken_atoms/domains_0.vtp"
grep -q ",L," "$WORK/broken_atoms/growth.csv" || fail "growth.csv has no L_A row to break"
AS_ANALYSIS=1 expect_reported "$WORK/broken_atoms" "analyze atoms tables without units" \
  "tracks.csv: time column 'time'; a analyze_atoms run names it 'time_ps'" "tracks.csv: column 'x' has no unit suffix" \
  "tracks.csv: column 'L' has no unit suffix" "tracks.csv: column 'area' has no unit suffix" \
  "growth.csv: quantity 'L' has no unit suffix" "profiles.csv: column 'centre' has no unit suffix" \
  "domains_0.vtp: DataArray 'points' has no units attribute"
# Totals of the model-unit methods without their per-length label: DBM's lattice is 2D, the phase
# field case is 2D.
mkdir -p "$WORK/broken_dbm_totals" "$WORK/broken_phasefield"
cp "$WORK/dbm_sod/config.resolved.toml" "$WORK/broken_dbm_totals/"
sed 's/"mass_per_length"/"mass"/' "$WORK/dbm_sod/summary.json" > "$WORK/broken_dbm_totals/summary.json"
cp "$WORK/phasefield_tiny/config.resolved.toml" "$WORK/broken_phasefield/"
sed '1s/,free_energy_per_length,/,free_energy,/' "$WORK/phasefield_tiny/series.csv" > "$WORK/broken_phasefield/series.csv"
expect_reported "$WORK/broken_dbm_totals" "a DBM total without its per-length label" \
  "summary.json: results key 'mass' is a total of a 2D run (model units); name it 'mass_per_length'"
expect_reported "$WORK/broken_phasefield" "a phase-field total without its per-length label" \
  "series.csv: column 'free_energy' is a total of a 2D run (model units); name it 'free_energy_per_length'"
# Field-analysis tables under their names before issue 15 (no units) and with a second time column.
mkdir -p "$WORK/broken_fields"
sed '1s/time_s,threshold_Pa,A,L_m,/time,threshold,A,L,/' "$WORK/fields_mpm/minkowski.csv" > "$WORK/broken_fields/minkowski.csv"
sed '1s/,mean_Pa,/,mean,/; 1s/,domain_size_R_m$/,domain_size_R,time_ps/' "$WORK/fields_mpm/stats.csv" > "$WORK/broken_fields/stats.csv"
AS_ANALYSIS=1 expect_reported "$WORK/broken_fields" "field-analysis tables without units" \
  "minkowski.csv: column 'threshold' has no unit suffix" "minkowski.csv: column 'L' has no unit suffix" \
  "minkowski.csv: column 'time' has no unit suffix" "stats.csv: column 'mean' has no unit suffix" \
  "stats.csv: column 'domain_size_R' has no unit suffix" "stats.csv: time columns ['time_s', 'time_ps']"
# analyze geometry's outputs under their names before issue 15 (no units) and a mesh without units.
mkdir -p "$WORK/broken_geometry"
sed 's/^total_volume_A3 /total_volume /; s/^surface_area_A2 /surface_area /' "$WORK/geometry_md/summary.txt" \
  > "$WORK/broken_geometry/summary.txt"
sed '1s/x_A,y_A,z_A/x,y,z/' "$WORK/geometry_md/clusters.csv" > "$WORK/broken_geometry/clusters.csv"
sed 's/ units="A3"//' "$WORK/geometry_md/delaunay.vtu" > "$WORK/broken_geometry/delaunay.vtu"
expect_reported "$WORK/broken_geometry" "analyze geometry's outputs without units" \
  "summary.txt: 'total_volume' has no unit suffix" "summary.txt: 'surface_area' has no unit suffix" \
  "clusters.csv: 'x' has no unit suffix" "clusters.csv: 'z' has no unit suffix" \
  "delaunay.vtu: DataArray 'volume' has no units attribute"
# The next method: a run folder of a method the checker has no unit system for is itself a violation.
mkdir -p "$WORK/broken_new_method"
printf "method = 'newmethod'\n" > "$WORK/broken_new_method/config.resolved.toml"
printf "step,time_s,energy\n0,0,0\n" > "$WORK/broken_new_method/series.csv"
expect_reported "$WORK/broken_new_method" "a method it has no unit system for" "method 'newmethod' has no unit system"
echo "conventions: every method's run folder follows docs/conventions.md; a broken folder is caught"

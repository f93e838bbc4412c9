#!/usr/bin/env bash
# An MPM run writes its folder (log, resolved config with derived values, series, VTK fields
# and particles with .pvd indexes, histograms, checkpoint; stop and resume: stop_resume.sh); runs that go wrong (particles
# leaving the grid, a fixed step beyond the CFL limit) stop with exit code 3 and keep their output.
source "$(dirname "$0")/lib.bash"
set -e
case="$ROOT/tests/cli/cases/mpm_tiny.toml"
export OMP_NUM_THREADS=2
"$SF" run "$case" --output "$WORK/straight" -q > /dev/null
for f in log.txt config.resolved.toml series.csv grid.pvd particles.pvd checkpoint.h5 histograms/hist_0.csv \
         fields/grid_000000000.vti; do
  [ -s "$WORK/straight/$f" ] || fail "run folder lacks $f"
done
grep -q "^particles = " "$WORK/straight/config.resolved.toml" || fail "no derived particle count"
grep -q "^time_step_initial_s = " "$WORK/straight/config.resolved.toml" || fail "no derived time step"
grep -q "^hugoniot_pressure_Pa = " "$WORK/straight/config.resolved.toml" || fail "no derived Hugoniot"
grep -q "^heat_conduction = false" "$WORK/straight/config.resolved.toml" || fail "heat_conduction (default off) not echoed"
# The HEL of the J2 solid, (K + 4G/3)·Y0/(2G) = ρ0 c_L² Y0/(2G), with G from the derived speeds:
# 4G/3 = ρ0 (c_L² − c0²) (docs/mpm.md; the two-wave test of test_waves.cpp measures its plateau).
awk -F' = ' '$1 == "al_hel_Pa" { hel = $2 } $1 == "al_longitudinal_speed_m_s" { cl = $2 }
  $1 == "c0" { c0 = $2 } $1 == "rho0" { rho = $2 } $1 == "yield_stress" { y = $2 }
  END { g = 0.75 * rho * (cl * cl - c0 * c0); want = rho * cl * cl * y / (2 * g)
        exit !(hel > 0 && (hel - want) / want < 1e-9 && (want - hel) / want < 1e-9) }' \
  "$WORK/straight/config.resolved.toml" || fail "derived al_hel_Pa is not (K + 4G/3) Y0 / (2G)"
[ "$(grep -c DataSet "$WORK/straight/grid.pvd")" -eq 5 ] || fail "grid.pvd should list 5 frames"
[ "$(wc -l < "$WORK/straight/series.csv")" -eq 22 ] || fail "series.csv should have 21 rows"
# Stress outputs (docs/mpm.md, "Stress outputs"): tensors and the shock-axis and von Mises scalars.
vtp=$(ls "$WORK/straight/fields/"particles_*.vtp | tail -1)
for a in stress deviator longitudinal_stress longitudinal_deviator von_mises body; do
  grep -q "Name=\"$a\"" "$vtp" || fail "particle frame lacks $a"
done
grep -q 'Name="stress" NumberOfComponents="9"' "$vtp" || fail "particle stress is not a 9-component tensor"
grep -q 'Name="von_mises"' "$WORK/straight/fields/grid_000000000.vti" || fail "grid frame lacks von_mises"
head -1 "$WORK/straight/series.csv" | grep -q "_longitudinal_stress_mean_Pa" || fail "series windows lack the longitudinal stress"
# The .vti is readable by `shockfield analyze`.
"$SF" analyze stats "$WORK/straight/fields/grid_000000000.vti" --array density -o "$WORK/stats" --no-plot > /dev/null \
  || fail "analyze cannot read the grid field"

grep -q "stay glued" "$WORK/straight/log.txt" && fail "one body: no note about glued bodies expected"

base=$(sed -n '/^method/,$p' "$case")
# [contact] (docs/mpm.md): a symmetric impact of the strip and its mirror image, two contact bodies;
# series.csv gains contact_node_count and contact_force_N_per_m, [derived] the body count; without [contact]
# the log says the bodies stay glued.
symmetric=${base/type = \"wall\"/type = \"symmetric\"}
symmetric=${symmetric/hi = \[0.4e-3, 0.6e-3\]/hi = [0.4e-3, 1.1e-3]}
printf '%s\n[contact]\nenabled = true\n' "$symmetric" > "$WORK/contact.toml"
"$SF" run "$WORK/contact.toml" --output "$WORK/contact" -q > /dev/null
grep -q "^contact_bodies = 2" "$WORK/contact/config.resolved.toml" || fail "no derived contact_bodies = 2"
head -1 "$WORK/contact/series.csv" | grep -q ",contact_node_count,contact_force_N_per_m$" || fail "series.csv lacks the contact columns"
awk -F, 'NR > 2 && $(NF - 1) > 0 && $NF > 0 { found = 1 } END { exit !found }' "$WORK/contact/series.csv" \
  || fail "no row with contact nodes and a contact force"
printf '%s\n' "$symmetric" > "$WORK/glued.toml"
"$SF" run "$WORK/glued.toml" --output "$WORK/glued" -q > /dev/null
grep -q "stay glued" "$WORK/glued/log.txt" || fail "no note that the two bodies stay glued"
head -1 "$WORK/glued/series.csv" | grep -q "contact_node_count" && fail "contact columns without [contact]"

base=$(sed -n '/^method/,$p' "$case")
expect_run_error() {
  run_expecting 3 "$@"
  grep -qF "run stopped" "$WORK/out/log.txt" || fail "log.txt lacks the diagnosis"
  [ "$(wc -l < "$WORK/out/series.csv")" -ge 2 ] || fail "series.csv lost its rows"
  [ -s "$WORK/out/failure.vtp" ] || fail "no failure.vtp"
}
# Tensile loading with no headroom: the free surface leaves the grid.
tensile=${base/type = \"wall\"/type = \"tensile\"}
expect_run_error "${tensile/hi = \[0.4e-3, 0.6e-3\]/hi = [0.4e-3, 0.5e-3]}" "left the grid"
# A fixed step just below the initial CFL limit: the shocked material's faster sound breaks it.
expect_run_error "${base/end_time = 40e-9/end_time = 40e-9
time_step = 3.3e-9}" "beyond the CFL limit"
echo "mpm_run: ok"

#!/usr/bin/env bash
# Bad PD case files: one clear message naming file, key and line, exit code 2, nothing left
# behind (horizon smaller than the spacing, unstable fixed step, bad material values, unknown
# keys and choices, a point with a singular shape tensor, an unknown slip system set, Euler angles
# out of range, a zero loading direction, inverted grain sizes, a PMB critical stretch of 0, a
# negative micromodulus, an LPS key given to PMB, a contact switch that is not a bool or is
# given to J2, a plane-stress LPS body that is not 2D, a plane key given to PMB).
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/pd_tiny.toml")

expect_error "${base/horizon_factor = 3.0/horizon_factor = 0.5}" "case.toml" "body.horizon_factor" "smaller than the spacing"
expect_error "${base/end_time = 2e-7/end_time = 2e-7
time_step = 1e-8}" "solver.time_step" "beyond the stable step"
expect_error "${base/poisson = 0.334/poisson = 0.6}" "material.poisson"
expect_error "${base/yield_stress = 270e6/yield_stress = -1.0}" "material.yield_stress"
expect_error "${base/model = \"j2\"/model = \"bcc_crystal\"}" "material.model" "expected one of"
expect_error "${base/spacing = 10e-6/spacing = 10e-6
colour = 1}" "unknown key" "body.colour"
expect_error "${base/counts = \[400\]/counts = [400, 2]}" "body.counts"
expect_error "${base/dim = 1
counts = \[400\]/dim = 2
counts = [40, 1]}" "body.horizon_factor" "shape tensor" "singular"
expect_error "${base/speed = 300.0/}" "loading.speed" "missing required value"
expect_error "${base/horizon_factor = 3.0/horizon_factor = 3.0
influence = \"cubic\"}" "body.influence" "expected one of"
crystal="${base/model = \"j2\"
density = 2703.0
young = 77.11e9
poisson = 0.334
yield_stress = 270e6/model = \"crystal\"
density = 8960.0}"
expect_error "${crystal/density = 8960.0/density = 8960.0
slip_systems = \"hcp\"}" "material.slip_systems" "fcc"
expect_error "${crystal/density = 8960.0/density = 8960.0
orientation = \"euler\"
euler_angles_deg = [30.0, 200.0, 10.0]}" "material.euler_angles_deg" "out of range"
expect_error "${crystal/density = 8960.0/density = 8960.0
direction = [0.0, 0.0, 0.0]}" "material.direction" "non-zero"
expect_error "${crystal/density = 8960.0/density = 8960.0
orientation = \"random_grains\"
grain_planes = [12, 8]}" "material.grain_planes" "lo <= hi"
pmb="${base/young = 77.11e9
poisson = 0.334
yield_stress = 270e6/micromodulus = 4e21
critical_stretch = 0.01}"
pmb="${pmb/model = \"j2\"/model = \"pmb\"}"
expect_error "${pmb/critical_stretch = 0.01/critical_stretch = 0.0}" "material.critical_stretch"
expect_error "${pmb/micromodulus = 4e21/micromodulus = -4e21}" "material.micromodulus"
expect_error "${pmb/critical_stretch = 0.01/critical_stretch = 0.01
shear = 26e9}" "material.shear" "only of model = \"lps\""
expect_error "${pmb/critical_stretch = 0.01/critical_stretch = 0.01
contact = \"yes\"}" "material.contact"
expect_error "${base/yield_stress = 270e6/yield_stress = 270e6
contact = true}" "material.contact" "only of model = \"pmb\" or \"lps\""
lps="${base/young = 77.11e9
poisson = 0.334
yield_stress = 270e6/bulk = 70e9
shear = 26e9
critical_stretch = 0.01}"
lps="${lps/model = \"j2\"/model = \"lps\"}"
expect_error "${lps/shear = 26e9/shear = 26e9
plane = \"stress\"}" "material.plane" "2D plate" "dim = 1"
expect_error "${lps/shear = 26e9/shear = 26e9
plane = \"membrane\"}" "material.plane" "expected one of"
expect_error "${pmb/critical_stretch = 0.01/critical_stretch = 0.01
plane = \"stress\"}" "material.plane" "only of model = \"lps\""
echo "pd_bad_input: all cases rejected cleanly"

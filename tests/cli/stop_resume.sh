#!/usr/bin/env bash
# One stop/resume test for every method, run once per method (ctest cli.stop_resume.<method>):
# a run stopped as by Ctrl-C (--stop-after) and resumed through the run driver writes the same
# output as an uninterrupted one, bitwise (same thread count), and the resumed log says where it
# picked up. Arguments: SF ROOT METHOD.
source "$(dirname "$0")/lib.bash"
set -e
method="${3:?usage: stop_resume.sh SF ROOT METHOD}"
export OMP_NUM_THREADS=2
cases="$ROOT/tests/cli/cases"
# Per method: the tiny case, the step to stop at and the files compared.
case "$method" in
  md) case_file="$cases/tiny_cu.toml"; stop=130; files="dumps/dump.300.lammpstrj thermo.csv" ;;
  md_analysis) case_file="$cases/tiny_cu_analysis.toml"; stop=130
               files="structures.csv clusters.csv dumps/dump.150.lammpstrj dumps/dump.300.lammpstrj thermo.csv" ;;
  mpm) case_file="$cases/mpm_tiny.toml"; stop=25; files="series.csv grid.pvd histograms/hist_0.csv thermo.csv" ;;
  pd) case_file="$cases/pd_tiny.toml"; stop=77
      files="series.csv profiles/index.csv profiles/profile_2.csv profiles/profile_4.csv thermo.csv
             profiles/points.pvd profiles/points_4.vtp dumps/dump.103.lammpstrj dumps/dump.138.lammpstrj" ;;
  # A ramped prescribed displacement stopped mid-ramp (t = 0.18 of 0.2 µs) and a velocity formula.
  pd_loading) case_file="$cases/pd_bar_loading.toml"; stop=23
              files="series.csv profiles/index.csv profiles/profile_2.csv profiles/profile_4.csv thermo.csv
                     profiles/points_4.vtp" ;;
  dbm) case_file="$cases/dbm_sod.toml"; stop=17
       files="series.csv profiles/index.csv profiles/profile_1.csv profiles/profile_2.csv grid.pvd
              fields/grid_000000040.vti thermo.csv" ;;
  granular) case_file="$cases/granular_tiny.toml"; stop=123
            files="series.csv energy_above.csv probes.csv spacetime_force.csv spacetime_velocity.csv signal.csv thermo.csv
                   profiles/grains.pvd profiles/grains_1.vtp profiles/grains_2.vtp dumps/dump.617.lammpstrj" ;;
  macroparticle) case_file="$cases/macroparticle_tiny.toml"; stop=123
                 files="thermo.csv dumps/dump.250.lammpstrj particles.pvd particles/particles_250.vtp" ;;
  phasefield) case_file="$cases/phasefield_tiny.toml"; stop=23; files="series.csv fields.pvd fields/xi_3.vti thermo.csv" ;;
  phasefield_sharp_front) case_file="$cases/phasefield_sharp_front_tiny.toml"; stop=57
                          files="series.csv tracks.csv fields.pvd fields/xi_2.vti fields/xi_3.vti thermo.csv" ;;
  *) fail "unknown method '$method'" ;;
esac
"$SF" run "$case_file" --output "$WORK/straight" -q > /dev/null
stop_then_resume "$case_file" "$WORK/split" "$stop"
grep -q "resumed from .* at step $stop" "$WORK/split/log.txt" || fail "the resumed run did not start at the checkpoint"
if [ "$method" = mpm ]; then  # the last particle frame as well
  files="$files fields/$(ls "$WORK/straight/fields" | grep vtp | tail -1)"
fi
same_files "$WORK/straight" "$WORK/split" $files
echo "stop_resume $method: resumed run is bitwise identical ($files)"

#!/usr/bin/env bash
# `shockfield run` of a pd case on 1, 2 and 4 MPI ranks (ctest label mpi; docs/parallel.md,
# "Peridynamics under mpirun"): a 2D LPS plate whose pre-crack runs (tests/mpi/cases/
# pd_plate_tension.toml) and a 1D PMB bar breaking into fragments (pd_bar_fragments.toml), bonds
# breaking across the ranks' cuts. Every output — thermo.csv, series.csv, the profiles (damage of
# every point), the .vtp frames and the LAMMPS dumps — must be byte-identical (cmp) to the serial
# run's: each owned point's bond sums add the same terms in the serial order from ghosts holding
# their owners' bits, and rank 0 writes from the gathered whole body with the serial code, so
# nothing is reordered (no round-off bound is needed). The same on the 2 x 2 grid (corner ghosts),
# on the 1 x 1 grid without mpirun
# and on 2 ranks x 2 OpenMP threads; the bar's final damage has broken bonds within δ on both sides
# of each of the 4-rank cuts; the point count of the profiles is exact. A run stopped after 30 steps on 4
# ranks and resumed on 2 is identical too. Bad input (more ranks than the body cuts into for δ, a
# correspondence model, the contact force, a [homogeneous] case) exits 2 on every rank with the
# message printed once and no run folder; a blow-up on 2 ranks exits 3 with the serial message and output.
# Usage: pd_ranks.sh SHOCKFIELD SOURCE_DIR MPIEXEC PART, PART one of ranks, restart, bad_input.
source "$(dirname "$0")/lib.bash"
PART="$4"
set -e
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
CASES="$ROOT/tests/mpi/cases"

[ "$PART" = bad_input ] || for c in pd_plate_tension pd_bar_fragments; do
  "$SF" run "$CASES/$c.toml" --output "$WORK/serial_$c" -q > /dev/null
done
if [ "$PART" = ranks ]; then
  for c in pd_plate_tension pd_bar_fragments; do
    for np in 1 2 4; do
      mpi $np run "$CASES/$c.toml" --output "$WORK/np${np}_$c" -q > "$WORK/np$np.txt"
      same_outputs "$WORK/serial_$c" "$WORK/np${np}_$c" "$c on $np ranks"
    done
    OMP_NUM_THREADS=2 "$MPIEXEC" --oversubscribe --allow-run-as-root --bind-to none -np 2 "$SF" run "$CASES/$c.toml" \
      --output "$WORK/hybrid_$c" -q > /dev/null
    same_outputs "$WORK/serial_$c" "$WORK/hybrid_$c" "$c on 2 ranks x 2 threads"
  done
  # --rank-grid 1x1 without mpirun: the decomposed path on one rank.
  "$SF" run "$CASES/pd_plate_tension.toml" --output "$WORK/grid1x1" -q --rank-grid 1x1 > /dev/null
  same_outputs "$WORK/serial_pd_plate_tension" "$WORK/grid1x1" "pd_plate_tension on the 1 x 1 rank grid"
  mpi 4 run "$CASES/pd_plate_tension.toml" --output "$WORK/grid2x2" --rank-grid 2x2 > "$WORK/grid.txt"
  same_outputs "$WORK/serial_pd_plate_tension" "$WORK/grid2x2" "pd_plate_tension on the 2 x 2 rank grid"
  grep -q "960 points, .* on 4 ranks (rank grid 2 x 2 x 1)" "$WORK/grid2x2/log.txt" || fail "the log does not give the rank grid"
  [ "$(grep -c "shockfield .* pd: .*(960 points" "$WORK/grid.txt")" -eq 1 ] || fail "the log header is not printed once"
  # Bonds broke across the cuts of the bar's 4 x 1 x 1 grid: its pieces of the 20 mm body (each
  # point's 50 µm cell) end at 4.975, 9.975 and 14.975 mm; δ = 0.15075 mm.
  grep -q "on 4 ranks (rank grid 4 x 1 x 1)" "$WORK/np4_pd_bar_fragments/log.txt" || fail "the bar is not cut along x"
  last="$WORK/np4_pd_bar_fragments/profiles/profile_2.csv"
  awk -F, 'NR > 1 { n++; for (k = 1; k <= 3; ++k) { c = k * 5e-3 - 25e-6
             if ($17 > 0 && $1 < c && $1 > c - 1.5075e-4) low[k] = 1
             if ($17 > 0 && $1 > c && $1 < c + 1.5075e-4) high[k] = 1 } }
           END { if (n != 400) { print "FAIL: " n " points in the profile, not 400"; exit 1 }
                 for (k = 1; k <= 3; ++k) if (!low[k] || !high[k]) { print "FAIL: no broken bond across cut " k; exit 1 }
                 print "ok: 400 points; broken bonds within δ on both sides of the 3 cuts" }' "$last"
fi

if [ "$PART" = restart ]; then
  for c in pd_plate_tension pd_bar_fragments; do
    stop_then_resume 30 2 "$WORK/restart_$c" "$CASES/$c.toml"
    same_outputs "$WORK/serial_$c" "$WORK/restart_$c" "$c stopped on 4 ranks at step 30, resumed on 2"
  done
fi
[ "$PART" = bad_input ] || { echo "pd_ranks $PART: passed"; exit 0; }

refused 4 "4 ranks cannot cut the body (0.0005 x 5e-05 x 5e-05 m) into pieces at least 0.0001508 m long (the horizon δ" \
  "$CASES/pd_bar_fragments.toml" --set 'body.counts=[10]'
refused 2 "as --rank-grid 1x2x1; at most 132 x 1 x 1 = 132 ranks fit" "$CASES/pd_bar_fragments.toml" --rank-grid 1x2
refused 2 "key 'material.model': pmb or lps under mpirun: the correspondence models run on one rank only" \
  "$ROOT/tests/cli/cases/pd_tiny.toml"
refused 2 "key 'material.contact': false under mpirun: the short-range contact force" "$CASES/pd_bar_fragments.toml" \
  --set material.contact=true
refused 2 "a [homogeneous] pd case runs on one rank only" "$ROOT/examples/pd_ofhc_compression/ofhc_compression.toml"
# A blow-up (velocities of 1e305 m/s: the first step is not finite) on 2 ranks: exit 3, the serial
# message (raised from the gathered body) and the serial failure profile.
fails_alike "non-finite positions or velocities at step 1" "pd blow-up" "$CASES/pd_bar_fragments.toml" \
  --set 'region[0].velocity_formula=["1e305 * (x - 10e-3)"]'
echo "pd_ranks bad_input: passed"

#!/usr/bin/env bash
# `shockfield run` of an MD case on 1, 2 and 4 MPI ranks (ctest label mpi; docs/parallel.md, "MD
# under mpirun"): tests/cli/cases/tiny_cu.toml (256 Cu atoms, EAM, NVT then NVE, 300 steps) with
# thermo.csv at full precision. Every thermo column must equal the serial run's within a relative
# 1e-10 of the column's largest magnitude: the decomposed sums (forces, densities, thermo
# partials) add the same terms in another order, and that round-off grows over 300 chaotic steps
# (observed up to 1.1e-13); the library tests hold the same bound
# (tests/mpi/md_ranks_mpi.cpp). final.data and every dump hold the same atom ids. The same for a
# Langevin first stage on 2 ranks x 2 threads. A run stopped
# after 130 steps on 4 ranks and resumed on 2 (and on 1) ends the same within the bound, the
# neighbour-list rebuild count included (the resumed run lists the atoms at the checkpoint's
# rebuild positions). A case with a stage or a box the decomposition does not do exits 2 on every rank
# with the message printed once and no run folder.
# Usage: md_run.sh SHOCKFIELD SOURCE_DIR MPIEXEC PART, PART one of ranks, restart, bad_input.
source "$(dirname "$0")/lib.bash"
PART="$4"
set -e
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
cp "$ROOT/tests/cli/cases/tiny_cu.toml" "$WORK/cu.toml"
full=(--set output.thermo_full_precision=true)

same_thermo() {  # REFERENCE RUN WHAT [COLUMN NOT COMPARED]
  awk -F, -v skip="${4:-}" -v what="$3" '
    FNR == 1 { for (c = 1; c <= NF; ++c) name[c] = $c; next }
    NR == FNR { rows = FNR; for (c = 1; c <= NF; ++c) { ref[FNR, c] = $c; a = $c < 0 ? -$c : $c; if (a > big[c]) big[c] = a }; next }
    { got = FNR; for (c = 1; c <= NF; ++c) if (name[c] != skip) {
        d = $c - ref[FNR, c]; d = d < 0 ? -d : d; s = big[c] > 0 ? big[c] : 1
        if (d / s > worst) { worst = d / s; at = name[c] " at row " FNR } } }
    END { if (got != rows) { print "FAIL: " what ": " got " thermo rows, not " rows; exit 1 }
          if (worst > 1e-10) { print "FAIL: " what ": " at " differs by a relative " worst; exit 1 }
          printf "ok: %s: %d thermo rows within a relative %.2g of the serial run (bound 1e-10)\n", what, rows, worst }' \
    "$1/thermo.csv" "$2/thermo.csv" || exit 1
}
ids() {  # the sorted atom ids of a LAMMPS data file
  awk '/^Atoms/ { on = 1; next } /^Velocities/ { on = 0 } on && NF > 4 { print $1 }' "$1" | sort -n
}
same_atoms() {  # REFERENCE RUN WHAT
  [ "$(ids "$1/final.data")" = "$(ids "$2/final.data")" ] || fail "$3: final.data holds other atom ids"
  [ "$(ids "$1/final.data" | wc -l)" -eq 256 ] || fail "$3: final.data does not hold 256 atoms"
  for f in "$1"/dumps/*; do
    cmp -s <(awk 'NR > 9 { print $1 }' "$f" | sort -n) <(awk 'NR > 9 { print $1 }' "$2/dumps/$(basename "$f")" | sort -n) ||
      fail "$3: $(basename "$f") holds other atom ids"
  done
  echo "ok: $3: final.data and $(ls "$1/dumps" | wc -l) dumps hold the serial run's 256 atom ids"
}

"$SF" run "$WORK/cu.toml" --output "$WORK/serial" -q "${full[@]}" > /dev/null
if [ "$PART" = ranks ]; then
  for np in 1 2 4; do
    quiet=(-q); [ $np -lt 4 ] || quiet=()  # on 4 ranks the log on stdout is checked below
    mpi $np run "$WORK/cu.toml" --output "$WORK/np$np" "${quiet[@]}" "${full[@]}" > "$WORK/np$np.txt"
    same_thermo "$WORK/serial" "$WORK/np$np" "tiny_cu on $np ranks"
    same_atoms "$WORK/serial" "$WORK/np$np" "tiny_cu on $np ranks"
  done
  grep -q "256 atoms, on 4 ranks (rank grid 1 x 2 x 2)" "$WORK/np4/log.txt" || fail "the log does not give the rank grid"
  # Rank 0 alone prints: one log header on stdout.
  [ "$(grep -c "shockfield .* md: .*(256 atoms" "$WORK/np4.txt")" -eq 1 ] || fail "the log header is not printed once: $(cat "$WORK/np4.txt")"
  # Langevin (random force keyed by step and atom id; the bath work of econserved summed over the
  # ranks) on 2 ranks x 2 OpenMP threads (unbound, so the threads may use both cores).
  langevin=(--set 'stage[0].ensemble="langevin"')
  "$SF" run "$WORK/cu.toml" --output "$WORK/serial_langevin" -q "${full[@]}" "${langevin[@]}" > /dev/null
  OMP_NUM_THREADS=2 "$MPIEXEC" --oversubscribe --allow-run-as-root --bind-to none -np 2 "$SF" run "$WORK/cu.toml" \
    --output "$WORK/hybrid_langevin" -q "${full[@]}" "${langevin[@]}" > /dev/null
  same_thermo "$WORK/serial_langevin" "$WORK/hybrid_langevin" "tiny_cu, langevin then nve, on 2 ranks x 2 threads"
  # On one rank mpirun takes the serial path: the serial bytes.
  cmp -s "$WORK/serial/thermo.csv" "$WORK/np1/thermo.csv" || fail "thermo.csv on 1 rank is not the serial one"
fi

if [ "$PART" = restart ]; then
  for np in 2 1; do
    stop_then_resume 130 $np "$WORK/restart$np" "$WORK/cu.toml" "${full[@]}"
    same_thermo "$WORK/serial" "$WORK/restart$np" "tiny_cu stopped on 4 ranks at step 130, resumed on $np"
    same_atoms "$WORK/serial" "$WORK/restart$np" "tiny_cu stopped on 4 ranks, resumed on $np"
  done
fi
[ "$PART" = bad_input ] || { echo "md_run $PART: passed"; exit 0; }

refused 2 "key 'stage[0].ensemble': expected nve, nvt or langevin under mpirun: npt runs on one rank only" "$WORK/cu.toml" \
  --set 'stage[0].ensemble="npt"' --set stage[0].pressure=0
refused 2 "key 'system.lattice.boundary': expected \"ppp\" under mpirun" "$WORK/cu.toml" --set 'system.lattice.boundary="pps"'
refused 4 "key 'output.profile_every': expected 0 under mpirun" "$WORK/cu.toml" --set output.profile_every=10
refused 2 "--rank-grid 4 x 1 x 1 has 4 ranks, the run has 2" "$WORK/cu.toml" --rank-grid 4x1x1
refused 4 "at most 2 x 2 x 2 = 8 ranks fit" "$WORK/cu.toml" --rank-grid 4x1x1
echo "md_run bad_input: passed"

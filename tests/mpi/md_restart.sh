#!/usr/bin/env bash
# MD stopped on 4 ranks and resumed on 2 (docs/parallel.md): tests/mpi/md_ranks_mpi.cpp --stop
# gathers the atoms on rank 0 into the serial checkpoint; --resume deals them out on 2 ranks and
# compares the end with the uninterrupted serial run.
# Usage: md_restart.sh TEST_PROGRAM MPIEXEC
set -euo pipefail
program=$1 mpiexec=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
launch=("$mpiexec" --oversubscribe --allow-run-as-root)
"${launch[@]}" -np 4 "$program" --stop "$work/checkpoint.h5"
test -s "$work/checkpoint.h5"
"${launch[@]}" -np 2 "$program" --resume "$work/checkpoint.h5"

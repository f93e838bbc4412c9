#!/usr/bin/env bash
# The fuzzers replayed under AddressSanitizer + UBSan (docs/robustness.md, "Under AddressSanitizer
# and UBSan"): every binary fuzz target with MUTANTS mutants of seed 3, then the whole corpus,
# through the sanitized SHOCKFIELD (the `debug` preset's) driven by the fuzzer FUZZ (a release
# shockfield_fuzz). Any crash, hang, sanitizer report or unexpected exit code fails (exit 1),
# with the failing inputs saved under WORK/failures/. Prints one line per target and a last
# line saying what was done.
#   usage: tests/fuzz/sanitizer_replay.sh SHOCKFIELD FUZZ [MUTANTS] [WORK]
set -euo pipefail
shockfield="$1"
fuzz="$2"
mutants="${3:-12}"
work="${4:-$(mktemp -d)}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
[ -x "$fuzz" ] && [ -x "$shockfield" ] || { echo "sanitizer replay: $fuzz or $shockfield not built"; exit 1; }
# A leak, an overflow or an undefined cast is a failure, reported on stderr (the fuzzer looks
# for it); the run-time diagnoses of the code under test (exit 2, 3) are not.
# allocator_may_return_null: libhdf5 asks for 10^18 bytes on a damaged checkpoint header and
# handles the null that glibc's malloc returns; ASan would abort instead.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:exitcode=86:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
targets="case_check case_check_examples case_run eam_funcfl eam_setfl eam_fs data points atoms atoms_gz hugoniot
         checkpoint checkpoint_mpm checkpoint_pd checkpoint_dbm checkpoint_granular checkpoint_phasefield
         resume_case material_file bridge_eos bridge_elastic"
start=$SECONDS
status=0
log="$work/replay.log"
mkdir -p "$work"
: > "$log"
for t in $targets; do
  "$fuzz" --shockfield "$shockfield" --source "$root" --work "$work/$t" --target "$t" \
    --mutants "$mutants" --seed 3 --timeout 120 --memory-limit 0 >> "$log" 2>&1 || status=1
done
"$fuzz" --shockfield "$shockfield" --source "$root" --work "$work/corpus" \
  --replay "$root/tests/fixtures/fuzz" --timeout 120 --memory-limit 0 >> "$log" 2>&1 || status=1
grep -E "^(fuzz|FAIL)" "$log" || true
total=$(awk '/^fuzz /{ n += $3 } END { print n + 0 }' "$log")
failures=$(awk '/^fuzz /{ for (i = 1; i < NF; ++i) if ($(i + 1) ~ /^failures/) n += $i } END { print n + 0 }' "$log")
echo "sanitizer replay (ASan+UBSan, $shockfield): $total inputs ($mutants mutants of each of $(echo $targets | wc -w)" \
  "targets, seed 3, and the corpus), $failures failures, $((SECONDS - start)) s"
exit $status

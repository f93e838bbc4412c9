#pragma once
// Running one fuzz input in a child process, so that a crash, an abort, a sanitizer report or a
// hang of the code under test is observed (and survived) by the fuzzer: either a function run in
// a fork() of the fuzzer (the parsers, in-process) or another program (the shockfield binary).
// The child's stdout and stderr go to files in its work folder; the child is killed with SIGKILL
// when it passes the time bound or its work folder passes the output bound.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace shockfield::fuzz {

struct Limits {
  double seconds = 30;                       ///< wall time of one input
  std::uintmax_t output_bytes = 64u << 20;   ///< everything the child writes to its work folder
  /// Address space of the child (RLIMIT_AS), so that a count trusted too far fails fast as
  /// std::bad_alloc instead of swapping the machine; not set under AddressSanitizer, which
  /// reserves terabytes of shadow memory (nor with 0: `--memory-limit 0`, for a sanitized
  /// shockfield binary driven by an unsanitized fuzzer).
  std::uintmax_t memory_bytes = std::uintmax_t{4} << 30;
};

struct Outcome {
  enum class Kind {
    accepted,      ///< exit 0 (or the function returned)
    input_error,   ///< exit 2 / InputError
    run_error,     ///< exit 3 / RunError: a run-time diagnosis
    stopped,       ///< exit 130 (--stop-after)
    other_error,   ///< any other exit code or exception type
    crashed,       ///< a signal (SIGSEGV, SIGABRT of a sanitizer, ...)
    timed_out,     ///< killed at the time bound
    too_much_output,
    non_finite_output,  ///< exit 0, but a result file holds nan or inf (a target's own check)
    invalid_output,     ///< exit 0, but a result file is refused by its own reader (a target's own check)
  };
  Kind kind = Kind::accepted;
  int detail = 0;       ///< exit code or signal
  std::string message;  ///< the error message (in-process) or the child's stderr, cut at 4 kB
  double seconds = 0;
  bool sanitizer_report = false;  ///< "runtime error:" or "==ERROR: ...Sanitizer" on stderr
};

const char* kind_name(Outcome::Kind k);

/// Runs `body` in a fork of this process, writing its output files into `work`. An InputError thrown by
/// body is input_error, a RunError run_error, another exception other_error.
Outcome run_function(const std::function<void()>& body, const std::filesystem::path& work,
                     const Limits& limits);

/// Runs argv[0] with arguments argv[1..] in `work` (which must exist), with one OpenMP thread.
Outcome run_program(const std::vector<std::string>& argv, const std::filesystem::path& work,
                    const Limits& limits);

}  // namespace shockfield::fuzz

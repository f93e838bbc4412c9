#pragma once
// Error types. Every failure a user can cause is an InputError whose message names the file,
// the key or line, and what was expected; a simulation that goes wrong is a RunError carrying a
// diagnosis. Both are caught by the command-line front end and turned into one line + exit code.
#include <stdexcept>
#include <string>

namespace shockfield {

/// Bad input: a case file, a potential file, a data file, a command-line value.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run that cannot go on (NaN, lost atoms, step too large): the output so far is kept.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run stopped on request (Ctrl-C, SIGTERM, --stop-after) after writing its checkpoint.
class StopRequested : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace shockfield

#pragma once
// Deterministic mutations of a valid input file, for the fuzz tests: the same seed always gives
// the same mutant. A text mutant gets one to three of
//   byte flip | a number replaced by an extreme token (NaN, inf, -0, 1e300, 1e-300, huge or
//   negative integers, nothing) | line deleted | line duplicated | truncation | two numbers swapped;
// a binary file (an HDF5 checkpoint) gets byte flips, zeroed or random runs, a repeated block and
// truncation. Half of the number replacements pick among a file's first numbers, where the
// headers (counts, grid steps, box bounds) are.
#include <cstdint>
#include <random>
#include <string>

namespace shockfield::fuzz {

class Mutator {
 public:
  Mutator(std::uint64_t seed, bool binary) : rng_(seed), binary_(binary) {}
  /// A mutant of `input`; description() then lists what was done.
  std::string mutate(const std::string& input);
  const std::string& description() const { return description_; }

 private:
  std::size_t below(std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  void note(const std::string& what);
  void flip_byte(std::string& s);
  void replace_number(std::string& s);
  void swap_numbers(std::string& s);
  void delete_line(std::string& s);
  void duplicate_line(std::string& s);
  void truncate(std::string& s);
  void binary_run(std::string& s);

  std::mt19937_64 rng_;
  bool binary_;
  std::string description_;
};

/// SplitMix64: the seed of mutant `index` of a run seeded with `seed` (well-mixed, so that
/// neighbouring indices give unrelated mutants).
std::uint64_t mutant_seed(std::uint64_t seed, std::uint64_t index);

}  // namespace shockfield::fuzz

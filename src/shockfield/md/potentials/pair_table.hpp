#pragma once
// Tabulated pair potential, LAMMPS `pair_style table linear|spline N` with
// `pair_coeff i j file KEYWORD [cutoff]` (pair_table.cpp, 29 Sep 2021), same arithmetic:
//
// 1. The file's section (pair_table_file.hpp) is interpolated by cubic splines in r
//    (Numerical Recipes `spline`/`splint`): E(r) with end slopes −F(r_1), −F(r_n); F(r) with end
//    slopes FPRIME, else the one-sided differences (F_2 − F_1)/(r_2 − r_1), (F_n − F_{n−1})/(r_n − r_{n−1}).
//    Skipped for `linear` when the section is `RSQ` with n = N and rhi = cutoff ("match"): the
//    file's values are the inner table.
// 2. The inner table: N points s_k = r_in² + kΔ, Δ = (r_c² − r_in²)/(N − 1), r_in = rlo (R, RSQ)
//    or r_1, holding E(√s_k) and F(√s_k)/√s_k.
// 3. Look-up of a pair at s = r² < r_c²: k = int((s − r_in²)/Δ), t = (s − s_k)/Δ;
//    linear: E = E_k + t(E_{k+1} − E_k), F/r likewise;
//    spline: cubic spline in s through the nodes, with end slopes dE/ds = −F/(2r) and, for F/r,
//    (F'/r − F/r²)/(2r) from FPRIME (at the last point only if r_c = r_n) or else the secant over
//    0.1Δ of the file's spline:  a = 1 − t, b = t,
//    y = a y_k + b y_{k+1} + ((a³ − a) y''_k + (b³ − b) y''_{k+1}) Δ²/6.
// A pair closer than r_in stops the run (RunError), as LAMMPS's "Pair distance < table inner
// cutoff". Every type pair needs its own table (LAMMPS does not mix tables).
#include <atomic>
#include <string>
#include <vector>

#include "shockfield/md/potential.hpp"
#include "shockfield/md/potentials/pair_loop.hpp"
#include "shockfield/md/potentials/pair_table_file.hpp"

namespace shockfield::md::potentials {

enum class TableInterpolation { linear, spline };

/// The inner table of one type pair (step 2 above).
struct InnerTable {
  struct Node {
    double rsq;  ///< s_k, Å²
    double e;    ///< E(√s_k), eV
    double f;    ///< F(√s_k)/√s_k, eV/Å²
    double de;   ///< linear: E_{k+1} − E_k; spline: E''(s_k) in s
    double df;   ///< linear: (F/r)_{k+1} − (F/r)_k; spline: (F/r)''(s_k) in s
  };
  std::string source;  ///< "file section KEYWORD", for messages
  double cut = 0;      ///< r_c, Å
  double innersq = 0;  ///< r_in², Å²
  double delta = 0;    ///< Δ, Å²
  std::vector<Node> node;
};

/// Builds the inner table of `points` (N) nodes from a file section up to `cutoff` (steps 1-2).
/// InputError when the cutoff is not within (r_1, r_n] of the section.
InnerTable build_inner_table(const PairTableSection& section, TableInterpolation interpolation,
                             int points, double cutoff);

class TablePotential final : public Potential {
 public:
  /// `tables` and, for every type pair [i * ntypes + j] (symmetric), the index of its table.
  TablePotential(TableInterpolation interpolation, int ntypes, std::vector<InnerTable> tables,
                 std::vector<int> pair_table);

  std::string style() const override { return "table"; }
  double cutoff() const override { return cutoff_; }
  void check_types(const Atoms& atoms) const override;
  void compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) override;

  struct PairView;  ///< one type pair's table as the kernel reads it

 private:
  std::vector<PairView> views() const;
  [[noreturn]] void fail_outside_table(const Atoms& atoms, const geometry::NeighborList& list,
                                       const std::vector<PairView>& views) const;

  TableInterpolation interpolation_;
  int ntypes_;
  double cutoff_ = 0;
  std::vector<InnerTable> tables_;
  std::vector<int> pair_table_;
  std::atomic<bool> outside_{false};  // set by the kernel for a pair closer than r_in
  ThreadScratch scratch_;
};

}  // namespace shockfield::md::potentials

#include "shockfield/md/potentials/pair_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "shockfield/core/error.hpp"

namespace shockfield::md::potentials {
namespace {

// Numerical Recipes `spline` as in pair_table.cpp: second derivatives y2 of the cubic spline
// through (x_k, y_k) with end slopes yp1, ypn (a natural end where a slope exceeds 0.99e30).
template <class X, class Y>
std::vector<double> spline_second_derivatives(std::size_t n, X x, Y y, double yp1, double ypn) {
  std::vector<double> y2(n), u(n);
  if (yp1 > 0.99e30) {
    y2[0] = u[0] = 0.0;
  } else {
    y2[0] = -0.5;
    u[0] = (3.0 / (x(1) - x(0))) * ((y(1) - y(0)) / (x(1) - x(0)) - yp1);
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double sig = (x(i) - x(i - 1)) / (x(i + 1) - x(i - 1));
    const double p = sig * y2[i - 1] + 2.0;
    y2[i] = (sig - 1.0) / p;
    u[i] = (y(i + 1) - y(i)) / (x(i + 1) - x(i)) - (y(i) - y(i - 1)) / (x(i) - x(i - 1));
    u[i] = (6.0 * u[i] / (x(i + 1) - x(i - 1)) - sig * u[i - 1]) / p;
  }
  double qn = 0.0, un = 0.0;
  if (!(ypn > 0.99e30)) {
    qn = 0.5;
    un = (3.0 / (x(n - 1) - x(n - 2))) * (ypn - (y(n - 1) - y(n - 2)) / (x(n - 1) - x(n - 2)));
  }
  y2[n - 1] = (un - qn * u[n - 2]) / (qn * y2[n - 2] + 1.0);
  for (std::size_t k = n - 1; k-- > 0;) y2[k] = y2[k] * y2[k + 1] + u[k];
  return y2;
}

// A cubic spline through tabulated points (Numerical Recipes `splint`, bisection for the interval).
struct Spline {
  const std::vector<double>& x;
  const std::vector<double>& y;
  std::vector<double> y2;

  double operator()(double at) const {
    std::size_t lo = 0, hi = x.size() - 1;
    while (hi - lo > 1) {
      const std::size_t k = (hi + lo) >> 1;
      if (x[k] > at) hi = k;
      else lo = k;
    }
    const double h = x[hi] - x[lo];
    const double a = (x[hi] - at) / h;
    const double b = (at - x[lo]) / h;
    return a * y[lo] + b * y[hi] + ((a * a * a - a) * y2[lo] + (b * b * b - b) * y2[hi]) * (h * h) / 6.0;
  }
};

Spline file_spline(const std::vector<double>& r, const std::vector<double>& y, double slope_lo,
                   double slope_hi) {
  auto x_at = [&r](std::size_t k) { return r[k]; };
  auto y_at = [&y](std::size_t k) { return y[k]; };
  return {r, y, spline_second_derivatives(r.size(), x_at, y_at, slope_lo, slope_hi)};
}

// Spline second derivatives in s over the nodes' member `value` with end slopes d0, dn.
template <class Member>
void node_spline(std::vector<InnerTable::Node>& node, Member value, Member second, double d0, double dn) {
  auto x_at = [&node](std::size_t k) { return node[k].rsq; };
  auto y_at = [&node, value](std::size_t k) { return node[k].*value; };
  const auto y2 = spline_second_derivatives(node.size(), x_at, y_at, d0, dn);
  for (std::size_t k = 0; k < node.size(); ++k) node[k].*second = y2[k];
}

// The table, or an InputError when a value overflowed (a file value near 1e308 splined).
InnerTable check_finite(InnerTable t) {
  for (std::size_t k = 0; k < t.node.size(); ++k) {
    const auto& n = t.node[k];
    if (!std::isfinite(n.e) || !std::isfinite(n.f) || !std::isfinite(n.de) || !std::isfinite(n.df))
      throw InputError(fmt::format("the table {} gives a non-finite energy or force at r = {} Å once "
                                   "interpolated: are its values (or FPRIME) near the largest double?",
                                   t.source, std::sqrt(n.rsq)));
  }
  return t;
}

}  // namespace

InnerTable build_inner_table(const PairTableSection& s, TableInterpolation interpolation, int points,
                             double cutoff) {
  InnerTable t;
  t.source = fmt::format("{} section {}", s.path, s.keyword);
  t.cut = cutoff;
  const double rlo = s.first_r(), rhi = s.last_r();
  if (cutoff <= rlo || cutoff > rhi)
    throw InputError(fmt::format("cutoff {} Å is outside the table {}: expected rlo < cutoff <= rhi "
                                 "with rlo = {} Å, rhi = {} Å", cutoff, t.source, rlo, rhi));
  const auto n = static_cast<std::size_t>(points), last = n - 1;
  const bool match = interpolation == TableInterpolation::linear && s.r.size() == n &&
                     s.spacing == PairTableSection::Spacing::rsq && s.rhi == cutoff;
  std::optional<Spline> e_file, f_file;
  if (!match) {
    const std::size_t m = s.r.size();
    e_file.emplace(file_spline(s.r, s.e, -s.f[0], -s.f[m - 1]));
    const double fplo = s.has_fprime ? s.fplo : (s.f[1] - s.f[0]) / (s.r[1] - s.r[0]);
    const double fphi = s.has_fprime ? s.fphi : (s.f[m - 1] - s.f[m - 2]) / (s.r[m - 1] - s.r[m - 2]);
    f_file.emplace(file_spline(s.r, s.f, fplo, fphi));
  }
  t.innersq = rlo * rlo;
  t.delta = (cutoff * cutoff - t.innersq) / static_cast<double>(last);
  t.node.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    auto& node = t.node[k];
    node.rsq = t.innersq + static_cast<double>(k) * t.delta;
    const double r = std::sqrt(node.rsq);
    node.e = match ? s.e[k] : (*e_file)(r);
    node.f = match ? s.f[k] : (*f_file)(r);
    if (interpolation == TableInterpolation::linear) node.f /= r;
  }
  if (interpolation == TableInterpolation::linear) {
    for (std::size_t k = 0; k < last; ++k) {
      t.node[k].de = t.node[k + 1].e - t.node[k].e;
      t.node[k].df = t.node[k + 1].f - t.node[k].f;
    }
    return check_finite(std::move(t));
  }
  // Spline in s = r²: dE/ds = −F/(2r) at both ends.
  const double inner = std::sqrt(t.innersq);
  node_spline(t.node, &InnerTable::Node::e, &InnerTable::Node::de, -t.node[0].f / (2.0 * inner),
              -t.node[last].f / (2.0 * cutoff));
  // d(F/r)/ds at the ends: from FPRIME, else the secant over 0.1Δ of the file's spline of F.
  constexpr double secant = 0.1;
  double fp0, fpn;
  if (s.has_fprime) {
    fp0 = (s.fplo / inner - t.node[0].f / t.innersq) / (2.0 * inner);
  } else {
    const double rsq1 = t.innersq, rsq2 = rsq1 + secant * t.delta;
    fp0 = ((*f_file)(std::sqrt(rsq2)) / std::sqrt(rsq2) - t.node[0].f / std::sqrt(rsq1)) / (secant * t.delta);
  }
  if (s.has_fprime && cutoff == s.r.back()) {
    fpn = (s.fphi / cutoff - t.node[last].f / (cutoff * cutoff)) / (2.0 * cutoff);
  } else {
    const double rsq2 = cutoff * cutoff, rsq1 = rsq2 - secant * t.delta;
    fpn = (t.node[last].f / std::sqrt(rsq2) - (*f_file)(std::sqrt(rsq1)) / std::sqrt(rsq1)) / (secant * t.delta);
  }
  for (auto& node : t.node) node.f /= std::sqrt(node.rsq);
  node_spline(t.node, &InnerTable::Node::f, &InnerTable::Node::df, fp0, fpn);
  return check_finite(std::move(t));
}

namespace {

}  // namespace

// What the kernel needs of one type pair's table.
struct TablePotential::PairView {
  double cutsq, innersq, invdelta, deltasq6;
  const InnerTable::Node* node;
  int bins;  // N − 1
};

namespace {

using PairView = TablePotential::PairView;

// The node below s = r² inside the cutoff, or −1 when s lies outside the table (below r_in, in or
// past the last bin, or NaN: int(NaN) would index anywhere).
int table_bin(const PairView& p, double rsq) {
  if (!(rsq >= p.innersq)) return -1;
  const int k = static_cast<int>((rsq - p.innersq) * p.invdelta);
  return k < p.bins ? k : -1;
}

template <TableInterpolation I>
struct TableKernel {
  const PairView* views;
  const int* type;
  int ntypes;
  std::atomic<bool>* outside;

  bool operator()(int i, int j, double rsq, double& fpair, double& energy) const {
    const PairView& p = views[type[i] * ntypes + type[j]];
    if (rsq >= p.cutsq) return false;
    const int k = table_bin(p, rsq);
    if (k < 0) {
      outside->store(true, std::memory_order_relaxed);
      return false;
    }
    const InnerTable::Node& lo = p.node[k];
    if constexpr (I == TableInterpolation::linear) {
      const double fraction = (rsq - lo.rsq) * p.invdelta;
      fpair = lo.f + fraction * lo.df;
      energy = lo.e + fraction * lo.de;
    } else {
      const InnerTable::Node& hi = p.node[k + 1];
      const double b = (rsq - lo.rsq) * p.invdelta, a = 1.0 - b;
      const double ca = a * a * a - a, cb = b * b * b - b;
      fpair = a * lo.f + b * hi.f + (ca * lo.df + cb * hi.df) * p.deltasq6;
      energy = a * lo.e + b * hi.e + (ca * lo.de + cb * hi.de) * p.deltasq6;
    }
    return true;
  }
};

}  // namespace

TablePotential::TablePotential(TableInterpolation interpolation, int ntypes,
                               std::vector<InnerTable> tables, std::vector<int> pair_table)
    : interpolation_(interpolation), ntypes_(ntypes), tables_(std::move(tables)),
      pair_table_(std::move(pair_table)) {
  for (const auto& t : tables_) cutoff_ = std::max(cutoff_, t.cut);
}

void TablePotential::check_types(const Atoms& atoms) const {
  if (atoms.ntypes() != ntypes_)
    throw InputError(fmt::format("pair style table: tables for {} atom types, the atoms have {}",
                                 ntypes_, atoms.ntypes()));
}

std::vector<TablePotential::PairView> TablePotential::views() const {
  std::vector<PairView> views;
  for (const int t : pair_table_) {
    const InnerTable& table = tables_[static_cast<std::size_t>(t)];
    views.push_back({table.cut * table.cut, table.innersq, 1.0 / table.delta,
                     table.delta * table.delta / 6.0, table.node.data(),
                     static_cast<int>(table.node.size()) - 1});
  }
  return views;
}

void TablePotential::compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) {
  const std::vector<PairView> views = this->views();
  outside_.store(false);
  if (interpolation_ == TableInterpolation::linear)
    accumulate_pair_forces(atoms, list, TableKernel<TableInterpolation::linear>{views.data(), atoms.type.data(), ntypes_, &outside_}, out, scratch_);
  else
    accumulate_pair_forces(atoms, list, TableKernel<TableInterpolation::spline>{views.data(), atoms.type.data(), ntypes_, &outside_}, out, scratch_);
  if (outside_.load()) fail_outside_table(atoms, list, views);
}

void TablePotential::fail_outside_table(const Atoms& atoms, const geometry::NeighborList& list,
                                        const std::vector<PairView>& views) const {
  for (std::size_t i = 0; i < list.nlocal(); ++i) {
    for (auto k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(list.neighbors[static_cast<std::size_t>(k)]);
      const double rsq = (atoms.x[i] - atoms.x[j]).squaredNorm();
      const int ti = atoms.type[i], tj = atoms.type[j];
      const auto pair = static_cast<std::size_t>(ti * ntypes_ + tj);
      if (rsq >= views[pair].cutsq || table_bin(views[pair], rsq) >= 0) continue;
      const InnerTable& t = tables_[static_cast<std::size_t>(pair_table_[pair])];
      throw RunError(fmt::format(
          "pair style table: atoms {} and {} (types {} {}) are {} Å apart, outside the table {} "
          "(it covers {} to {} Å; LAMMPS stops with \"Pair distance < table inner cutoff\")",
          atoms.id[i], atoms.id[j], ti + 1, tj + 1, std::sqrt(rsq), t.source, std::sqrt(t.innersq), t.cut));
    }
  }
  throw RunError("pair style table: a pair distance fell outside its table");
}

}  // namespace shockfield::md::potentials

#pragma once
// Rheological statistics of a field (Xu et al. 2015, §3.1, scheme (ii)): spatial correlation function,
// structure factor S(k) and the characteristic domain size R from its first moment. The field is
// taken as periodic; void cells count as the mean (δΘ = 0).
#include <vector>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// A radially averaged function: values[i] at radius (or |k|) x[i] from count[i] grid points.
struct RadialProfile {
  std::vector<double> x;
  std::vector<double> values;
  std::vector<std::size_t> count;
};

/// S(k) = |Σ_x δΘ(x) e^{−ik·x}|² / N, averaged over shells |k| ∈ [(j − ½)Δk, (j + ½)Δk),
/// Δk = 2π / (longest box side), j ≥ 1 (k = 0 left out); x[i] is the mean |k| of the shell.
RadialProfile structure_factor(const GridFieldView& field);

/// C(r) = ⟨δΘ(x) δΘ(x + r)⟩ / ⟨δΘ²⟩ (C(0) = 1), over periodic separations, averaged in shells of
/// width one grid spacing (smallest spacing); x[i] is the mean |r| of the shell.
RadialProfile correlation_function(const GridFieldView& field);

/// Characteristic domain size R = 2π / k₁ with k₁ = Σ_k |k| S(k) / Σ_k S(k), the first moment of
/// the structure factor over every wave vector k ≠ 0 (not the shell averages). InputError if the
/// field is constant.
double characteristic_size(const GridFieldView& field);

}  // namespace shockfield::analysis

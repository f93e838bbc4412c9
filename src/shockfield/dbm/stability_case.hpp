#pragma once
// The linear stability check of a dbm case before it runs (linear_stability.hpp; docs/dbm.md,
// [model] stability_check): the von Neumann analysis of the scheme about every uniform state the
// case is made of or heads for — the [initial] states, inflow states, the exact star states of a
// Riemann start, the CJ and von Neumann states of a [reaction] — refusing (or warning about) a
// set-up that amplifies perturbations, with the growth rate and what to change.
// The GLS model (non-ideal force, kind = "gls") is not covered: the analysis is of BGK only.
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/dbm/case_file.hpp"
#include "shockfield/dbm/linear_stability.hpp"

namespace shockfield::dbm {

/// Default-constructed: not checked (what a GLS case records).
struct CaseStability {
  std::string mode = "off";             ///< "error", "warn" or "off" ([model] stability_check)
  std::string verdict = "not checked";  ///< "stable", "unstable" or "not checked"
  std::string worst_state;
  StabilityReport worst;  ///< the report of the state with the largest growth rate
  double stable_dt = 0.0;  ///< the smallest stable_dt over the states
};

/// Reads [model] stability_check and analyses the states of `c` (read completely, but for this
/// check). "error": an unstable state is an InputError on model.stability_check naming the state,
/// the growth rate and the remedy; "warn": the same message on stderr.
CaseStability check_case_stability(const Config& model, const DbmCase& c);

/// linear_stability_* keys of [derived].
void derive_stability(const Config& root, const CaseStability& s);

}  // namespace shockfield::dbm

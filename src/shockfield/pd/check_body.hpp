#pragma once
// The sub-body `shockfield run --check` builds a pd model on (run_case.cpp): small enough to check
// quickly, large enough to hold every kind of point of the whole body.
#include "shockfield/pd/case_file.hpp"

namespace shockfield::pd {

/// The body --check builds the model on (the whole body for a points file).
BodySpec checked_body(const BodySpec& body);
/// Whether a sub-body of checked_body has every kind of point of the body (else its stable step is
/// an estimate).
bool holds_every_kind(const BodySpec& sub, const BodySpec& body);

}  // namespace shockfield::pd

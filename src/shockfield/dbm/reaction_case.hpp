#pragma once
// The optional [reaction] table of a dbm case file: the one-step reactive DBM (reaction.hpp) with
// its rate law, heat release and the ZND-like ignition start (docs/dbm.md, "Detonation").
#include <optional>

#include "shockfield/core/config.hpp"
#include "shockfield/dbm/case_file.hpp"

namespace shockfield::dbm {

/// Reads [reaction] when present (after the rest of the case); InputError naming the key.
std::optional<ReactionSpec> read_reaction(const Config& root, const DbmCase& c);

/// CJ speed, CJ and von Neumann states into [derived].
void derive_reaction(const Config& root, const ReactionSpec& spec);

}  // namespace shockfield::dbm

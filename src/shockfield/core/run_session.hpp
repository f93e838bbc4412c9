#pragma once
// The opening every method's run makes once its case file validated: the run folder (created,
// emptied with --overwrite, or reopened with --resume), log.txt with a header line and the
// provenance lines, and config.resolved.toml (a resumed run keeps the one it started with unless
// it accepted a changed case).
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/logger.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield {

struct RunSession {
  std::filesystem::path folder;
  std::filesystem::path checkpoint;  ///< folder/checkpoint.h5
  Logger log;
};

/// The checkpoint file of a run folder.
std::filesystem::path run_session_checkpoint(const std::filesystem::path& folder);

/// `method` names the method in the header line, `summary` its size ("12800 atoms");
/// `provenance` lines follow the header; `rewrite_resolved`: a resumed run writes
/// config.resolved.toml anew.
RunSession open_run_session(const Config& root, const RunOptions& options, const std::string& method,
                            const std::string& summary, const std::vector<std::string>& provenance,
                            bool rewrite_resolved);

}  // namespace shockfield

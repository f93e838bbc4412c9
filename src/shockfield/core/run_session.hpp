#pragma once
// The opening every method's run makes once its case file validated: the run folder (created,
// emptied with --overwrite, or reopened with --resume), log.txt with a header line, and
// config.resolved.toml (a resumed run keeps the one it started with).
#include <filesystem>
#include <string>

#include "shockfield/core/config.hpp"
#include "shockfield/core/logger.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield {

struct RunSession {
  std::filesystem::path folder;
  std::filesystem::path checkpoint;  ///< folder/checkpoint.h5
  Logger log;
};

/// `method` names the method in the header line, `summary` its size ("12800 atoms").
RunSession open_run_session(const Config& root, const RunOptions& options, const std::string& method,
                            const std::string& summary);

}  // namespace shockfield

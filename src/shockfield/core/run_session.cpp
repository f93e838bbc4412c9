#include "shockfield/core/run_session.hpp"

#include <fmt/format.h>
#include <omp.h>

#include "shockfield/core/run_folder.hpp"

namespace shockfield {

std::filesystem::path run_session_checkpoint(const std::filesystem::path& folder) { return folder / "checkpoint.h5"; }

RunSession open_run_session(const Config& root, const RunOptions& options, const std::string& method,
                            const std::string& summary, const std::vector<std::string>& provenance,
                            bool rewrite_resolved) {
  const std::filesystem::path folder = run_folder_path(options);
  prepare_run_folder(folder, options);
  RunSession s{folder, run_session_checkpoint(folder), Logger(folder / "log.txt", !options.quiet, options.resume)};
  s.log.info("shockfield {} {}: {} ({}, {} threads) -> {}", SHOCKFIELD_VERSION, method, options.case_file.string(),
             summary, omp_get_max_threads(), folder.string());
  for (const std::string& line : provenance) s.log.info("provenance: {}", line);
  if (!options.resume || rewrite_resolved) write_file_atomically(folder / "config.resolved.toml", root.resolved_toml());
  return s;
}

}  // namespace shockfield

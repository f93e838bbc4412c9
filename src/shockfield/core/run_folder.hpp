#pragma once
// The run folder: created only after the case file validated, so a bad case leaves nothing
// behind. Refuses to overwrite an existing folder unless asked to.
#include <filesystem>

#include "shockfield/core/run_options.hpp"

namespace shockfield {

/// The folder a run writes to: --output, else runs/<case file stem>.
std::filesystem::path run_folder_path(const RunOptions& options);
/// Creates (or, with --overwrite, empties) the folder; with --resume it must exist.
void prepare_run_folder(const std::filesystem::path& folder, const RunOptions& options);
/// Writes text to `file` through a temporary file and a rename (never half-written); every
/// write checked (io/checked_file): RunError naming the file when one fails.
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace shockfield

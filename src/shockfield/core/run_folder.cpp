#include "shockfield/core/run_folder.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checked_file.hpp"

namespace shockfield {

// runs/<case file name>, except that a case file called case.toml (every example's) is named
// by its folder, so that two examples run from one place do not share runs/case.
std::filesystem::path run_folder_path(const RunOptions& options) {
  if (options.output) return *options.output;
  const std::filesystem::path& file = options.case_file;
  std::filesystem::path name = file.stem();
  if (name == "case") {
    const auto folder = std::filesystem::absolute(file).lexically_normal().parent_path().filename();
    if (!folder.empty()) name = folder;
  }
  return std::filesystem::path("runs") / name;
}

void prepare_run_folder(const std::filesystem::path& folder, const RunOptions& options) {
  namespace fs = std::filesystem;
  if (options.resume) {
    if (!fs::is_directory(folder))
      throw InputError(fmt::format("--resume: run folder '{}' does not exist", folder.string()));
    return;
  }
  if (fs::exists(folder)) {
    if (!options.overwrite)
      throw InputError(fmt::format("run folder '{}' exists; pass --overwrite to replace it, "
                                   "--resume to continue it, or --output to choose another",
                                   folder.string()));
    fs::remove_all(folder);
  }
  fs::create_directories(folder);
}

void write_file_atomically(const std::filesystem::path& file, const std::string& text) {
  io::replace_file(file, text);
}

}  // namespace shockfield

#include "shockfield/app/analyze_atoms_inputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/io/extxyz.hpp"
#include "shockfield/io/lammps_data.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;
namespace aa = shockfield::analysis::atoms;

// A .gz file decompressed by the system's gzip (gzip -dc) into memory (the readers hold every
// frame in memory anyway).
std::string gunzip(const fs::path& file) {
  const std::string name = file.string();
  if (name.find('\'') != std::string::npos)
    throw InputError(fmt::format("{}: a .gz file name with a quote cannot be passed to gzip; rename it", name));
  FILE* pipe = popen(("gzip -dc -- '" + name + "' 2>/dev/null").c_str(), "r");
  if (!pipe) throw InputError(fmt::format("{}: cannot start gzip to decompress it", name));
  std::string text;
  char buffer[1 << 16];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, got);
  if (pclose(pipe) != 0)
    throw InputError(fmt::format("{}: gzip -dc failed: not a gzip file, or a truncated or corrupt one", name));
  return text;
}

bool looks_like_dump(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot be opened for reading", file.string()));
  std::string line;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) return line.rfind("ITEM:", 0) == 0;
  throw InputError(fmt::format("{}: the file is empty", file.string()));
}

// The name without a trailing .gz.
fs::path without_gz(const fs::path& file) { return file.extension() == ".gz" ? file.stem() : file.filename(); }

bool is_extxyz_name(const fs::path& file) {
  const fs::path ext = without_gz(file).extension();
  return ext == ".xyz" || ext == ".extxyz";
}

// The step number of a run folder's dumps/dump.<step>.<ext>, for ordering.
long long step_of(const fs::path& file) {
  const std::string name = file.filename().string();
  const auto first = name.find('.'), second = name.find('.', first + 1);
  try {
    return std::stoll(name.substr(first + 1, second - first - 1));
  } catch (const std::exception&) {
    return -1;
  }
}

std::vector<InputFile> run_folder_frames(const fs::path& folder) {
  const fs::path dumps = folder / "dumps";
  if (!fs::is_directory(dumps))
    throw InputError(fmt::format("{}: a folder but not a shockfield MD run folder (no dumps/ inside)", folder.string()));
  std::vector<fs::path> series, xyz;
  for (const auto& e : fs::directory_iterator(dumps)) {
    if (e.path().extension() == ".lammpstrj") series.push_back(e.path());
    if (e.path().extension() == ".xyz") xyz.push_back(e.path());
  }
  if (!series.empty() && !xyz.empty())
    throw InputError(fmt::format("{}: dumps/ holds both dump.*.lammpstrj and dump.*.xyz frames; give the files "
                                 "of one series", folder.string()));
  const InputKind kind = series.empty() ? InputKind::extxyz : InputKind::dump;
  if (series.empty()) series = std::move(xyz);
  if (series.empty())
    throw InputError(fmt::format("{}: no dumps/dump.*.lammpstrj or dumps/dump.*.xyz in the run folder", folder.string()));
  std::sort(series.begin(), series.end(), [](const fs::path& x, const fs::path& y) { return step_of(x) < step_of(y); });
  std::vector<InputFile> files;
  for (const auto& f : series) files.push_back({f, kind});
  return files;
}

}  // namespace

std::vector<InputFile> expand_inputs(const std::vector<std::string>& inputs, const std::string& format) {
  std::vector<InputFile> files;
  for (const std::string& input : inputs) {
    const fs::path path(input);
    if (fs::is_directory(path)) {
      for (InputFile& f : run_folder_frames(path)) files.push_back(std::move(f));
      continue;
    }
    InputKind kind = InputKind::dump;
    if (format == "data") kind = InputKind::data;
    else if (format == "extxyz" || (format == "auto" && is_extxyz_name(path))) kind = InputKind::extxyz;
    else if (format == "auto" && path.extension() != ".gz" && !looks_like_dump(path)) kind = InputKind::data;
    if (kind == InputKind::data && path.extension() == ".gz")
      throw InputError(fmt::format("{}: data files are read uncompressed; decompress it first", input));
    files.push_back({path, kind});
  }
  return files;
}

aa::AtomFrame InputFrames::frame(std::size_t f) const {
  if (data_frame) return *data_frame;
  return aa::frame_from_dump(dumps[f], sources[f]);
}

InputFrames read_input(const InputFile& input, const std::array<geometry::Boundary, 3>& data_boundary) {
  const std::string source = input.path.string();
  InputFrames out;
  if (input.kind == InputKind::data) {
    const io::DataFile data = io::read_data(input.path, data_boundary);
    out.dumps.push_back(io::make_dump_frame(0, data.box, data.atoms, {"id", "type", "x", "y", "z"}));
    out.dumps.back().source = source;  // messages about the frame name the data file
    out.sources.push_back(source);
    aa::AtomFrame frame = aa::frame_from_atoms(0, data.box, data.atoms, source);
    out.data_frame = std::move(frame);
    return out;
  }
  const bool gz = input.path.extension() == ".gz";
  std::istringstream text(gz ? gunzip(input.path) : std::string());
  if (input.kind == InputKind::extxyz) {
    std::vector<int> lines;
    out.dumps = gz ? io::read_extxyz(text, source, &lines) : io::read_extxyz(input.path, &lines);
    for (int line : lines) out.sources.push_back(fmt::format("{}:{}", source, line));
  } else {
    out.dumps = gz ? io::read_dump(text, source) : io::read_dump(input.path);
    out.sources.assign(out.dumps.size(), source);
  }
  if (out.dumps.empty()) throw InputError(fmt::format("{}: no frame in the file", source));
  return out;
}

fs::path output_name(const InputFile& input) {
  fs::path name = without_gz(input.path);  // written uncompressed
  if (input.kind != InputKind::dump) name.replace_extension(".dump");
  return name;
}

}  // namespace shockfield::app

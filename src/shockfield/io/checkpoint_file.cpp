#include "shockfield/io/checkpoint_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "shockfield/core/error.hpp"
#include "shockfield/core/provenance.hpp"
#include "shockfield/core/sha256.hpp"
#include "shockfield/io/checked_file.hpp"

namespace shockfield::io {
namespace {

constexpr const char* kChecksum = "checksum";
constexpr const char* kItems = "checksum_items";
constexpr const char* kFormat = "shockfield checkpoint";

// The case texts of the running case (CheckpointCaseScope): runs in one process follow each
// other (hugoniot sweeps, Python) and nest their scopes; parallel sweeps are separate processes.
CheckpointCaseScope::Texts& current_case() {
  static CheckpointCaseScope::Texts texts;
  return texts;
}

// The whole-file checksum: a trailer after the HDF5 image, "<tag><16 hex digits>\n", the FNV-1a
// hash of every byte before it. It is checked before libhdf5 parses anything: HDF5 trusts its own
// metadata, and a damaged file can make it read out of bounds (ASan, the sanitized parser fuzzer:
// a byte flipped inside an object header, seed 11 mutant 46). HDF5 ignores bytes past its
// end-of-file address, so the file stays an ordinary HDF5 file for h5dump and h5py.
constexpr std::string_view kTrailerTag = "\nshockfield checkpoint fnv1a64 ";
constexpr std::size_t kTrailerSize = kTrailerTag.size() + 16 + 1;

std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;  // FNV-1a 64-bit prime
  return hash;
}
constexpr std::uint64_t kFnvBasis = 14695981039346656037ull;  // FNV-1a 64-bit offset basis

std::string trailer(std::uint64_t hash) { return fmt::format("{}{:016x}\n", kTrailerTag, hash); }

// Reads the file once, in blocks, and compares the hash of its contents with its trailer.
void verify_trailer(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code error;
  const auto size = std::filesystem::file_size(file, error);
  if (!in || error) throw InputError(fmt::format("{}: cannot read the checkpoint", file.string()));
  const auto damaged = [&](const std::string& why) {
    return InputError(fmt::format("{}: damaged or truncated checkpoint ({}); it cannot be used for --resume",
                                  file.string(), why));
  };
  if (size < kTrailerSize) throw damaged("shorter than its checksum trailer");
  std::uint64_t hash = kFnvBasis;
  std::vector<char> block(1 << 20);
  for (std::uintmax_t left = size - kTrailerSize; left > 0;) {
    const auto n = static_cast<std::size_t>(std::min<std::uintmax_t>(left, block.size()));
    if (!in.read(block.data(), static_cast<std::streamsize>(n))) throw damaged("it ends while being read");
    hash = fnv1a(hash, block.data(), n);
    left -= n;
  }
  std::string stored(kTrailerSize, '\0');
  if (!in.read(stored.data(), static_cast<std::streamsize>(kTrailerSize))) throw damaged("it ends in its trailer");
  if (stored.compare(0, kTrailerTag.size(), kTrailerTag) != 0)
    throw damaged("no whole-file checksum trailer; written by a shockfield older than 2026-12-02, or cut short");
  if (stored != trailer(hash))
    throw damaged(fmt::format("whole-file checksum {:016x}, trailer says {}", hash,
                              stored.substr(kTrailerTag.size(), 16)));
}

Hdf5File open_checkpoint(const std::filesystem::path& file) {
  verify_trailer(file);
  try {
    return Hdf5File(file, Hdf5File::Mode::read);
  } catch (const InputError&) {
    throw InputError(fmt::format("{}: damaged or truncated checkpoint (not a readable HDF5 file)", file.string()));
  }
}

// Recomputes the checksum of an open checkpoint from its item list.
std::string recompute(const Hdf5File& h5) {
  PayloadChecksum sum;
  std::istringstream items(h5.string_attribute(kItems));
  std::string line;
  while (std::getline(items, line)) {
    if (line.size() < 3 || line[1] != ' ') throw InputError(fmt::format("{}: bad checksum item list", h5.path()));
    const char kind = line[0];
    const std::string name = line.substr(2);
    if (kind == 'f') {
      const double v = h5.attribute(name);
      sum.add(kind, name, &v, sizeof v);
    } else if (kind == 'n') {
      const std::int64_t v = h5.int_attribute(name);
      sum.add(kind, name, &v, sizeof v);
    } else if (kind == 's') {
      const std::string v = h5.string_attribute(name);
      sum.add(kind, name, v.data(), v.size());
    } else if (kind == 'u') {
      const std::string v = h5.units(name);
      sum.add(kind, name, v.data(), v.size());
    } else if (kind == 'd') {
      const auto v = h5.read_doubles(name);
      sum.add(kind, name, v.data(), v.size() * sizeof(double));
    } else if (kind == 'i') {
      const auto v = h5.read_ints(name);
      sum.add(kind, name, v.data(), v.size() * sizeof(std::int64_t));
    } else {
      throw InputError(fmt::format("{}: bad checksum item kind '{}'", h5.path(), kind));
    }
  }
  return sum.hex();
}

void verify(const Hdf5File& h5) {
  if (!h5.has_attribute(kChecksum) || !h5.has_attribute(kItems))
    throw InputError(fmt::format("{}: checkpoint has no checksum (damaged, or written by a shockfield older than "
                                 "checksummed checkpoints); it cannot be trusted for --resume",
                                 h5.path()));
  std::string computed;
  try {
    computed = recompute(h5);
  } catch (const InputError& e) {
    throw InputError(fmt::format("damaged or truncated checkpoint: {}", e.what()));
  }
  const std::string stored = h5.string_attribute(kChecksum);
  if (computed != stored)
    throw InputError(fmt::format("{}: damaged checkpoint: checksum {} of its contents, {} stored", h5.path(), computed,
                                 stored));
}

}  // namespace

void PayloadChecksum::mix(const void* data, std::size_t bytes) { hash_ = fnv1a(hash_, data, bytes); }

void PayloadChecksum::add(char kind, const std::string& name, const void* data, std::size_t bytes) {
  items_ += fmt::format("{} {}\n", kind, name);
  mix(&kind, 1);
  mix(name.data(), name.size() + 1);  // with its terminating NUL, so names cannot run into data
  const auto count = static_cast<std::uint64_t>(bytes);
  mix(&count, sizeof count);
  mix(data, bytes);
}

std::string PayloadChecksum::hex() const { return fmt::format("{:016x}", hash_); }

CheckpointCaseScope::CheckpointCaseScope(Texts texts) : previous_(std::move(current_case())) {
  current_case() = std::move(texts);
}
CheckpointCaseScope::~CheckpointCaseScope() { current_case() = std::move(previous_); }

CheckpointWriter::CheckpointWriter(std::filesystem::path file, const std::string& method, std::int64_t format_version)
    : file_(std::move(file)), h5_(file_, Hdf5File::Mode::memory) {
  set_attribute("format", std::string(kFormat));
  set_attribute("method", method);
  set_count("format_version", format_version);
  set_attribute("shockfield_version", shockfield_version());
  set_attribute("git_commit", shockfield_git_commit());
  set_attribute("case", current_case().resolved);
  set_attribute("case_sha256", sha256_hex(current_case().resolved));
  set_attribute("case_input", current_case().input);
}

void CheckpointWriter::set_attribute(const std::string& name, double value) {
  h5_.set_attribute(name, value);
  sum_.add('f', name, &value, sizeof value);
}

void CheckpointWriter::set_attribute(const std::string& name, const std::string& value) {
  h5_.set_attribute(name, value);
  sum_.add('s', name, value.data(), value.size());
}

void CheckpointWriter::set_count(const std::string& name, std::int64_t value) {
  h5_.set_int_attribute(name, value);
  sum_.add('n', name, &value, sizeof value);
}

void CheckpointWriter::write(const std::string& name, const std::string& units, const std::vector<double>& data,
                             std::vector<hsize_t> shape) {
  h5_.write(name, data, std::move(shape), units);
  sum_.add('d', name, data.data(), data.size() * sizeof(double));
  sum_.add('u', name, units.data(), units.size());
}

void CheckpointWriter::write(const std::string& name, const std::string& units, const std::vector<std::int64_t>& data,
                             std::vector<hsize_t> shape) {
  h5_.write(name, data, std::move(shape), units);
  sum_.add('i', name, data.data(), data.size() * sizeof(std::int64_t));
  sum_.add('u', name, units.data(), units.size());
}

void CheckpointWriter::commit() {
  h5_.set_attribute(kItems, sum_.items());
  h5_.set_attribute(kChecksum, sum_.hex());
  const std::vector<unsigned char> bytes = h5_.image();
  h5_.close();
  const std::filesystem::path tmp = file_.string() + ".tmp";
  try {
    const std::string_view contents(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::string end = trailer(fnv1a(kFnvBasis, bytes.data(), bytes.size()));
    const std::string_view parts[] = {contents, end};
    write_file_checked(tmp, parts, true);
  } catch (const RunError& e) {
    throw RunError(fmt::format("{}: cannot write the checkpoint ({}); the previous checkpoint is kept", file_.string(),
                               e.what()));
  }
  try {
    verify(open_checkpoint(tmp));
  } catch (const InputError& e) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw RunError(fmt::format("{}: the new checkpoint did not read back ({}); the previous one is kept",
                               file_.string(), e.what()));
  }
  rename_checked(tmp, file_, true);
}

CheckpointReader::CheckpointReader(const std::filesystem::path& file) : h5_(open_checkpoint(file)) { verify(h5_); }

std::int64_t CheckpointReader::count(const std::string& name) const {
  const std::int64_t v = h5_.int_attribute(name);
  if (v < 0) throw InputError(fmt::format("{}: attribute '{}' = {} is not a count (negative)", h5_.path(), name, v));
  return v;
}

std::string CheckpointReader::method() const {
  return h5_.has_attribute("method") ? h5_.string_attribute("method") : std::string();
}

std::string CheckpointReader::input_case() const {
  const std::string text = h5_.has_attribute("case_input") ? h5_.string_attribute("case_input") : std::string();
  if (text.empty())
    throw InputError(fmt::format("{}: the checkpoint does not hold the case it was written with (`case_input`: "
                                 "written before 2026-12-03 or outside a run), so --resume cannot check the case; "
                                 "resume it with the shockfield that wrote it, or start a new run",
                                 h5_.path()));
  return text;
}

void CheckpointReader::require(const std::string& method, std::int64_t version) const {
  const std::string found = this->method();
  if (!found.empty() && found != method)
    throw InputError(fmt::format("{}: a {} checkpoint, not a {} one", h5_.path(), found, method));
  const double stored = h5_.has_attribute("format_version") ? h5_.attribute("format_version") : 0;
  const bool described = h5_.has_attribute("format") && h5_.string_attribute("format") == kFormat;
  if (described && stored == static_cast<double>(version)) return;
  if (!described || stored < static_cast<double>(version))
    throw InputError(fmt::format("{}: {} checkpoint format {} is older than the supported {} (written before "
                                 "self-describing checkpoints, docs/checkpoints.md); resume it with the shockfield "
                                 "that wrote it, or start a new run",
                                 h5_.path(), method, stored, version));
  throw InputError(fmt::format("{}: {} checkpoint format {} is newer than the supported {}; use the shockfield that "
                               "wrote it",
                               h5_.path(), method, stored, version));
}

}  // namespace shockfield::io

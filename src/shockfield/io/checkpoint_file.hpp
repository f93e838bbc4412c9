#pragma once
// The one way every method writes and reads its checkpoint (HDF5, io/hdf5_file):
//
//   write: the file is built in memory, with a 64-bit FNV-1a checksum over every attribute and
//          dataset (name, length and bytes, in the order written) stored as the attributes
//          `checksum` and `checksum_items`; its bytes, then a trailer holding the FNV-1a hash of
//          the whole image, go to <file>.tmp with checked writes and an fsync; the temporary
//          file is read back and both checksums verified; only then is it renamed over <file>
//          and the folder fsynced. Until that rename the previous checkpoint is untouched; on
//          any failure the temporary file is removed and RunError names it (exit 3).
//   read:  the trailer's whole-file hash is verified before libhdf5 parses the file (a damaged
//          file must not reach HDF5's metadata parser), then the file is opened and its item
//          checksum verified before anything is used; a truncated or damaged checkpoint (or
//          one written without checksums) is refused by name with InputError (exit 2), never
//          read as zeros.
//
// Self-description (docs/checkpoints.md): the writer stores on the root group `format`
// ("shockfield checkpoint"), `method`, `format_version` (an integer, one sequence per method),
// `shockfield_version`, `git_commit`, the resolved case of the run that wrote it (`case`, the
// text of its config.resolved.toml), `case_sha256`, and `case_input` (the case as read, after
// --set, which `--resume` compares with the case it is given); every dataset is one named quantity
// with a `units` attribute; counters (steps, rows written, ids) are integers.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/io/hdf5_file.hpp"

namespace shockfield::io {

/// Checksum over the items of a checkpoint (FNV-1a, 64 bit: Fowler, Noll and Vo's hash).
class PayloadChecksum {
 public:
  /// Adds one item: its kind letter and name, its byte count, its bytes.
  void add(char kind, const std::string& name, const void* data, std::size_t bytes);
  std::string hex() const;
  const std::string& items() const { return items_; }

 private:
  void mix(const void* data, std::size_t bytes);
  std::uint64_t hash_ = 14695981039346656037ull;  // FNV-1a 64-bit offset basis
  std::string items_;                             // "<kind> <name>\n" per item, in order
};

/// The case texts stored in every checkpoint written while a CheckpointCaseScope is alive (the run
/// driver holds one around each save): `case` (the resolved case) and `case_input` (the case as
/// read). Outside one (unit tests) both attributes are empty.
class CheckpointCaseScope {
 public:
  struct Texts {
    std::string resolved;
    std::string input;
  };
  explicit CheckpointCaseScope(Texts texts);
  ~CheckpointCaseScope();
  CheckpointCaseScope(const CheckpointCaseScope&) = delete;
  CheckpointCaseScope& operator=(const CheckpointCaseScope&) = delete;

 private:
  Texts previous_;
};

class CheckpointWriter {
 public:
  /// Starts a checkpoint of `method` in its layout `format_version` (the self-describing
  /// attributes above are written here).
  CheckpointWriter(std::filesystem::path file, const std::string& method, std::int64_t format_version);
  /// A real-valued attribute (a time, a time step, an accumulated energy).
  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, const std::string& value);
  /// An integer attribute: a step, a number of rows or frames written, an index.
  void set_count(const std::string& name, std::int64_t value);
  /// One named quantity and its unit ("m", "m/s", "Pa", "1" for a pure number or a model unit).
  void write(const std::string& name, const std::string& units, const std::vector<double>& data,
             std::vector<hsize_t> shape = {});
  void write(const std::string& name, const std::string& units, const std::vector<std::int64_t>& data,
             std::vector<hsize_t> shape = {});
  /// Writes, verifies and renames (see the top of this file). Nothing reaches `file` before.
  void commit();

 private:
  std::filesystem::path file_;
  Hdf5File h5_;
  PayloadChecksum sum_;
};

class CheckpointReader {
 public:
  /// Opens `file` and verifies its checksum; InputError naming the file when it does not match.
  explicit CheckpointReader(const std::filesystem::path& file);
  const Hdf5File& h5() const { return h5_; }
  /// A step or row count: an integer attribute ≥ 0, else InputError naming the file and the
  /// attribute.
  std::int64_t count(const std::string& name) const;
  /// The `method` attribute ("" for a checkpoint older than self-describing ones).
  std::string method() const;
  /// The case as read by the run that wrote it (`case_input`); InputError naming the file when the
  /// checkpoint has none (written before 2026-12-03, or outside a run).
  std::string input_case() const;
  /// InputError naming the file unless it is a checkpoint of `method` in layout `version`; an
  /// older layout is named with its version and what to do.
  void require(const std::string& method, std::int64_t version) const;

 private:
  Hdf5File h5_;
};

}  // namespace shockfield::io

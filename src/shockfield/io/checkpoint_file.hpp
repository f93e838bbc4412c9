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

class CheckpointWriter {
 public:
  explicit CheckpointWriter(std::filesystem::path file);
  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, const std::string& value);
  void write(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> shape = {});
  void write(const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> shape = {});
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
  /// A step or row count stored as a double attribute: a whole number in [0, 2^53] (the
  /// doubles that convert to an integer exactly), else InputError naming the file and the
  /// attribute — never an unclamped cast of NaN or 1e300.
  std::int64_t count(const std::string& name) const;
  /// InputError naming the file unless its `format_version` attribute is `version`.
  void require_format(double version) const;

 private:
  Hdf5File h5_;
};

}  // namespace shockfield::io

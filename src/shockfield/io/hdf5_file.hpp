#pragma once
// Minimal RAII wrapper over the HDF5 C API for checkpoints: flat datasets of doubles and 64-bit
// integers with a shape and an optional `units` string attribute, and scalar attributes (double,
// 64-bit integer, string) on the root group. Every H5* return code is
// tested: a failed write or close throws RunError, a failed read InputError, each naming the
// file. Checkpoints are built in memory (Mode::memory) and written to disk by
// io/checkpoint_file with checked POSIX calls, so libhdf5 itself never meets a full disk.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shockfield::io {

class Hdf5File {
 public:
  enum class Mode { read, create, memory };
  /// `memory`: an in-memory file (`file` only names it in messages), read back with image().
  Hdf5File(const std::filesystem::path& file, Mode mode);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  /// `units` non-empty: stored as the dataset's string attribute `units`.
  void write(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> shape = {},
             const std::string& units = "");
  void write(const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> shape = {},
             const std::string& units = "");
  std::vector<double> read_doubles(const std::string& name) const;
  std::vector<std::int64_t> read_ints(const std::string& name) const;
  bool has(const std::string& name) const;
  /// The dataset's `units` attribute; InputError naming the file and dataset when it has none.
  std::string units(const std::string& name) const;
  /// Whether a dataset holds integers (read_ints) rather than reals.
  bool is_integer(const std::string& name) const;
  /// The shape of a dataset (its dimensions, slowest first).
  std::vector<hsize_t> shape(const std::string& name) const;
  /// The datasets of the root group, in name order.
  std::vector<std::string> dataset_names() const;

  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, const std::string& value);
  void set_int_attribute(const std::string& name, std::int64_t value);
  bool has_attribute(const std::string& name) const;
  /// A numeric attribute as a double (an integer one converted).
  double attribute(const std::string& name) const;
  /// An attribute stored as an integer; InputError when it is stored as a real or a string.
  std::int64_t int_attribute(const std::string& name) const;
  std::string string_attribute(const std::string& name) const;

  /// The bytes of the whole file as it would be on disk (flushed first).
  std::vector<unsigned char> image() const;
  /// Closes the file; RunError when HDF5 cannot (the destructor closes silently instead).
  void close();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  hid_t file_ = -1;
  std::uintmax_t bytes_on_disk_ = 0;  ///< read mode: no dataset or attribute can be larger
};

}  // namespace shockfield::io

#pragma once
// Minimal RAII wrapper over the HDF5 C API for checkpoints: flat datasets of doubles and 64-bit
// integers with a shape, and scalar attributes on the root group. Every H5* return code is
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

  void write(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> shape = {});
  void write(const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> shape = {});
  std::vector<double> read_doubles(const std::string& name) const;
  std::vector<std::int64_t> read_ints(const std::string& name) const;
  bool has(const std::string& name) const;

  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, const std::string& value);
  bool has_attribute(const std::string& name) const;
  double attribute(const std::string& name) const;
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

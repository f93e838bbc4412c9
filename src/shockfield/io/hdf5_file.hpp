#pragma once
// Minimal RAII wrapper over the HDF5 C API for checkpoints: flat datasets of doubles and 64-bit
// integers with a shape, and scalar attributes on the root group.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shockfield::io {

class Hdf5File {
 public:
  enum class Mode { read, create };
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
  double attribute(const std::string& name) const;
  std::string string_attribute(const std::string& name) const;

 private:
  std::string path_;
  hid_t file_ = -1;
};

}  // namespace shockfield::io

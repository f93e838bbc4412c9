#include "shockfield/io/hdf5_file.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::io {
namespace {
template <class T>
void write_dataset(hid_t file, const std::string& path, const std::string& name, const std::vector<T>& data,
                   std::vector<hsize_t> shape, hid_t type) {
  if (shape.empty()) shape = {static_cast<hsize_t>(data.size())};
  const hid_t space = H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr);
  const hid_t set = H5Dcreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = set < 0 ? -1 : H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  if (status < 0) throw RunError(fmt::format("{}: cannot write dataset '{}'", path, name));
}

template <class T>
std::vector<T> read_dataset(hid_t file, const std::string& path, const std::string& name, hid_t type) {
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw InputError(fmt::format("{}: checkpoint has no dataset '{}'", path, name));
  const hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<std::size_t>(n));
  const herr_t status = H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(set);
  if (status < 0) throw InputError(fmt::format("{}: cannot read dataset '{}'", path, name));
  return out;
}
}  // namespace

Hdf5File::Hdf5File(const std::filesystem::path& file, Mode mode) : path_(file.string()) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr noise
  file_ = mode == Mode::create ? H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)
                               : H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0)
    throw InputError(fmt::format("{}: cannot {} HDF5 file", path_, mode == Mode::create ? "create" : "open"));
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5File::write(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> shape) {
  write_dataset(file_, path_, name, data, std::move(shape), H5T_NATIVE_DOUBLE);
}
void Hdf5File::write(const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> shape) {
  write_dataset(file_, path_, name, data, std::move(shape), H5T_NATIVE_INT64);
}
std::vector<double> Hdf5File::read_doubles(const std::string& name) const {
  return read_dataset<double>(file_, path_, name, H5T_NATIVE_DOUBLE);
}
std::vector<std::int64_t> Hdf5File::read_ints(const std::string& name) const {
  return read_dataset<std::int64_t>(file_, path_, name, H5T_NATIVE_INT64);
}
bool Hdf5File::has(const std::string& name) const { return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0; }

void Hdf5File::set_attribute(const std::string& name, double value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(file_, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attr);
  H5Sclose(space);
}

void Hdf5File::set_attribute(const std::string& name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(file_, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, type, value.c_str());
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

double Hdf5File::attribute(const std::string& name) const {
  const hid_t attr = H5Aopen(file_, name.c_str(), H5P_DEFAULT);
  if (attr < 0) throw InputError(fmt::format("{}: checkpoint has no attribute '{}'", path_, name));
  double value = 0;
  H5Aread(attr, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attr);
  return value;
}

std::string Hdf5File::string_attribute(const std::string& name) const {
  const hid_t attr = H5Aopen(file_, name.c_str(), H5P_DEFAULT);
  if (attr < 0) throw InputError(fmt::format("{}: checkpoint has no attribute '{}'", path_, name));
  const hid_t type = H5Aget_type(attr);
  std::string value(H5Tget_size(type), '\0');
  H5Aread(attr, type, value.data());
  H5Tclose(type);
  H5Aclose(attr);
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

}  // namespace shockfield::io

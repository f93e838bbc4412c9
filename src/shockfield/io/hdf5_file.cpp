#include "shockfield/io/hdf5_file.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/hdf5_handle.hpp"

namespace shockfield::io {
namespace {

using Handle = Hdf5Handle;

void write_attribute(hid_t object, const std::string& path, const std::string& name, hid_t type, const void* value);
void write_string_attribute(hid_t object, const std::string& path, const std::string& name, const std::string& value);

template <class T>
void write_dataset(hid_t file, const std::string& path, const std::string& name, const std::vector<T>& data,
                   std::vector<hsize_t> shape, hid_t type, const std::string& units) {
  if (shape.empty()) shape = {static_cast<hsize_t>(data.size())};
  Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose);
  Handle set(space.ok() ? H5Dcreate2(file, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1,
             H5Dclose);
  const bool written = set.ok() && H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) >= 0;
  if (written && !units.empty()) write_string_attribute(set.get(), path, name + "/units", units);
  if (!written || !set.close() || !space.close())
    throw RunError(fmt::format("{}: cannot write dataset '{}'", path, name));
}

template <class T>
std::vector<T> read_dataset(hid_t file, const std::string& path, const std::string& name, hid_t type,
                            std::uintmax_t bytes_on_disk) {
  Handle set(H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0 ? H5Dopen2(file, name.c_str(), H5P_DEFAULT) : -1, H5Dclose);
  if (!set.ok()) throw InputError(fmt::format("{}: checkpoint has no dataset '{}'", path, name));
  Handle space(H5Dget_space(set.get()), H5Sclose);
  const hssize_t n = space.ok() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  Handle stored(H5Dget_type(set.get()), H5Tclose);
  if (n < 0 || !stored.ok() || H5Tget_size(stored.get()) != sizeof(T))
    throw InputError(fmt::format("{}: dataset '{}' is damaged (no size or the wrong type)", path, name));
  if (static_cast<std::uintmax_t>(n) > bytes_on_disk / sizeof(T))
    throw InputError(fmt::format("{}: dataset '{}' claims {} values, more than the file's {} bytes hold (damaged)",
                                 path, name, n, bytes_on_disk));
  std::vector<T> out(static_cast<std::size_t>(n));
  if (H5Dread(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw InputError(fmt::format("{}: cannot read dataset '{}'", path, name));
  return out;
}

// `name` may be "<dataset>/<attribute>" (for messages); the attribute is its last component.
void write_attribute(hid_t object, const std::string& path, const std::string& name, hid_t type, const void* value) {
  const std::string attribute = name.substr(name.rfind('/') + 1);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(space.ok() ? H5Acreate2(object, attribute.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT) : -1,
              H5Aclose);
  const bool written = attr.ok() && H5Awrite(attr.get(), type, value) >= 0;
  if (!written || !attr.close() || !space.close())
    throw RunError(fmt::format("{}: cannot write attribute '{}'", path, name));
}

void write_string_attribute(hid_t object, const std::string& path, const std::string& name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!type.ok() || H5Tset_size(type.get(), value.size() + 1) < 0)
    throw RunError(fmt::format("{}: cannot write attribute '{}'", path, name));
  write_attribute(object, path, name, type.get(), value.c_str());
}

// A string attribute of `object` (the root group or a dataset), at most `limit` bytes.
std::string read_string_attribute(hid_t object, const std::string& path, const std::string& name,
                                  const std::string& attribute, std::uintmax_t limit) {
  Handle attr(H5Aexists(object, attribute.c_str()) > 0 ? H5Aopen(object, attribute.c_str(), H5P_DEFAULT) : -1,
              H5Aclose);
  if (!attr.ok()) throw InputError(fmt::format("{}: checkpoint has no attribute '{}'", path, name));
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  const std::size_t size = type.ok() ? H5Tget_size(type.get()) : 0;
  if (size == 0 || size > limit || H5Tget_class(type.get()) != H5T_STRING)
    throw InputError(fmt::format("{}: attribute '{}' is not a string", path, name));
  std::string value(size, '\0');
  if (H5Aread(attr.get(), type.get(), value.data()) < 0)
    throw InputError(fmt::format("{}: cannot read attribute '{}'", path, name));
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}


hid_t open_file(const std::string& path, Hdf5File::Mode mode) {
  if (mode == Hdf5File::Mode::read) return H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (mode == Hdf5File::Mode::create) return H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  // In memory, never written to disk by HDF5 (backing_store = 0), grown 1 MiB at a time.
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.ok() || H5Pset_fapl_core(access.get(), 1 << 20, 0) < 0) return -1;
  return H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
}

}  // namespace

Hdf5File::Hdf5File(const std::filesystem::path& file, Mode mode) : path_(file.string()) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr noise
  file_ = open_file(path_, mode);
  std::error_code size_error;
  bytes_on_disk_ = mode == Mode::read ? std::filesystem::file_size(file, size_error) : UINTMAX_MAX;
  if (size_error) bytes_on_disk_ = 0;
  if (file_ >= 0) return;
  if (mode == Mode::read) throw InputError(fmt::format("{}: cannot open HDF5 file", path_));
  throw RunError(fmt::format("{}: cannot create HDF5 file", path_));
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5File::close() {
  const hid_t f = file_;
  file_ = -1;
  if (f >= 0 && H5Fclose(f) < 0) throw RunError(fmt::format("{}: closing the HDF5 file failed", path_));
}

std::vector<unsigned char> Hdf5File::image() const {
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) throw RunError(fmt::format("{}: cannot flush the HDF5 file", path_));
  const ssize_t size = H5Fget_file_image(file_, nullptr, 0);
  std::vector<unsigned char> bytes(size > 0 ? static_cast<std::size_t>(size) : 0);
  if (size <= 0 || H5Fget_file_image(file_, bytes.data(), bytes.size()) != size)
    throw RunError(fmt::format("{}: cannot take the image of the HDF5 file", path_));
  return bytes;
}

void Hdf5File::write(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> shape,
                     const std::string& units) {
  write_dataset(file_, path_, name, data, std::move(shape), H5T_NATIVE_DOUBLE, units);
}
void Hdf5File::write(const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> shape,
                     const std::string& units) {
  write_dataset(file_, path_, name, data, std::move(shape), H5T_NATIVE_INT64, units);
}
std::vector<double> Hdf5File::read_doubles(const std::string& name) const {
  return read_dataset<double>(file_, path_, name, H5T_NATIVE_DOUBLE, bytes_on_disk_);
}
std::vector<std::int64_t> Hdf5File::read_ints(const std::string& name) const {
  return read_dataset<std::int64_t>(file_, path_, name, H5T_NATIVE_INT64, bytes_on_disk_);
}
bool Hdf5File::has(const std::string& name) const { return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0; }

std::string Hdf5File::units(const std::string& name) const {
  Handle set(has(name) ? H5Dopen2(file_, name.c_str(), H5P_DEFAULT) : -1, H5Dclose);
  if (!set.ok()) throw InputError(fmt::format("{}: checkpoint has no dataset '{}'", path_, name));
  return read_string_attribute(set.get(), path_, name + "/units", "units", bytes_on_disk_);
}

bool Hdf5File::is_integer(const std::string& name) const {
  Handle set(has(name) ? H5Dopen2(file_, name.c_str(), H5P_DEFAULT) : -1, H5Dclose);
  Handle type(set.ok() ? H5Dget_type(set.get()) : -1, H5Tclose);
  if (!type.ok()) throw InputError(fmt::format("{}: checkpoint has no dataset '{}'", path_, name));
  return H5Tget_class(type.get()) == H5T_INTEGER;
}

std::vector<hsize_t> Hdf5File::shape(const std::string& name) const {
  Handle set(has(name) ? H5Dopen2(file_, name.c_str(), H5P_DEFAULT) : -1, H5Dclose);
  Handle space(set.ok() ? H5Dget_space(set.get()) : -1, H5Sclose);
  const int rank = space.ok() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 0 || rank > H5S_MAX_RANK) throw InputError(fmt::format("{}: checkpoint has no dataset '{}'", path_, name));
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) != rank)
    throw InputError(fmt::format("{}: dataset '{}' is damaged (no shape)", path_, name));
  return dims;
}

std::vector<std::string> Hdf5File::dataset_names() const {
  // By index (H5Gget_info, H5Lget_name_by_idx): the same calls in HDF5 1.10 and 1.12+.
  H5G_info_t group;
  if (H5Gget_info(file_, &group) < 0) throw InputError(fmt::format("{}: cannot list the datasets", path_));
  std::vector<std::string> names;
  for (hsize_t k = 0; k < group.nlinks; ++k) {
    const ssize_t length = H5Lget_name_by_idx(file_, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (length <= 0 || static_cast<std::uintmax_t>(length) > bytes_on_disk_)
      throw InputError(fmt::format("{}: cannot list the datasets (damaged)", path_));
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(file_, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    Handle object(H5Oopen(file_, name.c_str(), H5P_DEFAULT), H5Oclose);
    if (object.ok() && H5Iget_type(object.get()) == H5I_DATASET) names.push_back(name);
  }
  return names;
}
bool Hdf5File::has_attribute(const std::string& name) const { return H5Aexists(file_, name.c_str()) > 0; }

void Hdf5File::set_attribute(const std::string& name, double value) {
  write_attribute(file_, path_, name, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5File::set_attribute(const std::string& name, const std::string& value) {
  write_string_attribute(file_, path_, name, value);
}

void Hdf5File::set_int_attribute(const std::string& name, std::int64_t value) {
  write_attribute(file_, path_, name, H5T_NATIVE_INT64, &value);
}

double Hdf5File::attribute(const std::string& name) const {
  Handle attr(has_attribute(name) ? H5Aopen(file_, name.c_str(), H5P_DEFAULT) : -1, H5Aclose);
  if (!attr.ok()) throw InputError(fmt::format("{}: checkpoint has no attribute '{}'", path_, name));
  double value = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    throw InputError(fmt::format("{}: cannot read attribute '{}'", path_, name));
  return value;
}

std::int64_t Hdf5File::int_attribute(const std::string& name) const {
  Handle attr(has_attribute(name) ? H5Aopen(file_, name.c_str(), H5P_DEFAULT) : -1, H5Aclose);
  if (!attr.ok()) throw InputError(fmt::format("{}: checkpoint has no attribute '{}'", path_, name));
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  if (!type.ok() || H5Tget_class(type.get()) != H5T_INTEGER)
    throw InputError(fmt::format("{}: attribute '{}' is not stored as an integer", path_, name));
  std::int64_t value = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_INT64, &value) < 0)
    throw InputError(fmt::format("{}: cannot read attribute '{}'", path_, name));
  return value;
}

std::string Hdf5File::string_attribute(const std::string& name) const {
  return read_string_attribute(file_, path_, name, name, bytes_on_disk_);
}

}  // namespace shockfield::io

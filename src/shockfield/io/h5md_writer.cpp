#include "shockfield/io/h5md_writer.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::io {
namespace {

namespace fs = std::filesystem;

// A failed HDF5 call while writing: RunError naming the file and what was being written.
void require(bool ok, const std::string& path, const std::string& what) {
  if (!ok) throw RunError(fmt::format("{}: cannot write the H5MD trajectory ({})", path, what));
}

Hdf5Handle make_group(hid_t parent, const std::string& name, const std::string& path) {
  Hdf5Handle group(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  require(group.ok(), path, "group " + name);
  return group;
}

// Variable-length UTF-8 strings: what h5py reads as str (MDAnalysis compares units as str).
void string_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values,
                      const std::string& path) {
  std::vector<const char*> pointers;
  for (const auto& v : values) pointers.push_back(v.c_str());
  Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  const bool sized = type.ok() && H5Tset_size(type.get(), H5T_VARIABLE) >= 0 &&
                     H5Tset_cset(type.get(), H5T_CSET_UTF8) >= 0;
  const hsize_t n = values.size();
  Hdf5Handle space(values.size() == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose);
  Hdf5Handle attr(sized && space.ok() ? H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT)
                                      : -1, H5Aclose);
  require(attr.ok() && H5Awrite(attr.get(), type.get(), pointers.data()) >= 0, path, "attribute " + name);
}

void int_attribute(hid_t object, const std::string& name, const std::vector<std::int32_t>& values,
                   const std::string& path) {
  const hsize_t n = values.size();
  Hdf5Handle space(values.size() == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose);
  Hdf5Handle attr(space.ok() ? H5Acreate2(object, name.c_str(), H5T_NATIVE_INT32, space.get(), H5P_DEFAULT, H5P_DEFAULT)
                             : -1, H5Aclose);
  require(attr.ok() && H5Awrite(attr.get(), H5T_NATIVE_INT32, values.data()) >= 0, path, "attribute " + name);
}

// An extendable dataset of rows of `row` values: shape [0, row...], unlimited along the first axis,
// chunked by one row (a frame is written and read whole).
void make_series(hid_t group, const std::string& name, hid_t type, const std::vector<hsize_t>& row,
                 const std::string& unit, const std::string& path) {
  std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{row.empty() ? hsize_t(1024) : hsize_t(1)};
  for (hsize_t d : row) dims.push_back(d), max.push_back(d), chunk.push_back(d);
  Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max.data()), H5Sclose);
  Hdf5Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  const bool chunked = plist.ok() && H5Pset_chunk(plist.get(), static_cast<int>(chunk.size()), chunk.data()) >= 0;
  Hdf5Handle set(chunked && space.ok() ? H5Dcreate2(group, name.c_str(), type, space.get(), H5P_DEFAULT, plist.get(),
                                                    H5P_DEFAULT)
                                       : -1, H5Dclose);
  require(set.ok(), path, "dataset " + name);
  if (!unit.empty()) string_attribute(set.get(), "unit", {unit}, path);
}

// Appends one row to the extendable dataset `name` of `group`, which holds `rows` rows.
void append_row(hid_t group, const std::string& name, hid_t type, const void* data, hsize_t rows,
                const std::string& path) {
  Hdf5Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  Hdf5Handle old_space(set.ok() ? H5Dget_space(set.get()) : -1, H5Sclose);
  const int rank = old_space.ok() ? H5Sget_simple_extent_ndims(old_space.get()) : -1;
  require(rank >= 1 && rank <= 3, path, "dataset " + name);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(old_space.get(), dims.data(), nullptr);
  dims[0] = rows + 1;
  require(H5Dset_extent(set.get(), dims.data()) >= 0, path, "extending " + name);
  Hdf5Handle space(H5Dget_space(set.get()), H5Sclose);
  std::vector<hsize_t> start(dims.size(), 0), count = dims;
  start[0] = rows, count[0] = 1;
  Hdf5Handle memory(H5Screate_simple(rank, count.data(), nullptr), H5Sclose);
  const bool selected =
      space.ok() && H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr) >= 0;
  require(selected && memory.ok() && H5Dwrite(set.get(), type, memory.get(), space.get(), H5P_DEFAULT, data) >= 0, path,
          "frame of " + name);
}

void time_independent(hid_t group, const std::string& name, const std::vector<std::int64_t>& values,
                      const std::string& path) {
  const hsize_t n = values.size();
  Hdf5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  Hdf5Handle set(space.ok() ? H5Dcreate2(group, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                                         H5P_DEFAULT)
                            : -1, H5Dclose);
  require(set.ok() && H5Dwrite(set.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0, path,
          "dataset " + name);
}

}  // namespace

H5mdWriter::H5mdWriter(const fs::path& file, const H5mdLayout& layout, std::optional<std::int64_t> resume_step)
    : path_(file.string()), elements_(layout.elements), particles_(layout.particles) {
  if (layout.species.size() != particles_ || layout.ids.size() != particles_)
    throw RunError(fmt::format("{}: H5MD layout of {} particles with {} species and {} ids", path_, particles_,
                               layout.species.size(), layout.ids.size()));
  if (resume_step && fs::exists(file)) open_for_resume(*resume_step);
  else create(layout);
}

std::vector<std::string> H5mdWriter::time_groups() const {
  std::vector<std::string> groups{"/particles/all/box/edges"};
  for (const auto& e : elements_) groups.push_back("/particles/all/" + e.name);
  return groups;
}

void H5mdWriter::create(const H5mdLayout& layout) {
  file_ = Hdf5Handle(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  require(file_.ok(), path_, "creating the file");
  {
    Hdf5Handle h5md = make_group(file_.get(), "h5md", path_);
    int_attribute(h5md.get(), "version", {1, 1}, path_);
    Hdf5Handle author = make_group(h5md.get(), "author", path_);
    string_attribute(author.get(), "name", {"shockfield"}, path_);
    Hdf5Handle creator = make_group(h5md.get(), "creator", path_);
    string_attribute(creator.get(), "name", {"shockfield"}, path_);
    string_attribute(creator.get(), "version", {layout.creator_version}, path_);
  }
  Hdf5Handle particles = make_group(file_.get(), "particles", path_);
  Hdf5Handle all = make_group(particles.get(), "all", path_);
  {
    Hdf5Handle box = make_group(all.get(), "box", path_);
    int_attribute(box.get(), "dimension", {3}, path_);
    string_attribute(box.get(), "boundary", {layout.boundary.begin(), layout.boundary.end()}, path_);
  }
  time_independent(all.get(), "species", layout.species, path_);
  time_independent(all.get(), "id", layout.ids, path_);
  for (const std::string& name : time_groups()) {
    Hdf5Handle group = make_group(file_.get(), name, path_);
    make_series(group.get(), "step", H5T_STD_I64LE, {}, "", path_);
    make_series(group.get(), "time", H5T_IEEE_F64LE, {}, layout.time_unit, path_);
  }
  // The value datasets: the box edges [frames, 3, 3] (the box vectors as rows, the form of H5MD's
  // edges MDAnalysis reads), each element [frames, particles, 3].
  {
    Hdf5Handle edges(H5Gopen2(file_.get(), "/particles/all/box/edges", H5P_DEFAULT), H5Gclose);
    make_series(edges.get(), "value", H5T_IEEE_F64LE, {3, 3}, layout.length_unit, path_);
  }
  for (const auto& e : elements_) {
    Hdf5Handle group(H5Gopen2(file_.get(), ("/particles/all/" + e.name).c_str(), H5P_DEFAULT), H5Gclose);
    make_series(group.get(), "value", H5T_IEEE_F64LE, {particles_, 3}, e.unit, path_);
  }
  require(H5Fflush(file_.get(), H5F_SCOPE_LOCAL) >= 0, path_, "flushing");
}

void H5mdWriter::open_for_resume(std::int64_t resume_step) {
  H5E_BEGIN_TRY { file_ = Hdf5Handle(H5Fopen(path_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose); }
  H5E_END_TRY;
  if (!file_.ok())
    throw InputError(fmt::format("{}: cannot open the H5MD trajectory to resume it (damaged: was the run killed while "
                                 "writing a frame?); move it away and resume again to start a new one",
                                 path_));
  // Frames up to resume_step are kept: count them from the position steps (increasing).
  std::vector<std::int64_t> steps;
  for (const std::string& group : time_groups()) {
    Hdf5Handle set(-1, H5Dclose);
    H5E_BEGIN_TRY { set = Hdf5Handle(H5Dopen2(file_.get(), (group + "/value").c_str(), H5P_DEFAULT), H5Dclose); }
    H5E_END_TRY;
    Hdf5Handle space(set.ok() ? H5Dget_space(set.get()) : -1, H5Sclose);
    hsize_t dims[3] = {0, 0, 0};
    const int rank = space.ok() ? H5Sget_simple_extent_dims(space.get(), dims, nullptr) : -1;
    const bool matches = group.ends_with("/edges") ? rank == 3 && dims[1] == 3 : rank == 3 && dims[1] == particles_;
    if (!matches)
      throw InputError(fmt::format("{}: the H5MD trajectory has no {} of {} particles (another run's file?)", path_,
                                   group, particles_));
  }
  {
    Hdf5Handle set(H5Dopen2(file_.get(), "/particles/all/box/edges/step", H5P_DEFAULT), H5Dclose);
    Hdf5Handle space(set.ok() ? H5Dget_space(set.get()) : -1, H5Sclose);
    const hssize_t n = space.ok() ? H5Sget_simple_extent_npoints(space.get()) : -1;
    // A damaged file may claim any count: no more steps than its bytes can hold.
    if (n > 0 && static_cast<std::uintmax_t>(n) > fs::file_size(path_) / sizeof(std::int64_t))
      throw InputError(fmt::format("{}: the H5MD trajectory claims {} frames, more than its size holds (damaged)",
                                   path_, n));
    steps.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    if (n < 0 || (n > 0 && H5Dread(set.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, steps.data()) < 0))
      throw InputError(fmt::format("{}: cannot read the frames' steps of the H5MD trajectory", path_));
  }
  while (frames_ < steps.size() && steps[frames_] <= resume_step) ++frames_;
  for (const std::string& group : time_groups())
    for (const char* name : {"step", "time", "value"}) {
      Hdf5Handle set(H5Dopen2(file_.get(), (group + "/" + name).c_str(), H5P_DEFAULT), H5Dclose);
      Hdf5Handle space(set.ok() ? H5Dget_space(set.get()) : -1, H5Sclose);
      hsize_t dims[3] = {0, 0, 0};
      const int rank = space.ok() ? H5Sget_simple_extent_dims(space.get(), dims, nullptr) : -1;
      dims[0] = frames_;
      if (rank < 1 || H5Dset_extent(set.get(), dims) < 0)
        throw InputError(fmt::format("{}: cannot cut the H5MD trajectory's {}/{} back to step {}", path_, group, name,
                                     resume_step));
    }
}

void H5mdWriter::append(std::int64_t step, double time, const std::array<double, 9>& box_vectors,
                        const std::vector<std::vector<double>>& values) {
  if (values.size() != elements_.size())
    throw RunError(fmt::format("{}: a frame of {} elements for {}", path_, values.size(), elements_.size()));
  const auto groups = time_groups();
  for (std::size_t k = 0; k < groups.size(); ++k) {
    Hdf5Handle group(H5Gopen2(file_.get(), groups[k].c_str(), H5P_DEFAULT), H5Gclose);
    require(group.ok(), path_, groups[k]);
    append_row(group.get(), "step", H5T_NATIVE_INT64, &step, frames_, path_);
    append_row(group.get(), "time", H5T_NATIVE_DOUBLE, &time, frames_, path_);
    if (k == 0) {
      append_row(group.get(), "value", H5T_NATIVE_DOUBLE, box_vectors.data(), frames_, path_);
    } else {
      const std::vector<double>& v = values[k - 1];
      if (v.size() != particles_ * 3)
        throw RunError(fmt::format("{}: {} values of {} for {} particles", path_, v.size(), elements_[k - 1].name,
                                   particles_));
      append_row(group.get(), "value", H5T_NATIVE_DOUBLE, v.data(), frames_, path_);
    }
  }
  ++frames_;
  require(H5Fflush(file_.get(), H5F_SCOPE_LOCAL) >= 0, path_, "flushing");
}

}  // namespace shockfield::io

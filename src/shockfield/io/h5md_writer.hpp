#pragma once
// H5MD trajectories (P. de Buyl, P. H. Colberg, F. Höfling, "H5MD: A structured, efficient, and
// portable file format for molecular data", Comput. Phys. Commun. 185 (2014) 1546–1553; version
// 1.1 of the specification), the HDF5 layout MDAnalysis, VMD's h5md plugin and LAMMPS's
// `dump h5md` share:
//   /h5md                     attribute version = [1, 1]; groups author (name), creator (name, version)
//   /particles/all/box        attributes dimension = 3, boundary = ["periodic" | "none"] × 3;
//                             edges/{step,time,value}: the box vectors (rows) of every frame
//   /particles/all/<element>/{step,time,value}   value [frames, particles, 3], attribute `unit`
//   /particles/all/species, /particles/all/id     per particle, time-independent
// Particles keep one order through the file (the caller's, e.g. sorted by id) and their count is
// fixed. Each frame extends the datasets by one row and flushes the file, so a run killed between
// frames leaves every written frame readable; a kill during the write itself can damage the file
// (HDF5 has no journal), which a resume then refuses by name.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/io/hdf5_handle.hpp"

namespace shockfield::io {

/// A per-particle 3-vector written every frame: its H5MD element name and unit string, e.g.
/// {"position", "Angstrom"}, {"velocity", "Angstrom ps-1"}.
struct H5mdElement {
  std::string name;
  std::string unit;
};

struct H5mdLayout {
  std::size_t particles = 0;
  std::array<std::string, 3> boundary{"periodic", "periodic", "periodic"};  ///< per axis: periodic | none
  std::vector<H5mdElement> elements;
  std::vector<std::int64_t> species;  ///< per particle (1-based types), in the file's order
  std::vector<std::int64_t> ids;      ///< per particle, in the file's order
  std::string length_unit = "Angstrom";
  std::string time_unit = "ps";
  std::string creator_version;  ///< the shockfield version and commit
};

class H5mdWriter {
 public:
  /// Creates `file`; with `resume_step`, opens the file a stopped run wrote instead (a new one if
  /// there is none) and drops its frames after that step. InputError naming the file when it
  /// cannot be opened or holds another particle count or other elements.
  H5mdWriter(const std::filesystem::path& file, const H5mdLayout& layout, std::optional<std::int64_t> resume_step);

  /// Appends a frame: `values[k]` holds particles × 3 values of layout.elements[k] in the file's
  /// particle order; `box_vectors` the cell's edge vectors a, b, c as rows (a triclinic cell's
  /// (lx, 0, 0), (xy, ly, 0), (xz, yz, lz)). RunError naming the file when HDF5 cannot write.
  void append(std::int64_t step, double time, const std::array<double, 9>& box_vectors,
              const std::vector<std::vector<double>>& values);

  /// Frames in the file.
  std::size_t frames() const { return frames_; }

 private:
  void create(const H5mdLayout& layout);
  void open_for_resume(std::int64_t resume_step);
  /// The time-dependent groups: the box edges, then one per element.
  std::vector<std::string> time_groups() const;

  std::string path_;
  Hdf5Handle file_{-1, nullptr};
  std::vector<H5mdElement> elements_;
  std::size_t particles_ = 0;
  std::size_t frames_ = 0;
};

}  // namespace shockfield::io

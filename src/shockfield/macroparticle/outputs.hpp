#pragma once
// What a macroparticle run writes besides the driver's thermo table: LAMMPS text dumps
// (dumps/dump.<step>.lammpstrj: id type x y z vx vy vz szz in m, m/s, Pa; OVITO opens the series)
// and VTK particles (particles/particles_<step>.vtp indexed by particles.pvd: velocity and σ_zz,
// for ParaView), every dump_every / vtk_every steps. A resumed run drops frames past its
// checkpoint and continues the series.
#include <filesystem>
#include <optional>

#include "shockfield/io/vtk_xml.hpp"
#include "shockfield/macroparticle/case_file.hpp"
#include "shockfield/macroparticle/rod.hpp"

namespace shockfield::macroparticle {

class RodOutputs {
 public:
  RodOutputs(const std::filesystem::path& folder, const OutputSpec& spec, std::optional<std::int64_t> resume_step);
  /// Whether the forces of `step` need per-particle virials (a frame is due).
  bool needs_per_atom(std::int64_t step) const;
  void write_due(const Rod& rod);

 private:
  void write_dump(const Rod& rod) const;
  void write_vtk(const Rod& rod);

  std::filesystem::path folder_;
  OutputSpec spec_;
  io::PvdSeries pvd_;
  std::int64_t last_step_ = -1;
};

}  // namespace shockfield::macroparticle

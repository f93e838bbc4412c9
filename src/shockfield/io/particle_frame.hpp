#pragma once
// A frame of particles (PD points, granular grains) written the two ways other tools read it, from
// one set of values: a VTK PolyData file (.vtp, io/vtk_xml, indexed by a .pvd) for ParaView, and,
// on request, a LAMMPS text dump (io/lammps_dump, `units si`) for OVITO, LAMMPS `read_dump` /
// `rerun` and `shockfield analyze atoms` (docs/conventions.md, "Particle frames").
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::io {

struct ParticleFrame {
  long long step = 0;          ///< ITEM: TIMESTEP
  double time = 0.0;           ///< [s], ITEM: TIME and the .pvd entry
  std::vector<double> xyz;     ///< positions, x y z interleaved [m]
  std::vector<int> type;       ///< LAMMPS atom type per particle (1-based); empty: all 1, no `type` array
  double margin = 0.0;         ///< the dump's box is the positions' extent ± margin per axis [m]
  std::vector<VtkArray> arrays;  ///< per-particle values with their units
  std::size_t size() const { return xyz.size() / 3; }
};

/// The frame as a LAMMPS `dump custom` frame in `units si`: `id` (1-based particle index), `type`,
/// `x y z`, then the arrays' columns — `velocity` → vx vy vz and `force` → fx fy fz (LAMMPS's
/// names), another vector a → a_x a_y a_z, a 3×3 tensor s (symmetric) → s_xx s_yy s_zz s_xy s_xz
/// s_yz (the order of LAMMPS stress/atom), a scalar by its name. Box bounds `ss ss ss` (free
/// bodies) enclosing every particle with `margin`; ITEM: UNITS si and ITEM: TIME.
DumpFrame particle_dump_frame(const ParticleFrame& frame);

/// Writes frames as `<folder>/<stem>_<k>.vtp` indexed by `<folder>/<stem>.pvd` and, with `dumps`,
/// `<run>/dumps/dump.<step>.lammpstrj` (the step zero-padded to `pad` digits, as MD names its
/// dumps, so `shockfield analyze atoms <run>` reads them), values printed in the shortest text that
/// reads back to the same double. A resumed run (resume_time) keeps the .pvd entries up to it; the
/// .pvd names its times' unit, time_units="s".
class ParticleOutput {
 public:
  ParticleOutput() = default;
  ParticleOutput(const std::filesystem::path& run, const std::filesystem::path& folder, std::string stem,
                 VtkFormat vtk, bool dumps, int pad, const double* resume_time);
  /// Frame `index`'s files.
  void write(const ParticleFrame& frame, std::int64_t index);

 private:
  std::filesystem::path run_, folder_;
  std::string stem_;
  VtkFormat vtk_;
  bool dumps_ = false;
  int pad_ = 1;
  PvdSeries pvd_;
};

/// The digits of the last step, `pad` for ParticleOutput (and MD's dump_pad default).
int step_digits(long long last_step);

}  // namespace shockfield::io

#include "shockfield/app/analyze_atoms_voids.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "shockfield/analysis/atoms/atom_surfaces.hpp"
#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/app/python_helpers.hpp"
#include "shockfield/geometry/delaunay_output.hpp"

namespace shockfield::app {

void add_void_options(CLI::App& cmd, VoidArgs& a) {
  cmd.add_option("--voids", a.probe,
                 "Voids: the cavities of the atoms' Delaunay division for a ball of this radius (Å; larger than the "
                 "crystal's interstitial holes, e.g. 0.6 a for fcc), regions the ball moves in without reaching the "
                 "outside; writes OUTPUT/voids.csv (per frame and void: volume and area of the surface through "
                 "the centres of the atoms around it, centre, equivalent radius), OUTPUT/voids_<timestep>.vtp and "
                 "OUTPUT/voids.png (volume and area against time)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--voids-atomic-volume", a.atomic_volume,
                 "Volume per atom of the crystal (Å³) for the voids' missing_volume_A3; default: (box volume − the voids' "
                 "volumes) / atoms, right for a periodic box (give it for a sample with free surfaces)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--voids-margin", a.margin,
                 "Periodic images of the atoms within this distance (Å) of the faces join the division, so that a "
                 "void across a periodic face is found whole (default 15, at most half the box; a larger void "
                 "across a face needs a larger margin)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--voids-min-volume", a.min_volume, "Leave out voids smaller than this (Å³; a vacancy is about one atomic volume)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

SurfaceSeries::SurfaceSeries(std::string name, const std::string& csv_header,
                             const std::function<std::filesystem::path(const std::filesystem::path&)>& add_file)
    : name_(std::move(name)), add_file_(add_file), csv_(add_file(name_ + ".csv")) {
  csv_.write(csv_header);
}

void SurfaceSeries::end_frame(long long timestep, const std::vector<std::array<double, 3>>& points,
                              const std::vector<std::array<std::int32_t, 3>>& triangles) {
  csv_.flush();
  geometry::write_surface_vtp(add_file_(fmt::format("{}_{}.vtp", name_, timestep)), points, triangles, "A");
}

void SurfaceSeries::close() {
  if (csv_.is_open()) csv_.close();
}

void SurfaceSeries::plot(const std::filesystem::path& folder) const {
  const auto png = folder / (name_ + ".png");
  if (plot_csv("surfaces", folder / (name_ + ".csv"), png)) std::printf("wrote %s\n", png.string().c_str());
}

VoidOutput::VoidOutput(const VoidArgs& args, std::function<std::filesystem::path(const std::filesystem::path&)> add_file)
    : args_(args) {
  if (!on()) return;
  files_ = SurfaceSeries("voids", analysis::atoms::csv_header(analysis::atoms::void_columns()), add_file);
}

void VoidOutput::add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame) {
  namespace aa = analysis::atoms;
  const aa::VoidResult r = aa::find_voids(frame, aa::VoidSearch{*args_.probe, args_.atomic_volume, args_.margin, args_.min_volume});
  std::size_t number = 0;
  for (const aa::Void& v : r.voids)
    files_.csv() << fmt::format("{},{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{},{}\n", frame_index,
                                frame.timestep, ++number, v.cells, v.volume, v.area, aa::equivalent_radius(v.volume),
                                v.missing_volume, aa::equivalent_radius(v.missing_volume), v.centre.x(), v.centre.y(),
                                v.centre.z(), v.surface_atoms, v.euler_characteristic, v.manifold ? 1 : 0);
  voids_ += number;
  files_.end_frame(frame.timestep, r.surfaces.points, r.surfaces.triangles);
}

}  // namespace shockfield::app

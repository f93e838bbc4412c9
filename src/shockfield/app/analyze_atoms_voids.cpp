#include "shockfield/app/analyze_atoms_voids.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "shockfield/app/python_helpers.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/delaunay_output.hpp"
#include "shockfield/geometry/rolling_ball.hpp"

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
                 "Volume per atom of the crystal (Å³) for the voids' missing_volume; default: (box volume − the voids' "
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

double equivalent_radius(double volume) { return std::cbrt(3.0 * std::max(volume, 0.0) / (4.0 * std::numbers::pi)); }

SurfaceSeries::SurfaceSeries(std::string name, const std::string& csv_header,
                             const std::function<std::filesystem::path(const std::filesystem::path&)>& add_file)
    : name_(std::move(name)), add_file_(add_file), csv_(add_file(name_ + ".csv")) {
  csv_.write(csv_header);
}

void SurfaceSeries::end_frame(long long timestep, const std::vector<std::array<double, 3>>& points,
                              const std::vector<std::array<std::int32_t, 3>>& triangles) {
  csv_.flush();
  geometry::write_surface_vtp(add_file_(fmt::format("{}_{}.vtp", name_, timestep)), points, triangles);
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
  files_ = SurfaceSeries("voids",
                         "frame,timestep,void,cells,volume,area,equivalent_radius,missing_volume,missing_radius,x,y,z,"
                         "surface_atoms,euler_characteristic,manifold\n",
                         add_file);
}

// The atoms and, along periodic dimensions, their images within `margin` of the faces, so that
// a void across a periodic face is closed in the (non-periodic) division.
std::vector<std::array<double, 3>> with_images(const analysis::atoms::AtomFrame& frame, double margin) {
  std::vector<std::array<double, 3>> points;
  const geometry::Box& box = frame.box;
  for (const Vec3& x0 : frame.positions) {
    Vec3 x = x0;
    for (int d = 0; d < 3; ++d)
      if (box.periodic(d)) x[d] -= box.length()[d] * std::floor((x[d] - box.lo[d]) / box.length()[d]);
    for (int sx = -1; sx <= 1; ++sx)
      for (int sy = -1; sy <= 1; ++sy)
        for (int sz = -1; sz <= 1; ++sz) {
          const int shift[3] = {sx, sy, sz};
          Vec3 image = x;
          bool keep = true;
          for (int d = 0; d < 3 && keep; ++d) {
            if (shift[d] == 0) continue;
            image[d] += shift[d] * box.length()[d];
            keep = box.periodic(d) && image[d] >= box.lo[d] - margin && image[d] < box.hi[d] + margin;
          }
          if (keep) points.push_back({image.x(), image.y(), image.z()});
        }
  }
  return points;
}

void VoidOutput::add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame) {
  const geometry::Box& box = frame.box;
  double margin = args_.margin.value_or(15.0);
  for (int d = 0; d < 3; ++d)
    if (box.periodic(d)) margin = std::min(margin, 0.5 * box.length()[d]);
  const auto division = geometry::delaunay_division<3>(with_images(frame, margin), fmt::format("the atoms of timestep {}", frame.timestep));
  // A void near a periodic face is found whole in several copies (it and its images): the copies
  // have the same centre once wrapped into the box; one is kept, with its centre wrapped.
  std::vector<geometry::Cavity> cavities;
  for (geometry::Cavity& c : geometry::rolling_ball_cavities(division, *args_.probe)) {
    Vec3 centre(c.centroid[0], c.centroid[1], c.centroid[2]);
    std::array<int, 3> image{0, 0, 0};
    box.wrap(centre, image);
    const bool copy = std::any_of(cavities.begin(), cavities.end(), [&](const geometry::Cavity& k) {
      return box.minimum_image(Vec3(k.centroid[0], k.centroid[1], k.centroid[2]) - centre).norm() < 1e-3;
    });
    if (copy) continue;
    c.centroid = {centre.x(), centre.y(), centre.z()};
    cavities.push_back(std::move(c));
  }
  double cavity_volume = 0;
  for (const geometry::Cavity& c : cavities) cavity_volume += c.surface.volume;
  const double omega = args_.atomic_volume.value_or((frame.box.volume() - cavity_volume) / static_cast<double>(frame.size()));
  std::vector<std::array<std::int32_t, 3>> triangles;
  std::size_t number = 0;
  for (const geometry::Cavity& c : cavities) {
    if (c.surface.volume < args_.min_volume) continue;
    std::vector<char> on_surface(division.points.size(), 0);
    for (const auto& t : c.surface.triangles)
      for (std::int32_t v : t) on_surface[static_cast<std::size_t>(v)] = 1;
    // The missing atoms' volume: the polyhedron less the surface atoms' own cells' share in it.
    const double missing = c.surface.volume - omega * c.vertex_solid_angle / (4.0 * std::numbers::pi);
    files_.csv() << fmt::format("{},{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{},{}\n", frame_index,
                        frame.timestep, ++number, c.cells, c.surface.volume, c.surface.area, equivalent_radius(c.surface.volume),
                        missing, equivalent_radius(missing), c.centroid[0], c.centroid[1], c.centroid[2],
                        std::count(on_surface.begin(), on_surface.end(), 1), c.surface.euler_characteristic,
                        c.surface.manifold ? 1 : 0);
    triangles.insert(triangles.end(), c.surface.triangles.begin(), c.surface.triangles.end());
  }
  voids_ += number;
  files_.end_frame(frame.timestep, division.points, triangles);
}

}  // namespace shockfield::app

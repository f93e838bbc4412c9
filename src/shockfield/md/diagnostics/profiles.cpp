#include "shockfield/md/diagnostics/profiles.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "shockfield/core/error.hpp"

#include "shockfield/core/units.hpp"

namespace shockfield::md {

using namespace units::metal;

Profile bin_profile(const Simulation& sim, int axis, double width) {
  const Atoms& a = sim.atoms;
  const double lo = sim.box.lo[axis], length = sim.box.hi[axis] - lo;
  const int nbins = std::max(1, static_cast<int>(std::ceil(length / width - 1e-9)));
  const Vec3 l = sim.box.length();
  const double area = l.prod() / l[axis];
  // The last slab ends at the box face: it is narrower when the length is not a multiple of the
  // width, and its density and pressure divide by its own volume (LAMMPS fix ave/chunk divides
  // every bin by the full width, so its last bin reads low).
  auto bin_width = [&](int b) { return b + 1 < nbins ? width : length - (nbins - 1) * width; };
  std::vector<int> bin_of(a.nlocal);
  Profile p;
  p.step = sim.step;
  p.time = sim.time;
  p.bins.resize(static_cast<std::size_t>(nbins));
  std::vector<double> mass(nbins, 0.0);
  std::vector<Vec3> momentum(nbins, Vec3::Zero());
  // In a tilted cell x and y bin the fractional coordinate s: slabs parallel to the face the
  // other two edges span, each of volume V·width/L as an orthogonal slab's (along z, s·lz = z −
  // zlo).
  const bool fractional = sim.box.triclinic() && axis != 2;
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    const double offset =
        fractional ? sim.box.to_fractional(a.x[i])[axis] * length : a.x[i][axis] - lo;
    const int b = std::clamp(static_cast<int>(std::floor(offset / width)), 0, nbins - 1);
    bin_of[i] = b;
    const double m = a.mass_of(i);
    mass[b] += m;
    momentum[b] += m * a.v[i];
    ++p.bins[b].count;
  }
  std::vector<Voigt6> kinetic(nbins, Voigt6::Zero());
  for (int b = 0; b < nbins; ++b)
    if (mass[b] > 0) p.bins[b].velocity = momentum[b] / mass[b];
  const bool have_virial = sim.forces.per_atom && sim.forces.virial_atom.size() == a.nlocal;
  std::vector<Voigt6> virial(nbins, Voigt6::Zero());
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    const int b = bin_of[i];
    const Vec3 u = a.v[i] - p.bins[b].velocity;
    const double m = a.mass_of(i);
    kinetic[b] += m * (Voigt6() << u.x() * u.x(), u.y() * u.y(), u.z() * u.z(), u.x() * u.y(),
                       u.x() * u.z(), u.y() * u.z()).finished();
    if (have_virial) virial[b] += sim.forces.virial_atom[i];
  }
  for (int b = 0; b < nbins; ++b) {
    ProfileBin& bin = p.bins[b];
    const double volume = area * bin_width(b);
    bin.position = lo + b * width + 0.5 * bin_width(b);
    bin.density = mass[b] / volume * amu_per_A3_to_g_per_cc;
    const double dof = 3.0 * bin.count - 3.0;
    bin.temperature = dof > 0 ? mvv2e * (kinetic[b][0] + kinetic[b][1] + kinetic[b][2]) / (dof * boltz) : 0.0;
    bin.pressure = (mvv2e * kinetic[b] + virial[b]) / volume * nktv2p * bar_to_GPa;
  }
  return p;
}

std::vector<std::string> profile_columns() {
  return {"step", "time_ps", "bin", "position_A", "count", "density_g_cc", "vx_A_ps", "vy_A_ps",
          "vz_A_ps", "temperature_K", "pxx_GPa", "pyy_GPa", "pzz_GPa", "pxy_GPa", "pxz_GPa", "pyz_GPa"};
}

std::vector<double> profile_row(const Profile& p, std::size_t b) {
  const ProfileBin& bin = p.bins[b];
  return {static_cast<double>(p.step), p.time, static_cast<double>(b), bin.position,
          static_cast<double>(bin.count), bin.density, bin.velocity.x(), bin.velocity.y(),
          bin.velocity.z(), bin.temperature, bin.pressure[0], bin.pressure[1], bin.pressure[2],
          bin.pressure[3], bin.pressure[4], bin.pressure[5]};
}

}  // namespace shockfield::md

namespace shockfield::md {

std::vector<Profile> read_profiles_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open profiles file", file.string()));
  std::string line;
  std::getline(in, line);
  const std::size_t ncol = profile_columns().size();
  std::vector<Profile> frames;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    std::vector<double> v;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) v.push_back(std::strtod(cell.c_str(), nullptr));
    if (v.size() != ncol)
      throw InputError(fmt::format("{}:{}: expected {} columns, found {}", file.string(), line_no, ncol, v.size()));
    const auto step = static_cast<std::int64_t>(v[0]);
    if (frames.empty() || frames.back().step != step) {
      frames.emplace_back();
      frames.back().step = step;
      frames.back().time = v[1];
    }
    ProfileBin b;
    b.position = v[3];
    b.count = static_cast<int>(v[4]);
    b.density = v[5];
    b.velocity = Vec3(v[6], v[7], v[8]);
    b.temperature = v[9];
    for (int k = 0; k < 6; ++k) b.pressure[k] = v[10 + k];
    frames.back().bins.push_back(b);
  }
  return frames;
}

}  // namespace shockfield::md

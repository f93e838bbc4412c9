#include "shockfield/md/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/geometry/shrink_wrap.hpp"
#include "shockfield/md/decomposition.hpp"
#include "shockfield/md/force_evaluation.hpp"
#include "shockfield/md/ghosts.hpp"

namespace shockfield::md {

using units::metal::boltz;
using units::metal::mvv2e;
using units::metal::nktv2p;

Simulation::Simulation(geometry::Box box_, Atoms atoms_, std::unique_ptr<Potential> potential_,
                       double timestep, double skin_)
    : box(std::move(box_)), atoms(std::move(atoms_)), potential(std::move(potential_)), dt(timestep),
      skin(skin_), shrink_margin(geometry::shrink_margin(box)) {}

void Simulation::shrink_wrap() {
  geometry::shrink_wrap(box, std::span<const Vec3>(atoms.x.data(), atoms.nlocal), shrink_margin);
}

void Simulation::rebuild() {
  if (domain) {
    domain->rebuild(atoms, box, potential->cutoff() + skin);
  } else {
    shrink_wrap();
    rebuild_ghosts(atoms, box, potential->cutoff() + skin);
  }
  geometry::build_neighbor_list(atoms.x, atoms.nlocal, potential->cutoff() + skin, true, list);
  x_rebuild_.assign(atoms.x.begin(), atoms.x.begin() + static_cast<std::ptrdiff_t>(atoms.nlocal));
  box_rebuild_ = box;
  ++rebuilds;
  steps_since_rebuild = 0;
}

void Simulation::flip_cell(const geometry::CellFlip& flip) {
  box.apply_flip(flip);
  for (std::size_t i = 0; i < atoms.nlocal; ++i) atoms.image[i] = geometry::flipped_image(atoms.image[i], flip);
  x_rebuild_.clear();  // needs_rebuild_here(): a list of another cell
}

void Simulation::restore_rebuild_state(const std::vector<Vec3>& x_rebuild, const geometry::Box& box_rebuild) {
  const std::vector<Vec3> x_now(atoms.x.begin(), atoms.x.begin() + static_cast<std::ptrdiff_t>(atoms.nlocal));
  const geometry::Box box_now = box;
  atoms.clear_ghosts();
  for (std::size_t i = 0; i < atoms.nlocal; ++i) atoms.x[i] = x_rebuild[i];
  box = box_rebuild;
  rebuild_ghosts(atoms, box, potential->cutoff() + skin);
  geometry::build_neighbor_list(atoms.x, atoms.nlocal, potential->cutoff() + skin, true, list);
  x_rebuild_ = x_rebuild;
  box_rebuild_ = box_rebuild;
  for (std::size_t i = 0; i < atoms.nlocal; ++i) atoms.x[i] = x_now[i];
  box = box_now;
  atoms.update_ghost_positions(box);
}

bool Simulation::needs_rebuild() const {
  const bool here = needs_rebuild_here();
  return domain ? domain->any(here) : here;  // every rank rebuilds when one must
}

std::vector<double> Simulation::over_ranks(std::vector<double> partials) const {
  return domain ? domain->sum(partials) : partials;
}

bool Simulation::needs_rebuild_here() const {
  if (x_rebuild_.size() != atoms.nlocal) return true;
  if (steps_since_rebuild < neighbor_delay || steps_since_rebuild % neighbor_every != 0) return false;
  if (!neighbor_check) return true;
  const double limit2 = 0.25 * skin * skin;
  bool moved = false;
#pragma omp parallel for reduction(|| : moved) schedule(static)
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    if ((atoms.x[i] - x_rebuild_[i]).squaredNorm() > limit2) moved = true;
  if (moved) return true;
  // A box that changed (deform, barostat) moves ghosts; rebuild when a face moved by half the skin
  // (or a tilt factor, which moves a face by as much).
  for (int d = 0; d < 3; ++d)
    if (std::abs(box.lo[d] - box_rebuild_.lo[d]) > 0.5 * skin ||
        std::abs(box.hi[d] - box_rebuild_.hi[d]) > 0.5 * skin ||
        std::abs(box.tilt[d] - box_rebuild_.tilt[d]) > 0.5 * skin)
      return true;
  return false;
}

namespace {
using Clock = std::chrono::steady_clock;
double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }
}  // namespace

void Simulation::compute_forces(bool per_atom) {
  ++steps_since_rebuild;
  const Clock::time_point t0 = Clock::now();
  const bool rebuilding = needs_rebuild();
  if (rebuilding) rebuild();
  else atoms.update_ghost_positions(box);
  const Clock::time_point t1 = Clock::now();
  (rebuilding ? neighbor_seconds : ghost_seconds) += seconds_between(t0, t1);
  evaluate_forces(atoms, *potential, list, forces, per_atom);
  force_seconds += seconds_between(t1, Clock::now());
}

void Simulation::setup(bool per_atom) {
  rebuild();
  evaluate_forces(atoms, *potential, list, forces, per_atom);
}

void Simulation::advance(const std::function<bool(std::int64_t)>& want_per_atom) {
  for (auto& fix : fixes) fix->initial_integrate(*this);
  // The drift of this step is Δt·v(t+Δt/2): its largest value tells a time step too large.
  double vmax2 = 0;
#pragma omp parallel for reduction(max : vmax2) schedule(static)
  for (std::size_t i = 0; i < atoms.nlocal; ++i) vmax2 = std::max(vmax2, atoms.v[i].squaredNorm());
  if (domain) vmax2 = domain->max(vmax2);
  max_drift_ = std::sqrt(vmax2) * dt;
  for (auto& fix : fixes) fix->post_integrate(*this);
  ++step;
  // t = step·Δt (LAMMPS: atime + (step − atimestep)·dt with a fixed dt), not a sum of Δt: the sum
  // drifts (2000 steps of 0.001 ps give 1.9999999999998905) and the drift shows in every time printed.
  time = static_cast<double>(step) * dt;
  per_atom_this_step = want_per_atom(step);
  compute_forces(per_atom_this_step);
#ifndef NDEBUG
  if (domain) domain->check_total(atoms);  // every step: no atom lost or duplicated across ranks
#endif
  for (auto& fix : fixes) fix->post_force(*this);
  for (auto& fix : fixes) fix->final_integrate(*this);
  for (auto& fix : fixes) fix->end_of_step(*this);
}

double Simulation::kinetic_energy() const {
  double sum = 0;
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (std::size_t i = 0; i < atoms.nlocal; ++i) sum += atoms.mass_of(i) * atoms.v[i].squaredNorm();
  return 0.5 * mvv2e * over_ranks({sum})[0];
}

ThermoState Simulation::thermo() const {
  ThermoState s;
  Voigt6 kin = Voigt6::Zero();
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    const double m = atoms.mass_of(i);
    const Vec3& v = atoms.v[i];
    kin += m * (Voigt6() << v.x() * v.x(), v.y() * v.y(), v.z() * v.z(), v.x() * v.y(),
                v.x() * v.z(), v.y() * v.z()).finished();
  }
  Voigt6 virial = forces.virial;
  double energy = forces.energy, count = static_cast<double>(atoms.nlocal);
  if (domain) {  // every rank's partial sums, added in rank order
    std::vector<double> partials{energy, count};
    partials.insert(partials.end(), kin.data(), kin.data() + 6);
    partials.insert(partials.end(), virial.data(), virial.data() + 6);
    const std::vector<double> total = domain->sum(partials);
    energy = total[0], count = total[1];
    for (int c = 0; c < 6; ++c) kin[c] = total[2 + c], virial[c] = total[8 + c];
  }
  kin *= mvv2e;
  s.kinetic = 0.5 * (kin[0] + kin[1] + kin[2]);
  const double dof = std::max(3.0 * count - 3.0, 1.0);
  s.temperature = 2.0 * s.kinetic / (dof * boltz);
  s.potential = energy;
  s.volume = box.volume();
  // LAMMPS compute pressure: P = (N_dof k T + Σ r·f) / (3V); tensor uses Σ m v v + virial.
  s.pressure = (dof * boltz * s.temperature + virial[0] + virial[1] + virial[2]) / (3.0 * s.volume) * nktv2p;
  s.pressure_tensor = (kin + virial) / s.volume * nktv2p;
  return s;
}

void Simulation::check_health() const {
  // One parallel pass finds the first bad atom (if any) and the fastest speed; the diagnosis of
  // the bad atom is then made on it alone, so the message is that of a serial scan.
  // A triclinic cell is bounded by its faces: its fixed dimensions compare fractional coordinates.
  const bool triclinic = box.triclinic();
  auto outside_fixed = [&](std::size_t i, int d) {
    if (box.boundary[d] != geometry::Boundary::fixed) return false;
    if (triclinic) {
      const double s = box.to_fractional(atoms.x[i])[d];
      return s < 0 || s >= 1;
    }
    return atoms.x[i][d] < box.lo[d] || atoms.x[i][d] >= box.hi[d];
  };
  auto bad_atom = [&](std::size_t i) {
    return !atoms.x[i].allFinite() || !atoms.v[i].allFinite() || !atoms.f[i].allFinite() ||
           outside_fixed(i, 0) || outside_fixed(i, 1) || outside_fixed(i, 2);
  };
  const auto n = static_cast<std::ptrdiff_t>(atoms.nlocal);
  std::ptrdiff_t first_bad = n;
  double vmax2 = 0;
#pragma omp parallel for schedule(static) reduction(min : first_bad) reduction(max : vmax2)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (bad_atom(i)) first_bad = std::min(first_bad, k);
    vmax2 = std::max(vmax2, atoms.v[i].squaredNorm());
  }
  if (domain) {  // every rank stops when one finds a bad atom (it throws the diagnosis)
    vmax2 = domain->max(vmax2);
    if (domain->any(first_bad < n) && first_bad == n)
      throw RunError(fmt::format("step {}: another rank found a lost or non-finite atom", step));
  }
  if (first_bad < n) {
    const auto i = static_cast<std::size_t>(first_bad);
    if (!atoms.x[i].allFinite() || !atoms.v[i].allFinite() || !atoms.f[i].allFinite())
      throw RunError(fmt::format(
          "step {}: atom {} has a non-finite position, velocity or force (x = {} {} {}, v = {} {} {}); "
          "the time step ({} ps) is probably too large or two atoms overlap",
          step, atoms.id[i], atoms.x[i].x(), atoms.x[i].y(), atoms.x[i].z(), atoms.v[i].x(),
          atoms.v[i].y(), atoms.v[i].z(), dt));
    for (int d = 0; d < 3; ++d)
      if (outside_fixed(i, d))
        throw RunError(fmt::format("step {}: lost atom {}: it left the fixed {} boundary of the box "
                                   "([{}, {}]{}) at {} = {}",
                                   step, atoms.id[i], "xyz"[d], box.lo[d], box.hi[d],
                                   triclinic ? fmt::format(", tilt {} {} {}", box.tilt[0], box.tilt[1], box.tilt[2]) : "",
                                   "xyz"[d], atoms.x[i][d]));
  }
  // A displacement of more than the skin in one step means the list missed pairs.
  if (std::sqrt(vmax2) * dt > 0.5 * skin)
    throw RunError(fmt::format("step {}: an atom moves {:.3g} Å per step, more than half the neighbour "
                               "skin ({} Å); the time step ({} ps) is too large for these velocities",
                               step, std::sqrt(vmax2) * dt, skin, dt));
}

}  // namespace shockfield::md

#include "shockfield/mpm/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fmt/format.h>
#include <omp.h>

#include "shockfield/core/error.hpp"

namespace shockfield::mpm {

void SimulationOptions::validate() const {
  if (!(courant > 0.0 && courant <= 1.0))
    throw InputError(fmt::format("mpm: courant = {} (expected 0 < C <= 1)", courant));
  if (!(flip >= 0.0 && flip <= 1.0)) throw InputError(fmt::format("mpm: flip = {} (expected 0 <= flip <= 1)", flip));
  if (xpic_order < 0 || xpic_order > 16)
    throw InputError(fmt::format("mpm: xpic_order = {} (expected 0 = off, or an order 1..16)", xpic_order));
  if (xpic_order > 0 && flip != 1.0)
    throw InputError(fmt::format("mpm: xpic_order = {} with flip = {}: XPIC replaces the FLIP/PIC blend (set one of "
                                 "them)", xpic_order, flip));
  if (!(min_time_step >= 0.0)) throw InputError(fmt::format("mpm: min_time_step = {} (expected >= 0 s)", min_time_step));
  contact.validate();
}

Simulation::Simulation(const GridSpec& grid, std::vector<materials::SolidMaterial> materials, Particles particles,
                       SimulationOptions options)
    : grid_(grid, false), materials_(std::move(materials)), particles_(std::move(particles)), options_(options) {
  options_.validate();
  if (particles_.size() == 0) throw InputError("mpm: the simulation has no particles");
  for (const auto& m : materials_) m.validate();
  double min_mass = particles_.mass[0];
  int bodies = 1;
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    if (particles_.body[p] < 0)
      throw InputError(fmt::format("mpm: particle {} has body {} (expected >= 0)", p, particles_.body[p]));
    bodies = std::max(bodies, particles_.body[p] + 1);
    const int id = particles_.material[p];
    if (id < 0 || id >= static_cast<int>(materials_.size()))
      throw InputError(fmt::format("mpm: particle {} has material index {} (expected 0..{})", p, id,
                                   materials_.size() - 1));
    if (options_.shape != ShapeKind::Linear)
      for (int a = 0; a < grid_.dim(); ++a)
        if (!(particles_.half_size[p][a] > 0.0 && 2.0 * particles_.half_size[p][a] < grid_.spec().cell_size[a]))
          throw InputError(fmt::format("mpm: GIMP needs particle half-widths in (0, h/2); particle {} has {} m along "
                                       "axis {} with h = {} m", p, particles_.half_size[p][a], a,
                                       grid_.spec().cell_size[a]));
    if (grid_.dim() == 2 && particles_.v[p][2] != 0.0)
      throw InputError(fmt::format("mpm: particle {} has z velocity {} m/s in a 2D (plane strain) run (expected 0)", p,
                                   particles_.v[p][2]));
    min_mass = std::min(min_mass, particles_.mass[p]);
  }
  mass_floor_ = 1e-9 * min_mass;
  grid_.set_layers(options_.contact.enabled ? bodies : 1);  // one field per body with contact
  wrap_particles();  // the grid's fields are allocated by the first step (allocate_grid)
}

void Simulation::add_hook(Stage stage, Hook hook) { hooks_[static_cast<std::size_t>(stage)].push_back(std::move(hook)); }

void Simulation::run_hooks(Stage stage) {
  for (auto& h : hooks_[static_cast<std::size_t>(stage)]) h(*this);
}

double Simulation::stable_time_step() const {
  double fastest = 0.0;
  const auto n = static_cast<std::ptrdiff_t>(particles_.size());
#pragma omp parallel for schedule(static) reduction(max : fastest)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    const auto p = static_cast<std::size_t>(q);
    fastest = std::max(fastest, particles_.state[p].sound_speed + particles_.v[p].norm());
  }
  return std::min(options_.courant * grid_.min_cell_size() / fastest, conduction_time_step());
}

double Simulation::conduction_time_step() const {
  if (!options_.heat_conduction) return std::numeric_limits<double>::infinity();
  return HeatConduction::stable_time_step(particles_, materials_, options_.courant, grid_.min_cell_size(), grid_.dim());
}

void Simulation::step(double max_dt) {
  // The fastest signal of the previous step's end, unless a hook or the caller may have changed
  // the particles since (max over the same values either way).
  dt_ = fastest_known_ ? std::min(options_.courant * grid_.min_cell_size() / fastest_, conduction_time_step())
                       : stable_time_step();
  fastest_known_ = false;
  if (max_dt > 0.0) dt_ = std::min(dt_, max_dt);
  if (!(std::isfinite(dt_) && dt_ > 0.0) || dt_ < options_.min_time_step)
    throw RunError(fmt::format("mpm: time step {} s at t = {} s (step {}) is not usable (minimum {} s)", dt_, time_,
                               steps_, options_.min_time_step));
  run_hooks(Stage::BeforeStep);

  allocate_grid();
  transfer_.build(grid_, particles_, options_.shape);
  if (options_.smooth_dilatation) smoothed_mean_stress_correction();
  transfer_.to_grid(grid_, particles_, mean_stress_correction_);
  if (options_.heat_conduction) heat_.step(transfer_, grid_.size(), particles_, materials_, dt_);
  update_grid();
  run_hooks(Stage::AfterGridUpdate);
  nodal_velocities(true);
  per_thread_.assign(static_cast<std::size_t>(omp_get_max_threads()), {0.0, particles_.size()});
  if (options_.scheme == UpdateScheme::USL) {
    grid_to_particles(false);  // L_p below uses the same nodal velocities
  } else {
    grid_to_particles(true);  // MUSL: the updated momenta are remapped to the grid on the way
    couple_bodies();           // the velocities L_p is taken from obey the contact law too
    grid_.apply_walls(grid_.momentum);
    nodal_velocities(false);
  }
  update_materials();
  fastest_ = 0.0;
  std::size_t lost = particles_.size();
  for (const auto& t : per_thread_) fastest_ = std::max(fastest_, t.fastest), lost = std::min(lost, t.lost);
  if (lost < particles_.size()) throw_left_grid(lost);
  time_ += dt_;
  ++steps_;
  fastest_known_ = hooks_[static_cast<std::size_t>(Stage::EndOfStep)].empty();
  run_hooks(Stage::EndOfStep);
}

void Simulation::allocate_grid() {
  grid_.allocate();
  node_velocity_.resize(grid_.field_size(), Vec3::Zero());
  node_acceleration_.resize(grid_.field_size(), Vec3::Zero());
}

ContactStats Simulation::couple_bodies() {
  return grid_.layers() > 1 ? apply_contact(grid_, options_.contact.friction, mass_floor_, dt_) : ContactStats{};
}

void Simulation::run_until(double t_end) {
  while (time_ < t_end * (1.0 - 1e-12)) step(t_end - time_);
}

void Simulation::update_grid() {
  // m_i dv_i/dt = f_i (eq. 12), contact between bodies, walls, then the force contact and walls
  // leave (for the FLIP update, so the contact force reaches the particles' velocities).
  old_momentum_.resize(grid_.field_size());
  const auto n = static_cast<std::ptrdiff_t>(grid_.field_size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    old_momentum_[u] = grid_.momentum[u];
    grid_.momentum[u] += dt_ * grid_.force[u];
  }
  contact_stats_ = couple_bodies();
  grid_.apply_walls(grid_.momentum);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    grid_.force[u] = (grid_.momentum[u] - old_momentum_[u]) / dt_;
  }
}

void Simulation::nodal_velocities(bool with_acceleration) {
  const auto n = static_cast<std::ptrdiff_t>(grid_.field_size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    const auto i = static_cast<std::size_t>(q);
    const bool massive = grid_.mass[i] > mass_floor_;  // nodes without mass carry no velocity
    node_velocity_[i] = massive ? Vec3(grid_.momentum[i] / grid_.mass[i]) : Vec3::Zero();
    if (with_acceleration) node_acceleration_[i] = massive ? Vec3(grid_.force[i] / grid_.mass[i]) : Vec3::Zero();
  }
}

void Simulation::track_fastest(std::size_t p) {
  // The stable step's max_p(c_p + |v_p|), taken while the point is in cache.
  double& fastest = per_thread_[static_cast<std::size_t>(omp_get_thread_num())].fastest;
  fastest = std::max(fastest, particles_.state[p].sound_speed + particles_.v[p].norm());
}

void Simulation::grid_to_particles(bool remap) {
  // FLIP/PIC velocity update and the move; positions are wrapped into periodic axes here, and a
  // point that left the grid is reported at the end of the step. The first step is PIC: it
  // projects the initial velocities onto the field the grid carries. A velocity jump inside a
  // stencil (two bodies meeting at ±v) otherwise stays in the particles as sub-cell noise that
  // FLIP never damps (it is invisible to the grid until the points cross cells) and relaxes the
  // deviatoric stress behind the shock (docs/theory/mpm.md, "Deviatoric stress behind shocks").
  // PIC conserves momentum, and a uniform velocity is unchanged by it (partition of unity).
  const double flip = steps_ == 0 && options_.project_initial_velocity ? 0.0 : options_.flip;
  const bool xpic = options_.xpic_order > 0 && flip > 0.0;
  if (xpic) xpic_velocities();
  // `first` is the nodal acceleration for FLIP/PIC, XPIC's nodal velocity with it
  auto update = [&](std::size_t p, const Vec3& first, const Vec3& vel) {
    particles_.x[p] += dt_ * vel;
    particles_.v[p] = xpic ? first : Vec3(flip * (particles_.v[p] + dt_ * first) + (1.0 - flip) * vel);
    if (!grid_.wrap_position(particles_.x[p])) {
      std::size_t& lost = per_thread_[static_cast<std::size_t>(omp_get_thread_num())].lost;
      lost = std::min(lost, p);
    }
  };
  const auto& first = xpic ? xpic_velocity_ : node_acceleration_;
  if (remap) transfer_.interpolate_and_remap(grid_, particles_, first, node_velocity_, update);
  else transfer_.interpolate(first, node_velocity_, update);
}

void Simulation::xpic_velocities() {
  // XPIC(m), Hammerquist & Nairn (2017). With S the grid → particle interpolation and S⁺ the
  // particles' mass-weighted projection onto the grid, the particle velocities V carry the field the
  // grid can represent plus a null-space part the grid does not see (S⁺ of it is zero). FLIP keeps
  // the null-space part for ever — the sub-cell noise that cycles shocked metal through reverse
  // yield (docs/theory/mpm.md, "Deviatoric stress behind shocks") — and PIC (V ← S S⁺ V) also damps
  // what the grid does represent. XPIC(m) takes the nodal field v* whose interpolation S v* best
  // reproduces V, by m terms of the Neumann series of (S⁺S)⁻¹:
  //   v*_m = Σ_{k=0}^{m−1} (I − S⁺S)^k v^n,   v^n = S⁺V (the nodal velocity before the update),
  // i.e. S v*_m = [I − (I − S S⁺)^m] V: modes the grid resolves (eigenvalue of S S⁺ near 1) are
  // kept as in FLIP, the null space (eigenvalue 0) is removed as in PIC; m = 1 is PIC. Then
  //   v_p ← Σ_i N_ip (v*_m,i + v^L_i − v^n_i),
  // with v^L the nodal velocity after the update, contact, walls and hooks (v^L − v^n = Δt·a).
  // S⁺S conserves Σ_i m_i v_i in each body's layer, so v* has the momentum of v^n, and the contact
  // law's exchange between bodies is all in v^L − v^n. Increments are zeroed where walls constrain
  // the nodes (there v* = v^n, so the particles take v^L).
  const std::size_t n = grid_.field_size();
  xpic_velocity_.resize(n);
  xpic_increment_.resize(n);
  node_scratch_.resize(n);
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t q = 0; q < count; ++q) {
    const auto i = static_cast<std::size_t>(q);
    const bool massive = grid_.mass[i] > mass_floor_;
    xpic_velocity_[i] = massive ? Vec3(old_momentum_[i] / grid_.mass[i]) : Vec3::Zero();  // v^n
    xpic_increment_[i] = xpic_velocity_[i];
  }
  for (int k = 1; k < options_.xpic_order; ++k) {
    point_values_.resize(particles_.size());
    transfer_.interpolate(xpic_increment_, xpic_increment_,
                          [&](std::size_t p, const Vec3& at_point, const Vec3&) { point_values_[p] = at_point; });
    transfer_.mass_weighted_to_grid(particles_, point_values_, node_scratch_);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t q = 0; q < count; ++q) {  // increment ← (I − S⁺S) increment
      const auto i = static_cast<std::size_t>(q);
      if (grid_.mass[i] > mass_floor_) xpic_increment_[i] -= node_scratch_[i] / grid_.mass[i];
      else xpic_increment_[i].setZero();
    }
    grid_.apply_walls(xpic_increment_);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t q = 0; q < count; ++q)
      xpic_velocity_[static_cast<std::size_t>(q)] += xpic_increment_[static_cast<std::size_t>(q)];
  }
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t q = 0; q < count; ++q) {  // v* + (v^L − v^n)
    const auto i = static_cast<std::size_t>(q);
    if (grid_.mass[i] > mass_floor_) xpic_velocity_[i] += node_velocity_[i] - old_momentum_[i] / grid_.mass[i];
  }
}

void Simulation::smooth_dilatation() {
  // The volumetric part of L_p replaced by its mass-weighted average over the nodes of the point's
  // stencil (B-bar, Hughes 1980; in MPM Coombs et al. 2018): with M_n the nodal masses, N the
  // shape functions and M_p the point masses,
  //   tr L̄ = N M_n⁻¹ Nᵀ M_p tr L,   tr L̄_p = Σ_j v_j·B̄_jp,   B̄_jp = Σ_i N_ip Σ_q m_q N_iq ∇N_jq / m_i,
  // so two rows of points in one cell compress alike. Without it a shock front only a few cells
  // wide compresses the rows of a cell differently, leaves an odd-even density and pressure
  // pattern the grid does not see at rest (a null space of f_i = −Σ_p V_p σ_p·∇N_ip) but that
  // forces the nodes as it crosses cells, and the ringing it drives relaxes the deviator behind
  // the shock (docs/theory/mpm.md, "Deviatoric stress behind shocks"). The in-plane diagonal
  // absorbs the change (plane strain keeps L_zz = 0). The grid force uses the same B̄
  // (smoothed_mean_stress_correction), so the two are work-conjugate.
  const int dim = grid_.dim();
  point_values_.resize(particles_.size());
  const auto n = static_cast<std::ptrdiff_t>(particles_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    const auto p = static_cast<std::size_t>(q);
    point_values_[p] = Vec3(particles_.velocity_gradient[p].trace(), 1.0, 0.0);
  }
  smooth_point_values();
  transfer_.interpolate(node_scratch_, node_scratch_, [&](std::size_t p, const Vec3& smoothed, const Vec3&) {
    Mat3& l = particles_.velocity_gradient[p];
    const double shift = (smoothed[0] - l.trace()) / dim;
    for (int a = 0; a < dim; ++a) l(a, a) += shift;
  });
}

void Simulation::smoothed_mean_stress_correction() {
  // The B-bar internal force: the stress power of the smoothed update is
  //   Σ_p V_p σ_p : L̄_p = Σ_p V_p [σ'_p : L_p + π_p tr L̄_p],
  // with π_p the in-plane mean stress (tr σ over the d in-plane axes, / d) and σ' = σ − π I_d. The
  // grid force conjugate to it, P = −Σ_j f_j·v_j, is f_j = −Σ_p V_p (σ'_p ∇N_jp + π_p B̄_jp), and by
  // the symmetry of N M_n⁻¹ Nᵀ (smooth_dilatation) Σ_p V_p π_p B̄_jp = Σ_p m_p π̃_p ∇N_jp with
  //   π̃_p = Σ_i N_ip (Σ_q N_iq V_q π_q) / m_i,
  // i.e. f_j = −Σ_p (V_p σ_p + c_p I_d)·∇N_jp,  c_p = m_p π̃_p − V_p π_p  (docs/theory/mpm.md, "B-bar").
  const int dim = grid_.dim();
  point_values_.resize(particles_.size());
  mean_stress_correction_.resize(particles_.size());
  const auto n = static_cast<std::ptrdiff_t>(particles_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    const auto p = static_cast<std::size_t>(q);
    const Mat3 sigma = particles_.state[p].stress();
    double mean = 0.0;
    for (int a = 0; a < dim; ++a) mean += sigma(a, a);
    mean_stress_correction_[p] = -particles_.volume(p) * mean / dim;  // −V_p π_p, π̃ added below
    point_values_[p] = Vec3(-mean_stress_correction_[p] / particles_.mass[p], 1.0, 0.0);  // V_p π_p / m_p
  }
  smooth_point_values();
  transfer_.interpolate(node_scratch_, node_scratch_, [&](std::size_t p, const Vec3& smoothed, const Vec3&) {
    mean_stress_correction_[p] += particles_.mass[p] * smoothed[0];
  });
}

void Simulation::smooth_point_values() {
  // node_scratch_[i].x = Σ_q m_q N_iq u_q / m_i for u_q = point_values_[q].x, with m_i = Σ_q m_q N_iq
  // formed by the same sum (point_values_[q].y = 1) so that it does not need the grid's fields;
  // zero on nodes without mass (the mass floor of the nodal velocities).
  node_scratch_.resize(grid_.field_size());
  transfer_.mass_weighted_to_grid(particles_, point_values_, node_scratch_);
  const auto nn = static_cast<std::ptrdiff_t>(grid_.field_size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t q = 0; q < nn; ++q) {
    Vec3& node = node_scratch_[static_cast<std::size_t>(q)];
    node = node[1] > mass_floor_ ? Vec3(node[0] / node[1], 0.0, 0.0) : Vec3::Zero();
  }
}

void Simulation::update_materials() {
  // L_p = Σ_i v_i ⊗ ∇N_i(x_p), then the material update of the point with it.
  const double length = grid_.min_cell_size();
  const bool plane_strain = grid_.dim() == 2;
  std::size_t failed = particles_.size();
  std::string why;
  const bool smooth = options_.smooth_dilatation;
  transfer_.gradient(node_velocity_, particles_.velocity_gradient, [&](std::size_t p) {
    if (smooth) return;  // the update follows once every L_p is known
    update_material(p, length, plane_strain, failed, why);
  });
  if (smooth) {
    smooth_dilatation();
    const auto n = static_cast<std::ptrdiff_t>(particles_.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t q = 0; q < n; ++q)
      update_material(static_cast<std::size_t>(q), length, plane_strain, failed, why);
  }
  if (failed < particles_.size())
    throw RunError(fmt::format("mpm: particle {} at t = {} s (step {}): {}", failed, time_, steps_, why));
}

void Simulation::update_material(std::size_t p, double length, bool plane_strain, std::size_t& failed,
                                 std::string& why) {
  const Mat3& l = particles_.velocity_gradient[p];
  const auto& mat = materials_[static_cast<std::size_t>(particles_.material[p])];
  try {
    mat.update(particles_.state[p], particles_.mass[p] / particles_.volume0[p], l, dt_, length, plane_strain);
  } catch (const RunError& e) {
#pragma omp critical(mpm_material_failure)
    if (p < failed) {
      failed = p;
      why = e.what();
    }
  }
  track_fastest(p);
}

void Simulation::wrap_particles() {
  for (std::size_t p = 0; p < particles_.size(); ++p)
    if (!grid_.wrap_position(particles_.x[p])) throw_left_grid(p);
}

void Simulation::throw_left_grid(std::size_t p) const {
  const Vec3& x = particles_.x[p];
  throw RunError(fmt::format("mpm: particle {} at ({}, {}, {}) m has left the grid at t = {} s", p, x[0], x[1], x[2],
                             time_));
}

}  // namespace shockfield::mpm

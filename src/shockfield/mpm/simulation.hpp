#pragma once
// The material point method simulation (Xu et al. 2015, §2.2.2): owns its grid, particles and
// materials, and its explicit time loop. One step (MUSL, Sulsky, Zhou & Schreyer, Comput. Phys.
// Commun. 87 (1995) 236; USL as an option):
//   1. Δt = C·Δx_min / max_p(c_p + |v_p|)                        (stable step, Xu et al. (2015) §2.2.2)
//   2. particles → grid: m_i, m_i v_i, f_i^int                   (eq. 12)
//   3. grid: m_i v_i += f_i Δt; rigid walls                       (eq. 12, explicit)
//   4. grid → particles: v_p += Δt Σ N_i f_i/m_i (FLIP; PIC v_p = Σ N_i v_i in the first step;
//      or XPIC(m), Hammerquist & Nairn 2017), x_p += Δt Σ N_i v_i
//   5. MUSL: map the new particle momenta back to the grid and impose walls again
//   6. L_p = Σ_i v_i ⊗ ∇N_i(x_p); material update of every point (materials::SolidMaterial)
// With `contact` (contact.hpp), each body has its own nodal fields: step 2 scatters every point into
// its body's layer, and the contact law couples the layers after step 3 and after the MUSL remap
// of step 5 (so both the particle update and L_p see it).
// With `heat_conduction`, step 2 is followed by an explicit conduction step on the same stencils
// (heat_conduction.hpp), and Δt is also bounded by the diffusion limit C·h²/(2·d·α_max).
// Hooks run at named stages so drivers add loading, diagnostics and output without touching the
// loop: BeforeStep (Δt known), AfterGridUpdate (nodal momenta after step 3, may be modified),
// EndOfStep.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "shockfield/materials/solid_material.hpp"
#include "shockfield/mpm/contact.hpp"
#include "shockfield/mpm/grid.hpp"
#include "shockfield/mpm/heat_conduction.hpp"
#include "shockfield/mpm/particles.hpp"
#include "shockfield/mpm/transfer.hpp"

namespace shockfield::mpm {

enum class UpdateScheme { MUSL, USL };
enum class Stage { BeforeStep, AfterGridUpdate, EndOfStep };

struct SimulationOptions {
  UpdateScheme scheme = UpdateScheme::MUSL;
  ShapeKind shape = ShapeKind::Linear;
  double courant = 0.3;        ///< C of the stable step, in (0, 1]
  double flip = 1.0;           ///< FLIP fraction of the velocity update (1 FLIP, 0 PIC)
  /// XPIC(m) velocity update (Hammerquist & Nairn 2017) instead of the FLIP/PIC blend: 0 off, m >= 1
  /// (1 is PIC; larger m keeps more of what the grid resolves and drops the null-space noise).
  int xpic_order = 0;
  /// Replace tr L_p by its mass-weighted nodal average over the point's stencil, and the grid force
  /// by the work-conjugate B-bar force (simulation.cpp).
  bool smooth_dilatation = false;
  /// The first step is PIC (flip 0): the initial velocities are projected onto the grid's field
  /// (simulation.cpp, grid_to_particles). Off only to study what it removes.
  bool project_initial_velocity = true;
  double min_time_step = 0.0;  ///< RunError when Δt falls below this [s]
  bool heat_conduction = false;  ///< solve heat conduction with the materials' conductivities
  ContactOptions contact{};      ///< multi-body contact (off: all bodies share one grid field)

  void validate() const;
};

class Simulation {
 public:
  using Hook = std::function<void(Simulation&)>;

  Simulation(const GridSpec& grid, std::vector<materials::SolidMaterial> materials, Particles particles,
             SimulationOptions options = {});

  void add_hook(Stage stage, Hook hook);
  /// Δt = C·Δx_min / max_p(c_p + |v_p|) for the current state (and, with heat conduction, at
  /// most C·Δx_min² / (2·d·α_max)).
  double stable_time_step() const;
  /// One step of at most `max_dt` (defaults to the stable step).
  void step(double max_dt = 0.0);
  /// Step until time() reaches t_end; the last step is shortened to land on it.
  void run_until(double t_end);

  double time() const { return time_; }
  long step_count() const { return steps_; }
  double last_time_step() const { return dt_; }
  /// Sets the clock of a run restored from a checkpoint (particles restored by the caller).
  void restore_clock(double time, long steps, double last_dt) { time_ = time, steps_ = steps, dt_ = last_dt; }
  const Grid& grid() const { return grid_; }
  Grid& grid() { return grid_; }
  const Particles& particles() const { return particles_; }
  Particles& particles() {
    fastest_known_ = false;  // the caller may change velocities or states
    return particles_;
  }
  const std::vector<materials::SolidMaterial>& materials() const { return materials_; }
  const SimulationOptions& options() const { return options_; }
  /// Bodies with their own grid field: 1 + the largest Particles::body with contact on, else 1.
  int contact_bodies() const { return grid_.layers(); }
  /// The contact law's action in the last step, after its momentum update (zero without contact).
  const ContactStats& contact_stats() const { return contact_stats_; }

 private:
  void run_hooks(Stage stage);
  /// C·Δx_min² / (2·d·α_max) with heat conduction, +∞ without.
  double conduction_time_step() const;
  /// The grid's nodal fields and the nodal velocities and accelerations, at the first step.
  void allocate_grid();
  void update_grid();
  /// The contact law on the nodal momenta (contact.hpp), with more than one body layer.
  ContactStats couple_bodies();
  /// v_i = (m v)_i / m_i and (with_acceleration) a_i = f_i / m_i; zero on nodes without mass.
  void nodal_velocities(bool with_acceleration);
  /// v_p, x_p from the grid (with `remap`, fused with the MUSL remap of the momenta).
  void grid_to_particles(bool remap);
  /// XPIC(m): the nodal velocity the particles take, v*_m + (v^L − v^n) (simulation.cpp).
  void xpic_velocities();
  /// L_p from the nodal velocities, then the material update of every point (the last
  /// particle loop of a step).
  void update_materials();
  /// The material update of point p with its L_p (records the first failure in failed/why).
  void update_material(std::size_t p, double length, bool plane_strain, std::size_t& failed, std::string& why);
  /// tr L_p ← its mass-weighted nodal average (options.smooth_dilatation, B-bar).
  void smooth_dilatation();
  /// The B-bar force's per-point term c_p = m_p π̃_p − V_p π_p added to V_p σ_p in step 2, so the
  /// grid force is work-conjugate to the smoothed L_p (options.smooth_dilatation).
  void smoothed_mean_stress_correction();
  /// node_scratch_.x ← the mass-weighted nodal average of point_values_.x (point_values_.y = 1).
  void smooth_point_values();
  /// Record c_p + |v_p| for the next stable step.
  void track_fastest(std::size_t p);
  void wrap_particles();
  [[noreturn]] void throw_left_grid(std::size_t p) const;

  Grid grid_;
  std::vector<materials::SolidMaterial> materials_;
  Particles particles_;
  SimulationOptions options_;
  Transfer transfer_;
  HeatConduction heat_;
  std::array<std::vector<Hook>, 3> hooks_;
  std::vector<Vec3> old_momentum_;
  std::vector<Vec3> node_velocity_;
  std::vector<Vec3> node_acceleration_;
  std::vector<Vec3> xpic_velocity_, xpic_increment_;  // XPIC(m): v*, its last term
  std::vector<Vec3> node_scratch_;  // a nodal sum on its way (XPIC's S⁺S of the term, the smoothed tr L)
  std::vector<Vec3> point_values_;  // a value per particle on its way to the grid
  std::vector<double> mean_stress_correction_;  // B-bar force term c_p (empty: option off)
  struct alignas(64) PerThread {  // one cache line per OpenMP thread
    double fastest;    ///< max_p c_p + |v_p| [m/s]
    std::size_t lost;  ///< smallest index of a point that left the grid (size() if none)
  };
  std::vector<PerThread> per_thread_;
  double fastest_ = 0.0;
  bool fastest_known_ = false;
  double mass_floor_ = 0.0;
  ContactStats contact_stats_{};
  double time_ = 0.0;
  double dt_ = 0.0;
  long steps_ = 0;
};

}  // namespace shockfield::mpm

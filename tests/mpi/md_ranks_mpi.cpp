// MD on however many ranks mpirun starts (ctest label mpi: 1, 2 and 4 ranks, 2 ranks x 2 threads),
// against the serial run of the same system that every rank also makes (docs/parallel.md, "MD on
// the rank grid"). Cases: Cu EAM (Cu_u3) and argon LJ fcc crystals, thermally perturbed, under NVE
// and Nose-Hoover NVT; and a crystal translated diagonally at the largest speed the run allows
// (0.45 Å per step, 0.9 of the half-skin: check_health refuses more; 120 steps move an atom
// 31 Å along each axis, about three pieces), so that atoms cross the pieces'
// faces, edges and corners many times. Checked:
//   - the forces of the first step equal the serial ones by atom id within 1e-11 eV/Å (the sums
//     over neighbours and the EAM densities are added in another order: round-off of a ~10 eV/Å
//     sum of ~100 terms is ~1e-14 eV/Å; 1e-11 leaves room and still fails on any lost pair, whose
//     force is >1e-4 eV/Å);
//   - every step: the global atom count is N; the thermo (pe, ke, pressure) equals the serial one
//     to a relative 1e-10 (round-off grown by the trajectories' divergence over ≤ 120 steps);
//   - at the end: every id 1..N is owned by exactly one rank, and the positions equal the serial
//     ones within 1e-8 Å (minimum image).
// Exit 0 when every rank passes. Usage: test_md_ranks_mpi [PxQxR] | --stop FILE | --resume FILE
#include <fmt/format.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "shockfield/core/config.hpp"
#include "shockfield/core/rng.hpp"
#include "shockfield/md/checkpoint.hpp"
#include "shockfield/md/decomposition.hpp"
#include "shockfield/md/fixes/langevin.hpp"
#include "shockfield/md/fixes/nose_hoover.hpp"
#include "shockfield/md/fixes/nve.hpp"
#include "shockfield/md/lattice.hpp"
#include "shockfield/md/potentials/registry.hpp"
#include "shockfield/md/simulation.hpp"
#include "shockfield/md/velocity.hpp"
#include "shockfield/parallel/rank_grid.hpp"

using namespace shockfield;
using namespace shockfield::md;

namespace {

int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok && failures++ < 20) std::fprintf(stderr, "rank %d: %s\n", parallel::Communicator::world().rank(), what.c_str());
}

struct Case {
  std::string name, potential;
  double a0, mass;
  int cells;
  std::string ensemble;  // nve, nvt (Nose-Hoover) or langevin (random forces keyed by atom id)
  double translation;  // speed along (1,1,1) as a fraction of the largest allowed, 0: none
  int steps;
};

Atoms crystal(const Case& c, geometry::Box& box) {
  LatticeSpec spec;
  spec.a0 = c.a0;
  const Lattice lattice(spec);
  box = lattice.box({c.cells, c.cells, c.cells}, {geometry::Boundary::periodic, geometry::Boundary::periodic,
                                                  geometry::Boundary::periodic});
  Atoms atoms;
  atoms.mass = {c.mass};
  atoms.type_names = {""};
  lattice.create_atoms(box, atoms);
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    for (int d = 0; d < 3; ++d) atoms.x[i][d] += 0.05 * (2.0 * rng::uniform(7, i, d) - 1.0);
  create_velocities(atoms, c.translation > 0 ? 10.0 : 600.0, 4928459);
  return atoms;
}

Simulation simulation(const Case& c, const geometry::Box& box, Atoms atoms) {
  const Config config = Config::parse(c.potential, "test.toml");
  Simulation sim(box, std::move(atoms), potentials::make_potential(config, ".", 1), 0.001, 1.0);
  if (c.translation > 0) {
    const double speed = c.translation * 0.5 * sim.skin / sim.dt / std::sqrt(3.0);
    for (auto& v : sim.atoms.v) v += Vec3(speed, speed, speed);
  }
  if (c.ensemble == "nvt") sim.fixes.push_back(std::make_unique<FixNoseHoover>(300.0, 0.1));
  else if (c.ensemble == "langevin") sim.fixes.push_back(std::make_unique<FixLangevin>(300.0, 0.1, 87));
  else sim.fixes.push_back(std::make_unique<FixNve>());
  return sim;
}

// Every rank's owned atoms by id: id -> (x, f).
std::map<long long, std::array<Vec3, 2>> by_id(const Simulation& sim) {
  std::vector<double> mine;
  for (std::size_t i = 0; i < sim.atoms.nlocal; ++i) {
    mine.push_back(static_cast<double>(sim.atoms.id[i]));
    for (int d = 0; d < 3; ++d) mine.push_back(sim.atoms.x[i][d]);
    for (int d = 0; d < 3; ++d) mine.push_back(sim.atoms.f[i][d]);
  }
  const std::vector<double> all = sim.domain ? sim.domain->comm().all_gather(mine) : mine;
  std::map<long long, std::array<Vec3, 2>> out;
  for (std::size_t k = 0; k < all.size(); k += 7) {
    const auto id = static_cast<long long>(all[k]);
    check(out.count(id) == 0, "atom " + std::to_string(id) + " is owned twice");
    out[id] = {Vec3(all[k + 1], all[k + 2], all[k + 3]), Vec3(all[k + 4], all[k + 5], all[k + 6])};
  }
  return out;
}

// The largest distance (minimum image) between an atom's positions in the two runs, by id.
double largest_position_difference(const Simulation& serial, const Simulation& split) {
  const auto a = by_id(serial), b = by_id(split);
  const Vec3 length = serial.box.length();
  double worst = 0;
  for (const auto& [id, xf] : a) {
    if (!b.count(id)) continue;
    Vec3 dx = b.at(id)[0] - xf[0];
    for (int d = 0; d < 3; ++d) dx[d] -= length[d] * std::round(dx[d] / length[d]);
    worst = std::max(worst, dx.norm());
  }
  return worst;
}

bool close(double a, double b, double relative) { return std::abs(a - b) <= relative * std::max(1.0, std::abs(b)); }

void run_case(const Case& c, const parallel::Dims3& given) {
  geometry::Box box;
  const Atoms all = crystal(c, box);
  Simulation serial = simulation(c, box, all);
  serial.setup(false);

  const parallel::Communicator world = parallel::Communicator::world();
  const double range = serial.potential->cutoff() + serial.skin;
  const parallel::Dims3 dims = md_rank_grid(box, range, world.size(), given);
  auto domain = std::make_shared<Decomposition>(world, dims, box, range);
  Atoms mine = all;
  keep_own_atoms(*domain, mine);
  Simulation split = simulation(c, box, std::move(mine));
  split.domain = domain;
  split.setup(false);

  const std::string what = c.name + fmt::format(" on {}x{}x{}", dims[0], dims[1], dims[2]);
  const long long n = static_cast<long long>(all.nlocal);
  double force_difference = 0;
  {
    const auto a = by_id(serial), b = by_id(split);
    check(static_cast<long long>(b.size()) == n, what + ": atoms lost or duplicated at the start");
    double worst = 0;
    for (const auto& [id, xf] : a) worst = std::max(worst, (b.count(id) ? (b.at(id)[1] - xf[1]).norm() : 1e300));
    check(worst <= 1e-11, what + fmt::format(": forces differ from the serial ones by {:.3g} eV/Å", worst));
    force_difference = worst;
  }
  const auto no_output = [](std::int64_t) { return false; };
  for (int s = 0; s < c.steps; ++s) {
    serial.advance(no_output);
    split.advance(no_output);
    check(domain->total_atoms(split.atoms) == n, what + fmt::format(": step {}: {} atoms, not {}", s + 1,
                                                                  domain->total_atoms(split.atoms), n));
    const ThermoState t0 = serial.thermo(), t1 = split.thermo();
    check(close(t1.potential, t0.potential, 1e-10) && close(t1.kinetic, t0.kinetic, 1e-10) &&
              close(t1.pressure, t0.pressure, 1e-10),
          what + fmt::format(": step {}: thermo pe {} ke {} p {} vs serial {} {} {}", s + 1, t1.potential, t1.kinetic,
                             t1.pressure, t0.potential, t0.kinetic, t0.pressure));
  }
  check(static_cast<long long>(by_id(split).size()) == n, what + ": atoms lost or duplicated at the end");
  const double worst = largest_position_difference(serial, split);
  check(worst <= 1e-8, what + fmt::format(": positions differ from the serial ones by {:.3g} Å", worst));
  if (world.is_root())
    std::printf("%s: %lld atoms, %d steps, %lld rebuilds; largest difference from serial: first forces %.3g eV/Å, "
                "final positions %.3g Å\n", what.c_str(), n, c.steps, static_cast<long long>(split.rebuilds),
                force_difference, worst);
}

// A run stopped on one rank count and resumed on another (tests/mpi/md_restart.sh): `--stop FILE`
// runs the Cu EAM NVE case 20 steps decomposed, gathers the atoms on rank 0 and writes the serial
// checkpoint; `--resume FILE` reads it on every rank, deals the atoms out, runs 20 more steps and
// compares with the uninterrupted serial 40 steps: positions within 1e-8 Å by id, thermo within
// a relative 1e-10 (round-off, as above).
void stop_or_resume(const Case& c, const std::string& mode, const std::string& file) {
  constexpr int half = 20;
  geometry::Box box;
  const Atoms all = crystal(c, box);
  const parallel::Communicator world = parallel::Communicator::world();
  Simulation whole = simulation(c, box, all);
  const double range = whole.potential->cutoff() + whole.skin;
  auto domain = std::make_shared<Decomposition>(world, md_rank_grid(box, range, world.size(), {0, 0, 0}), box, range);
  const auto no_output = [](std::int64_t) { return false; };
  if (mode == "--resume") read_checkpoint(file, whole);  // every rank reads the whole system
  Atoms mine = whole.atoms;
  keep_own_atoms(*domain, mine);
  Simulation split = simulation(c, box, std::move(mine));
  split.step = whole.step;
  split.time = whole.time;
  split.domain = domain;
  split.setup(false);
  for (int s = 0; s < half; ++s) split.advance(no_output);
  if (mode == "--stop") {
    Atoms gathered = gather_atoms(*domain, split.atoms);
    if (world.is_root()) {
      Simulation at_stop = simulation(c, box, std::move(gathered));
      at_stop.step = split.step;
      at_stop.time = split.time;
      at_stop.setup(false);
      write_checkpoint(file, at_stop, {0, split.step});
      std::printf("%s: stopped at step %lld on %d ranks, %zu atoms gathered\n", c.name.c_str(),
                  static_cast<long long>(split.step), world.size(), at_stop.atoms.nlocal);
    }
    return;
  }
  Simulation serial = simulation(c, box, all);
  serial.setup(false);
  for (int s = 0; s < 2 * half; ++s) serial.advance(no_output);
  check(split.step == serial.step, "the resumed run ends at another step");
  check(by_id(split).size() == by_id(serial).size(), "atoms lost or duplicated in the resumed run");
  const double worst = largest_position_difference(serial, split);
  check(worst <= 1e-8, fmt::format("resumed: positions differ from the uninterrupted serial run by {:.3g} Å", worst));
  const ThermoState t0 = serial.thermo(), t1 = split.thermo();
  check(close(t1.potential, t0.potential, 1e-10) && close(t1.kinetic, t0.kinetic, 1e-10),
        fmt::format("resumed: thermo pe {} ke {} vs uninterrupted {} {}", t1.potential, t1.kinetic, t0.potential, t0.kinetic));
  if (world.is_root())
    std::printf("%s: resumed on %d ranks to step %lld; largest position difference from the uninterrupted serial "
                "run %.3g Å\n", c.name.c_str(), world.size(), static_cast<long long>(split.step), worst);
}

}  // namespace

int main(int argc, char** argv) {
  const parallel::Environment mpi(argc, argv);
  const parallel::Communicator world = parallel::Communicator::world();
  const std::string mode = argc > 2 ? argv[1] : "";
  parallel::Dims3 given{0, 0, 0};
  if (argc == 2) given = parallel::parse_rank_grid(argv[1]);
  const std::string eam = "style = \"eam\"\nfile = \"Cu_u3.eam\"\n";
  const std::string lj = "style = \"lj/cut\"\nepsilon = 0.0104\nsigma = 3.4\ncutoff = 8.5\n";
  const Case cases[] = {
      {"Cu EAM NVE", eam, 3.615, 63.55, 6, "nve", 0.0, 50},
      {"Cu EAM NVT", eam, 3.615, 63.55, 6, "nvt", 0.0, 50},
      {"Cu EAM Langevin", eam, 3.615, 63.55, 6, "langevin", 0.0, 50},
      {"Ar LJ NVE", lj, 5.26, 39.948, 5, "nve", 0.0, 50},
      {"Ar LJ NVT", lj, 5.26, 39.948, 5, "nvt", 0.0, 50},
      {"Cu EAM across corners", eam, 3.615, 63.55, 6, "nve", 0.9, 120},
  };
  try {
    if (mode == "--stop" || mode == "--resume") stop_or_resume(cases[0], mode, argv[2]);
    else for (const Case& c : cases) run_case(c, given);
  } catch (const std::exception& e) {
    check(false, std::string("exception: ") + e.what());
  }
  const int passed = world.min(failures == 0 ? 1 : 0);
  if (world.is_root()) std::printf("%s (%d ranks, %d threads)\n", passed ? "passed" : "FAILED", world.size(), omp_get_max_threads());
  return passed ? 0 : 1;
}

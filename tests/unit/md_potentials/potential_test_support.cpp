#include "unit/md_potentials/potential_test_support.hpp"

#include <algorithm>
#include <cmath>

#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/md/force_evaluation.hpp"
#include "shockfield/md/ghosts.hpp"
#include "shockfield/md/potentials/registry.hpp"

namespace shockfield::md::potentials::testing {

System load_dump_system(const std::filesystem::path& file) {
  const auto frames = io::read_dump(file);
  const auto& frame = frames.front();
  System s;
  s.box = frame.box;
  const auto ids = frame.ids();
  const auto types = frame.types();
  const auto x = frame.positions();
  int ntypes = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    s.atoms.add(x[i], types[i] - 1, ids[i]);
    ntypes = std::max(ntypes, types[i]);
  }
  s.atoms.mass.assign(static_cast<std::size_t>(ntypes), 1.0);
  return s;
}

std::unique_ptr<Potential> potential_from_toml(const std::string& toml, int ntypes) {
  const Config root = Config::parse(toml, "test.toml");
  auto potential = make_potential(root.table("potential"), std::filesystem::current_path(), ntypes);
  root.check_unknown_keys();
  return potential;
}

Evaluation evaluate(const System& system, Potential& potential, bool per_atom) {
  System s = system;
  constexpr double skin = 0.5;  // a realistic list: pairs beyond the cutoff must be skipped
  rebuild_ghosts(s.atoms, s.box, potential.cutoff() + skin);
  geometry::NeighborList list;
  build_neighbor_list(s.atoms.x, s.atoms.nlocal, potential.cutoff() + skin, true, list);
  Evaluation e;
  evaluate_forces(s.atoms, potential, list, e.result, per_atom);
  e.force.assign(s.atoms.f.begin(), s.atoms.f.begin() + static_cast<std::ptrdiff_t>(s.atoms.nlocal));
  return e;
}

double max_norm_relative(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    diff = std::max(diff, std::abs(a[k] - b[k]));
    scale = std::max(scale, std::abs(b[k]));
  }
  return diff / scale;
}

}  // namespace shockfield::md::potentials::testing

#include "shockfield/md/state_arrays.hpp"

#include "shockfield/core/state_array.hpp"
#include "shockfield/md/ghosts.hpp"

namespace shockfield::md {

std::vector<StateArray> atom_state_arrays(Simulation& sim, const AtomUnits& units) {
  Atoms& a = sim.atoms;
  // A neighbour rebuild resizes x, type and f (and energy_atom while computing) to owned +
  // ghost entries: room for the most the box can give keeps them in place. Reserved, not
  // touched: the pages beyond the entries in use are never written.
  const std::size_t room = most_entries(a.nlocal, sim.box, sim.potential->cutoff() + sim.skin);
  a.x.reserve(room);
  a.type.reserve(room);
  a.f.reserve(room);
  std::vector<StateArray> arrays{state_array("positions", a.x, a.nlocal, units.length),
                                 state_array("velocities", a.v, a.nlocal, units.velocity),
                                 state_array("forces", a.f, a.nlocal, units.force),
                                 state_array("types", a.type, a.nlocal),
                                 state_array("ids", a.id, a.nlocal),
                                 state_array("images", a.image, a.nlocal)};
  if (!sim.forces.energy_atom.empty()) {
    sim.forces.energy_atom.reserve(room);
    arrays.push_back(state_array("energies", sim.forces.energy_atom, a.nlocal, units.energy));
  }
  return arrays;
}

std::vector<DerivedArray> box_arrays(const geometry::Box& box, const std::string& length_unit) {
  auto three = [&length_unit](const char* name, const Vec3& v) {
    return DerivedArray{name, {v.x(), v.y(), v.z()}, {3}, length_unit};
  };
  DerivedArray cell{"cell", {}, {3, 3}, length_unit};
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 3; ++k) cell.values.push_back(box.edge(d)[k]);
  return {three("box_lo", box.lo), three("box_hi", box.hi), three("box_tilt", box.tilt), std::move(cell)};
}

}  // namespace shockfield::md

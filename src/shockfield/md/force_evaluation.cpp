#include "shockfield/md/force_evaluation.hpp"

namespace shockfield::md {

void evaluate_forces(Atoms& atoms, Potential& potential, const geometry::NeighborList& list,
                     ForceResult& result, bool per_atom) {
  atoms.f.assign(atoms.size(), Vec3::Zero());
  result.reset(atoms.size(), per_atom);
  potential.compute(atoms, list, result);
  atoms.reverse_sum(atoms.f);
  atoms.f.resize(atoms.nlocal);
  if (per_atom) {
    atoms.reverse_sum(result.energy_atom);
    atoms.reverse_sum(result.virial_atom);
    result.energy_atom.resize(atoms.nlocal);
    result.virial_atom.resize(atoms.nlocal);
  }
}

}  // namespace shockfield::md

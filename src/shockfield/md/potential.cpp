#include "shockfield/md/potential.hpp"

namespace shockfield::md {

void ForceResult::reset(std::size_t n, bool want_per_atom) {
  energy = 0;
  virial.setZero();
  per_atom = want_per_atom;
  if (want_per_atom) {
    energy_atom.assign(n, 0.0);
    virial_atom.assign(n, Voigt6::Zero());
  } else {
    energy_atom.clear();
    virial_atom.clear();
  }
}

}  // namespace shockfield::md

#include "shockfield/mpm/particles.hpp"

namespace shockfield::mpm {

void Particles::add(const Vec3& position, const Vec3& velocity, double volume, const Vec3& half,
                    const materials::SolidMaterial& mat, int material_id, int body_id) {
  x.push_back(position);
  v.push_back(velocity);
  mass.push_back(mat.eos.rho0 * volume);
  volume0.push_back(volume);
  half_size.push_back(half);
  material.push_back(material_id);
  body.push_back(body_id);
  velocity_gradient.push_back(Mat3::Zero());
  state.push_back(mat.initial_state());
}

Totals totals(const Particles& p) {
  Totals t;
  for (std::size_t i = 0; i < p.size(); ++i) {
    t.mass += p.mass[i];
    t.momentum += p.mass[i] * p.v[i];
    t.kinetic += 0.5 * p.mass[i] * p.v[i].squaredNorm();
    t.internal += p.mass[i] * p.state[i].energy;
  }
  return t;
}

}  // namespace shockfield::mpm

#include "shockfield/analysis/atoms/burgers_circuit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <numeric>
#include <unordered_map>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

constexpr double kReliableError = 0.25;  // half the 0.577 gap between vectors of S, with margin
constexpr double kMaxBond = 1.5;         // a step longer than this (nn distances) is not a bond

std::vector<Vec3i> make_step_set() {
  std::vector<Vec3i> s;
  for (int i = 0; i < 3; ++i)  // perfect a/2<110>: two components ±3, one 0
    for (int j = i + 1; j < 3; ++j)
      for (int si : {3, -3})
        for (int sj : {3, -3}) {
          Vec3i v = Vec3i::Zero();
          v[i] = si;
          v[j] = sj;
          s.push_back(v);
        }
  const std::vector<Vec3i> perfect = s;
  // Mirror in the plane of normal n: v − 2 (v·n)/(n·n) n; v·n = ±6 for out-of-plane steps, so the
  // mirror is v ∓ 4n, an integer vector of the same length (18 = 3² + 3²).
  for (const Vec3i& n : {Vec3i(1, 1, 1), Vec3i(-1, 1, 1), Vec3i(1, -1, 1), Vec3i(1, 1, -1)})
    for (const Vec3i& v : perfect) {
      const int vn = v.dot(n);
      if (vn == 0) continue;
      const Vec3i m = v - (2 * vn / 3) * n;
      if (std::find(s.begin(), s.end(), m) == s.end()) s.push_back(m);
    }
  return s;
}

// Nearest vector of S to `step` (units a/6) and the distance to it.
std::pair<Vec3i, double> nearest_step(const Vec3& step) {
  const auto& set = frank_step_set();
  Vec3i best = set.front();
  double best_d2 = INFINITY;
  for (const Vec3i& v : set) {
    const double d2 = (step - v.cast<double>()).squaredNorm();
    if (d2 < best_d2) best_d2 = d2, best = v;
  }
  return {best, std::sqrt(best_d2)};
}

int gcd3(const Vec3i& v) { return std::gcd(std::gcd(std::abs(v[0]), std::abs(v[1])), std::abs(v[2])); }

}  // namespace

CrystalFrame CrystalFrame::from_orient(const std::array<Vec3i, 3>& orient, double lattice_constant,
                                       const std::string& what) {
  if (!(lattice_constant > 0) || !std::isfinite(lattice_constant))
    throw InputError(fmt::format("{}: the lattice constant must be a finite number > 0 (got {})", what, lattice_constant));
  const char* axis = "xyz";
  for (int d = 0; d < 3; ++d)
    if (orient[d].isZero()) throw InputError(fmt::format("{}: orient {} is the zero vector", what, axis[d]));
  for (int d = 0; d < 3; ++d)
    for (int e = d + 1; e < 3; ++e)
      if (orient[d].dot(orient[e]) != 0)
        throw InputError(fmt::format("{}: orient {} and {} are not orthogonal", what, axis[d], axis[e]));
  if (orient[0].cross(orient[1]).dot(orient[2]) <= 0)
    throw InputError(fmt::format("{}: orient x, y, z are not right-handed ((x × y)·z must be > 0)", what));
  CrystalFrame c;
  for (int d = 0; d < 3; ++d) c.crystal_from_lab.col(d) = orient[d].cast<double>().normalized();
  c.lattice_constant = lattice_constant;
  return c;
}

double CrystalFrame::neighbor_distance() const { return lattice_constant / std::numbers::sqrt2; }
double CrystalFrame::bond_cutoff() const { return 0.5 * (1.0 / std::numbers::sqrt2 + 1.0) * lattice_constant; }

const std::vector<Vec3i>& frank_step_set() {
  static const std::vector<Vec3i> set = make_step_set();
  return set;
}

std::vector<std::size_t> circuit_around(const AtomFrame& frame, const NeighborTable& table, const AxisCircuit& spec) {
  if (!(spec.axis.norm() > 0)) throw InputError("Burgers circuit: the axis must be a non-zero vector");
  if (!(spec.radius > 0) || !(spec.band > 0) || !(spec.slab > 0) || spec.band >= spec.radius)
    throw InputError(fmt::format("Burgers circuit: expected radius > band > 0 and slab > 0 (got radius {}, band {}, slab {})",
                                 spec.radius, spec.band, spec.slab));
  table.require({spec.bond_cutoff, 0}, "Burgers circuit");
  const Vec3 xi = spec.axis.normalized();
  const Vec3 e1 = (std::abs(xi.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(xi).normalized();
  const Vec3 e2 = xi.cross(e1);  // (e1, e2, ξ) right-handed: increasing θ is right-handed about ξ
  // The atoms of the band and their angle θ about the axis.
  std::unordered_map<std::size_t, int> index_of;
  std::vector<std::size_t> atoms;
  std::vector<double> theta;
  std::size_t start = 0;
  double start_score = INFINITY;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const Vec3 d = frame.box.minimum_image(frame.positions[i] - spec.centre);
    const double along = d.dot(xi);
    const Vec3 perp = d - along * xi;
    const double rho = perp.norm();
    if (std::abs(along) > spec.slab || std::abs(rho - spec.radius) > spec.band) continue;
    const double t = std::atan2(perp.dot(e2), perp.dot(e1));
    const double score = std::pow(t * spec.radius, 2) + std::pow(rho - spec.radius, 2) + along * along;
    if (score < start_score) start_score = score, start = atoms.size();
    index_of.emplace(i, static_cast<int>(atoms.size()));
    atoms.push_back(i);
    theta.push_back(t);
  }
  if (atoms.size() < 3)
    throw InputError(fmt::format("Burgers circuit around ({:.6g}, {:.6g}, {:.6g}): only {} atoms in the band of radius {} ± {} Å "
                                 "(slab ± {} Å); widen the band or the slab",
                                 spec.centre.x(), spec.centre.y(), spec.centre.z(), atoms.size(), spec.radius, spec.band, spec.slab));
  // Breadth-first search over (atom, sheet): crossing the cut θ = ±π counter-clockwise adds one to
  // the sheet. The shortest path from (start, 0) to (start, 1) winds once, right-handed.
  constexpr int kSheets = 5, kOffset = 2;
  const double cut2 = spec.bond_cutoff * spec.bond_cutoff;
  const std::size_t n = atoms.size();
  std::vector<int> previous(n * kSheets, -2);
  auto state = [&](std::size_t k, int sheet) { return k * kSheets + static_cast<std::size_t>(sheet + kOffset); };
  std::deque<std::size_t> queue{state(start, 0)};
  previous[queue.front()] = -1;
  const std::size_t goal = state(start, 1);
  while (!queue.empty() && previous[goal] == -2) {
    const std::size_t s = queue.front();
    queue.pop_front();
    const std::size_t k = s / kSheets;
    const int sheet = static_cast<int>(s % kSheets) - kOffset;
    const std::size_t i = atoms[k];
    for (int entry : table.of(i)) {
      if (table.delta(i, entry).squaredNorm() >= cut2) break;  // nearest first
      const auto found = index_of.find(static_cast<std::size_t>(table.owner(entry)));
      if (found == index_of.end()) continue;
      const std::size_t m = static_cast<std::size_t>(found->second);
      double turn = theta[m] - theta[k];
      turn -= 2 * std::numbers::pi * std::round(turn / (2 * std::numbers::pi));
      const double reached = theta[k] + turn;
      const int next_sheet = sheet + (reached > std::numbers::pi ? 1 : reached <= -std::numbers::pi ? -1 : 0);
      if (next_sheet < -kOffset || next_sheet >= kSheets - kOffset) continue;
      const std::size_t t = state(m, next_sheet);
      if (previous[t] != -2) continue;
      previous[t] = static_cast<int>(s);
      queue.push_back(t);
    }
  }
  if (previous[goal] == -2)
    throw InputError(fmt::format("Burgers circuit around ({:.6g}, {:.6g}, {:.6g}): no closed path of bonds (< {} Å) among the {} "
                                 "atoms of the band winds around the axis; widen the band or the slab",
                                 spec.centre.x(), spec.centre.y(), spec.centre.z(), spec.bond_cutoff, n));
  std::vector<std::size_t> circuit;
  for (int s = previous[goal]; s != -1; s = previous[static_cast<std::size_t>(s)])
    circuit.push_back(atoms[static_cast<std::size_t>(s) / kSheets]);
  std::reverse(circuit.begin(), circuit.end());  // start first, in the winding order
  return circuit;
}

std::vector<std::size_t> circuit_of_ids(const AtomFrame& frame, const std::vector<std::int64_t>& ids) {
  if (ids.size() < 3) throw InputError(fmt::format("Burgers circuit: {} atom ids given, a circuit needs at least 3", ids.size()));
  std::unordered_map<std::int64_t, std::size_t> index;
  for (std::size_t i = 0; i < frame.size(); ++i) index.emplace(frame.ids.empty() ? std::int64_t(i + 1) : frame.ids[i], i);
  std::vector<std::size_t> circuit;
  for (std::int64_t id : ids) {
    const auto found = index.find(id);
    if (found == index.end()) throw InputError(fmt::format("Burgers circuit: no atom with id {} in the frame", id));
    circuit.push_back(found->second);
  }
  return circuit;
}

BurgersResult burgers_vector(const AtomFrame& frame, const std::vector<std::size_t>& circuit, const CrystalFrame& crystal) {
  BurgersResult r;
  r.circuit = circuit;
  const double unit = crystal.lattice_constant / 6.0, nn = crystal.neighbor_distance();
  for (std::size_t k = 0; k < circuit.size(); ++k) {
    const std::size_t i = circuit[k], j = circuit[(k + 1) % circuit.size()];
    if (i >= frame.size() || j >= frame.size()) throw InputError("Burgers circuit: an atom index is outside the frame");
    const Vec3 step = frame.box.minimum_image(frame.positions[j] - frame.positions[i]);
    if (step.norm() > kMaxBond * nn)
      throw InputError(fmt::format("Burgers circuit: step {} (atom {} to {}) is {:.4g} Å long, more than {} nearest-neighbour "
                                   "distances ({:.4g} Å): the atoms are not neighbours",
                                   k + 1, i + 1, j + 1, step.norm(), kMaxBond, nn));
    const auto [mapped, distance] = nearest_step(crystal.crystal_from_lab * step / unit);
    r.sixths -= mapped;  // FS/RH: b = −Σ s_k
    r.max_step_error = std::max(r.max_step_error, distance * unit / nn);
  }
  r.reliable = r.max_step_error < kReliableError;
  r.lab = crystal.crystal_from_lab.transpose() * r.sixths.cast<double>() * unit;
  return r;
}

std::string BurgersResult::kind() const {
  Vec3i a = sixths.cwiseAbs();
  std::sort(a.data(), a.data() + 3);
  if (a == Vec3i(0, 0, 0)) return "none";
  if (a == Vec3i(0, 3, 3)) return "perfect a/2<110>";
  if (a == Vec3i(1, 1, 2)) return "Shockley a/6<112>";
  if (a == Vec3i(2, 2, 2)) return "Frank a/3<111>";
  if (a == Vec3i(0, 1, 1)) return "stair-rod a/6<110>";
  if (a == Vec3i(0, 0, 2)) return "Hirth a/3<100>";
  return "other";
}

std::string BurgersResult::text() const {
  if (sixths.isZero()) return "0";
  const int g = std::gcd(gcd3(sixths), 6);
  const Vec3i v = sixths / g;
  const int denominator = 6 / g;
  const std::string vector = fmt::format("[{} {} {}]", v[0], v[1], v[2]);
  return denominator == 1 ? vector : fmt::format("{}/{}", vector, denominator);
}

}  // namespace shockfield::analysis::atoms

#include "shockfield/md/system_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>

#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/md/ghosts.hpp"
#include "shockfield/md/lattice.hpp"

namespace shockfield::md {
namespace {

std::array<geometry::Boundary, 3> read_boundary(const Config& t) {
  const std::string codes = t.get_string_or("boundary", "ppp");
  if (codes.size() != 3) t.fail("boundary", fmt::format("expected three letters from p, f, s (e.g. \"ppf\"), got \"{}\"", codes));
  std::array<geometry::Boundary, 3> b{};
  for (int d = 0; d < 3; ++d) {
    try {
      b[d] = geometry::parse_boundary(std::string(1, codes[d]), "boundary");
    } catch (const InputError& e) {
      t.fail("boundary", e.what());
    }
  }
  return b;
}

// masses = [...] (amu) and elements = ["Cu", ...], one per atom type, both optional. A type with
// no mass keeps 0 (the MD driver then takes it from the potential file, or stops). The data
// file's Masses section and "# Cu" comments are the defaults; the case file overrides them.
void read_types(const Config& t, std::size_t ntypes, Atoms& atoms) {
  atoms.mass.resize(ntypes, 0.0);
  atoms.type_names.resize(ntypes, "");
  if (t.has("masses")) atoms.mass = t.get_doubles("masses", ntypes, Range::positive());
  if (t.has("elements")) {
    const auto names = t.get_strings("elements");
    if (names.size() != ntypes)
      t.fail("elements", fmt::format("expected {} element names (one per atom type), got {}", ntypes, names.size()));
    atoms.type_names = names;
  }
}

// Three integers (Miller indices, repeat counts); `fallback` is recorded when the key is absent.
std::array<int, 3> read_int3(const Config& t, const char* key, const std::array<int, 3>& fallback) {
  const auto v = t.get_doubles_or(key, {double(fallback[0]), double(fallback[1]), double(fallback[2])});
  std::array<int, 3> out{};
  for (std::size_t d = 0; d < 3 && v.size() == 3; ++d) {
    if (v[d] != std::round(v[d]) || std::abs(v[d]) > 1e6) t.fail(key, "expected three integers");
    out[d] = static_cast<int>(v[d]);
  }
  if (v.size() != 3) t.fail(key, fmt::format("expected three integers, got {} values", v.size()));
  return out;
}

// A [[system.group]] of build_system, kept to count a crystal's atoms under --check.
struct GroupRule {
  std::string name;
  std::optional<Region> region;
  std::vector<int> types;
  bool match(const Vec3& x, int type) const {
    return region ? region->match(x) : std::find(types.begin(), types.end(), type) != types.end();
  }
};

// A crystal --check counts instead of building: its lattice, its whole box, one repeat cell's box
// (with the same boundaries) and the number of repeat cells.
struct CrystalSites {
  Lattice lattice;
  geometry::Box whole, cell;
  double cells = 0.0;
};

std::vector<std::size_t> sites_per_type(const Lattice& lattice, const geometry::Box& box, std::size_t ntypes) {
  std::vector<std::size_t> per_type(ntypes, 0);
  lattice.for_each_site(box, [&](const Vec3&, int type) { ++per_type[static_cast<std::size_t>(type)]; });
  return per_type;
}

// The sites per type of a crystal without regions, without visiting them all: one repeat cell
// counted and multiplied (create_atoms keeps a periodic or fixed face site in exactly one cell),
// plus the hi face create_atoms also fills on each shrink-wrapped axis (Lattice::for_each_site):
// the sites of a slab one cell thick along that axis with the face filled minus without it. The
// axes are taken in turn, each slab filling the faces of the axes before it, so that a site on
// two or three hi faces is counted once.
std::vector<std::size_t> repeated_crystal_sites(const CrystalSites& c, std::size_t ntypes) {
  geometry::Box faces_open = c.whole;
  for (geometry::Boundary& b : faces_open.boundary)
    if (b == geometry::Boundary::shrink) b = geometry::Boundary::fixed;
  geometry::Box cell = c.cell;
  cell.boundary = faces_open.boundary;
  std::vector<std::size_t> per_type = sites_per_type(c.lattice, cell, ntypes);
  for (std::size_t& n : per_type) n = static_cast<std::size_t>(static_cast<double>(n) * c.cells);
  for (std::size_t d = 0; d < 3; ++d) {
    if (c.whole.boundary[d] != geometry::Boundary::shrink) continue;
    geometry::Box slab = faces_open;
    slab.hi[static_cast<int>(d)] = slab.lo[static_cast<int>(d)] + cell.length()[static_cast<int>(d)];
    const std::vector<std::size_t> without = sites_per_type(c.lattice, slab, ntypes);
    slab.boundary[d] = faces_open.boundary[d] = geometry::Boundary::shrink;
    const std::vector<std::size_t> with = sites_per_type(c.lattice, slab, ntypes);
    for (std::size_t t = 0; t < ntypes; ++t) per_type[t] += with[t] - without[t];
  }
  return per_type;
}

// The crystal under --check: atoms per type after the deletions, and per group. Without regions
// (no [[system.delete]], groups by type only) repeated_crystal_sites; else every site is visited
// once, without storing it (~3·10^7 sites a second: 9 s for 2.6·10^8).
std::vector<std::size_t> count_crystal(const CrystalSites& c, std::size_t ntypes, const std::vector<Region>& deletes,
                                       const std::vector<GroupRule>& groups, std::vector<std::size_t>& in_group,
                                       std::size_t& deleted) {
  std::vector<std::size_t> per_type(ntypes, 0);
  in_group.assign(groups.size(), 0);
  const bool regions = !deletes.empty() || std::any_of(groups.begin(), groups.end(), [](const GroupRule& g) {
                         return g.region.has_value();
                       });
  if (!regions) {
    per_type = repeated_crystal_sites(c, ntypes);
    for (std::size_t g = 0; g < groups.size(); ++g)
      for (int type : groups[g].types) in_group[g] += per_type[static_cast<std::size_t>(type)];
    return per_type;
  }
  c.lattice.for_each_site(c.whole, [&](const Vec3& x, int type) {
    for (const Region& r : deletes)
      if (r.match(x)) {
        ++deleted;
        return;
      }
    ++per_type[static_cast<std::size_t>(type)];
    for (std::size_t g = 0; g < groups.size(); ++g) in_group[g] += groups[g].match(x, type) ? 1 : 0;
  });
  return per_type;
}

// With `sites` set (--check of a crystal of more than kFewCells along an axis), only the first few
// cells are created: enough for the nearest-neighbour distances of the overlap check.
constexpr int kFewCells = 3;

BuiltSystem from_lattice(const Config& lat, bool check, std::optional<CrystalSites>& sites) {
  LatticeSpec spec;
  spec.style = parse_lattice_style(lat.get_choice("style", lattice_style_names()), "style");
  spec.a0 = lat.get_double("a0", Range::positive());
  const char* orient_keys[3] = {"orient_x", "orient_y", "orient_z"};
  for (int d = 0; d < 3; ++d) {
    std::array<int, 3> unit{};
    unit[d] = 1;
    spec.orient[d] = read_int3(lat, orient_keys[d], unit);
  }
  if (lat.has("c_over_a")) {
    if (spec.style != LatticeStyle::hcp) lat.fail("c_over_a", "c/a is only used by style = \"hcp\"");
    spec.c_over_a = lat.get_double("c_over_a", Range::positive());
  }
  const auto repeat = read_int3(lat, "repeat", {1, 1, 1});
  for (int d = 0; d < 3; ++d)
    if (repeat[d] < 1) lat.fail("repeat", "expected three counts >= 1 [nx, ny, nz]");
  const auto boundary = read_boundary(lat);
  // The number of types: from masses, else elements, else the largest basis type.
  std::size_t ntypes = lat.has("masses") ? lat.get_doubles("masses", 0).size()
                       : lat.has("elements") ? lat.get_strings("elements").size() : 0;
  if ((lat.has("masses") || lat.has("elements")) && ntypes == 0)
    lat.fail(lat.has("masses") ? "masses" : "elements", "expected one entry per atom type");
  int basis_size = 0;
  try {
    basis_size = Lattice(spec).basis_size();  // validates the orientation
  } catch (const InputError& e) {
    lat.fail("orient_x", e.what());
  }
  if (lat.has("basis_types")) {
    const double max_type = ntypes ? static_cast<double>(ntypes) : 32.0;
    for (long long t : lat.get_ints("basis_types", static_cast<std::size_t>(basis_size), Range::closed(1, max_type)))
      spec.basis_types.push_back(static_cast<int>(t) - 1);
  }
  if (static_cast<double>(repeat[0]) * repeat[1] * repeat[2] * basis_size > kMaxGridPoints)
    lat.fail("repeat", fmt::format("{} x {} x {} cells of {} atoms; expected at most {:.0e} atoms", repeat[0], repeat[1],
                                   repeat[2], basis_size, kMaxGridPoints));
  const Lattice lattice(spec);
  if (ntypes == 0)
    ntypes = spec.basis_types.empty() ? 1 : static_cast<std::size_t>(*std::max_element(spec.basis_types.begin(), spec.basis_types.end()) + 1);
  BuiltSystem sys;
  read_types(lat, ntypes, sys.atoms);
  sys.box = lattice.box(repeat, boundary);
  if (lat.has("tilt")) {  // LAMMPS create_box on a prism region (units box): a restricted triclinic cell
    const auto t = lat.get_doubles("tilt", 3, Range::closed(-1e9, 1e9));
    sys.box.tilt = Vec3(t[0], t[1], t[2]);
    try {
      sys.box.check_tilt("the tilted box");
    } catch (const InputError& e) {
      lat.fail("tilt", e.what());
    }
  }
  // The count by repeat cells of --check holds for whole repeats only, not for a tilted cell.
  if (check && !sys.box.triclinic() && *std::max_element(repeat.begin(), repeat.end()) > kFewCells) {
    std::array<int, 3> few{};
    for (int d = 0; d < 3; ++d) few[d] = std::min(repeat[d], kFewCells);
    lattice.create_atoms(lattice.box(few, boundary), sys.atoms);
    sites = CrystalSites{lattice, sys.box, lattice.box({1, 1, 1}, boundary),
                         static_cast<double>(repeat[0]) * repeat[1] * repeat[2]};
  } else {
    lattice.create_atoms(sys.box, sys.atoms);
  }
  return sys;
}

BuiltSystem from_data_file(const Config& system) {
  const std::filesystem::path file = system.get_input_file("data_file");  // relative to the case file
  const auto boundary = read_boundary(system);
  io::DataFile data = io::read_data(file, boundary);
  BuiltSystem sys{data.box, std::move(data.atoms), {}, {}, {}};
  sys.file_masses = sys.atoms.mass;
  std::fill(sys.atoms.mass.begin(), sys.atoms.mass.end(), 0.0);  // masses = [...] or the potential's first
  read_types(system, sys.atoms.mass.size(), sys.atoms);
  return sys;
}

}  // namespace

std::optional<std::string> find_overlap(const geometry::Box& box, const Atoms& atoms, double min_distance) {
  Atoms copy = atoms;
  rebuild_ghosts(copy, box, min_distance);
  geometry::NeighborList list;
  geometry::build_neighbor_list(copy.x, copy.nlocal, min_distance, true, list);
  for (std::size_t i = 0; i < copy.nlocal; ++i) {
    if (list.offset[i] == list.offset[i + 1]) continue;
    const auto j = static_cast<std::size_t>(list.neighbors[static_cast<std::size_t>(list.offset[i])]);
    const std::size_t owner = j < copy.nlocal ? j : static_cast<std::size_t>(copy.ghost_owner[j - copy.nlocal]);
    return fmt::format("atoms {} and {} are {:.4g} Å apart, closer than {} Å (overlapping atoms)",
                       std::min(copy.id[i], copy.id[owner]), std::max(copy.id[i], copy.id[owner]),
                       (copy.x[j] - copy.x[i]).norm(), min_distance);
  }
  return std::nullopt;
}

std::size_t BuiltSystem::atom_count() const {
  if (counted_types.empty()) return atoms.nlocal;
  return std::accumulate(counted_types.begin(), counted_types.end(), std::size_t{0});
}

double BuiltSystem::total_mass() const {
  double mass = 0.0;
  if (counted_types.empty())
    for (std::size_t i = 0; i < atoms.nlocal; ++i) mass += atoms.mass_of(i);
  for (std::size_t t = 0; t < counted_types.size(); ++t) mass += static_cast<double>(counted_types[t]) * atoms.mass[t];
  return mass;
}

BuiltSystem build_system(const Config& system, bool check) {
  const bool has_lattice = system.has("lattice"), has_data = system.has("data_file");
  if (has_lattice == has_data)
    system.fail(has_data ? "data_file" : "lattice",
                "expected exactly one of [system.lattice] (build a crystal) or data_file = \"...\" (read a LAMMPS data file)");
  std::optional<CrystalSites> sites;  // set: the crystal is counted
  BuiltSystem sys = has_lattice ? from_lattice(system.table("lattice"), check, sites) : from_data_file(system);

  std::size_t deleted = 0;
  std::vector<Region> deletes;
  for (const Config& t : system.tables("delete")) deletes.push_back(region_from_config(t));
  if (!sites)
    for (const Region& r : deletes) deleted += delete_atoms(r, sys.atoms);
  std::vector<GroupRule> rules;

  for (const Config& t : system.tables("group")) {
    const std::string name = t.get_string("name");
    if (name == "all") t.fail("name", "'all' is predefined; choose another group name");
    if (t.has("shape") == t.has("types"))
      t.fail(t.has("types") ? "types" : "name", "expected exactly one of shape = ... (a region) or types = [...]");
    const std::uint32_t bit = sys.groups.bit(name);
    GroupRule rule{name, std::nullopt, {}};
    if (t.has("shape")) rule.region = region_from_config(t);
    else
      for (long long ty : t.get_ints("types", 0, Range::closed(1, sys.atoms.ntypes()))) rule.types.push_back(int(ty) - 1);
    if (!sites) {
      const std::size_t count = rule.region ? add_to_group(bit, *rule.region, sys.atoms)
                                            : add_to_group(bit, rule.types, sys.atoms);
      system.derive(fmt::format("atoms_in_group_{}", name), static_cast<long long>(count));
    }
    rules.push_back(std::move(rule));
  }
  if (sites) {
    std::vector<std::size_t> in_group;
    sys.counted_types = count_crystal(*sites, static_cast<std::size_t>(sys.atoms.ntypes()), deletes, rules, in_group,
                                      deleted);
    for (std::size_t g = 0; g < rules.size(); ++g)
      system.derive(fmt::format("atoms_in_group_{}", rules[g].name), static_cast<long long>(in_group[g]));
  }

  const double min_distance = system.get_double_or("min_distance", 0.1, Range::positive());
  if (const auto overlap = find_overlap(sys.box, sys.atoms, min_distance)) system.fail("min_distance", *overlap);
  if (sys.atom_count() == 0) system.fail(has_lattice ? "lattice" : "data_file", "the system has no atoms");

  system.derive("atoms", static_cast<long long>(sys.atom_count()));
  system.derive("atoms_deleted", static_cast<long long>(deleted));
  system.derive("box_lengths", fmt::format("{} {} {}", sys.box.length().x(), sys.box.length().y(), sys.box.length().z()));
  return sys;
}

}  // namespace shockfield::md

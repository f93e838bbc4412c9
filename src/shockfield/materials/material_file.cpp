#include "shockfield/materials/material_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/core/provenance.hpp"
#include "shockfield/core/sha256.hpp"
#include "shockfield/io/checked_file.hpp"

namespace shockfield::materials {

namespace fs = std::filesystem;

const std::vector<MaterialKey>& material_keys() {
  const Range positive = Range::positive(), non_negative = Range::non_negative();
  static const std::vector<MaterialKey> keys{
      {"eos.rho0", positive, "kg/m^3", "reference density of the Mie-Gruneisen EOS"},
      {"eos.c0", positive, "m/s", "intercept of Us = c0 + s Up (+ s2 Up^2)"},
      {"eos.s", Range::closed(0.0, 10.0), "-", "slope s of the Us-Up Hugoniot"},
      {"eos.s2", {}, "s/m", "quadratic coefficient of the Us-Up Hugoniot (0: linear)"},
      {"eos.gamma0", Range::closed(0.0, 10.0), "-", "Gruneisen coefficient at rho0 (rho*gamma = rho0*gamma0)"},
      {"elasticity.density", positive, "kg/m^3", "density of the state the elastic constants belong to"},
      {"elasticity.temperature", non_negative, "K", "temperature of that state"},
      {"elasticity.c11", positive, "Pa", "cubic elastic constant C11"},
      {"elasticity.c12", {}, "Pa", "cubic elastic constant C12"},
      {"elasticity.c44", positive, "Pa", "cubic elastic constant C44"},
      {"elasticity.bulk", positive, "Pa", "isotropic bulk modulus K"},
      {"elasticity.shear", positive, "Pa", "isotropic shear modulus G"},
      {"strength.yield_stress", non_negative, "Pa", "J2 initial yield stress"},
      {"strength.tangent_modulus", non_negative, "Pa", "J2 linear hardening (tangent) modulus"},
      {"strength.g0", positive, "Pa", "initial slip resistance of the crystal law"},
      {"strength.strain_rate", positive, "1/s", "strain rate at which the strength was measured"},
      {"thermal.heat_capacity", positive, "J/(kg K)", "specific heat c_v"},
      {"thermal.conductivity", non_negative, "W/(m K)", "heat conductivity"},
      {"thermal.initial_temperature", positive, "K", "initial temperature"},
      {"spall.strength", positive, "Pa", "spall strength (tensile mean stress at failure)"},
      {"spall.strain_rate", positive, "1/s", "strain rate at which the spall strength was measured"},
      {"atoms.cohesive_energy", positive, "J", "cohesive (binding) energy per atom e0 of the relaxed crystal, > 0"},
      {"atoms.lattice_constant", positive, "m", "zero-pressure lattice constant a0 of the atoms' cubic crystal"},
      {"atoms.atomic_mass", positive, "kg", "mass of one atom"},
      {"phasefield.a", Range::closed(0.0, 1.0), "-", "bulk parameter a of the double well f (Xu et al. (2015) eq 38)"},
      {"phasefield.interface_width", positive, "m", "logistic length W = sqrt(2 D tau) of the diffuse front"},
      {"phasefield.relaxation_time", positive, "s", "relaxation time tau of f, the time unit of the model"},
      {"phasefield.front_speed", {}, "m/s", "c0 of the sharp-front law v = c0 + s D kappa (kind = sharp_front)"},
      {"phasefield.curvature_coefficient", positive, "m^2/s", "D of the sharp-front law v = c0 + s D kappa"},
  };
  return keys;
}

namespace {

constexpr const char* kSections[] = {"eos", "elasticity", "strength", "thermal", "spall", "atoms", "phasefield"};

std::pair<std::string, std::string> split(std::string_view dotted) {
  const auto dot = dotted.find('.');
  return {std::string(dotted.substr(0, dot)), std::string(dotted.substr(dot + 1))};
}

// Cubic stability (Born): C44 > 0, C11 > |C12|, C11 + 2C12 > 0; the three come together.
void check_cubic(const Config& e) {
  const bool any = e.has("c11") || e.has("c12") || e.has("c44");
  if (!any) return;
  for (const char* k : {"c11", "c12", "c44"})
    if (!e.has(k)) e.fail(k, "missing: the cubic constants c11, c12 and c44 come together");
  const double c11 = e.get_double("c11"), c12 = e.get_double("c12");
  if (!(c11 > std::abs(c12)) || !(c11 + 2.0 * c12 > 0.0))
    e.fail("c12", fmt::format("c11 = {} Pa, c12 = {} Pa is not a stable cubic crystal (expected c11 > |c12| and "
                              "c11 + 2 c12 > 0)",
                              c11, c12));
}

// Every provenance value as "key = value" (arrays of tables by index).
void provenance_leaves(const toml::table& t, const std::string& prefix, std::vector<std::pair<std::string, std::string>>& out);
void provenance_node(const toml::node& n, const std::string& key, std::vector<std::pair<std::string, std::string>>& out) {
  if (const auto* sub = n.as_table()) {
    provenance_leaves(*sub, key + ".", out);
  } else if (const auto* arr = n.as_array(); arr && arr->is_array_of_tables()) {
    for (std::size_t i = 0; i < arr->size(); ++i) provenance_node(*arr->get(i), fmt::format("{}[{}]", key, i), out);
  } else if (const auto* s = n.as_string()) {
    out.emplace_back(key, s->get());
  } else {
    std::ostringstream text;
    n.visit([&](const auto& v) { text << v; });
    out.emplace_back(key, text.str());
  }
}
void provenance_leaves(const toml::table& t, const std::string& prefix, std::vector<std::pair<std::string, std::string>>& out) {
  for (const auto& [k, v] : t) provenance_node(v, prefix + std::string(k.str()), out);
}

std::string quoted(const std::string& text) {
  std::ostringstream out;
  out << toml::value<std::string>(text);
  return out.str();
}

}  // namespace

MaterialFile MaterialFile::load(const fs::path& file) {
  MaterialFile m;
  m.path_ = fs::absolute(file).lexically_normal();
  const Config root = Config::load(file, {});  // [provenance] is set aside by the case loader
  const toml::table raw = toml::parse_file(file.string());
  if (raw.contains("derived")) root.fail("derived", "a material file has no [derived] table");
  if (const toml::node* p = raw.get("provenance")) {
    if (!p->is_table()) root.fail("provenance", "expected a table [provenance]");
    m.provenance_ = *p->as_table();
  }
  root.get_string_or("name", "");
  root.get_string_or("description", "");
  for (const char* section : kSections) {
    const auto t = root.optional_table(section);
    if (!t) continue;
    t->get_string_or("note", "");
    if (std::string_view(section) == "eos") t->get_choice_or("model", {"mie_gruneisen"}, "mie_gruneisen");
    if (std::string_view(section) == "atoms") t->get_choice_or("crystal", {"sc", "bcc", "fcc", "diamond"}, "fcc");
    if (std::string_view(section) == "phasefield") {
      m.strings_["phasefield.kind"] = t->get_choice_or("kind", {"field", "sharp_front"}, "field");
      if (t->has("law")) m.strings_["phasefield.law"] = t->get_choice("law", {"paper", "allen_cahn"});
    }
    if (std::string_view(section) == "elasticity") {
      t->get_choice_or("average", {"voigt", "reuss", "hill"}, "hill");
      check_cubic(*t);
    }
    for (const MaterialKey& k : material_keys()) {
      const auto [s, key] = split(k.name);
      if (s == section && t->has(key)) m.values_[k.name] = t->get_double(key, k.range);
    }
  }
  root.check_unknown_keys();
  m.sha256_ = sha256_file_hex(m.path_);
  return m;
}

std::optional<double> MaterialFile::get(std::string_view key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::string> MaterialFile::get_string(std::string_view key) const {
  const auto it = strings_.find(key);
  if (it == strings_.end()) return std::nullopt;
  return it->second;
}

void MaterialFile::missing(std::string_view key, const std::string& needed_by, const std::string& alternative) const {
  const auto [section, name] = split(key);
  std::string unit;
  for (const MaterialKey& k : material_keys())
    if (key == k.name) unit = fmt::format(" ({}, {})", k.meaning, k.unit);
  throw InputError(fmt::format("{}: missing {}{} in [{}]: {} needs it; add it to the material file or give {}",
                               path_.string(), key, unit, section, needed_by, alternative));
}

std::vector<std::string> MaterialFile::summary_lines() const {
  std::vector<std::string> lines{fmt::format("{} (sha256 {})", path_.string(), sha256_)};
  std::vector<std::pair<std::string, std::string>> leaves;
  provenance_leaves(provenance_, "provenance.", leaves);
  if (leaves.empty()) lines.emplace_back("no [provenance]: a hand-written material");
  for (const auto& [k, v] : leaves) lines.push_back(fmt::format("{} = {}", k, v));
  return lines;
}

std::optional<MaterialFile> open_material_file(const Config& t) {
  if (!t.has("file")) return std::nullopt;
  MaterialFile f = MaterialFile::load(t.get_input_file("file"));
  const std::string prefix = t.key_path("file");
  t.derive(prefix + ".sha256", f.sha256());
  std::vector<std::pair<std::string, std::string>> leaves;
  provenance_leaves(f.provenance(), prefix + ".provenance.", leaves);
  for (const auto& [k, v] : leaves) t.derive(k, v);
  return f;
}

double file_default(const Config& t, std::string_view key, const MaterialFile& file, std::string_view file_key,
                    double value, const Range& range, double scale) {
  const double v = value / scale;
  if (!range.contains(v))
    throw InputError(fmt::format("{}: key '{}' = {} gives {} = {}, expected {} ({} does not give {}, so the "
                                 "material file's value is used)",
                                 file.path().string(), file_key, value, t.key_path(key), v, range.describe(), t.file(),
                                 t.key_path(key)));
  return t.get_double_or(key, v, range);
}

double case_or_file(const Config& t, std::string_view key, const MaterialFile* file,
                    std::initializer_list<std::string_view> file_keys, std::optional<double> fallback, Range range,
                    const std::string& needed_by) {
  if (t.has(key) || !file) {
    if (!fallback || t.has(key)) return t.get_double(key, range);
    return t.get_double_or(key, *fallback, range);
  }
  for (std::string_view fk : file_keys)
    if (const auto v = file->get(fk)) return file_default(t, key, *file, fk, *v, range);
  if (fallback) return t.get_double_or(key, *fallback, range);
  file->missing(*file_keys.begin(), needed_by, fmt::format("{} in {}", t.key_path(key), t.file()));
}

IsotropicModuli cubic_average(double c11, double c12, double c44, std::string_view average) {
  const double bulk = (c11 + 2.0 * c12) / 3.0;
  const double voigt = (c11 - c12 + 3.0 * c44) / 5.0;
  const double reuss = 5.0 * (c11 - c12) * c44 / (4.0 * c44 + 3.0 * (c11 - c12));
  if (average == "voigt") return {bulk, voigt};
  if (average == "reuss") return {bulk, reuss};
  if (average == "hill") return {bulk, 0.5 * (voigt + reuss)};
  throw InputError(fmt::format("unknown average '{}' (expected voigt, reuss or hill)", average));
}

std::string material_file_text(const std::string& name, const std::map<std::string, double>& values,
                               const std::map<std::string, std::string>& notes, const toml::table& provenance) {
  std::string text = "# shockfield material file (docs/materials.md); SI units, stated per key.\n";
  text += fmt::format("name = {}\n", quoted(name));
  for (const char* section : kSections) {
    std::string body;
    for (const auto& [key, note] : notes)
      if (split(key).first == section) body += fmt::format("{} = {}\n", split(key).second, quoted(note));
    for (const MaterialKey& k : material_keys()) {
      const auto it = values.find(k.name);
      if (it == values.end() || split(k.name).first != section) continue;
      body += fmt::format("{} = {}  # {}, {}\n", split(k.name).second, it->second, k.unit, k.meaning);
    }
    if (!body.empty()) text += fmt::format("\n[{}]\n{}", section, body);
  }
  if (!provenance.empty()) {
    toml::table wrapped;
    wrapped.insert("provenance", provenance);
    std::ostringstream out;
    out << "\n" << wrapped << "\n";
    text += out.str();
  }
  return text;
}

toml::table bridge_provenance_entry(const std::vector<std::string>& command_line) {
  return toml::table{{"command", shell_command_line(command_line)},
                     {"date", iso8601_utc_now()},
                     {"shockfield_version", SHOCKFIELD_VERSION}};
}

void write_bridged_material(const fs::path& file, bool update, const std::string& name, const std::string& bridge,
                            const std::map<std::string, double>& values,
                            const std::map<std::string, std::string>& notes, const toml::table& entry) {
  std::map<std::string, double> all;
  std::map<std::string, std::string> all_notes;
  toml::table provenance;
  if (update && fs::exists(file)) {
    const MaterialFile old = MaterialFile::load(file);
    for (const MaterialKey& k : material_keys())
      if (const auto v = old.get(k.name)) all[k.name] = *v;
    const toml::table raw = toml::parse_file(file.string());
    for (const char* section : kSections)
      if (const toml::table* t = raw[section].as_table())
        for (const auto& [key, v] : *t)
          if (const auto* text = v.as_string()) all_notes[fmt::format("{}.{}", section, key.str())] = text->get();
    provenance = old.provenance();
    // The sections this bridge writes are replaced whole: no stale value of an older fit stays.
    for (const auto& [key, v] : values) {
      const auto same_section = [&](const auto& kv) { return split(kv.first).first == split(key).first; };
      std::erase_if(all, same_section);
      std::erase_if(all_notes, same_section);
    }
  }
  for (const auto& [key, v] : values) all[key] = v;
  for (const auto& [key, note] : notes) all_notes[key] = note;
  provenance.insert_or_assign(bridge, entry);
  io::replace_file(file, material_file_text(name, all, all_notes, provenance));
}

}  // namespace shockfield::materials

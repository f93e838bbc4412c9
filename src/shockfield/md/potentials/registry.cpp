#include "shockfield/md/potentials/registry.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <functional>
#include <utility>

#include "shockfield/core/error.hpp"
#include "shockfield/md/potentials/adp.hpp"
#include "shockfield/md/potentials/eam.hpp"
#include "shockfield/md/potentials/eam_file.hpp"
#include "shockfield/md/potentials/eam_tables.hpp"
#include "shockfield/md/potentials/lj_cut.hpp"
#include "shockfield/md/potentials/pair_table.hpp"
#include "shockfield/md/potentials/pair_table_file.hpp"

namespace shockfield::md::potentials {
namespace {

using Factory = std::function<std::unique_ptr<Potential>(const Config&, const std::filesystem::path&, int)>;

// Reads a potential file, turning a reader's InputError into one that also names the case key.
template <class Read>
auto read_for_key(const Config& table, std::string_view key, Read&& read) {
  try {
    return read();
  } catch (const InputError& e) {
    table.fail(key, fmt::format("cannot use the potential file: {}", e.what()));
  }
}

std::unique_ptr<Potential> make_funcfl(const Config& table, const std::filesystem::path& case_dir,
                                       int ntypes) {
  const auto path = find_potential_file(table, "file", case_dir);
  std::vector<FuncflFile> files{read_for_key(table, "file", [&] { return read_funcfl(path); })};
  // pair_coeff * * file: every type uses the one file.
  auto tables = tabulate_funcfl(files, std::vector<int>(static_cast<std::size_t>(ntypes), 0));
  return std::make_unique<EamPotential>("eam", std::move(tables),
                                        std::vector<std::string>(static_cast<std::size_t>(ntypes)));
}

// The file element of each atom type from `elements` (pair_coeff * * file El_1 ... El_n).
std::vector<int> type_elements(const Config& table, const SetflFile& file, int ntypes) {
  const auto elements = table.get_strings("elements");
  const std::string available = fmt::format("{}", fmt::join(file.elements, " "));
  if (static_cast<int>(elements.size()) != ntypes)
    table.fail("elements", fmt::format("expected one element per atom type ({} names, one of: {}), "
                                       "found {}", ntypes, available, elements.size()));
  std::vector<int> type_element;
  for (const auto& name : elements) {
    const int e = file.element_index(name);
    if (e < 0)
      table.fail("elements", fmt::format("element '{}' is not in {} (it has: {})", name,
                                         file.path, available));
    type_element.push_back(e);
  }
  return type_element;
}

std::unique_ptr<Potential> make_setfl(const Config& table, const std::filesystem::path& case_dir,
                                      int ntypes, bool finnis_sinclair) {
  const auto path = find_potential_file(table, "file", case_dir);
  const auto file = read_for_key(table, "file", [&] { return read_setfl(path, finnis_sinclair); });
  return std::make_unique<EamPotential>(finnis_sinclair ? "eam/fs" : "eam/alloy",
                                        tabulate_setfl(file, type_elements(table, file, ntypes)),
                                        table.get_strings("elements"));
}

// pair_style adp; pair_coeff * * file El_1 ... El_n as for eam/alloy.
std::unique_ptr<Potential> make_adp(const Config& table, const std::filesystem::path& case_dir, int ntypes) {
  const auto path = find_potential_file(table, "file", case_dir);
  const auto file = read_for_key(table, "file", [&] { return read_adp(path); });
  return std::make_unique<AdpPotential>(tabulate_adp(file, type_elements(table, file.setfl, ntypes)),
                                        table.get_strings("elements"));
}

std::unique_ptr<Potential> make_lj_cut(const Config& table, const std::filesystem::path&, int ntypes) {
  const double cutoff = table.get_double("cutoff", Range::positive());
  const bool shift = table.get_bool_or("shift", false);
  const auto n = static_cast<std::size_t>(ntypes);
  std::vector<std::optional<LjCoeff>> set(n * n);
  if (table.has("epsilon") || table.has("sigma")) {
    const LjCoeff all{table.get_double("epsilon", Range::non_negative()),
                      table.get_double("sigma", Range::positive()), cutoff};
    std::fill(set.begin(), set.end(), all);
  }
  for (const auto& pair : table.tables("pair")) {
    const auto types = pair.get_ints("types", 2, Range::closed(1, ntypes));
    const LjCoeff c{pair.get_double("epsilon", Range::non_negative()),
                    pair.get_double("sigma", Range::positive()),
                    pair.get_double_or("cutoff", cutoff, Range::positive())};
    const auto i = static_cast<std::size_t>(types[0] - 1), j = static_cast<std::size_t>(types[1] - 1);
    set[i * n + j] = set[j * n + i] = c;
  }
  try {
    return std::make_unique<LjCutPotential>(ntypes, mix_lj(ntypes, set), shift);
  } catch (const InputError& e) {
    table.fail("pair", e.what());
  }
}

// The most nodes of one inner table (`points`): 40 bytes each, 400 MB at this bound.
constexpr long long kMaxTablePoints = 10'000'000;

// One pair_coeff of pair_style table: the table `keyword` of `file`, up to `cutoff` (nullopt: the
// table's last distance), and the case table that gave it (for messages).
struct TableCoeff {
  Config where;
  std::filesystem::path file;
  std::string keyword;
  std::optional<double> cutoff;
};

std::optional<double> optional_cutoff(const Config& table) {
  if (!table.has("cutoff")) return std::nullopt;
  return table.get_double("cutoff", Range::positive());
}

InnerTable tabulate(const TableCoeff& c, TableInterpolation interpolation, int points) {
  const auto section = read_for_key(c.where, "keyword", [&] { return read_pair_table(c.file, c.keyword); });
  try {
    return build_inner_table(section, interpolation, points, c.cutoff.value_or(section.last_r()));
  } catch (const InputError& e) {
    c.where.fail(c.cutoff ? "cutoff" : "keyword", e.what());
  }
}

// pair_style table linear|spline N; `file`, `keyword`, `cutoff` stand for pair_coeff * *, each
// [[potential.pair]] for pair_coeff i j (its own file optional). Every type pair needs a table.
std::unique_ptr<Potential> make_table(const Config& table, const std::filesystem::path& case_dir, int ntypes) {
  const auto interpolation = table.get_choice("interpolation", {"linear", "spline"}) == "linear"
                                 ? TableInterpolation::linear : TableInterpolation::spline;
  const int points = static_cast<int>(table.get_int("points", Range::closed(2, kMaxTablePoints)));
  std::optional<std::filesystem::path> file;
  if (table.has("file")) file = find_potential_file(table, "file", case_dir);
  const auto cutoff = optional_cutoff(table);
  const auto n = static_cast<std::size_t>(ntypes);
  std::vector<std::optional<TableCoeff>> set(n * n);
  if (table.has("keyword")) {
    if (!file) table.fail("file", "a table file for `keyword` (pair_coeff * * file keyword)");
    std::fill(set.begin(), set.end(), TableCoeff{table, *file, table.get_string("keyword"), cutoff});
  }
  for (const auto& pair : table.tables("pair")) {
    const auto types = pair.get_ints("types", 2, Range::closed(1, ntypes));
    std::filesystem::path pair_file;
    if (pair.has("file")) pair_file = find_potential_file(pair, "file", case_dir);
    else if (file) pair_file = *file;
    else pair.fail("file", "a table file, here or in [potential]");
    const auto pair_cutoff = optional_cutoff(pair);
    const TableCoeff c{pair, pair_file, pair.get_string("keyword"), pair_cutoff ? pair_cutoff : cutoff};
    const auto i = static_cast<std::size_t>(types[0] - 1), j = static_cast<std::size_t>(types[1] - 1);
    set[i * n + j] = set[j * n + i] = c;
  }
  std::vector<InnerTable> tables;
  std::vector<int> pair_table(n * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) {
      if (!set[i * n + j])
        table.fail("pair", fmt::format("a table for type pair {} {} (`keyword`, or a [[potential.pair]] "
                                       "with types = [{}, {}]; LAMMPS does not mix tables)", i + 1, j + 1, i + 1, j + 1));
      pair_table[i * n + j] = pair_table[j * n + i] = static_cast<int>(tables.size());
      tables.push_back(tabulate(*set[i * n + j], interpolation, points));
    }
  }
  return std::make_unique<TablePotential>(interpolation, ntypes, std::move(tables), std::move(pair_table));
}

// The explicit style table.
const std::vector<std::pair<std::string, Factory>>& factories() {
  static const std::vector<std::pair<std::string, Factory>> table{
      {"lj/cut", make_lj_cut},
      {"table", make_table},
      {"eam", make_funcfl},
      {"eam/alloy", [](const Config& c, const std::filesystem::path& d, int n) { return make_setfl(c, d, n, false); }},
      {"eam/fs", [](const Config& c, const std::filesystem::path& d, int n) { return make_setfl(c, d, n, true); }},
      {"adp", make_adp},
  };
  return table;
}

}  // namespace

std::vector<std::string> potential_styles() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : factories()) names.push_back(name);
  return names;
}

std::unique_ptr<Potential> make_potential(const Config& table, const std::filesystem::path& case_dir,
                                          int ntypes) {
  if (ntypes < 1) throw InputError(fmt::format("{}: [{}] needs at least one atom type, found {}",
                                               table.file(), table.path(), ntypes));
  const std::string style = table.get_choice("style", potential_styles());
  for (const auto& [name, factory] : factories())
    if (name == style) return factory(table, case_dir, ntypes);
  table.fail("style", "a known style");  // unreachable: get_choice checked the name
}

std::optional<double> potential_type_mass(const Potential& potential, int t) {
  if (const auto* eam = dynamic_cast<const EmbeddedAtomPotential*>(&potential)) return eam->type_mass(t);
  return std::nullopt;
}

std::optional<std::string> potential_type_element(const Potential& potential, int t) {
  if (const auto* eam = dynamic_cast<const EmbeddedAtomPotential*>(&potential)) {
    const auto& names = eam->type_names();
    if (static_cast<std::size_t>(t) < names.size() && !names[static_cast<std::size_t>(t)].empty())
      return names[static_cast<std::size_t>(t)];
  }
  return std::nullopt;
}

std::filesystem::path find_potential_file(const Config& table, std::string_view key,
                                          const std::filesystem::path& case_dir) {
  std::vector<std::filesystem::path> folders{case_dir};
  if (const char* env = std::getenv("LAMMPS_POTENTIALS"); env && *env) folders.emplace_back(env);
  folders.push_back(lammps_potential_dir);
  return table.get_input_file(key, folders);
}

}  // namespace shockfield::md::potentials

#pragma once
// Material files (docs/materials.md): a TOML file with the constitutive numbers of one solid —
// [eos], [elasticity], [strength], [thermal], [spall], [atoms], each optional, SI units — and a
// [provenance] table saying where they came from (the `shockfield bridge` command that wrote
// them, its input run folders and the SHA-256 of their resolved configurations, the fit and its
// uncertainty). A solid case references one with `file = "cu_md.toml"` in its material table
// (MPM [[material]], PD [material]), resolved relative to the case file; the case's own keys
// override single values of it. Xu et al. (2015) §1, §5: what a small scale learns becomes the
// constitutive law of the next one, without retyping a number.
#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "shockfield/core/config.hpp"

namespace shockfield::materials {

/// One numeric key of a material file: dotted name ("eos.c0"), allowed range, SI unit, meaning.
struct MaterialKey {
  const char* name;
  Range range;
  const char* unit;
  const char* meaning;
};
/// Every numeric key, in the order the sections are written.
const std::vector<MaterialKey>& material_keys();

class MaterialFile {
 public:
  /// Reads and validates `file` (unknown keys, ranges, finiteness, cubic stability); every
  /// error is an InputError naming the file, the key and its line.
  static MaterialFile load(const std::filesystem::path& file);

  const std::filesystem::path& path() const { return path_; }
  const std::string& sha256() const { return sha256_; }
  /// The file's [provenance] table (empty for a hand-written file without one).
  const toml::table& provenance() const { return provenance_; }
  /// The value of a dotted key ("eos.c0"), or nothing when the file does not give it.
  std::optional<double> get(std::string_view key) const;
  /// A checked string value ("phasefield.kind", "phasefield.law"), or nothing when not given.
  std::optional<std::string> get_string(std::string_view key) const;
  /// InputError: the file lacks `key`, which `needed_by` (e.g. "MPM [[material]] 'cu'") needs;
  /// `alternative` says where else it may be given.
  [[noreturn]] void missing(std::string_view key, const std::string& needed_by, const std::string& alternative) const;
  /// "path (sha256 …)" and one "provenance.<key> = value" line per provenance value, for a log.
  std::vector<std::string> summary_lines() const;

 private:
  std::filesystem::path path_;
  std::string sha256_;
  std::map<std::string, double, std::less<>> values_;
  std::map<std::string, std::string, std::less<>> strings_;
  toml::table provenance_;
};

/// If the material table `t` has `file`: loads that material file (relative to the case file;
/// recorded as an input file, so the run's provenance hashes it and --resume notices a change)
/// and records its path, SHA-256 and every provenance value under [derived] as
/// "<table>.file.sha256", "<table>.file.provenance.<key>".
std::optional<MaterialFile> open_material_file(const Config& t);

/// `value` (the material file's `file_key`, divided by `scale` to the case key's unit) as the
/// default of the case key `key` of `t`: an InputError naming the material file, its key, the
/// case key and `range` when it is outside the range the case key accepts (a value from a file is
/// checked as strictly as one typed into the case).
double file_default(const Config& t, std::string_view key, const MaterialFile& file, std::string_view file_key,
                    double value, const Range& range, double scale = 1.0);

/// The case value of `key` in `t` when given; else the first of `file_keys` the material file
/// has (checked against `range` by file_default and recorded in the resolved case as if given);
/// else `fallback`; else an InputError naming the material file and its first key (or, without a
/// file, the case's missing key). `needed_by` names the model that needs the value.
double case_or_file(const Config& t, std::string_view key, const MaterialFile* file,
                    std::initializer_list<std::string_view> file_keys, std::optional<double> fallback, Range range,
                    const std::string& needed_by);

/// Isotropic moduli of a cubic crystal by the Voigt, Reuss or Hill average (Hill 1952):
/// K = (C11 + 2C12)/3 for all three; G_V = (C11 − C12 + 3C44)/5,
/// G_R = 5(C11 − C12)C44 / (4C44 + 3(C11 − C12)), G_H = (G_V + G_R)/2.
struct IsotropicModuli {
  double bulk = 0, shear = 0;
};
IsotropicModuli cubic_average(double c11, double c12, double c44, std::string_view average);

/// Text of a material file: `name`, the numeric values of `values` (dotted keys of
/// material_keys(), written per section with their unit and meaning as comments), the string
/// values of `notes` (dotted "section.key": note, eos.model, elasticity.average) and
/// [provenance] as given.
std::string material_file_text(const std::string& name, const std::map<std::string, double>& values,
                               const std::map<std::string, std::string>& notes, const toml::table& provenance);

/// The common part of a bridge's provenance entry: command (argv, shell-quoted), date (ISO 8601
/// UTC) and shockfield_version.
toml::table bridge_provenance_entry(const std::vector<std::string>& command_line);

/// Writes a material file for `bridge`: with `update` and an existing file, its values, strings
/// and provenance entries are kept except the sections this bridge gives (replaced whole); its [provenance.<bridge>]
/// becomes `entry`. The file is replaced atomically (io::replace_file).
void write_bridged_material(const std::filesystem::path& file, bool update, const std::string& name,
                            const std::string& bridge, const std::map<std::string, double>& values,
                            const std::map<std::string, std::string>& notes, const toml::table& entry);

}  // namespace shockfield::materials

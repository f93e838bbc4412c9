#pragma once
// Case-file reading with validation. A Config is a view on one TOML table of a case file. Every
// typed read records the value (or its default) in the resolved configuration; once a case is
// parsed, check_unknown_keys() reports every key nobody read. Every failure is an InputError
// naming the file, the dotted key, its line and what was expected.
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace shockfield {

/// Inclusive or exclusive bounds on a number read from a case file.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  /// False for NaN and +-inf whatever the bounds ("a finite number").
  bool contains(double v) const;
  /// An integer compared exactly (no rounding to double at the bounds).
  bool contains(long long v) const;
  std::string describe() const;
};

class Config {
 public:
  /// Parses a TOML file; syntax errors become InputError with file:line:column.
  static Config load(const std::filesystem::path& file);
  /// Parses a case file for a run (config_case.cpp). `overrides` are `--set` values,
  /// "dotted.key=value" with the value in TOML syntax (1.5, 10, true, "text", [1, 2]; elements
  /// of arrays of tables as stage[1].steps); they replace or add values before anything reads the
  /// case, so a wrong key or type is refused as the file's would be, the message naming --set. A
  /// file that carries [derived] (a config.resolved.toml fed back) is accepted: every derive()
  /// then checks its fresh value against the stored one (doubles to 1e-12 relative, others
  /// exactly). [provenance] is ignored.
  static Config load(const std::filesystem::path& file, const std::vector<std::string>& overrides);
  /// Parses TOML text (tests); `name` stands in for the file name in messages.
  static Config parse(std::string_view text, const std::string& name = "<string>");

  const std::string& file() const { return shared_->file; }
  /// Dotted path of this table ("" for the root).
  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;

  bool has(std::string_view key) const;

  // Required values.
  double get_double(std::string_view key, Range range = {}) const;
  long long get_int(std::string_view key, Range range = {}) const;
  bool get_bool(std::string_view key) const;
  std::string get_string(std::string_view key) const;
  /// A string that must be one of `choices`.
  std::string get_choice(std::string_view key, const std::vector<std::string>& choices) const;
  std::vector<double> get_doubles(std::string_view key, std::size_t count, Range range = {}) const;
  std::vector<long long> get_ints(std::string_view key, std::size_t count, Range range = {}) const;
  std::vector<std::string> get_strings(std::string_view key) const;
  /// A file named by a string key, resolved relative to the case file's folder; it must exist and
  /// be a regular file. Recorded as its absolute path in the resolved configuration and in
  /// input_files() (so provenance hashes it).
  std::filesystem::path get_input_file(std::string_view key) const;
  /// The same with the folders a relative name is looked up in, in order (e.g. the case file's
  /// folder, then the LAMMPS potential folder); the error lists every place tried.
  std::filesystem::path get_input_file(std::string_view key,
                                       const std::vector<std::filesystem::path>& folders) const;

  // Optional values with a default (the default is recorded in the resolved config).
  double get_double_or(std::string_view key, double fallback, Range range = {}) const;
  long long get_int_or(std::string_view key, long long fallback, Range range = {}) const;
  bool get_bool_or(std::string_view key, bool fallback) const;
  std::string get_string_or(std::string_view key, const std::string& fallback) const;
  std::string get_choice_or(std::string_view key, const std::vector<std::string>& choices,
                            const std::string& fallback) const;
  std::vector<double> get_doubles_or(std::string_view key, const std::vector<double>& fallback,
                                     Range range = {}) const;

  /// A sub-table; required() throws if it is missing.
  Config table(std::string_view key) const;
  std::optional<Config> optional_table(std::string_view key) const;
  /// A sub-table whose keys all have defaults: when absent, an empty one (its get_*_or give, and
  /// record, their defaults, so the resolved configuration still shows the table).
  Config table_or_empty(std::string_view key) const;
  /// An array of tables ([[key]]); empty when absent.
  std::vector<Config> tables(std::string_view key) const;

  /// Records a derived value (time step in fs, atom count, ...) under [derived] in the resolved
  /// configuration. Values are stored as given.
  void derive(const std::string& key, double value) const;
  void derive(const std::string& key, long long value) const;
  void derive(const std::string& key, const std::string& value) const;
  /// After derivation, for a replayed resolved configuration: a key of its [derived] that this
  /// case never derived is an InputError. Does nothing for a case without [derived].
  void check_replayed_derived() const;

  /// Absolute paths of every file read through get_input_file(), in reading order, once each.
  const std::vector<std::filesystem::path>& input_files() const;
  /// The case as read: the parsed table after --set overrides, without [derived]/[provenance].
  std::string case_toml() const;
  /// resolved_toml() carries `provenance` as its [provenance] table.
  void set_provenance(const toml::table& provenance) const;

  /// Throws InputError listing every key of the file that was never read.
  void check_unknown_keys() const;
  /// The resolved configuration: every value read (with defaults) plus [derived].
  std::string resolved_toml() const;

  /// Error naming this file and key, with the key's line when it has one.
  [[noreturn]] void fail(std::string_view key, const std::string& expectation) const;

 private:
  struct Shared {
    std::string file;
    toml::table root;
    toml::table resolved;
    std::set<std::string> read_keys;
    std::map<std::string, std::string> overrides;  ///< dotted key -> the --set text that set it
    std::optional<toml::table> replayed_derived;   ///< [derived] of a resolved file fed back
    std::set<std::string> derived_keys;            ///< every key derive() was given
    std::vector<std::filesystem::path> input_files;
    std::optional<toml::table> provenance;
  };
  Config(std::shared_ptr<Shared> shared, const toml::table* table, std::string path)
      : shared_(std::move(shared)), table_(table), path_(std::move(path)) {}
  const toml::node* node(std::string_view key) const;
  void mark(std::string_view key) const;
  template <class T>
  void record(std::string_view key, const T& value) const;
  double number(std::string_view key, const toml::node& n, Range range) const;
  void apply_override(const std::string& text);
  /// The --set text that set `dotted_key` or a table holding it (or, with `descendants`, a value
  /// inside it), or nullptr.
  const std::string* override_for(const std::string& dotted_key, bool descendants = false) const;
  void check_replayed(const std::string& key, const toml::node& fresh) const;

  std::shared_ptr<Shared> shared_;
  const toml::table* table_ = nullptr;
  std::string path_;
};

}  // namespace shockfield

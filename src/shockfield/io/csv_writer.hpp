#pragma once
// Time-series CSV: a header line of column names, then one row per record, flushed at once so
// a stopped run keeps every row written; a failed write throws RunError naming the file
// (io/checked_file). Opening in append mode (restart) keeps the old rows up
// to a given value of the first column.
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/io/checked_file.hpp"

namespace shockfield::io {

class CsvWriter {
 public:
  CsvWriter() = default;
  /// Creates `file` with `columns`. With `resume_from` set, keeps the existing rows whose first
  /// column is <= *resume_from (a resumed run rewrites what came after its checkpoint). Values are
  /// written with 10 significant digits, or with `full_precision` as the shortest text that reads
  /// back to the same double.
  CsvWriter(const std::filesystem::path& file, std::vector<std::string> columns,
            const double* resume_from = nullptr, bool full_precision = false);

  void row(const std::vector<double>& values);
  bool is_open() const { return out_.is_open(); }
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  CheckedOutput out_;
  std::vector<std::string> columns_;
  bool full_precision_ = false;
};

}  // namespace shockfield::io

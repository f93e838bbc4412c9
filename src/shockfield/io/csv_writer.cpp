#include "shockfield/io/csv_writer.hpp"

#include <fmt/format.h>

#include <fstream>

#include "shockfield/core/error.hpp"

namespace shockfield::io {

CsvWriter::CsvWriter(const std::filesystem::path& file, std::vector<std::string> columns,
                     const double* resume_from, bool full_precision)
    : columns_(std::move(columns)), full_precision_(full_precision) {
  std::vector<std::string> kept;
  if (resume_from && std::filesystem::exists(file)) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      double first = 0;
      try {
        first = std::stod(line.substr(0, line.find(',')));
      } catch (const std::exception&) {
        throw InputError(fmt::format("{}: row '{}' does not start with a number; cannot resume it", file.string(), line));
      }
      if (first <= *resume_from) kept.push_back(line);
    }
  }
  out_ = CheckedOutput(file);
  for (std::size_t i = 0; i < columns_.size(); ++i) out_ << (i ? "," : "") << columns_[i];
  out_ << '\n';
  for (const auto& line : kept) out_ << line << '\n';
  out_.flush();
}

void CsvWriter::row(const std::vector<double>& values) {
  std::string line;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) line += ',';
    line += full_precision_ ? fmt::format("{}", values[i]) : fmt::format("{:.10g}", values[i]);
  }
  line += '\n';
  out_.write(line);
  out_.flush();
}

}  // namespace shockfield::io

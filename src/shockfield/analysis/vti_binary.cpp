#include "shockfield/analysis/vti_binary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <functional>

#include "shockfield/core/error.hpp"
#include "shockfield/io/vtk_zlib.hpp"

namespace shockfield::analysis {
namespace {

std::string_view start_tag(std::string_view text, std::string_view element) {
  const auto p = text.find(element);
  if (p == std::string_view::npos) return {};
  return text.substr(p, text.find('>', p) - p);
}

// Decodes base64 4-character group by group (white space skipped), so that a header and data
// encoded one after the other ('=' padding in between) decode like one stream.
class Base64 {
 public:
  Base64(std::string_view text, std::size_t pos, std::string where)
      : text_(text), pos_(pos), where_(std::move(where)) {}
  /// The next n bytes; fewer if the text ends (or reaches '<').
  std::string take(std::size_t n) {
    while (pending_.size() < n && group()) {
    }
    const std::string out = pending_.substr(0, n);
    pending_.erase(0, out.size());
    return out;
  }

 private:
  static int sextet(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;  // '=' padding
  }
  bool group() {
    std::array<char, 4> g{};
    for (std::size_t i = 0; i < 4;) {
      if (pos_ >= text_.size() || text_[pos_] == '<') return false;
      const char c = text_[pos_++];
      if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
      if (sextet(c) < 0 && c != '=')
        throw InputError(fmt::format("{}: '{}' is not a base64 character", where_, c));
      g[i++] = c;
    }
    std::uint32_t bits = 0;
    int bytes = 3;
    for (const char c : g) {
      bits = bits << 6 | static_cast<std::uint32_t>(std::max(sextet(c), 0));
      bytes -= c == '=';
    }
    for (int b = 0; b < bytes; ++b) pending_.push_back(static_cast<char>(bits >> (16 - 8 * b)));
    return true;
  }

  std::string_view text_;
  std::size_t pos_;
  std::string where_;
  std::string pending_;
};

template <class T>
T load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

template <class T>
double as_double(const char* p) {
  return static_cast<double>(load<T>(p));
}

struct TypeInfo {
  std::string_view name;
  std::size_t size;
  double (*convert)(const char*);
};
constexpr std::array<TypeInfo, 10> kTypes{{{"Int8", 1, as_double<std::int8_t>},
                                           {"UInt8", 1, as_double<std::uint8_t>},
                                           {"Int16", 2, as_double<std::int16_t>},
                                           {"UInt16", 2, as_double<std::uint16_t>},
                                           {"Int32", 4, as_double<std::int32_t>},
                                           {"UInt32", 4, as_double<std::uint32_t>},
                                           {"Int64", 8, as_double<std::int64_t>},
                                           {"UInt64", 8, as_double<std::uint64_t>},
                                           {"Float32", 4, as_double<float>},
                                           {"Float64", 8, as_double<double>}}};

// Header and values of one array, read through `take(n)` (the next n bytes).
std::vector<double> decode(const VtiBinary& a, std::size_t count,
                           const std::function<std::string(std::size_t)>& take) {
  const std::string_view file = start_tag(a.text, "<VTKFile");
  const std::string where = fmt::format("{}: DataArray '{}'", a.where, a.name);
  const std::string compressor = xml_attribute(file, "compressor");
  if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
    throw InputError(fmt::format("{} is compressed with {}; only vtkZLibDataCompressor (ParaView: Compressor "
                                 "Type ZLib) or uncompressed data is read",
                                 where, compressor));
  const std::string order = xml_attribute(file, "byte_order"),
                    header = xml_attribute(file, "header_type");
  if (order != "LittleEndian" && order != "BigEndian")
    throw InputError(
        fmt::format("{}: byte_order=\"{}\" in <VTKFile>; expected LittleEndian or "
                    "BigEndian",
                    where, order));
  if (!header.empty() && header != "UInt32" && header != "UInt64")
    throw InputError(
        fmt::format("{}: header_type=\"{}\"; expected UInt32 or UInt64", where, header));
  const auto type = std::find_if(kTypes.begin(), kTypes.end(),
                                 [&](const TypeInfo& t) { return t.name == a.type; });
  if (type == kTypes.end())
    throw InputError(fmt::format("{} has type=\"{}\"; expected Int8 … UInt64, Float32 or Float64",
                                 where, a.type));
  const bool swap = (order == "BigEndian") != (std::endian::native == std::endian::big);
  const auto native = [&](std::string bytes) {
    if (swap) std::reverse(bytes.begin(), bytes.end());
    return bytes;
  };
  // Uncompressed, every value takes at least a byte; zlib packs at most io::kZlibMaxExpansion bytes
  // into one, so a larger count is a corrupt header, not an allocation to attempt.
  const std::size_t packing = compressor.empty() ? 1 : io::kZlibMaxExpansion;
  if (count > a.text.size() * packing)
    throw InputError(fmt::format("{}: {} values cannot fit in a file of {} bytes", where, count, a.text.size()));
  const std::size_t header_size = header == "UInt64" ? 8 : 4;
  const std::uint64_t bytes = count * type->size;
  std::string data;
  if (!compressor.empty()) {
    data = io::vtk_zlib_decompress(take, header_size, native, bytes, where);
  } else {
    const std::string h = native(take(header_size));
    if (h.size() < header_size) throw InputError(fmt::format("{}: the data ends in its header", where));
    const std::uint64_t stored = header_size == 8 ? load<std::uint64_t>(h.data()) : load<std::uint32_t>(h.data());
    if (stored != bytes)
      throw InputError(fmt::format("{}: the header says {} bytes; expected {} ({} values of {})", where, stored,
                                   bytes, count, a.type));
    data = take(static_cast<std::size_t>(bytes));
    if (data.size() < bytes)
      throw InputError(fmt::format("{}: {} bytes expected, the data ends after {}", where, bytes, data.size()));
  }
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i)
    values[i] = type->convert(native(data.substr(i * type->size, type->size)).data());
  return values;
}

}  // namespace

std::string xml_attribute(std::string_view tag, const std::string& key) {
  const auto p = tag.find(" " + key + "=\"");
  if (p == std::string_view::npos) return "";
  const auto b = p + key.size() + 3;
  return std::string(tag.substr(b, tag.find('"', b) - b));
}

std::vector<double> VtiBinary::inline_values(std::size_t body, std::size_t count) const {
  Base64 in(text, body, fmt::format("{}: DataArray '{}'", where, name));
  return decode(*this, count, [&](std::size_t n) { return in.take(n); });
}

std::vector<double> VtiBinary::appended_values(double offset, std::size_t count) const {
  const std::string_view appended = start_tag(text, "<AppendedData");
  const auto underscore = text.find('_', text.find("<AppendedData"));
  if (appended.empty() || underscore == std::string_view::npos)
    throw InputError(
        fmt::format("{}: DataArray '{}' is appended but the file has no "
                    "<AppendedData> … _ section",
                    where, name));
  // Range first: the cast of an offset beyond size_t would be undefined.
  if (!(offset >= 0.0 && offset <= static_cast<double>(text.size())) || offset != std::floor(offset))
    throw InputError(fmt::format("{}: DataArray '{}' has offset {}; expected a whole number from 0 "
                                 "to the file's size, {} bytes", where, name, offset, text.size()));
  std::size_t pos = underscore + 1 + static_cast<std::size_t>(offset);
  const std::string encoding = xml_attribute(appended, "encoding");
  if (encoding == "base64") {
    Base64 in(text, pos, fmt::format("{}: DataArray '{}'", where, name));
    return decode(*this, count, [&](std::size_t n) { return in.take(n); });
  }
  if (encoding != "raw")
    throw InputError(
        fmt::format("{}: <AppendedData encoding=\"{}\">; expected raw or base64", where, encoding));
  return decode(*this, count, [&](std::size_t n) {
    const std::string out(text.substr(std::min(pos, text.size()), n));
    pos += out.size();
    return out;
  });
}

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open", path));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string piece_file(const std::string& parallel_file, const std::string& source, const std::string& extension,
                       const std::string& where) {
  namespace fs = std::filesystem;
  const fs::path file = fs::path(source).lexically_normal();
  if (file.extension() != extension || file.is_absolute() || file.empty() || *file.begin() == "..")
    throw InputError(fmt::format("{}: expected a {} file next to or below the .p{}", where, extension,
                                 extension.substr(1)));
  return (fs::path(parallel_file).parent_path() / file).string();
}

}  // namespace shockfield::analysis

#include "shockfield/io/vtk_xml.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <type_traits>

#include "shockfield/core/error.hpp"
#include "shockfield/core/run_folder.hpp"

namespace shockfield::io {

namespace {

const char* format_name(VtkEncoding e) { return e == VtkEncoding::Ascii ? "ascii" : "binary"; }

// VTK's uncompressed inline binary: the UInt64 byte count and the raw values, each base64-encoded.
template <class T>
std::string binary_block(const std::vector<T>& v) {
  const std::uint64_t bytes = v.size() * sizeof(T);
  unsigned char header[sizeof bytes];
  std::memcpy(header, &bytes, sizeof bytes);
  return base64(header, sizeof header) + base64(reinterpret_cast<const unsigned char*>(v.data()), bytes) + "\n";
}

template <class T>
void write_data_array(std::ostream& out, const char* type, const std::string& name, int components,
                      const std::vector<T>& v, VtkEncoding encoding) {
  out << fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"{}\">\n", type, name,
                     components, format_name(encoding));
  if (encoding == VtkEncoding::Base64) {
    out << binary_block(v);
  } else {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if constexpr (std::is_integral_v<T>) out << v[i];
      else out << fmt::format("{:.9g}", v[i]);
      out << ((i % 9 == 8 || i + 1 == v.size()) ? '\n' : ' ');
    }
  }
  out << "        </DataArray>\n";
}

void write_array(std::ostream& out, const VtkArray& a, VtkEncoding encoding) {
  write_data_array(out, "Float64", a.name, a.components, a.values, encoding);
}

}  // namespace

std::string base64(const unsigned char* data, std::size_t size) {
  static constexpr char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t b0 = data[i], b1 = i + 1 < size ? data[i + 1] : 0u, b2 = i + 2 < size ? data[i + 2] : 0u;
    const std::uint32_t n = (b0 << 16) | (b1 << 8) | b2;
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < size ? table[(n >> 6) & 63] : '=';
    out += i + 2 < size ? table[n & 63] : '=';
  }
  return out;
}

void write_vti(const std::filesystem::path& file, const VtkImage& image, VtkEncoding encoding) {
  std::ostringstream out;
  const auto& n = image.points;
  for (const VtkArray& a : image.point_data)
    if (a.values.size() != n[0] * n[1] * n[2] * static_cast<std::size_t>(a.components))
      throw RunError(fmt::format("{}: array '{}' has {} values for {} points", file.string(), a.name, a.values.size(),
                                 n[0] * n[1] * n[2]));
  const std::string extent = fmt::format("0 {} 0 {} 0 {}", n[0] - 1, n[1] - 1, n[2] - 1);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << fmt::format("  <ImageData WholeExtent=\"{}\" Origin=\"{:.17g} {:.17g} {:.17g}\" Spacing=\"{:.17g} {:.17g} {:.17g}\">\n",
                     extent, image.origin[0], image.origin[1], image.origin[2], image.spacing[0], image.spacing[1],
                     image.spacing[2])
      << fmt::format("    <Piece Extent=\"{}\">\n", extent) << "      <PointData>\n";
  for (const VtkArray& a : image.point_data) write_array(out, a, encoding);
  out << "      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n  </ImageData>\n</VTKFile>\n";
  write_file_atomically(file, out.str());
}

void write_vtp(const std::filesystem::path& file, const std::vector<double>& xyz, const std::vector<VtkArray>& point_data,
               VtkEncoding encoding) {
  const std::size_t n = xyz.size() / 3;
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <PolyData>\n"
      << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                     "NumberOfPolys=\"0\">\n", n, n)
      << "      <PointData>\n";
  for (const VtkArray& a : point_data) write_array(out, a, encoding);
  out << "      </PointData>\n      <Points>\n";
  write_array(out, {"points", 3, xyz}, encoding);
  out << "      </Points>\n      <Verts>\n";
  // One vertex cell per point: connectivity 0..n-1, offsets 1..n.
  std::vector<std::int64_t> conn(n), offs(n);
  for (std::size_t i = 0; i < n; ++i) conn[i] = static_cast<std::int64_t>(i), offs[i] = static_cast<std::int64_t>(i + 1);
  write_data_array(out, "Int64", "connectivity", 1, conn, encoding);
  write_data_array(out, "Int64", "offsets", 1, offs, encoding);
  out << "      </Verts>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  write_file_atomically(file, out.str());
}

PvdSeries::PvdSeries(std::filesystem::path file, const double* keep_until) : file_(std::move(file)) {
  if (keep_until && std::filesystem::exists(file_)) {
    std::ifstream in(file_);
    const std::regex entry(R"re(timestep="([^"]+)".*file="([^"]+)")re");
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, entry) && std::stod(m[1].str()) <= *keep_until)
        entries_.emplace_back(std::stod(m[1].str()), m[2].str());
  }
  write();
}

void PvdSeries::add(double time, const std::string& data_file) {
  entries_.emplace_back(time, data_file);
  write();
}

void PvdSeries::write() const {
  std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n  <Collection>\n";
  for (const auto& [t, f] : entries_)
    text += fmt::format("    <DataSet timestep=\"{:.17g}\" part=\"0\" file=\"{}\"/>\n", t, f);
  text += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(file_, text);
}

}  // namespace shockfield::io

#include "shockfield/io/vtk_pieces.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "shockfield/core/error.hpp"
#include "shockfield/core/run_folder.hpp"

namespace shockfield::io {

namespace fs = std::filesystem;

namespace {

using Index3 = std::array<std::size_t, 3>;

// The values in the box [lo, lo + size) of an x-fastest array over `dims` entries of `components`.
template <class Values>
Values copy_box(const Values& values, const Index3& dims, std::size_t components, const Index3& lo, const Index3& size) {
  Values out;
  out.reserve(size[0] * size[1] * size[2] * components);
  for (std::size_t k = lo[2]; k < lo[2] + size[2]; ++k)
    for (std::size_t j = lo[1]; j < lo[1] + size[1]; ++j) {
      const std::size_t first = ((k * dims[1] + j) * dims[0] + lo[0]) * components;
      out.insert(out.end(), values.begin() + static_cast<long>(first),
                 values.begin() + static_cast<long>(first + size[0] * components));
    }
  return out;
}

// The arrays of `arrays` restricted to the box [lo, lo + size) of a grid of `dims` entries.
std::vector<VtkArray> arrays_in_box(const std::vector<VtkArray>& arrays, const Index3& dims, const Index3& lo,
                                    const Index3& size) {
  std::vector<VtkArray> out;
  for (const VtkArray& a : arrays)
    out.push_back({a.name, a.components, copy_box(a.values, dims, static_cast<std::size_t>(a.components), lo, size),
                   a.units, a.integer});
  return out;
}

// The <PDataArray> tags declaring `arrays` as the pieces store them.
std::string declare_arrays(const std::vector<VtkArray>& arrays, VtkPrecision precision) {
  std::string text;
  for (const VtkArray& a : arrays) {
    text += fmt::format("      <PDataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"",
                        data_array_type(a, precision), a.name, a.components);
    text += a.units.empty() ? "/>\n" : fmt::format(" units=\"{}\"/>\n", a.units);
  }
  return text;
}

// The piece files of frame `name`: `<name>/<stem>_<p><extension>`, as written in the summary
// (relative to its folder) and as paths.
struct PieceNames {
  PieceNames(const fs::path& folder, const std::string& name, const char* extension, std::size_t count) {
    const std::string stem = fs::path(name).filename().string();
    fs::remove_all(folder / name);  // no piece left of an earlier frame of this name (a rerun, a resume)
    fs::create_directories(folder / name);
    for (std::size_t p = 0; p < count; ++p) {
      sources.push_back(fmt::format("{}/{}_{}{}", stem, stem, p, extension));
      paths.push_back(folder / name / fmt::format("{}_{}{}", stem, p, extension));
    }
  }
  std::vector<std::string> sources;
  std::vector<fs::path> paths;
};

void check_pieces(int pieces) {
  if (pieces < 1) throw RunError(fmt::format("vtk_pieces = {}: a frame needs at least one piece", pieces));
}

}  // namespace

std::vector<VtkExtent> image_piece_extents(const Index3& points, int pieces) {
  check_pieces(pieces);
  int axis = 2;  // the axis with the most cells, the slowest of equal ones
  for (int d = 1; d >= 0; --d)
    if (points[static_cast<std::size_t>(d)] > points[static_cast<std::size_t>(axis)]) axis = d;
  const auto a = static_cast<std::size_t>(axis);
  const std::size_t cells = points[a] > 0 ? points[a] - 1 : 0;
  const std::size_t count = std::max<std::size_t>(1, std::min(cells, static_cast<std::size_t>(pieces)));
  const VtkExtent whole = VtkExtent::of(points);
  std::vector<VtkExtent> out(count, whole);
  for (std::size_t p = 0; p < count; ++p) {  // cells [p·C/N, (p+1)·C/N): points up to the last cell's far side
    out[p].lo[a] = p * cells / count;
    out[p].hi[a] = cells == 0 ? 0 : (p + 1) * cells / count;
  }
  return out;
}

VtkImage image_piece(const VtkImage& image, const VtkExtent& extent) {
  const Index3 size = extent.points();
  Index3 cell_dims{}, cell_lo{}, cell_size{};
  for (std::size_t d = 0; d < 3; ++d) {
    if (extent.hi[d] >= image.points[d] || extent.lo[d] > extent.hi[d] || (size[d] == 1 && image.points[d] > 1))
      throw RunError(fmt::format("piece extent {} is not a slab of whole cells of an image of {}×{}×{} points",
                                 extent.text(), image.points[0], image.points[1], image.points[2]));
    // VTK's cells: n − 1 along an axis of n > 1 points, one layer along an axis of a single point.
    cell_dims[d] = std::max<std::size_t>(image.points[d], 2) - 1;
    cell_lo[d] = image.points[d] > 1 ? extent.lo[d] : 0;
    cell_size[d] = std::max<std::size_t>(size[d], 2) - 1;
  }
  VtkImage piece;
  piece.points = size;
  piece.origin = image.origin;
  piece.spacing = image.spacing;
  piece.length_units = image.length_units;
  piece.point_data = arrays_in_box(image.point_data, image.points, extent.lo, size);
  piece.cell_data = arrays_in_box(image.cell_data, cell_dims, cell_lo, cell_size);
  if (!image.hidden_points.empty()) piece.hidden_points = copy_box(image.hidden_points, image.points, 1, extent.lo, size);
  return piece;
}

std::string write_image_frame(const fs::path& folder, const std::string& name, const VtkImage& image,
                              VtkFormat format) {
  check_pieces(format.pieces);
  if (format.pieces == 1) {
    write_vti(folder / (name + ".vti"), image, format);
    return name + ".vti";
  }
  const std::vector<VtkExtent> extents = image_piece_extents(image.points, format.pieces);
  const PieceNames pieces(folder, name, ".vti", extents.size());
  const VtkExtent whole = VtkExtent::of(image.points);
  for (std::size_t p = 0; p < extents.size(); ++p)
    write_vti_piece(pieces.paths[p], image_piece(image, extents[p]), format, extents[p], whole);
  std::string text = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <PImageData WholeExtent=\"{}\" GhostLevel=\"0\" Origin=\"{} {} {}\" Spacing=\"{} {} {}\"{}>\n"
      "    <PPointData>\n",
      whole.text(), image.origin[0], image.origin[1], image.origin[2], image.spacing[0], image.spacing[1],
      image.spacing[2], length_units_attribute(image));
  text += declare_arrays(image.point_data, format.precision);
  if (!image.hidden_points.empty())
    text += "      <PDataArray type=\"UInt8\" Name=\"vtkGhostType\" NumberOfComponents=\"1\"/>\n";
  text += "    </PPointData>\n    <PCellData>\n" + declare_arrays(image.cell_data, format.precision) + "    </PCellData>\n";
  for (std::size_t p = 0; p < extents.size(); ++p)
    text += fmt::format("    <Piece Extent=\"{}\" Source=\"{}\"/>\n", extents[p].text(), pieces.sources[p]);
  text += "  </PImageData>\n</VTKFile>\n";
  write_file_atomically(folder / (name + ".pvti"), text);
  return name + ".pvti";
}

std::string write_points_frame(const fs::path& folder, const std::string& name, const std::vector<double>& xyz,
                               const std::vector<VtkArray>& point_data, VtkFormat format,
                               const std::string& position_units) {
  check_pieces(format.pieces);
  if (format.pieces == 1) {
    write_vtp(folder / (name + ".vtp"), xyz, point_data, format, position_units);
    return name + ".vtp";
  }
  const std::size_t n = xyz.size() / 3, count = static_cast<std::size_t>(format.pieces);
  const PieceNames pieces(folder, name, ".vtp", count);
  for (std::size_t p = 0; p < count; ++p) {  // particles [p·n/N, (p+1)·n/N), consecutive
    const Index3 lo{p * n / count, 0, 0}, size{(p + 1) * n / count - p * n / count, 1, 1}, dims{n, 1, 1};
    write_vtp(pieces.paths[p], copy_box(xyz, dims, 3, lo, size), arrays_in_box(point_data, dims, lo, size), format,
              position_units);
  }
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <PPolyData GhostLevel=\"0\">\n    <PPointData>\n";
  text += declare_arrays(point_data, format.precision) + "    </PPointData>\n    <PPoints>\n";
  text += declare_arrays({{"points", 3, {}, position_units}}, format.precision) + "    </PPoints>\n";
  for (const std::string& source : pieces.sources) text += fmt::format("    <Piece Source=\"{}\"/>\n", source);
  text += "  </PPolyData>\n</VTKFile>\n";
  write_file_atomically(folder / (name + ".pvtp"), text);
  return name + ".pvtp";
}

}  // namespace shockfield::io

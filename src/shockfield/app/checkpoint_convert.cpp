#include "shockfield/app/checkpoint_convert.hpp"

#include <fmt/format.h>

#include <map>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/checkpoint.hpp"
#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/run_output.hpp"
#include "shockfield/dbm/velocity_model.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/granular/checkpoint.hpp"
#include "shockfield/io/checkpoint_file.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/md/checkpoint.hpp"
#include "shockfield/mpm/checkpoint.hpp"
#include "shockfield/pd/checkpoint.hpp"
#include "shockfield/phasefield/checkpoint.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;

// The layout each method's converter reads, and what it becomes by default.
struct MethodLayout {
  std::int64_t format;
  ConvertFormat output;
};
const std::map<std::string, MethodLayout>& layouts() {
  static const std::map<std::string, MethodLayout> table{
      {"md", {md::kCheckpointFormat, ConvertFormat::lammps_data}},
      {"macroparticle", {md::kCheckpointFormat, ConvertFormat::vtp}},
      {"mpm", {mpm::kCheckpointFormat, ConvertFormat::vtp}},
      {"pd", {pd::kCheckpointFormat, ConvertFormat::vtp}},
      {"granular", {granular::kCheckpointFormat, ConvertFormat::vtp}},
      {"phasefield.sharp_front", {phasefield::kSharpFrontCheckpointFormat, ConvertFormat::vtp}},
      {"dbm", {dbm::kCheckpointFormat, ConvertFormat::vti}},
      {"phasefield", {phasefield::kCheckpointFormat, ConvertFormat::vti}},
  };
  return table;
}

const char* format_name(ConvertFormat f) {
  switch (f) {
    case ConvertFormat::lammps_data: return "data";
    case ConvertFormat::vtp: return "vtp";
    case ConvertFormat::vti: return "vti";
    case ConvertFormat::list: return "list";
    case ConvertFormat::automatic: break;
  }
  return "auto";
}

std::string join_shape(const std::vector<hsize_t>& shape) {
  std::string s;
  for (const hsize_t d : shape) s += (s.empty() ? "" : ", ") + std::to_string(d);
  return "(" + s + ")";
}

std::string listing(const io::CheckpointReader& checkpoint) {
  const io::Hdf5File& h5 = checkpoint.h5();
  std::string out = fmt::format("{}: {} checkpoint, format {}, step {}, time {}\n", h5.path(), checkpoint.method(),
                                h5.int_attribute("format_version"), checkpoint.count("step"), h5.attribute("time"));
  out += fmt::format("written by shockfield {} (git {}); case sha256 {}\n", h5.string_attribute("shockfield_version"),
                     h5.string_attribute("git_commit"), h5.string_attribute("case_sha256"));
  for (const std::string& name : h5.dataset_names())
    out += fmt::format("  {:<24} {:<7} {:<16} {}\n", name, h5.is_integer(name) ? "int64" : "float64",
                       join_shape(h5.shape(name)), h5.units(name));
  return out;
}

// A dataset as one VTK array per particle (its trailing dimensions the components).
io::VtkArray particle_array(const io::Hdf5File& h5, const std::string& name) {
  const std::vector<hsize_t> shape = h5.shape(name);
  const int components = shape.size() == 2 ? static_cast<int>(shape[1]) : 1;
  return {name, components, h5.read_doubles(name), h5.units(name), h5.is_integer(name)};
}

// Every dataset with one entry per particle (a scalar, a 3-vector or a 3×3 tensor each) but the
// positions themselves.
std::vector<io::VtkArray> particle_arrays(const io::Hdf5File& h5, const std::string& positions, hsize_t n) {
  std::vector<io::VtkArray> arrays;
  for (const std::string& name : h5.dataset_names()) {
    const std::vector<hsize_t> shape = h5.shape(name);
    const bool per_particle = !shape.empty() && shape[0] == n && shape.size() <= 2 &&
                              (shape.size() == 1 || shape[1] == 3 || shape[1] == 9);
    if (name != positions && per_particle) arrays.push_back(particle_array(h5, name));
  }
  return arrays;
}

void write_particles(const io::CheckpointReader& checkpoint, const fs::path& out, io::VtkFormat vtk) {
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string method = checkpoint.method();
  if (method == "granular") {
    // A vertical chain: the grains' centres at depth + displacement below z = 0, drawn along z
    // upwards as the run's own grain frames are (granular/outputs.cpp).
    const std::vector<double> depth = h5.read_doubles("depth"), w = h5.read_doubles("displacement");
    if (w.size() != depth.size())
      throw InputError(fmt::format("{}: {} displacements for {} grains", h5.path(), w.size(), depth.size()));
    std::vector<double> xyz(3 * depth.size(), 0.0);
    for (std::size_t i = 0; i < depth.size(); ++i) xyz[3 * i + 2] = 0.0 - (depth[i] + w[i]);
    io::write_vtp(out, xyz, particle_arrays(h5, "", depth.size()), vtk);
    return;
  }
  const std::string positions = method == "phasefield.sharp_front" ? "domain_centre" : "position";
  const std::vector<hsize_t> shape = h5.shape(positions);
  if (shape.size() != 2 || shape[1] != 3)
    throw InputError(fmt::format("{}: dataset '{}' has shape {}, expected (n, 3)", h5.path(), positions,
                                 join_shape(shape)));
  io::write_vtp(out, h5.read_doubles(positions), particle_arrays(h5, positions, shape[0]), vtk, h5.units(positions));
}

void write_md_data(const io::CheckpointReader& checkpoint, const fs::path& out) {
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string file = h5.path();
  const std::vector<std::int64_t> id = h5.read_ints("id"), type = h5.read_ints("type"), image = h5.read_ints("image");
  const std::vector<double> x = h5.read_doubles("position"), v = h5.read_doubles("velocity");
  const std::vector<double> box = h5.read_doubles("box");
  const std::size_t n = id.size();
  if (type.size() != n || image.size() != 3 * n || x.size() != 3 * n || v.size() != 3 * n || (box.size() != 6 && box.size() != 9))
    throw InputError(fmt::format("{}: datasets id, type, image, position, velocity, box do not describe {} atoms", file, n));
  md::Atoms atoms;
  atoms.mass = h5.read_doubles("type_mass");
  std::istringstream names(h5.string_attribute("type_names"));
  for (std::string name; names >> name;) atoms.type_names.push_back(name == "-" ? "" : name);
  atoms.type_names.resize(atoms.mass.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (type[i] < 0 || type[i] >= atoms.ntypes())
      throw InputError(fmt::format("{}: atom {} has type {}, the file has {} types", file, id[i], type[i] + 1,
                                   atoms.ntypes()));
    atoms.add(Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]), static_cast<int>(type[i]), id[i],
              Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]));
    for (int d = 0; d < 3; ++d) atoms.image[i][d] = static_cast<int>(image[3 * i + d]);
  }
  geometry::Box b;
  b.lo = Vec3(box[0], box[1], box[2]);
  b.hi = Vec3(box[3], box[4], box[5]);
  if (box.size() == 9) b.tilt = Vec3(box[6], box[7], box[8]);  // a triclinic run: lo, hi, xy xz yz
  const std::string codes = h5.string_attribute("boundary");
  if (codes.size() != 3) throw InputError(fmt::format("{}: attribute 'boundary' = '{}', expected 3 codes", file, codes));
  for (int d = 0; d < 3; ++d)
    b.boundary[d] = geometry::parse_boundary(std::string(1, codes[d]), fmt::format("{}: boundary", file));
  io::DataWriteOptions options;
  options.title = fmt::format("LAMMPS data file: shockfield checkpoint {} at step {}", file, checkpoint.count("step"));
  io::write_data(out, b, atoms, options);
}

void write_dbm_grid(const io::CheckpointReader& checkpoint, const fs::path& out, io::VtkFormat vtk) {
  const io::Hdf5File& h5 = checkpoint.h5();
  dbm::Lattice l;
  l.nx = static_cast<int>(checkpoint.count("nx"));
  l.ny = static_cast<int>(checkpoint.count("ny"));
  l.dx = h5.attribute("dx"), l.dy = h5.attribute("dy");
  if (checkpoint.count("ghosts") != dbm::Lattice::ghosts)
    throw InputError(fmt::format("{}: {} ghost layers, this shockfield's lattice has {}", h5.path(),
                                 checkpoint.count("ghosts"), dbm::Lattice::ghosts));
  dbm::VelocityModel model{h5.string_attribute("velocity_model"), h5.read_doubles("velocity_x"),
                           h5.read_doubles("velocity_y"), h5.read_doubles("eta")};
  const std::vector<double> f = h5.read_doubles("f");
  if (model.vy.size() != model.vx.size() || model.eta.size() != model.vx.size() || f.size() != model.vx.size() * l.cells())
    throw InputError(fmt::format("{}: dataset 'f' has {} values, {} velocities on {} cells need {}", h5.path(),
                                 f.size(), model.vx.size(), l.cells(), model.vx.size() * l.cells()));
  const std::vector<double> phi = h5.has("reactant") ? h5.read_doubles("reactant") : std::vector<double>{};
  const double b = h5.attribute("b");
  io::VtkImage img = dbm::macro_cell_image(l, [&](int i, int j) { return dbm::macro_of(model, f.data() + l.at(i, j), l.cells(), b); });
  if (phi.size() == l.cells()) {
    std::vector<double> reactant;
    for (int j = 0; j < l.ny; ++j)
      for (int i = 0; i < l.nx; ++i) reactant.push_back(phi[l.at(i, j)]);
    img.cell_data.push_back({"reactant", 1, std::move(reactant), "1"});
  }
  img.length_units = "1";  // lattice units
  io::write_vti(out, img, vtk);
}

void write_phasefield_grid(const io::CheckpointReader& checkpoint, const fs::path& out, io::VtkFormat vtk) {
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::vector<hsize_t> shape = h5.shape("xi");  // (nz, ny, nx)
  if (shape.size() != 3) throw InputError(fmt::format("{}: dataset 'xi' has shape {}", h5.path(), join_shape(shape)));
  io::VtkImage img;
  const double dx = h5.attribute("dx");
  img.points = {shape[2], shape[1], shape[0]};
  img.spacing = {dx, dx, dx};
  img.length_units = "1";  // model units
  img.point_data.push_back({"xi", 1, h5.read_doubles("xi"), h5.units("xi")});
  io::write_vti(out, img, vtk);
}

}  // namespace

std::string convert_checkpoint(const ConvertRequest& request) {
  const io::CheckpointReader checkpoint(request.checkpoint);
  const std::string file = request.checkpoint.string();
  const std::string method = checkpoint.method();
  const auto layout = layouts().find(method);
  if (!checkpoint.h5().has_attribute("format") || layout == layouts().end())
    throw InputError(fmt::format("{}: not a self-describing shockfield checkpoint (no 'format' attribute or an unknown "
                                 "method '{}'; docs/checkpoints.md)",
                                 file, method));
  checkpoint.require(method, layout->second.format);
  const ConvertFormat format =
      request.format == ConvertFormat::automatic ? layout->second.output : request.format;
  if (format == ConvertFormat::list) return listing(checkpoint);
  if (format != layout->second.output)
    throw InputError(fmt::format("{}: a {} checkpoint converts to --format {}, not {}", file, method,
                                 format_name(layout->second.output), format_name(format)));
  fs::path out = request.output.value_or(fs::path(request.checkpoint).replace_extension(format_name(format)));
  if (format == ConvertFormat::lammps_data) write_md_data(checkpoint, out);
  if (format == ConvertFormat::vtp) write_particles(checkpoint, out, request.vtk);
  if (format == ConvertFormat::vti) {
    if (method == "dbm") write_dbm_grid(checkpoint, out, request.vtk);
    else write_phasefield_grid(checkpoint, out, request.vtk);
  }
  return fmt::format("{} ({} checkpoint, step {}) -> {}", file, method, checkpoint.count("step"), out.string());
}

}  // namespace shockfield::app

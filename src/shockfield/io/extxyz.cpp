#include "shockfield/io/extxyz.hpp"

#include <cmath>
#include <fmt/format.h>
#include <set>

namespace shockfield::io {
namespace {

// A property of the comment line: its name, type letter and the frame columns it holds.
struct Property {
  std::string name;
  char kind;  // R real, I integer
  std::vector<const std::vector<double>*> columns;
};

}  // namespace

void write_extxyz_frame(std::ostream& out, const DumpFrame& frame, const std::vector<std::string>& type_names,
                        const DumpWriteOptions& options) {
  const std::size_t n = frame.natoms();
  const std::vector<Vec3> pos = frame.positions();
  std::set<std::string> used{"type", "element", "x", "y", "z", "xu", "yu", "zu", "xs", "ys", "zs"};
  std::vector<Property> props;
  for (std::size_t c = 0; c < frame.columns.size(); ++c) {
    const std::string& name = frame.columns[c];
    if (used.count(name)) continue;
    // Vector triples written as one property (the names OVITO maps to Velocity and Force).
    const char* triples[2][4] = {{"vx", "vy", "vz", "velo"}, {"fx", "fy", "fz", "forces"}};
    bool triple = false;
    for (const auto& t : triples) {
      if (name != t[0] || !frame.has(t[1]) || !frame.has(t[2])) continue;
      props.push_back({t[3], 'R', {&frame.values[c], &frame.column(t[1]), &frame.column(t[2])}});
      used.insert({t[0], t[1], t[2]});
      triple = true;
    }
    if (!triple) props.push_back({name, is_integer_column(name) ? 'I' : 'R', {&frame.values[c]}});
  }

  fmt::memory_buffer buf;
  auto it = std::back_inserter(buf);
  const Vec3 l = frame.box.length(), t = frame.box.tilt;  // cell vectors a, b, c (restricted triclinic)
  fmt::format_to(it, "{}\nLattice=\"{} 0 0 {} {} 0 {} {} {}\" Origin=\"{} {} {}\" Properties=species:S:1:pos:R:3", n,
                 l.x(), t.x(), l.y(), t.y(), t.z(), l.z(), frame.box.lo.x(), frame.box.lo.y(), frame.box.lo.z());
  for (const Property& p : props) fmt::format_to(it, ":{}:{}:{}", p.name, p.kind, p.columns.size());
  fmt::format_to(it, " pbc=\"{} {} {}\" Timestep={}", frame.box.periodic(0) ? 'T' : 'F',
                 frame.box.periodic(1) ? 'T' : 'F', frame.box.periodic(2) ? 'T' : 'F', frame.timestep);
  if (frame.time) fmt::format_to(it, " Time={}", *frame.time);
  buf.push_back('\n');

  // Species: the element column's names, else the type's name, else the type number.
  const bool by_element = frame.has("element");
  const std::vector<std::string>& names = by_element ? frame.element_names : type_names;
  const std::vector<double>* type = by_element ? &frame.column("element") : frame.has("type") ? &frame.column("type") : nullptr;
  const auto real = [&](double v) {
    if (options.full_precision) fmt::format_to(it, " {}", v);
    else fmt::format_to(it, " {:g}", v);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const long long t = type ? std::llround((*type)[i]) : 0;
    const bool named = t >= 1 && static_cast<std::size_t>(t) <= names.size() && !names[t - 1].empty();
    if (named) fmt::format_to(it, "{}", names[static_cast<std::size_t>(t - 1)]);
    else fmt::format_to(it, "{}", t);
    for (int d = 0; d < 3; ++d) real(pos[i][d]);
    for (const Property& p : props)
      for (const auto* col : p.columns) {
        if (p.kind == 'I') fmt::format_to(it, " {}", std::llround((*col)[i]));
        else real((*col)[i]);
      }
    buf.push_back('\n');
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

}  // namespace shockfield::io

#pragma once
// LAMMPS text dump files (`dump custom` / `dump atom` format), orthogonal or triclinic boxes.
//
//   ITEM: TIMESTEP            one integer
//   ITEM: NUMBER OF ATOMS     one integer
//   ITEM: BOX BOUNDS pp pp ff three lines "lo hi"; a triclinic box "ITEM: BOX BOUNDS xy xz yz pp pp
//                             pp" and three lines "lo_bound hi_bound tilt" (the bounding box, as
//                             LAMMPS writes it; tilts beyond LAMMPS's limits are rejected)
//   ITEM: ATOMS id type x y z ...   one row per atom, any columns
//
// Optional `ITEM: UNITS` and `ITEM: TIME` sections (dump_modify units/time yes) are read too, and
// an `element` column of names (dump custom ... element with dump_modify element Cu ...).
// The writer produces the same header LAMMPS writes (dump custom, box bounds "%-1.16e"), which
// OVITO and LAMMPS `read_dump` open, except ITEM: TIME: the shortest text that reads back to the
// same double (LAMMPS's "%.16g" does not always, docs/conventions.md "Numbers in text").
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::io {

/// One snapshot of a dump file. Per-atom values are stored by column: values[c][i] is the value
/// of column columns[c] for the i-th row of the file.
struct DumpFrame {
  long long timestep = 0;
  std::optional<double> time;  ///< ITEM: TIME, when present
  std::string units;           ///< ITEM: UNITS, when present
  geometry::Box box;
  /// The two-letter LAMMPS boundary codes per dimension ("pp", "ff", "fs", "mm", ...). box.boundary
  /// holds the same reduced to one code per dimension: both p → periodic, any s or m → shrink,
  /// otherwise fixed.
  std::array<std::string, 3> bounds{"pp", "pp", "pp"};
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;
  /// The names of an `element` column: its values are 1-based indices into this list (the
  /// writer prints the names; the reader numbers the names in the order it first meets them).
  std::vector<std::string> element_names;
  std::string source;  ///< the file the frame was read from ("" if made in memory), for messages

  /// "file: dump frame of timestep N", the subject of the frame's error messages.
  std::string where() const;

  std::size_t natoms() const { return values.empty() ? 0 : values.front().size(); }
  /// Index of a column, or nullopt.
  std::optional<std::size_t> find(std::string_view column) const;
  bool has(std::string_view column) const { return find(column).has_value(); }
  /// The values of a column; throws InputError when the frame has no such column.
  const std::vector<double>& column(std::string_view name) const;
  /// Adds (or replaces) a column; its size must equal natoms() unless the frame has no column yet.
  void set_column(const std::string& name, std::vector<double> data);

  // Convenience accessors. Positions come from x/y/z, else xu/yu/zu (unwrapped), else xs/ys/zs
  // (scaled by the box); InputError when none of these is present.
  std::vector<std::int64_t> ids() const;
  std::vector<int> types() const;  ///< 1-based, as in the file
  std::vector<Vec3> positions() const;
};

/// Reads every frame of a dump file.
std::vector<DumpFrame> read_dump(const std::filesystem::path& file);
/// Reads every frame from a stream; `name` stands in for the file name in messages.
std::vector<DumpFrame> read_dump(std::istream& in, const std::string& name);

struct DumpWriteOptions {
  /// false: "%g" for real columns (6 significant digits, the LAMMPS default);
  /// true: the shortest text that reads back to the same double (round-trip exact).
  bool full_precision = false;
};

/// A frame of the owned atoms with the chosen per-atom fields, named as in LAMMPS `dump custom`:
/// id type element x y z xu yu zu ix iy iz vx vy vz fx fy fz mass (types written 1-based;
/// element: atoms.type_names, each of which must then be non-empty). Throws InputError naming an
/// unknown field or a type without a name. Further columns can be added with set_column().
DumpFrame make_dump_frame(long long timestep, const geometry::Box& box, const md::Atoms& atoms,
                          const std::vector<std::string>& fields);

/// Writes one frame (LAMMPS `dump custom` layout). Columns named id, type, mol, proc, ix, iy, iz
/// are written as integers. Throws InputError when columns differ in length.
void write_dump_frame(std::ostream& out, const DumpFrame& frame, const DumpWriteOptions& options = {});

/// Appends frames to one dump file (a trajectory), as `dump custom` does during a run.
class DumpWriter {
 public:
  DumpWriter(const std::filesystem::path& file, DumpWriteOptions options = {});
  void write(const DumpFrame& frame);
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  CheckedOutput out_;
  DumpWriteOptions options_;
};

/// True for the integer-valued per-atom attributes of `dump custom` (id type mol proc procp1 ix
/// iy iz), which the writers print as integers.
bool is_integer_column(std::string_view name);

/// The two-letter dump code of a Box boundary ("pp", "ff", "ss").
std::string dump_bounds_code(geometry::Boundary b);

}  // namespace shockfield::io

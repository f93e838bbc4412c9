#pragma once
// Extended XYZ writer and reader (the format of ASE and OVITO, https://github.com/libAtoms/extxyz):
//
//   <N>
//   Lattice="Lx 0 0 xy Ly 0 xz yz Lz" Origin="xlo ylo zlo" Properties=species:S:1:pos:R:3:... pbc="T T F" Timestep=<n>
//   <species> <x> <y> <z> ...
//
// A frame of per-atom columns (the same DumpFrame as the LAMMPS dump writer) is mapped to
// properties: type → species (the element name of the type, else the 1-based type number),
// x y z (or xu yu zu, xs ys zs) → pos:R:3, vx vy vz → velo:R:3, fx fy fz → forces:R:3, id and
// other integer columns → name:I:1, every other column → name:R:1.
#include <filesystem>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::io {

/// Writes one frame; `type_names` are the element symbols per 0-based type ("" or missing: the
/// type number is the species). Throws InputError when the frame has no positions.
void write_extxyz_frame(std::ostream& out, const DumpFrame& frame, const std::vector<std::string>& type_names,
                        const DumpWriteOptions& options = {});

/// Reads every frame of an extended XYZ file (one frame or many, back to back) as dump frames:
///  - the comment line's `Lattice="ax ay az bx by bz cx cy cz"` must be orthogonal or LAMMPS's
///    restricted triclinic cell (a along x, b in the xy plane: tilts xy = bx, xz = cx, yz = cy,
///    within LAMMPS's limits); a general cell is refused by name. `Origin="x y z"` (OVITO) is the box's
///    lo corner (default 0 0 0). Without a Lattice every axis is shrink-wrapped around the atoms.
///  - `pbc="T T F"` (default T T T with a Lattice, F F F without): T → periodic "pp", F →
///    shrink-wrapped "ss" (extended XYZ does not tell a fixed wall from a free surface);
///  - `Properties=name:type:count:...` (default species:S:1:pos:R:3): pos → x y z, velo (or
///    velocities) → vx vy vz, forces → fx fy fz, other R/I/L columns → one column each (`name`,
///    or `name[k]` for k = 1..count), a logical T/F as 1/0; S columns other than species are left
///    out. species → `type`: the number itself when every species of the file is a positive
///    integer (as the writer prints unnamed types), else 1, 2, ... in order of first appearance
///    with an `element` column of the names;
///  - `id` from an id:I:1 property, else 1..N in the order of the file;
///  - `Timestep=` (else the frame's index in the file) and `Time=`.
/// Every error is an InputError "name:line: what was expected" (a count that is not a number, a
/// row with too few or too many values, a non-finite number, a truncated frame, no pos property).
/// `count_lines`, when given, receives the line number of each frame's atom count (for messages
/// about a frame as a whole: duplicate ids, atoms outside the box).
std::vector<DumpFrame> read_extxyz(const std::filesystem::path& file, std::vector<int>* count_lines = nullptr);
/// The same from a stream; `name` stands in for the file name in messages.
std::vector<DumpFrame> read_extxyz(std::istream& in, const std::string& name, std::vector<int>* count_lines = nullptr);

}  // namespace shockfield::io

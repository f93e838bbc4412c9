#pragma once
// Extended XYZ writer (the format of ASE and OVITO, https://github.com/libAtoms/extxyz):
//
//   <N>
//   Lattice="Lx 0 0 0 Ly 0 0 0 Lz" Origin="xlo ylo zlo" Properties=species:S:1:pos:R:3:... pbc="T T F" Timestep=<n>
//   <species> <x> <y> <z> ...
//
// A frame of per-atom columns (the same DumpFrame as the LAMMPS dump writer) is mapped to
// properties: type → species (the element name of the type, else the 1-based type number),
// x y z (or xu yu zu, xs ys zs) → pos:R:3, vx vy vz → velo:R:3, fx fy fz → forces:R:3, id and
// other integer columns → name:I:1, every other column → name:R:1.
#include <ostream>
#include <string>
#include <vector>

#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::io {

/// Writes one frame; `type_names` are the element symbols per 0-based type ("" or missing: the
/// type number is the species). Throws InputError when the frame has no positions.
void write_extxyz_frame(std::ostream& out, const DumpFrame& frame, const std::vector<std::string>& type_names,
                        const DumpWriteOptions& options = {});

}  // namespace shockfield::io

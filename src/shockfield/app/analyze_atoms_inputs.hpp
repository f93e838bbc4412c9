#pragma once
// The inputs of `shockfield analyze atoms`: LAMMPS text dumps (one file or a series, .gz through
// gzip), LAMMPS data files, extended XYZ files (ASE, OVITO; one frame or many) and shockfield MD
// run folders (their dumps/dump.*.lammpstrj or dump.*.xyz in step order), each read into dump
// frames (written back with the results appended) and validated frame by frame.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::app {

enum class InputKind { dump, data, extxyz };

struct InputFile {
  std::filesystem::path path;
  InputKind kind;
};

/// The files of the command line in order (a run folder expands to its frames in step order).
/// `format`: auto (by extension .xyz/.extxyz[.gz], else a dump when the first line starts with
/// ITEM:, else a data file), dump, data or extxyz. InputError naming the input when unusable.
std::vector<InputFile> expand_inputs(const std::vector<std::string>& inputs, const std::string& format);

/// The frames of one input file.
struct InputFrames {
  std::vector<io::DumpFrame> dumps;                     ///< written back with the results appended
  std::vector<std::string> sources;                     ///< per frame: its name in messages
  std::optional<analysis::atoms::AtomFrame> data_frame;  ///< a data file's one frame (with its types)

  /// Frame f for the analyses, validated (InputError naming the file, and the line for extended XYZ).
  analysis::atoms::AtomFrame frame(std::size_t f) const;
};

/// Reads an input; `data_boundary` are the boundaries of a data file's box.
InputFrames read_input(const InputFile& input, const std::array<geometry::Boundary, 3>& data_boundary);

/// The file the annotated frames of an input are written to inside the output folder: the input's
/// name, without .gz; a data file or an extended XYZ file becomes <stem>.dump.
std::filesystem::path output_name(const InputFile& input);

}  // namespace shockfield::app

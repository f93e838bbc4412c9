#pragma once
// The Burgers-circuit part of `shockfield analyze atoms` (analysis/atoms/burgers_frame): its
// options, and per frame the circuits (given by a line, by atom ids, or placed around the line of
// each defect cluster) with their Frank-scheme Burgers vectors, written to OUTPUT/burgers.csv.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/burgers_frame.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::app {

struct BurgersArgs {
  std::string orient = "1 0 0,0 1 0,0 0 1";
  std::optional<double> lattice;          ///< Å; default: √2 × the median nearest-neighbour distance
  std::vector<std::string> lines;         ///< "x,y,z:ax,ay,az:radius"
  std::vector<std::string> id_circuits;   ///< "id,id,id,..."
  bool around_clusters = false;
  std::optional<double> band, slab;       ///< Å; defaults 0.5 a and 0.66 a
  std::optional<double> spacing;          ///< Å between circuits along a curved cluster; default 2 a

  bool any() const { return !lines.empty() || !id_circuits.empty() || around_clusters; }
};

void add_burgers_options(CLI::App& cmd, BurgersArgs& args);

class BurgersAnalysis {
 public:
  /// Parses the options (InputError naming the option); `clusters_on` says whether --clusters is.
  BurgersAnalysis(const BurgersArgs& args, bool clusters_on);
  /// Opens OUTPUT/burgers.csv (at `file`).
  void open(const std::filesystem::path& file);
  /// The circuits of one frame and their vectors: rows of burgers.csv, and the column
  /// burgers_circuit (circuit number of each atom on one, else 0) appended to the dump.
  void analyze(std::size_t frame_index, const analysis::atoms::AtomFrame& frame,
               const analysis::atoms::ClusterResult* clusters, io::DumpFrame& dump);
  void close() { out_.close(); }
  std::size_t circuits() const { return circuits_; }
  /// Automatic circuits (around clusters, or stations along a curved cluster) whose circuit could not be built (no closed bond path around them: a
  /// cluster on a void's surface, a tangle, bonds stretched past the cutoff), and the first reason.
  std::size_t skipped() const { return skipped_; }
  const std::string& first_skip() const { return first_skip_; }

 private:
  analysis::atoms::BurgersRequest request_;
  io::CheckedOutput out_;
  std::size_t circuits_ = 0, skipped_ = 0;
  std::string first_skip_;
};

}  // namespace shockfield::app

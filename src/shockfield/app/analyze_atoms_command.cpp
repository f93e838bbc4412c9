// `shockfield analyze atoms`: per-atom structure of atoms from LAMMPS dumps, LAMMPS data files,
// extended XYZ files or shockfield MD run folders — coordination, conventional CNA (LAMMPS
// cna/atom), adaptive CNA (Stukowski 2012), centro-symmetry (Kelchner et al. 1998), bond-pair
// types (Honeycutt & Andersen 1987) and diamond structures (Maras et al. 2016), all over one
// neighbour pass per frame (analysis/atoms/). Writes each input's frames again with the per-atom
// results appended as columns (OVITO colours by them) and structures.csv with the counts and
// fractions per structure per frame. Docs: docs/analysis-atoms.md.
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "shockfield/analysis/atoms/cluster_selection.hpp"
#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/app/analyze_atoms_burgers.hpp"
#include "shockfield/app/analyze_atoms_domains.hpp"
#include "shockfield/app/analyze_atoms_inputs.hpp"
#include "shockfield/app/analyze_atoms_profiles.hpp"
#include "shockfield/app/analyze_atoms_tracks.hpp"
#include "shockfield/app/analyze_atoms_voids.hpp"
#include "shockfield/app/analyze_atoms_voxels.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;
namespace aa = shockfield::analysis::atoms;

struct AtomsArgs {
  std::vector<std::string> inputs;
  std::string output = "analysis";
  std::string format = "auto";
  std::string data_boundary = "ppp";
  std::optional<double> coordination, cna, bond_pairs;
  bool adaptive_cna = false;
  bool diamond = false;
  std::string csp;
  std::optional<double> clusters;
  std::string cluster_select;
  std::size_t cluster_min_size = 1;
  BurgersArgs burgers;
  TrackArgs track;
  ProfileArgs profile;
  VoidArgs voids;
  DomainArgs domains;
  VoxelArgs voxel;
  int threads = 0;
  bool no_plot = false;
};

// --cluster-select and --voxel-select: the selection language of analysis/atoms/cluster_selection,
// with errors naming the option and the option that turns a needed analysis on.
aa::ClusterSelection parse_selection(const std::string& spec, aa::StructureAnalyses& s, bool excess_on,
                                     const char* option = "--cluster-select") {
  return aa::parse_cluster_selection(spec, s, excess_on, fmt::format("{} '{}'", option, spec), [](const std::string& m) {
    return m == "excess" ? std::string("--excess-energy") : m == "bpa" ? std::string("--bond-pairs") : "--" + m;
  });
}

aa::StructureAnalyses analyses_of(const AtomsArgs& a) {
  aa::StructureAnalyses s;
  if (a.coordination) s.coordination = aa::Coordination{*a.coordination};
  if (a.cna) s.cna = aa::ConventionalCna{*a.cna};
  if (a.bond_pairs) s.bond_pairs = aa::BondPairAnalysis{*a.bond_pairs};
  if (!a.csp.empty()) s.centro_symmetry = aa::CentroSymmetry{aa::CentroSymmetry::parse_neighbors(a.csp, "--csp")};
  if (a.diamond) s.diamond = aa::DiamondCna{};
  if (a.adaptive_cna || s.empty()) s.adaptive_cna = aa::AdaptiveCna{};
  if (a.clusters.has_value() != !a.cluster_select.empty())
    throw InputError("--clusters and --cluster-select go together: the cutoff and which atoms to cluster");
  if (a.clusters) {
    s.select = parse_selection(a.cluster_select, s, !a.profile.excess_energy.empty());
    s.clusters = aa::DefectClusters{*a.clusters, a.cluster_min_size};
  }
  return s;
}

// structures.csv: frame, timestep, atoms, then the counts and fractions of each structure method.
std::vector<std::string> summary_columns(const aa::StructureAnalyses& s) {
  std::vector<std::string> columns{"frame", "timestep", "atoms"};
  for (std::string& c : aa::structure_count_columns(s)) columns.push_back(std::move(c));
  return columns;
}

std::vector<double> summary_row(std::size_t frame, long long timestep, std::size_t natoms,
                                const aa::StructureAnalysisResult& r) {
  std::vector<double> row{double(frame), double(timestep), double(natoms)};
  for (double v : aa::structure_count_values(r)) row.push_back(v);
  return row;
}

// Outputs go to <name>.partial and are renamed when every input has been analysed; on an error
// the partial files (and the output folder, when this command created it) are removed, so
// nothing half-written is left.
class PendingOutputs {
 public:
  explicit PendingOutputs(const fs::path& folder) : folder_(folder), created_(!fs::exists(folder)) {
    fs::create_directories(folder);
  }
  fs::path add(const fs::path& name) {
    const fs::path final_path = folder_ / name;
    if (std::find(finals_.begin(), finals_.end(), final_path) != finals_.end())
      throw InputError(fmt::format("two inputs would both be written to {}; give inputs with different file names",
                                   final_path.string()));
    finals_.push_back(final_path);
    return final_path.string() + ".partial";
  }
  void commit() {
    for (const auto& f : finals_) fs::rename(f.string() + ".partial", f);
    finals_.clear();
    created_ = false;
  }
  ~PendingOutputs() {
    std::error_code ec;
    for (const auto& f : finals_) fs::remove(f.string() + ".partial", ec);
    if (created_) fs::remove(folder_, ec);  // only when empty
  }

 private:
  fs::path folder_;
  bool created_;
  std::vector<fs::path> finals_;
};

void run_atoms(const AtomsArgs& a) {
  if (a.threads > 0) omp_set_num_threads(a.threads);
  aa::StructureAnalyses analyses = analyses_of(a);
  std::array<geometry::Boundary, 3> boundary{};
  if (a.data_boundary.size() != 3)
    throw InputError(fmt::format("--data-boundary: expected three of p, f, s (e.g. ppf), got '{}'", a.data_boundary));
  for (int d = 0; d < 3; ++d) boundary[d] = geometry::parse_boundary(std::string(1, a.data_boundary[d]), "--data-boundary");
  const auto files = expand_inputs(a.inputs, a.format);
  if (files.empty()) throw InputError("analyze atoms: no input given");

  const fs::path out_dir(a.output);
  PendingOutputs pending(out_dir);
  ProfileOutput profiles(a.profile, analyses);
  const aa::AtomFrame* current_frame = nullptr;  // the frame being analysed and its dump: the excess
  const io::DumpFrame* current_dump = nullptr;   // energy's pe column
  if (profiles.excess())
    analyses.excess_energy = [&](const aa::StructureAnalysisResult& r) {
      return profiles.excess_energy(*current_frame, r, *current_dump);
    };
  io::CsvWriter summary(pending.add("structures.csv"), summary_columns(analyses));
  io::CsvWriter clusters;
  if (analyses.clusters) clusters = io::CsvWriter(pending.add("clusters.csv"), aa::cluster_columns("frame", "timestep"));
  VoidOutput voids(a.voids, [&pending](const fs::path& name) { return fs::path(pending.add(name)); });
  DomainOutput domains(a.domains, analyses.clusters.has_value(),
                       [&pending](const fs::path& name) { return fs::path(pending.add(name)); });
  if (profiles.profiles()) profiles.open(pending.add("profiles.csv"));
  VoxelOutput voxels(a.voxel, [&pending](const fs::path& name) { return fs::path(pending.add(name)); });
  const aa::ClusterSelection voxel_select =
      voxels.on() ? parse_selection(a.voxel.select, analyses, !a.profile.excess_energy.empty(), "--voxel-select")
                  : aa::ClusterSelection{};
  std::optional<TrackOutput> tracks;
  fs::path tracks_file, growth_file;
  if (a.track.track) {
    tracks.emplace(a.track, analyses.clusters.has_value());
    tracks_file = pending.add("tracks.csv");
    growth_file = pending.add("growth.csv");
  }
  std::optional<BurgersAnalysis> burgers;
  if (a.burgers.any()) {
    burgers.emplace(a.burgers, analyses.clusters.has_value());
    burgers->open(pending.add("burgers.csv"));
  }
  std::size_t frame_index = 0, total_atoms = 0;
  for (const InputFile& input : files) {
    const std::string source = input.path.string();
    const fs::path name = output_name(input);
    if (fs::exists(out_dir / name) && fs::equivalent(out_dir / name, input.path))
      throw InputError(fmt::format("{}: the output folder holds the input itself; choose another --output", source));
    io::DumpWriter writer(pending.add(name), io::DumpWriteOptions{true});
    InputFrames in = read_input(input, boundary);
    std::vector<io::DumpFrame>& dumps = in.dumps;
    for (std::size_t f = 0; f < dumps.size(); ++f) {
      const aa::AtomFrame frame = in.frame(f);
      if (frame.size() == 0)
        throw InputError(fmt::format("{}: the frame of timestep {} has no atoms", in.sources[f], frame.timestep));
      current_frame = &frame;
      current_dump = &dumps[f];
      const auto result = aa::analyze_structure(frame, analyses);
      aa::append_structure_columns(dumps[f], result, frame.size());
      if (profiles.profiles()) profiles.add(frame_index, frame, result);
      if (voids.on()) voids.add(frame_index, frame);
      if (domains.on()) domains.add(frame_index, frame, *result.clusters);
      if (voxels.on()) voxels.add(frame, voxel_select(result));
      if (tracks) tracks->add(frame_index, frame, *result.clusters, dumps[f]);
      if (burgers) burgers->analyze(frame_index, frame, result.clusters ? &*result.clusters : nullptr, dumps[f]);
      writer.write(dumps[f]);
      if (result.clusters)
        for (const auto& row : aa::cluster_rows(*result.clusters, double(frame_index), double(frame.timestep))) clusters.row(row);
      summary.row(summary_row(frame_index++, frame.timestep, frame.size(), result));
      total_atoms += frame.size();
    }
  }
  if (burgers) burgers->close();
  profiles.close();
  voids.close();
  domains.close();
  if (tracks) tracks->write(tracks_file, growth_file);
  pending.commit();
  if (!a.no_plot) {  // from the committed CSVs; before the summary lines, which scripts tail
    voids.plot(out_dir);
    domains.plot(out_dir);
  }
  std::printf("analysed %zu frames (%zu atoms) from %zu files; wrote %s/structures.csv and the annotated dumps\n",
              frame_index, total_atoms, files.size(), out_dir.string().c_str());
  if (voids.on()) std::printf("%zu voids in %s/voids.csv\n", voids.voids(), out_dir.string().c_str());
  if (domains.on())
    std::printf("%zu domains in %s/domains.csv%s\n", domains.domains(), out_dir.string().c_str(),
                domains.flat() > 0 ? fmt::format(" ({} flat ones without a surface)", domains.flat()).c_str() : "");
  if (voxels.on()) std::printf("%s\n", voxels.summary().c_str());
  if (burgers) std::printf("%zu Burgers circuits in %s/burgers.csv\n", burgers->circuits(), out_dir.string().c_str());
  if (burgers && burgers->skipped() > 0)
    std::printf("%zu clusters without a closed Burgers circuit were skipped (first: %s)\n", burgers->skipped(),
                burgers->first_skip().c_str());
}

}  // namespace

void add_analyze_atoms_command(CLI::App& analyze) {
  auto a = std::make_shared<AtomsArgs>();
  CLI::App* cmd = analyze.add_subcommand(
      "atoms",
      "Per-atom structure of atoms (Xu et al. (2015) §3.2.3, §4.4): coordination, conventional CNA\n"
      "(LAMMPS cna/atom codes 1 fcc, 2 hcp, 3 bcc, 4 ico, 5 other), adaptive CNA without a cutoff\n"
      "(Stukowski 2012, the same codes), centro-symmetry parameter (Kelchner et al. 1998, LAMMPS\n"
      "centro/atom's pairing), the atom type from Honeycutt-Andersen bond pairs and cubic/hexagonal\n"
      "diamond (Maras et al. 2016), all from one neighbour pass per frame. With no analysis option,\n"
      "adaptive CNA. Writes OUTPUT/<input name>\n"
      "(each input's frames with the results appended as columns coord, cna, acna, csp, bpa, cluster;\n"
      "a data file becomes <stem>.dump), OUTPUT/structures.csv (frame, timestep, atoms, then per\n"
      "method the count and fraction of each structure) and, with --clusters, OUTPUT/clusters.csv\n"
      "(Xu et al. (2015) §4.4.2's central-moment method); with --burgers-*, OUTPUT/burgers.csv (Burgers\n"
      "vectors of fcc dislocations by the Frank scheme of Xu et al. (2015) §3.2.3, FS/RH); with --track,\n"
      "OUTPUT/tracks.csv and OUTPUT/growth.csv (clusters followed in time, growth laws, Fig 72); with\n"
      "--voxel, OUTPUT/voxels_<timestep>.vti (the hcp fraction on a grid: a phase-field [initial] file);\n"
      "with --voids or --domains, the surfaces, volumes and areas of voids or of the phase domains of\n"
      "--clusters (OUTPUT/voids.csv or domains.csv, .vtp per frame, a PNG against time).\n"
      "Inputs: LAMMPS text dumps (one file or several, frames in order; orthogonal boxes; .gz\n"
      "through gzip, written back uncompressed), LAMMPS data files (atom style atomic), extended XYZ\n"
      "(ASE/OVITO .xyz/.extxyz, one or many frames, orthogonal Lattice; written back as <stem>.dump),\n"
      "shockfield MD run folders (their dumps/dump.*.lammpstrj or dump.*.xyz in step order). Outputs\n"
      "appear only when every input was read and analysed. See docs/analysis-atoms.md.");
  cmd->add_option("inputs", a->inputs, "Dump files, data files, extended XYZ files or MD run folders")->required()->check(CLI::ExistingPath);
  cmd->add_option("-o,--output", a->output, "Output folder (created if missing)")->capture_default_str();
  cmd->add_option("--format", a->format,
                  "Input file format: auto (.xyz, .extxyz [.gz]: extended XYZ; else a file whose first line starts "
                  "with ITEM: is a dump, else a data file), dump, data or extxyz")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "dump", "data", "extxyz"}));
  cmd->add_option("--data-boundary", a->data_boundary,
                  "Boundaries of data-file boxes (data files do not store them), one of p f s per axis")
      ->capture_default_str();
  cmd->add_option("--coordination", a->coordination, "Coordination number: neighbours closer than this cutoff (Å)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--cna", a->cna,
                  "Conventional CNA with this cutoff (Å), as LAMMPS cna/atom: 0.854 a for fcc, 1.207 a for bcc")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--adaptive-cna", a->adaptive_cna, "Adaptive CNA (no cutoff; the default analysis)");
  cmd->add_flag("--diamond", a->diamond,
                "Cubic and hexagonal diamond (Maras et al. 2016, as OVITO's Identify diamond structure): adaptive CNA "
                "of the second neighbours -> column dia (0 other, 1 cubic, 2 cubic first neighbour, 3 cubic second "
                "neighbour, 4 hexagonal, 5 and 6 its first and second neighbours) and dia_* columns of "
                "structures.csv");
  cmd->add_option("--csp", a->csp, "Centro-symmetry parameter with N neighbours: fcc (12), bcc (8) or an even N");
  cmd->add_option("--bond-pairs", a->bond_pairs,
                  "Atom type from Honeycutt-Andersen bond-pair indices of bonds shorter than this cutoff (Å)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--clusters", a->clusters,
                  "Cluster the atoms of --cluster-select: connected when closer than this cutoff (Å); writes "
                  "OUTPUT/clusters.csv (size, centre, central-moment ellipsoid semi-axes a >= b >= c and axes, "
                  "ellipsoid volume and surface, atomic volume) and the column cluster (1, 2, ... by size; 0: none)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--cluster-select", a->cluster_select,
                  "Which atoms to cluster: cna|acna|bpa:TYPE[,TYPE...] (any of them) or :!TYPE[,TYPE...] (none of "
                  "them; TYPE fcc hcp bcc ico other), dia:[!]TYPE[,...] (TYPE cubic cubic_first cubic_second "
                  "hexagonal hexagonal_first hexagonal_second other), csp>VALUE (Å²) or excess>VALUE (eV, with "
                  "--excess-energy); "
                  "e.g. acna:hcp, acna:!fcc, acna:!fcc,hcp (dislocation cores), excess>0.1");
  cmd->add_option("--cluster-min-size", a->cluster_min_size, "Drop clusters with fewer atoms")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  add_profile_options(*cmd, a->profile);
  add_void_options(*cmd, a->voids);
  add_domain_options(*cmd, a->domains);
  add_voxel_options(*cmd, a->voxel);
  add_track_options(*cmd, a->track);
  add_burgers_options(*cmd, a->burgers);
  cmd->add_flag("--no-plot", a->no_plot, "No voids.png or domains.png (CSV and .vtp only)");
  cmd->add_option("-j,--threads", a->threads, "OpenMP threads (default: OMP_NUM_THREADS, else all)")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([a] { run_atoms(*a); });
}

}  // namespace shockfield::app

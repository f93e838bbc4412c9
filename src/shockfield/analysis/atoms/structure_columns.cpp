#include "shockfield/analysis/atoms/structure_columns.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace shockfield::analysis::atoms {
namespace {

std::vector<double> codes(const std::vector<Structure>& s) {
  std::vector<double> out(s.size());
  std::transform(s.begin(), s.end(), out.begin(), [](Structure t) { return double(structure_code(t)); });
  return out;
}

}  // namespace

void append_structure_columns(io::DumpFrame& dump, const StructureAnalysisResult& r, std::size_t natoms) {
  if (natoms == 0) return;
  if (!r.coordination.empty()) dump.set_column("coord", {r.coordination.begin(), r.coordination.end()});
  if (r.cna) dump.set_column("cna", codes(r.cna->structure));
  if (r.adaptive_cna) dump.set_column("acna", codes(r.adaptive_cna->structure));
  if (!r.centro_symmetry.empty()) dump.set_column("csp", r.centro_symmetry);
  if (r.bond_pairs) dump.set_column("bpa", codes(r.bond_pairs->structure));
  if (r.diamond) {
    std::vector<double> dia(natoms);
    for (std::size_t i = 0; i < natoms; ++i) dia[i] = static_cast<double>(r.diamond->structure[i]);
    dump.set_column("dia", std::move(dia));
  }
  if (r.clusters) {
    std::vector<double> cluster(natoms);
    for (std::size_t i = 0; i < natoms; ++i) cluster[i] = r.clusters->cluster_of[i] + 1;
    dump.set_column("cluster", std::move(cluster));
  }
  if (!r.excess_energy.empty()) dump.set_column("excess", r.excess_energy);
}

std::vector<std::string> structure_count_columns(const StructureAnalyses& s) {
  std::vector<std::string> columns;
  for (const auto& [method, on] : {std::pair{"cna", s.cna.has_value()}, std::pair{"acna", s.adaptive_cna.has_value()},
                                   std::pair{"bpa", s.bond_pairs.has_value()}}) {
    if (!on) continue;
    for (Structure t : kStructures) columns.push_back(fmt::format("{}_{}_count", method, structure_name(t)));
    for (Structure t : kStructures) columns.push_back(fmt::format("{}_{}_fraction", method, structure_name(t)));
  }
  if (s.diamond) {
    for (DiamondStructure t : kDiamondStructures)
      columns.push_back(fmt::format("dia_{}_count", diamond_structure_name(t)));
    for (DiamondStructure t : kDiamondStructures)
      columns.push_back(fmt::format("dia_{}_fraction", diamond_structure_name(t)));
  }
  if (s.excess_energy) columns.insert(columns.end(), {"excess_reference_eV", "excess_mean_eV"});
  return columns;
}

std::vector<double> structure_count_values(const StructureAnalysisResult& r) {
  std::vector<double> row;
  auto add = [&row](const StructureCounts& counts) {
    for (Structure t : kStructures) row.push_back(double(counts.of(t)));
    for (Structure t : kStructures) row.push_back(counts.fraction(t));
  };
  if (r.cna) add(r.cna->counts);
  if (r.adaptive_cna) add(r.adaptive_cna->counts);
  if (r.bond_pairs) add(r.bond_pairs->counts);
  if (r.diamond) {
    for (DiamondStructure t : kDiamondStructures) row.push_back(double(r.diamond->of(t)));
    for (DiamondStructure t : kDiamondStructures) row.push_back(r.diamond->fraction(t));
  }
  if (r.excess_reference) {
    double sum = 0;
    for (double e : r.excess_energy) sum += e;
    row.insert(row.end(), {*r.excess_reference, r.excess_energy.empty() ? NAN : sum / double(r.excess_energy.size())});
  }
  return row;
}

std::vector<std::string> profile_columns(const std::vector<std::string>& methods, bool excess) {
  std::vector<std::string> columns{"bin", "lo_A", "hi_A", "centre_A", "atoms"};
  for (const std::string& m : methods)
    for (Structure t : kStructures) columns.push_back(fmt::format("{}_{}_fraction", m, structure_name(t)));
  if (excess) columns.push_back("mean_excess_eV");
  return columns;
}

std::vector<std::string> domain_columns() {
  return {"domain",         "atoms", "volume_A3", "area_A2", "equivalent_radius_A",  "atoms_volume_A3",
          "atoms_radius_A", "x_A",   "y_A",       "z_A",     "euler_characteristic", "manifold"};
}

std::vector<std::string> void_columns() {
  return {"void",     "cells",           "volume_A3",        "area_A2", "equivalent_radius_A",
          "missing_volume_A3", "missing_radius_A", "x_A", "y_A", "z_A", "surface_atoms", "euler_characteristic", "manifold"};
}

std::vector<std::string> burgers_columns() {
  return {"circuit", "source", "atoms", "centre_x_A", "centre_y_A", "centre_z_A", "axis_x", "axis_y", "axis_z",
          "radius_A", "b", "kind", "b_h6", "b_k6", "b_l6", "bx_A", "by_A", "bz_A", "max_step_error", "reliable"};
}

bool is_text_column(const std::string& name) { return name == "source" || name == "b" || name == "kind"; }

std::string csv_header(const std::vector<std::string>& columns) {
  std::string header = "frame,timestep";
  for (const std::string& c : columns) header += "," + c;
  return header + "\n";
}

}  // namespace shockfield::analysis::atoms

#include "shockfield/analysis/atoms/cluster_selection.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {

ClusterSelection parse_cluster_selection(const std::string& spec, StructureAnalyses& s, bool excess_on,
                                         const std::string& what, const std::function<std::string(const std::string&)>& enabled_by) {
  // csp>VALUE (Å²) and excess>VALUE (eV): a threshold on a per-atom value.
  for (const auto& [prefix, unit] : {std::pair{std::string("csp>"), "Å²"}, std::pair{std::string("excess>"), "eV"}}) {
    if (spec.rfind(prefix, 0) != 0) continue;
    const bool csp = prefix == "csp>";
    if (csp && !s.centro_symmetry) throw InputError(what + ": selecting by csp needs " + enabled_by("csp"));
    if (!csp && !excess_on) throw InputError(what + ": selecting by excess needs " + enabled_by("excess"));
    double threshold = 0;
    try {
      std::size_t used = 0;
      threshold = std::stod(spec.substr(prefix.size()), &used);
      if (used != spec.size() - prefix.size() || !std::isfinite(threshold)) throw std::invalid_argument(spec);
    } catch (const std::exception&) {
      throw InputError(fmt::format("{}: expected {}NUMBER ({})", what, prefix, unit));
    }
    return [threshold, csp](const StructureAnalysisResult& r) {
      const std::vector<double>& value = csp ? r.centro_symmetry : r.excess_energy;
      std::vector<bool> out(value.size());
      for (std::size_t i = 0; i < out.size(); ++i) out[i] = value[i] > threshold;
      return out;
    };
  }
  const auto colon = spec.find(':');
  const std::string method = spec.substr(0, colon);
  std::string names = colon == std::string::npos ? "" : spec.substr(colon + 1);
  const bool negate = !names.empty() && names[0] == '!';
  if (negate) names.erase(0, 1);
  const std::string expected = what +
                               ": expected cna|acna|bpa:[!]TYPE[,TYPE...] (TYPE fcc hcp bcc ico other), "
                               "dia:[!]TYPE[,TYPE...] (TYPE cubic cubic_first cubic_second hexagonal hexagonal_first "
                               "hexagonal_second other), csp>NUMBER or excess>NUMBER";
  if (method != "cna" && method != "acna" && method != "bpa" && method != "dia") throw InputError(expected);
  // The codes named (a comma-separated list of the method's type names).
  const auto listed_codes = [&](const auto& all, const auto& name_of) {
    std::vector<int> listed;
    for (std::size_t begin = 0; begin <= names.size();) {
      const std::size_t end = std::min(names.find(',', begin), names.size());
      const std::string name = names.substr(begin, end - begin);
      const auto t = std::find_if(all.begin(), all.end(), [&](auto x) { return name_of(x) == name; });
      if (t == all.end()) throw InputError(expected);
      listed.push_back(static_cast<int>(*t));
      begin = end + 1;
    }
    return listed;
  };
  const std::vector<int> listed = method == "dia" ? listed_codes(kDiamondStructures, diamond_structure_name)
                                                  : listed_codes(kStructures, structure_name);
  if (method == "cna" && !s.cna) throw InputError(what + ": selecting by cna needs " + enabled_by("cna"));
  if (method == "bpa" && !s.bond_pairs) throw InputError(what + ": selecting by bpa needs " + enabled_by("bpa"));
  if (method == "acna") s.adaptive_cna = AdaptiveCna{};
  if (method == "dia") s.diamond = DiamondCna{};
  return [method, listed, negate](const StructureAnalysisResult& r) {
    std::vector<int> codes;
    if (method == "dia") {
      for (DiamondStructure t : r.diamond->structure) codes.push_back(static_cast<int>(t));
    } else {
      const auto& types = method == "cna" ? r.cna->structure : method == "acna" ? r.adaptive_cna->structure
                                                                               : r.bond_pairs->structure;
      for (Structure t : types) codes.push_back(static_cast<int>(t));
    }
    std::vector<bool> out(codes.size());
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = (std::find(listed.begin(), listed.end(), codes[i]) != listed.end()) != negate;
    return out;
  };
}

std::vector<std::string> cluster_columns(const std::string& frame_column, const std::string& time_column) {
  return {frame_column, time_column, "cluster", "size", "x_A", "y_A", "z_A", "a_A", "b_A", "c_A", "axis1_x",
          "axis1_y", "axis1_z", "axis2_x", "axis2_y", "axis2_z", "axis3_x", "axis3_y", "axis3_z",
          "ellipsoid_volume_A3", "ellipsoid_surface_A2", "atomic_volume_A3"};
}

std::vector<std::vector<double>> cluster_rows(const ClusterResult& r, double frame_value, double time_value) {
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < r.clusters.size(); ++k) {
    const Cluster& c = r.clusters[k];
    std::vector<double> row{frame_value, time_value, double(k + 1), double(c.size)};
    for (int d = 0; d < 3; ++d) row.push_back(c.centre[d]);
    for (int d = 0; d < 3; ++d) row.push_back(c.semi_axes[d]);
    for (int axis = 0; axis < 3; ++axis)
      for (int d = 0; d < 3; ++d) row.push_back(c.axes(d, axis));
    row.insert(row.end(), {c.ellipsoid_volume, c.ellipsoid_surface, c.atomic_volume});
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace shockfield::analysis::atoms

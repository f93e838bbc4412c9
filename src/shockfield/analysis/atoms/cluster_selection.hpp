#pragma once
// Which atoms to cluster, and the rows of clusters.csv: shared by `shockfield analyze atoms`
// (--cluster-select) and an MD run's in-run [analysis] (cluster_select).
// The selection: "<cna|acna|bpa>:<structure>[,<structure>...]" (any of them),
// "<method>:!<structure>[,...]" (none of them), "dia:[!]<diamond type>[,...]", "csp><value>" or
// "excess><value>"; the analysis it reads must be on (acna and dia are switched on by it).
#include <functional>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/structure_analysis.hpp"

namespace shockfield::analysis::atoms {

/// Parses a selection; switches on acna or dia in `s` when the selection reads them, and throws
/// InputError starting with `what` (the option or key) when it is malformed or reads an analysis
/// that is off — `enabled_by(method)` names how the user turns that one on (csp, cna, bpa, excess).
ClusterSelection parse_cluster_selection(const std::string& spec, StructureAnalyses& s, bool excess_on,
                                         const std::string& what,
                                         const std::function<std::string(const std::string&)>& enabled_by);

/// clusters.csv's columns: the frame's two (frame, timestep for analyze atoms; step, time_ps in a
/// run), then cluster (1, 2, ... largest first), size (atoms), centre x_A y_A z_A, semi-axes a_A b_A
/// c_A (Å), the three unit axes axis<k>_x/y/z, ellipsoid_volume_A3, ellipsoid_surface_A2 and
/// atomic_volume_A3 (metal units named as docs/conventions.md says).
std::vector<std::string> cluster_columns(const std::string& frame_column, const std::string& time_column);
/// Their values, one row per cluster, starting with the frame's two values.
std::vector<std::vector<double>> cluster_rows(const ClusterResult& r, double frame_value, double time_value);

}  // namespace shockfield::analysis::atoms

// Exact validity checks and volumes of a Delaunay division (delaunay.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/predicates.hpp"

namespace shockfield::geometry {

template <int N>
std::string check_delaunay(const DelaunayDivision<N>& d) {
  const auto& S = d.simplices;
  const auto& nb = d.neighbours;
  if (nb.size() != S.size()) return "neighbour table size differs from the simplex count";
  for (std::size_t s = 0; s < S.size(); ++s) {
    PointRefs<N + 1> r;
    for (int j = 0; j <= N; ++j) {
      const std::int32_t v = S[s][j];
      if (v < 0 || static_cast<std::size_t>(v) >= d.points.size() || d.representative[v] != v)
        return fmt::format("simplex {} has an invalid vertex {}", s, v);
      r[j] = d.points[v].data();
    }
    if (orient<N>(r) <= 0) return fmt::format("simplex {} is not positively oriented", s);
    for (int i = 0; i <= N; ++i) {
      const std::int32_t n = nb[s][i];
      if (n < 0) continue;
      // The neighbour shares the face opposite vertex i and points back across it.
      int back = -1;
      for (int j = 0; j <= N; ++j)
        if (nb[n][j] == static_cast<std::int32_t>(s)) back = j;
      if (back < 0) return fmt::format("simplex {} -> {} is not symmetric", s, n);
      const std::int32_t across = S[n][back];
      for (int j = 0; j <= N; ++j)
        if (j != i && std::find(S[n].begin(), S[n].end(), S[s][j]) == S[n].end())
          return fmt::format("simplices {} and {} do not share their face", s, n);
      if (std::find(S[s].begin(), S[s].end(), across) != S[s].end())
        return fmt::format("simplices {} and {} share all vertices", s, n);
      PointRefs<N + 2> q;
      std::copy(r.begin(), r.end(), q.begin());
      q[N + 1] = d.points[across].data();
      if (in_sphere<N>(q) > 0)
        return fmt::format("vertex {} is inside the circumsphere of simplex {}", across, s);
    }
  }
  return {};
}

template <int N>
double simplex_volume(const DelaunayDivision<N>& d, std::size_t s) {
  const auto& v = d.simplices[s];
  const auto& o = d.points[v[N]];
  double e[N][N];
  for (int i = 0; i < N; ++i)
    for (int k = 0; k < N; ++k) e[i][k] = d.points[v[i]][k] - o[k];
  if constexpr (N == 2) return 0.5 * (e[0][0] * e[1][1] - e[0][1] * e[1][0]);
  else
    return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
            e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
            e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
           6.0;
}

template <int N>
double total_volume(const DelaunayDivision<N>& d) {
  double sum = 0.0;
  for (std::size_t s = 0; s < d.simplices.size(); ++s) sum += simplex_volume<N>(d, s);
  return sum;
}

template std::string check_delaunay<2>(const DelaunayDivision<2>&);
template std::string check_delaunay<3>(const DelaunayDivision<3>&);
template double simplex_volume<2>(const DelaunayDivision<2>&, std::size_t);
template double simplex_volume<3>(const DelaunayDivision<3>&, std::size_t);
template double total_volume<2>(const DelaunayDivision<2>&);
template double total_volume<3>(const DelaunayDivision<3>&);

}  // namespace shockfield::geometry

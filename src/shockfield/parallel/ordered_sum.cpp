#include "shockfield/parallel/ordered_sum.hpp"

#include <stdexcept>

namespace shockfield::parallel {

std::vector<double> ordered_sum(const Communicator& comm, const std::vector<double>& values,
                                const std::vector<long long>& index, int columns) {
  if (values.size() != index.size() * static_cast<std::size_t>(columns))
    throw std::logic_error("ordered_sum: values and indices differ in length");
  // Indices travel as doubles: exact below 2^53 items.
  const std::vector<double> all_values = comm.all_gather(values);
  const std::vector<double> all_index = comm.all_gather(std::vector<double>(index.begin(), index.end()));
  const std::size_t items = all_index.size(), q = static_cast<std::size_t>(columns);
  std::vector<double> ordered(items * q);
  std::vector<char> seen(items, 0);
  for (std::size_t n = 0; n < items; ++n) {
    const auto g = static_cast<std::size_t>(all_index[n]);
    if (all_index[n] < 0 || g >= items || seen[g]++) throw std::logic_error("ordered_sum: indices are not 0..n-1 once each");
    for (std::size_t c = 0; c < q; ++c) ordered[g * q + c] = all_values[n * q + c];
  }
  std::vector<double> sum(q, 0.0);
  for (std::size_t g = 0; g < items; ++g)
    for (std::size_t c = 0; c < q; ++c) sum[c] += ordered[g * q + c];
  return sum;
}

}  // namespace shockfield::parallel

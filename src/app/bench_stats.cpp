#include "bench_stats.h"

#include <algorithm>
#include <cmath>

namespace marble {

namespace {
// Nearest rank: the smallest value with at least p of the series at or below it.
double rank(const std::vector<double>& sorted, double p) {
  const auto n = sorted.size();
  auto k = static_cast<size_t>(std::ceil(p * static_cast<double>(n)));
  k = std::clamp<size_t>(k, 1, n);
  return sorted[k - 1];
}
}  // namespace

Spread spreadOf(std::vector<double> values) {
  Spread s;
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  s.min = values.front();
  s.max = values.back();
  s.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  s.p90 = rank(values, 0.9);
  return s;
}

}  // namespace marble

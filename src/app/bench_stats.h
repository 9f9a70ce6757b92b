#pragma once
// Order statistics of a series of per-frame measurements. Medians and percentiles rather than
// means: one frame descheduled by a neighbour's build should not move the headline number.
#include <vector>

namespace marble {

struct Spread {
  double median = 0, min = 0, max = 0, p90 = 0;
};

// All zero for an empty series. Percentiles use the nearest-rank definition (a value that
// was actually measured).
Spread spreadOf(std::vector<double> values);

}  // namespace marble

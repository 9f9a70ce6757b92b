// parallelForEachInTurn (core/parallel_for.h): every item runs exactly once, whichever thread takes
// it, items of uneven cost included; an exception from an item reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "marble/core/parallel_for.h"

namespace marble {
namespace {

TEST(ParallelForEachInTurn, EveryItemRunsOnce) {
  for (size_t count : {size_t{0}, size_t{1}, size_t{3}, size_t{1000}}) {
    std::vector<std::atomic<int>> runs(count);
    std::atomic<unsigned long> spin{0};
    parallelForEachInTurn(count, [&](size_t i) {
      for (size_t k = 0; k < (i % 7) * 2000; ++k) spin.fetch_add(1, std::memory_order_relaxed);  // uneven items
      runs[i].fetch_add(1);
    });
    for (size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << "item " << i << " of " << count;
  }
}

TEST(ParallelForEachInTurn, AnItemsExceptionReachesTheCaller) {
  EXPECT_THROW(parallelForEachInTurn(50, [](size_t i) {
                 if (i == 37) throw std::runtime_error("item 37");
               }),
               std::runtime_error);
}

}  // namespace
}  // namespace marble

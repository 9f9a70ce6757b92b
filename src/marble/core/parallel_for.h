#pragma once
// Splits [0, count) into one contiguous range per hardware thread (at most `maxThreads`) and runs
// `work(begin, end)` on each, the first range on the calling thread. For loops whose iterations
// are independent and write only their own elements, so the result does not depend on the split.
// Below `minPerThread` items per thread it runs on the calling thread alone (a thread's start
// costs ≈ 20-50 µs).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace marble {

inline unsigned workerThreadCount(size_t count, size_t minPerThread, unsigned maxThreads = 16) {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const size_t byWork = std::max<size_t>(1, count / std::max<size_t>(1, minPerThread));
  return static_cast<unsigned>(std::min<size_t>({hw, maxThreads, byWork}));
}

// Exceptions from any range are rethrown on the calling thread (the first range's first).
template <class Work>
void parallelFor(size_t count, size_t minPerThread, Work&& work) {
  const unsigned threads = workerThreadCount(count, minPerThread);
  if (threads <= 1) {
    work(size_t{0}, count);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  auto range = [&](unsigned i) {
    try {
      work(count * i / threads, count * (i + 1) / threads);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  std::vector<std::thread> helpers;
  helpers.reserve(threads - 1);
  for (unsigned i = 1; i < threads; ++i) helpers.emplace_back(range, i);
  range(0);
  for (std::thread& t : helpers) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

// Runs `work(i)` for every i in [0, count) on up to one thread per item (the calling thread one of
// them), each thread taking the next untaken item as it finishes one: for items of uneven cost
// (a file's pieces), where equal ranges would leave one thread waiting for the other.
template <class Work>
void parallelForEachInTurn(size_t count, Work&& work) {
  std::atomic<size_t> next{0};
  parallelFor(workerThreadCount(count, 1), 1, [&](size_t, size_t) {
    for (size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) work(i);
  });
}

}  // namespace marble

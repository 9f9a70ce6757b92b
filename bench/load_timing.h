#pragma once
// The clocks and the median the load benchmarks (load_compare.cpp, load_phases.cpp) report
// with: wall time for what the user waits, process CPU time (all threads) for what the load
// costs on a loaded machine, the calling thread's CPU time for the critical path. Header-only: the benchmarks link marble_lib, not the app's
// bench_clock.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace load_timing {

inline double wallMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
inline double cpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}
// The calling thread's CPU time: with the work split evenly over threads, about the wall time
// the load would take on free cores (it runs the serial steps and its share of each parallel one).
inline double threadMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

}  // namespace load_timing

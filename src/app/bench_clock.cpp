#include "bench_clock.h"

#include <time.h>

namespace marble {

namespace {
double ms(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}
}  // namespace

double wallMs() { return ms(CLOCK_MONOTONIC); }
double threadCpuMs() { return ms(CLOCK_THREAD_CPUTIME_ID); }
double processCpuMs() { return ms(CLOCK_PROCESS_CPUTIME_ID); }

}  // namespace marble

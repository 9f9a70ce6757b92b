#include "marble/core/memory_usage.h"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>

namespace marble {

size_t residentBytes() {
  // statm counts pages: "size resident shared text lib data dt". The second field is the RSS.
  std::ifstream statm("/proc/self/statm");
  size_t sizePages = 0, residentPages = 0;
  if (!(statm >> sizePages >> residentPages)) return 0;
  const long page = sysconf(_SC_PAGESIZE);
  return page > 0 ? residentPages * static_cast<size_t>(page) : 0;
}

size_t peakResidentBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0 || usage.ru_maxrss < 0) return 0;
  return static_cast<size_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

}  // namespace marble

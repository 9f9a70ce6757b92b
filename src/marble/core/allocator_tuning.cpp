#include "marble/core/allocator_tuning.h"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

namespace marble {

bool keepFreedMemoryForReuse() {
#if defined(M_MMAP_THRESHOLD) && defined(M_TRIM_THRESHOLD)
  // Both must be set: setting either one turns off glibc's dynamic adjustment of the other
  // (mallopt(3)), and a fixed 128 KiB mmap threshold alone made frames slower, not faster.
  const bool mmapSet = mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes) == 1;
  const bool trimSet = mallopt(M_TRIM_THRESHOLD, kTrimThresholdBytes) == 1;
  return mmapSet && trimSet;
#else
  return false;
#endif
}

}  // namespace marble

#include "marble/gl/handles.h"

namespace marble::gl {
long& liveObjectCount() {
  static long count = 0;
  return count;
}
}  // namespace marble::gl

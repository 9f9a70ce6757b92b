#pragma once
// GPU time of one pass, from GL_TIME_ELAPSED queries. Two queries alternate so that reading
// last frame's result never stalls on this frame's work.
#include "marble/gl/handles.h"

namespace marble {

class PassTimer {
public:
  void begin();
  void end();
  // Milliseconds of the most recent finished measurement (0 before the first).
  double milliseconds();
  // Blocks until the last measurement is available (for the CLI and benchmarks).
  double waitMilliseconds();

private:
  gl::TimerQuery queries_[2];
  int current_ = 0;
  bool pending_[2] = {false, false};
  double lastMs_ = 0.0;
};

}  // namespace marble

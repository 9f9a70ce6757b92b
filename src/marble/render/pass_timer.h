#pragma once
// GPU time of one pass, from GL_TIME_ELAPSED queries. Two queries alternate so that reading
// last frame's result never stalls on this frame's work.
//
// Serialized timing (setSerialized(true), `marble bench --serial-passes`): every pass waits
// for the work before it (glFinish) and for its own, and is timed by the wall clock. Slower
// (no overlap), but on llvmpipe the only way to see a pass's whole cost: its timer queries
// see the rasterizer threads only, not the vertex processing and binning done at the draw
// call, and a pass whose work is still queued when the next one starts is split between them.
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
  static void setSerialized(bool on);

private:
  gl::TimerQuery queries_[2];
  int current_ = 0;
  bool pending_[2] = {false, false};
  double lastMs_ = 0.0;
  double serialStartMs_ = 0.0;
};

}  // namespace marble

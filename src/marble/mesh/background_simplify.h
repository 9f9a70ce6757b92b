#pragma once
// simplifiedMesh (mesh_optimize.h) on a worker thread, for copies that take seconds (the light's
// proxy of a 1.6 M-triangle scan: ≈ 2 s) while the caller keeps drawing the full mesh. The thread
// owns its copy of the source and its result: dropping the handle before it finishes leaves the
// thread to finish and free them (nothing waits for an abandoned copy).
#include <memory>

#include "marble/mesh/mesh_optimize.h"

namespace marble {

class BackgroundSimplification {
public:
  BackgroundSimplification(Mesh source, size_t targetTriangles, float maxErrorUnits);
  // Whether the copy is made (take() will not wait).
  bool ready() const;
  // The copy; waits for it when not ready. Rethrows what simplifiedMesh threw (out of memory).
  // Once only.
  SimplifiedMesh take();

private:
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace marble

#pragma once
// simplifiedMesh (mesh_optimize.h) on a worker thread, for copies that take seconds (the light's
// proxy of a 1.6 M-triangle scan: ≈ 2 s) while the caller keeps drawing the full mesh. The thread
// owns its copy of the source and its result (core/background_job.h).
#include "marble/core/background_job.h"
#include "marble/mesh/mesh_optimize.h"

namespace marble {

class BackgroundSimplification {
public:
  BackgroundSimplification(Mesh source, size_t targetTriangles, float maxErrorUnits);
  // Whether the copy is made (take() will not wait).
  bool ready() const { return job_.ready(); }
  // The copy; waits for it when not ready. Rethrows what simplifiedMesh threw (out of memory).
  // Once only.
  SimplifiedMesh take() { return job_.take(); }

private:
  BackgroundJob<SimplifiedMesh> job_;
};

}  // namespace marble

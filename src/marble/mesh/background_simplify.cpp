#include "marble/mesh/background_simplify.h"

#include <memory>
#include <utility>

namespace marble {

BackgroundSimplification::BackgroundSimplification(Mesh source, size_t targetTriangles, float maxErrorUnits)
    // std::function needs a copyable callable: the source is shared, not copied again.
    : job_([source = std::make_shared<const Mesh>(std::move(source)), targetTriangles, maxErrorUnits] {
        return simplifiedMesh(*source, targetTriangles, maxErrorUnits);
      }) {}

}  // namespace marble

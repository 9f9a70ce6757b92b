#pragma once
// The first picture a user sees (a bare `marble view`, `marble render` and tools/run.sh): a
// recognizable stone, lit so that the glow through its thin parts and the reflections on its
// broad faces both read. The benchmark and the tests' built-in scene stay `Scene{}` (the
// paper's cream and ochre on chocolate), so their figures and pictures remain comparable.
#include "marble/scene/scene.h"

namespace marble {

Scene showcaseScene();

}  // namespace marble

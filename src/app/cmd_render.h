#pragma once
#include <string>

#include "scene_options.h"

namespace marble {

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  bool timings = false;
};

int runRenderCommand(const RenderOptions& o);

}  // namespace marble

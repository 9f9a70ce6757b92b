#pragma once
#include <string>

#include "scene_options.h"

namespace marble {

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  std::string hdr;  // optional linear EXR
  bool timings = false;
};

int runRenderCommand(const RenderOptions& o);

}  // namespace marble

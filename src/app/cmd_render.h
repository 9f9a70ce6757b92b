#pragma once
#include <string>

#include "scene_options.h"

namespace marble {

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  std::string hdr;  // optional linear EXR
  bool timings = false;
  int supersample = 1;  // render N x wider and higher, box-filter down to the scene's size
};

int runRenderCommand(const RenderOptions& o);

}  // namespace marble

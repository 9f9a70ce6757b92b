#pragma once
#include <string>

#include "../scene_options.h"

namespace marble {

struct ViewOptions {
  SceneOptions scene;
  int frames = 0;          // 0 = until closed
  std::string screenshot;  // saved after the last frame when set
  bool dev = false;        // shader hot reload from the source tree
};

int runViewCommand(const ViewOptions& o);

}  // namespace marble

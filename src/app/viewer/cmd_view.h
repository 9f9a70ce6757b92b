#pragma once
#include <string>

#include "../scene_options.h"
#include "marble/render/mesh_detail.h"

namespace marble {

struct ViewOptions {
  SceneOptions scene;
  int frames = 0;          // 0 = until closed
  std::string screenshot;  // saved after the last frame when set
  bool dev = false;        // shader hot reload from the source tree
  std::string turntable = "off";  // off, object, light: start turning (as the panel's turntable)
  float turntableSpeed = 15.0f;   // degrees per second
  std::string interactionDetail = "auto";  // auto, on, off (interaction_detail.h)
  float interactionResolution = kDefaultInteractionResolution;  // while moving; 1: off
  std::string interactionLightMaps = "on";  // the light's maps reduced while the object or light moves
};

int runViewCommand(const ViewOptions& o);

}  // namespace marble

#pragma once
#include <optional>
#include <string>

#include "scene_options.h"

namespace marble {

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  std::string hdr;  // optional linear EXR
  bool timings = false;
  int supersample = 0;  // render N x wider and higher, box-filter down to the scene's size; 0 = per --quality
  std::string quality = "draft";  // draft: the scene's settings; final: supersampled, full-resolution blur, no FXAA
  std::optional<int> turntable;   // frames of a turntable (none: a still)
  std::string turntableOf = "object";  // object | light
  std::string video;              // .mp4, .webm or .webp encoded from the turntable's frames
  int fps = 24;                   // the video's frame rate
};

int runRenderCommand(const RenderOptions& o);

}  // namespace marble

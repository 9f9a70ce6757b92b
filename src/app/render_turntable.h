#pragma once
// `marble render --turntable N`: N numbered frames of the object (or the light) turning a full
// circle about the vertical axis, each written atomically, then optionally encoded as a video.
#include <filesystem>
#include <string>

#include "marble/render/renderer.h"

namespace marble {

struct TurntableJob {
  int frames = 0;
  bool turnLight = false;        // false: the object turns
  std::filesystem::path folder;  // created if missing
  int supersample = 1;
  int fps = 24;
  std::string video;             // "" = frames only
};

// The printf pattern of the frame files in `folder` for a batch of `frames` ("frame_%04d.png":
// at least 4 digits, so that names sort in order).
std::string framePattern(const std::filesystem::path& folder, int frames);

// Renders the batch with `renderer` (mesh and environment set). What does not change between
// frames is made once and reused: the environment's prefiltered maps, the pattern's turbulence
// grid, and -- when only the light turns -- the camera's G-buffer. Prints a progress bar on
// stderr and the batch's time per frame on stdout.
void renderTurntable(Renderer& renderer, const Scene& scene, const TurntableJob& job);

}  // namespace marble

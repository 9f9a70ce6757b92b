#pragma once
// `marble bench`: renders a scene headless for a number of frames while something moves, and
// prints how long the frames and each pass took and how much memory they held (issue 8).
#include <string>

#include <CLI/CLI.hpp>

#include "scene_options.h"

namespace marble {

struct BenchOptions {
  SceneOptions scene;
  int frames = 20;
  int warmup = 3;
  std::string motion = "none";
  bool json = false;
  bool serialPasses = false;  // --serial-passes
  std::string turbulenceGrid = "on";  // --turbulence-grid on|off
  std::string drawOrder = "optimized";  // --draw-order optimized|file
  std::string lightProxy = "on";      // --light-proxy on|off
  std::string interactionDetail = "off";  // --interaction-detail on|off
  float interactionResolution = 1.0f;      // --interaction-resolution: every frame drawn at this scale
  std::string screenshot;  // --screenshot: the last frame as PNG (to see what the settings draw)
  std::string interactionLightMaps = "off";  // --interaction-light-maps on|off: the light's maps at that scale
};

void addBenchOptions(CLI::App& cmd, BenchOptions& o);
int runBenchCommand(const BenchOptions& o);

}  // namespace marble

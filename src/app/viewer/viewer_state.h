#pragma once
// Everything the viewer shows and edits, apart from GL: the scene, orbit controls, what
// the panel reports, and requests from the panel to the frame loop.
#include <deque>
#include <string>

#include "marble/render/renderer.h"
#include "marble/scene/orbit.h"
#include "marble/scene/scene.h"

namespace marble {

struct ViewerState {
  Scene scene;
  Orbit camera;
  Orbit light;
  std::string meshLabel;          // what is loaded, for the panel
  size_t triangles = 0;
  std::string meshPathInput;      // the panel's path box
  std::string presetName;         // the preset the material started from
  std::string status;             // last message (errors in red)
  bool statusIsError = false;
  std::deque<float> frameMs;      // recent frame times for the graph
  PassTimes passTimes;
  bool requestMeshLoad = false;
  bool requestScreenshot = false;
  bool requestShaderReload = false;
  bool showHelp = false;
  bool devMode = false;

  void setError(const std::string& message) { status = message; statusIsError = true; }
  void setStatus(const std::string& message) { status = message; statusIsError = false; }
};

// Draws the ImGui panel; edits `state` in place.
void drawPanel(ViewerState& state);
void drawHelpOverlay(ViewerState& state);

}  // namespace marble

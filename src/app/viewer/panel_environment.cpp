// The panel's Environment section: studio, none or an equirectangular .hdr map, its strength and
// turn; the stage (backdrop and its blur, ground). Loading is a request to the frame loop (viewer_actions.cpp), which keeps the previous
// environment when the file is bad.
#include <filesystem>

#include "panel_sections.h"
#include "panel_widgets.h"

namespace marble::viewer {
namespace {

// Picking "map": the loaded map if it is the scene's, else load the scene's (or the path box's).
void chooseMap(ViewerState& s) {
  RenderSettings& r = s.scene.render;
  if (!s.loadedEnvironment.empty() && (r.environment_map.empty() || r.environment_map == s.loadedEnvironment)) {
    r.environment = Environment::Map;
    r.environment_map = s.loadedEnvironment;
    return;
  }
  if (!r.environment_map.empty()) s.environmentPathInput = r.environment_map;
  if (s.environmentPathInput.empty()) {
    s.setError("no environment map loaded: enter a .hdr file in the path box and press Load (or drop one on the window)");
    return;
  }
  s.requestEnvironmentLoad = true;  // selects "map" once loaded
}

}  // namespace

void drawEnvironmentSection(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Environment")) return;
  RenderSettings& r = s.scene.render;
  Environment choice = r.environment;
  if (enumCombo("environment", choice, environmentChoices(),
                "Light from all around the object (marble mode): diffuse light and the reflections in the polish.\n"
                "studio: a built-in photo studio (softbox, strip lights). none: only the light.\n"
                "map: an equirectangular Radiance .hdr (twice as wide as high), loaded below.")) {
    if (choice == Environment::Map) chooseMap(s);
    else r.environment = choice;
  }
  ImGui::SliderFloat("strength##env", &r.environment_intensity, 0.0f, 4.0f, "%.2f");
  tooltip("Multiplies the environment's light. The studio is tuned for 0.6; a captured map is usually meant at 1.");
  ImGui::BeginDisabled(r.environment != Environment::Map);
  ImGui::SliderFloat("turn##env", &r.environment_rotation_deg, -180.0f, 180.0f, "%.0f deg");
  tooltip("Turns the map about the vertical axis: moves its sun and windows around the object.");
  ImGui::EndDisabled();
  // The stage (render/stage_pass.h): what surrounds the object in the picture.
  ImGui::Checkbox("backdrop", &r.backdrop);
  tooltip("Show the environment behind the object instead of the background colour (marble mode; `--backdrop on`).");
  ImGui::SameLine();
  ImGui::BeginDisabled(!r.backdrop);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::SliderFloat("blur##backdrop", &r.backdrop_blur, 0.0f, 1.0f, "%.2f");
  tooltip("How blurred the backdrop is: the roughness of the reflection that would show it (0 sharp, 1 a soft glow).");
  ImGui::EndDisabled();
  ImGui::Checkbox("ground", &r.ground);
  tooltip("A grey floor under the object receiving its shadow and a soft contact shadow, fading into the backdrop\n"
          "(marble mode; `--ground on`). Off in the comparison scenes.");
  if (inputText("path##env", s.environmentPathInput, "sky.hdr - or drop a .hdr file")) s.requestEnvironmentLoad = true;
  tooltip("An equirectangular Radiance .hdr, width = 2 x height (at most 8192 x 4096). Enter or Load.\n"
          "Reading and prefiltering takes a second or two; a bad file keeps the current environment.");
  if (ImGui::Button("Load##env")) s.requestEnvironmentLoad = true;
  if (!s.loadedEnvironment.empty()) {
    ImGui::SameLine();
    ImGui::TextWrapped("%s: %s", std::filesystem::path(s.loadedEnvironment).filename().c_str(), s.environmentLabel.c_str());
  }
}

}  // namespace marble::viewer

// The performance section: frame-time graph and each pass's GPU time. The renderer re-runs the
// light-depth and geometry passes only when their inputs change; a pass that did not run this
// frame shows "cached", not a stale number.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "marble/render/mesh_detail.h"

#include "panel_sections.h"
#include "panel_widgets.h"

namespace marble::viewer {
namespace {

void passLine(const char* name, double ms, bool ran, const char* tip) {
  if (ran) ImGui::Text("  %-12s %7.2f ms", name, ms);
  else ImGui::TextDisabled("  %-12s  cached", name);
  tooltip(tip);
}

// auto / on / off, and what auto means for the mesh that is loaded.
void drawInteractionDetailSetting(ViewerState& s) {
  static const char* const kNames[] = {"auto", "on", "off"};
  int current = static_cast<int>(s.interactionDetail);
  if (ImGui::Combo("detail moving", &current, kNames, 3)) s.interactionDetail = static_cast<InteractionDetailSetting>(current);
  static const std::string kTip =
      "Interaction detail: while the camera or the object moves, draw a simplified mesh (about " +
      std::to_string(kInteractionTriangles) +
      " triangles) and the full mesh again on the first still frame, which is then exactly the full picture. "
      "auto: on for meshes above " + std::to_string(kInteractionMinTriangles) + " triangles.";
  tooltip(kTip.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled(interactionDetailApplies(s.interactionDetail, s.triangles) ? "(on)" : "(off)");
}

}  // namespace

void drawPerformanceSection(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Performance", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const std::vector<float> v(s.frameMs.begin(), s.frameMs.end());
  float avg = 0, worst = 0;
  for (float f : v) {
    avg += f;
    worst = std::max(worst, f);
  }
  if (!v.empty()) avg /= static_cast<float>(v.size());
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%.1f ms (%.0f FPS), worst %.0f", avg, avg > 0 ? 1000.0f / avg : 0.0f, worst);
  if (!v.empty())
    ImGui::PlotLines("##frames", v.data(), static_cast<int>(v.size()), 0, overlay, 0.0f, std::max(1.0f, worst * 1.1f),
                     ImVec2(ImGui::GetContentRegionAvail().x, 48.0f * ImGui::GetIO().FontGlobalScale));
  tooltip("Frame time (CPU wall clock) over the last 120 frames. With vsync on it cannot go below the refresh.");
  drawInteractionDetailSetting(s);
  const PassTimes& t = s.passTimes;
  ImGui::TextUnformatted("GPU time per pass:");
  passLine("light depth", t.lightDepthMs, t.lightDepthRan, "Depth map from the light. Re-runs when the light, mesh or turntable moves.");
  passLine("geometry", t.geometryMs, t.geometryRan, "G-buffer (normal, depth) from the camera. Re-runs when the camera, mesh or size changes.");
  const bool marble = s.scene.render.mode == RenderMode::Marble;
  if (!marble)
    passLine("albedo", t.albedoMs, t.albedoRan, "The marble pattern, once per visible pixel. Re-runs with the geometry or when the pattern changes. (Marble mode evaluates it in the post pass.)");
  if (marble && s.scene.render.subsurface_resolution == SubsurfaceResolution::Half)
    passLine("blur depth", t.blurDepthMs, t.blurDepthRan, "The depth at the blur's half resolution, so the lighting and blur shade only the object. Re-runs with the geometry.");
  passLine("lighting", t.lightingMs, t.lightingRan, "Screen-space shading of the object's pixels. Marble mode: the light entering the stone, at the blur's resolution; re-runs when the light, view, scattering, IOR or translucency changes. Other modes: when anything but exposure and background changes.");
  if (marble)
    passLine("subsurface blur", t.subsurfaceBlurMs, t.lightingRan, "Screen-space diffusion of the light under the surface (marble mode, half or full resolution), with the lighting.");
  passLine("post", t.postMs, t.postRan, "Marble mode: blurred light x albedo + reflections, then tone mapping; evaluates the pattern when the view or pattern changed, reuses the stored diffuse part when only gloss, exposure or background changed. Runs whenever anything changed.");
  if (sceneHasStage(s.scene))
    passLine("stage", t.stageMs, t.stageRan, "Backdrop and ground around the object (and, when the model moved, the floor's contact map). Runs whenever anything changed.");
  if (s.scene.render.mode != RenderMode::Floor && s.scene.render.antialias == Antialias::Fxaa)
    passLine("fxaa", t.fxaaMs, t.fxaaRan, "Antialiasing (FXAA) of the displayed picture, on the tiles the object can cover: blends across contrast edges. Runs whenever anything changed.");
  if (s.scene.render.mode == RenderMode::Floor) passLine("floor", t.floorMs, t.floorRan, "The mesh once, flat-shaded: the cheapest frame (benchmarks).");
}

}  // namespace marble::viewer

// The performance section: frame-time graph and each pass's GPU time, for the passes of the
// frame (render/pass_list.h). A cached pass re-runs only when an input it declares changed; one
// that did not run this frame shows "cached", not a stale number. Each tooltip says what the
// pass makes and, from its declaration, what makes it re-run in the current mode.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "marble/render/mesh_detail.h"

#include "panel_sections.h"
#include "panel_widgets.h"

namespace marble::viewer {
namespace {

void passLine(const PassDecl& d, const PassTimes& t, const Scene& scene) {
  if (t.ran[d.pass]) ImGui::Text("  %-15s %7.2f ms", d.label, t.ms[d.pass]);
  else ImGui::TextDisabled("  %-15s  cached", d.label);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))  // the text is made only when shown
    tooltip((std::string(d.what) + " " + passInputsText(d.pass, scene)).c_str());
}

// auto / on / off, and what auto means for the mesh that is loaded.
void drawInteractionDetailSetting(ViewerState& s) {
  static const char* const kNames[] = {"auto", "on", "off"};
  int current = static_cast<int>(s.interactionDetail);
  if (ImGui::Combo("detail moving", &current, kNames, 3)) s.interactionDetail = static_cast<InteractionDetailSetting>(current);
  static const std::string kTip =
      "Interaction detail: while the camera or the object moves, draw a simplified mesh (at most about " +
      std::to_string(kInteractionTriangles) +
      " triangles) and the full mesh again on the first still frame, which is then exactly the full picture. "
      "auto: on for meshes above " + std::to_string(kInteractionMinTriangles) + " triangles.";
  tooltip(kTip.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled(interactionDetailApplies(s.interactionDetail, s.triangles) ? "(on)" : "(off)");
  ImGui::SliderFloat("resolution moving", &s.interactionResolution, Renderer::kMinResolutionScale, 1.0f, "%.2f");
  ImGui::Checkbox("light maps at that resolution", &s.interactionLightMaps);
  tooltip("Dynamic resolution: while the camera, the object or the light moves, every pass draws at this fraction of "
          "the view's width and height and the picture is stretched to the view; the first still frame is drawn at "
          "full resolution, exactly the full picture. 1: off.");
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
  for (const PassDecl& d : passList())
    if (passInFrame(d.pass, s.scene))
      passLine(d, t, s.scene);
}

}  // namespace marble::viewer

// The viewer's panel, docked at the left edge at a fixed width and the window's full height.
// Docked rather than floating so it never covers the object: the 3D view is drawn in the rest
// of the window (cmd_view.cpp offsets it by panelWidth), with its own aspect ratio, so the
// object stays centred in what you can see. Tab hides the panel for a full-window view.
#include <algorithm>

#include "marble/scene/material_scattering.h"
#include "panel_sections.h"
#include "panel_widgets.h"

namespace marble {

void drawPanel(ViewerState& s) {
  using namespace viewer;
  if (!s.showPanel) {
    s.panelWidth = 0;
    return;
  }
  const ImGuiIO& io = ImGui::GetIO();
  // Wide enough for label + slider at the UI scale, but never more than 45% of a small window.
  const float width = std::min(390.0f * io.FontGlobalScale, io.DisplaySize.x * 0.45f);
  s.panelWidth = width;
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, io.DisplaySize.y), ImGuiCond_Always);
  ImGui::Begin("marble", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushItemWidth(-ImGui::CalcTextSize("Oren-Nayar sigma ").x);  // labels stay readable
  drawTopBar(s);
  ImGui::Separator();

  // The status line is pinned under the scrolling sections, so an error is always visible.
  float footer = 0;
  if (!s.status.empty())
    footer = ImGui::CalcTextSize(s.status.c_str(), nullptr, false, ImGui::GetContentRegionAvail().x).y +
             ImGui::GetStyle().ItemSpacing.y * 3;
  ImGui::BeginChild("sections", ImVec2(0, -footer));
  ImGui::PushItemWidth(-ImGui::CalcTextSize("Oren-Nayar sigma ").x);
  drawMaterialSections(s);
  drawLightSection(s);
  drawEnvironmentSection(s);
  drawViewSection(s);
  drawMeshSection(s);
  drawFilesSection(s);
  drawExportSection(s);
  drawPerformanceSection(s);
  // In the radius form the coefficients follow base colour, radius and ior wherever they were
  // edited (or reset), open section or not.
  resolveScattering(s.scene.material);
  ImGui::PopItemWidth();
  ImGui::EndChild();
  if (!s.status.empty()) {
    ImGui::Separator();
    if (s.statusIsError) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", s.status.c_str());
    if (s.statusIsError) ImGui::PopStyleColor();
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace marble

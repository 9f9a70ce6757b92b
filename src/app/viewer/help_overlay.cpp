// The help overlay (F1 or ?): every shortcut and mouse gesture, in one window at the centre.
#include <imgui.h>

#include "viewer_state.h"

namespace marble {
namespace {

struct Shortcut {
  const char* keys;
  const char* what;
};

constexpr Shortcut kShortcuts[] = {
    {"Left drag", "orbit the camera"},
    {"Middle drag, Ctrl+left drag", "pan"},
    {"Wheel", "zoom"},
    {"Shift+left drag, right drag", "move the light around the object"},
    {"F", "frame the object"},
    {"Home", "reset the view to the scene's camera"},
    {"T", "turntable on/off (View section: object or light)"},
    {"Ctrl+Z", "undo a parameter change"},
    {"Ctrl+Y, Ctrl+Shift+Z", "redo"},
    {"F12", "screenshot (PNG, unique name, path in the panel)"},
    {"Tab", "hide/show the panel"},
    {"R", "reload shaders from shaders/ (marble view --dev)"},
    {"F1, ?", "this help"},
    {"Escape", "close this help, then quit"},
    {"Drop a file", "load it as the mesh (a .hdr: the environment map; a .json or a PNG marble rendered: the scene)"},
    {"Ctrl+click a slider", "type an exact value"},
};

}  // namespace

void drawHelpOverlay(ViewerState& s) {
  const ImVec2 ds = ImGui::GetIO().DisplaySize;
  // Centred in the 3D view, not the window, so it does not sit on the panel.
  ImGui::SetNextWindowPos(ImVec2((ds.x + s.panelWidth) * 0.5f, ds.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  ImGui::Begin("Help - shortcuts", &s.showHelp, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const auto& k : kShortcuts) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.45f, 1.0f), "%s", k.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.what);
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("Hover any parameter for what it does. Shortcuts pause while typing in a box.");
  ImGui::End();
}

}  // namespace marble

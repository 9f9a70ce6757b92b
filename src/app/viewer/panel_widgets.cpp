#include "panel_widgets.h"

#include <cstdio>


namespace marble::viewer {

bool inputText(const char* label, std::string& value, const char* hint) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%s", value.c_str());
  const auto flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll;
  const bool enter = hint ? ImGui::InputTextWithHint(label, hint, buf, sizeof buf, flags)
                          : ImGui::InputText(label, buf, sizeof buf, flags);
  value = buf;
  return enter;
}

bool colour(const char* label, glm::vec3& value, const char* tip) {
  // Values are linear RGB; ImGui shows them as they are stored (the preset files' numbers).
  const bool changed = ImGui::ColorEdit3(label, &value.x, ImGuiColorEditFlags_Float);
  tooltip(tip);
  return changed;
}

bool sectionHeader(const char* title, bool defaultOpen, const char* resetTip, bool& reset) {
  reset = false;
  // AllowItemOverlap lets the reset button sit on the header line, where it costs no space
  // and is reachable with the section closed too.
  const ImGuiTreeNodeFlags flags =
      ImGuiTreeNodeFlags_AllowItemOverlap | (defaultOpen ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None);
  const bool open = ImGui::CollapsingHeader(title, flags);
  if (resetTip) {
    const float w = ImGui::CalcTextSize("reset").x + ImGui::GetStyle().FramePadding.x * 2;
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - w);
    ImGui::PushID(title);
    reset = ImGui::SmallButton("reset");
    tooltip(resetTip);
    ImGui::PopID();
  }
  return open;
}

void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  tooltip(text);
}

}  // namespace marble::viewer

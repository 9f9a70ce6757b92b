#pragma once
// Small ImGui helpers shared by the panel's sections: every parameter gets a tooltip, the material's
// widgets come from its parameters' descriptions (panel_material.cpp), every section a header with a reset button.
#include <imgui.h>

#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "marble/scene/enum_choice.h"

namespace marble::viewer {

inline void tooltip(const char* text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

// A text box bound to a std::string; returns true when Enter was pressed in it.
bool inputText(const char* label, std::string& value, const char* hint = nullptr);


bool colour(const char* label, glm::vec3& value, const char* tip);

template <typename Enum>
bool enumCombo(const char* label, Enum& value, std::initializer_list<const char*> names, const char* tip) {
  int i = static_cast<int>(value);
  const bool changed = ImGui::Combo(label, &i, names.begin(), static_cast<int>(names.size()));
  if (changed) value = static_cast<Enum>(i);
  tooltip(tip);
  return changed;
}

// The same for an enum with a name table (scene/enum_choice.h): the combo shows its labels.
template <typename Enum>
bool enumCombo(const char* label, Enum& value, std::span<const EnumChoice> table, const char* tip) {
  const std::vector<const char*> labels = choiceLabelsByValue(table);
  int i = static_cast<int>(value);
  const bool changed = ImGui::Combo(label, &i, labels.data(), static_cast<int>(labels.size()));
  if (changed) value = static_cast<Enum>(i);
  tooltip(tip);
  return changed;
}

// A collapsing header; when open, a right-aligned "reset" button on the first line of the
// section. Returns whether the section is open; sets `reset` when the button was clicked.
bool sectionHeader(const char* title, bool defaultOpen, const char* resetTip, bool& reset);

// A grey "(?)" after the previous item, with a tooltip.
void helpMarker(const char* text);

}  // namespace marble::viewer

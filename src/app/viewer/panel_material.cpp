// The material sections of the panel, one per parameter group (scene/material_params.h), each
// parameter's widget, range and tooltip from its description; each section resets to the
// preset the material came from. A parameter the current render mode does not read is shown
// disabled, its tooltip naming the modes that use it; one the material's other values make
// unused (ParamDesc::active: sigma_a_mm in the radius form) is disabled saying why, or hidden
// (a vein model's keys while vein_model is "paper").
#include <algorithm>
#include <string>

#include "material_sections.h"
#include "panel_sections.h"
#include "panel_widgets.h"
#include "marble/scene/material_params.h"

namespace marble::viewer {
namespace {

ImGuiSliderFlags sliderFlags(const ParamDesc& p) {
  return p.slider.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
}

// The widget of one parameter; true when the user changed it.
bool paramWidget(const ParamDesc& p, Material& m) {
  ParamValue v = p.get(m);
  switch (p.type) {
    case ParamType::Text: return false;  // name and description: the Files section
    case ParamType::UInt: {
      int i = static_cast<int>(std::min<long long>(std::get<long long>(v), 1000000000));
      if (!ImGui::InputInt(p.label, &i)) return false;
      v = static_cast<long long>(std::max(0, i));
      break;
    }
    case ParamType::Int: {
      int i = static_cast<int>(std::get<long long>(v));
      if (!ImGui::SliderInt(p.label, &i, static_cast<int>(p.slider.lo), static_cast<int>(p.slider.hi), "%d",
                            sliderFlags(p)))
        return false;
      v = static_cast<long long>(i);
      break;
    }
    case ParamType::Float: {
      float hi = p.slider.hi;
      if (p.atMost) {  // the loader's cross-field rule (turb_size <= resolution)
        const ParamValue bound = findParam(p.atMost)->get(m);
        hi = std::min(hi, std::holds_alternative<float>(bound) ? std::get<float>(bound)
                                                               : static_cast<float>(std::get<long long>(bound)));
      }
      if (!ImGui::SliderFloat(p.label, &std::get<float>(v), p.slider.lo, hi, p.slider.format, sliderFlags(p)))
        return false;
      break;
    }
    case ParamType::Vec3:
      if (!ImGui::SliderFloat3(p.label, &std::get<glm::vec3>(v).x, p.slider.lo, p.slider.hi, p.slider.format,
                               sliderFlags(p)))
        return false;
      break;
    case ParamType::Colour:
      // Values are linear RGB; ImGui shows them as they are stored (the preset files' numbers).
      if (!ImGui::ColorEdit3(p.label, &std::get<glm::vec3>(v).x, ImGuiColorEditFlags_Float)) return false;
      break;
    case ParamType::Choice: {
      int current = 0;
      std::vector<const char*> labels;
      for (size_t i = 0; i < p.choices.size(); ++i) {
        labels.push_back(p.choices[i].label);
        if (p.choices[i].value == std::get<long long>(v)) current = static_cast<int>(i);
      }
      if (!ImGui::Combo(p.label, &current, labels.data(), static_cast<int>(labels.size()))) return false;
      v = static_cast<long long>(p.choices[static_cast<size_t>(current)].value);
      break;
    }
  }
  p.set(m, v);
  return true;
}

}  // namespace

void drawMaterialSections(ViewerState& s) {
  Material& m = s.scene.material;
  const RenderMode mode = s.scene.render.mode;
  for (const auto& g : paramGroups()) {
    if (g.id == ParamGroup::Identity) continue;
    bool reset;
    const std::string tip = std::string("Set the ") + g.title + " parameters back to preset \"" + s.presetName + "\".";
    const bool open = sectionHeader(g.title, true, tip.c_str(), reset);
    if (reset) resetSection(m, s.presetMaterial, g.id);
    if (!open) continue;
    for (const auto& p : materialParams()) {
      if (p.group != g.id || p.type == ParamType::Text) continue;
      const bool active = paramActive(p, m);
      if (!active && p.hideInactive) continue;
      const bool used = modeReads(p, mode) && active;
      ImGui::BeginDisabled(!used);
      paramWidget(p, m);
      ImGui::EndDisabled();
      if (used)
        tooltip(p.tooltip);
      else
        tooltip(unusedTooltip(p, m, mode).c_str());
    }
  }
  validateForPanel(m);
}

}  // namespace marble::viewer

#pragma once
// The panel's material sections are the parameter groups (scene/material_params.h); "reset
// this section to the preset" copies one group. Header-only and GL-free so
// tests/viewer_ranges_test.cpp can check that a reset touches its own section and nothing else.
#include <algorithm>
#include <string>

#include "marble/scene/material_params.h"

namespace marble::viewer {

inline void resetSection(Material& m, const Material& preset, ParamGroup section) {
  groupOf(section).assign(m, preset);
}

// The loader's cross-field rules (a parameter at most another's value, turb_size <= resolution),
// applied as the panel's sliders move: whatever the panel makes can be saved and loaded.
inline void validateForPanel(Material& m) {
  for (const auto& p : materialParams()) {
    if (!p.atMost || p.type != ParamType::Float) continue;
    const ParamValue bound = findParam(p.atMost)->get(m);
    const float hi = std::holds_alternative<float>(bound) ? std::get<float>(bound)
                                                          : static_cast<float>(std::get<long long>(bound));
    p.set(m, std::min(std::get<float>(p.get(m)), hi));
  }
}

// The tooltip of a control whose value does not reach the picture: its own, and why -- the mode
// `mode` does not read it (naming the modes that do), or `m`'s other values make it unused.
inline std::string unusedTooltip(const ParamDesc& p, const Material& m, RenderMode mode) {
  if (!modeReads(p, mode))
    return std::string(p.tooltip) + "\n\nThe '" + renderModeName(mode) + "' mode does not read this; used by: " +
           modeNames(p.modes) + ".";
  if (!paramActive(p, m)) return std::string(p.tooltip) + "\n\nNot used now: " + p.inactive + ".";
  return p.tooltip;
}

}  // namespace marble::viewer

#include <stdexcept>

#include "marble/scene/scene.h"

namespace marble {

const std::vector<std::string>& renderModeNames() {
  static const std::vector<std::string> names = {"paper", "marble", "phong", "oren-nayar", "subsurface",
                                                 "reflectance", "albedo", "light-depth", "thickness",
                                                 "depth", "position", "normal", "floor"};
  return names;
}

RenderMode parseRenderMode(const std::string& name) {
  const auto& names = renderModeNames();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<RenderMode>(i);
  std::string all;
  for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown render mode \"" + name + "\"; known: " + all);
}

const std::string& renderModeName(RenderMode mode) { return renderModeNames().at(static_cast<size_t>(mode)); }

bool modeShowsAlbedo(RenderMode mode) {
  switch (mode) {
    case RenderMode::LightDepth:
    case RenderMode::Thickness:
    case RenderMode::Depth:
    case RenderMode::Position:
    case RenderMode::Normal:
    case RenderMode::Floor:
      return false;
    default:
      return true;
  }
}

Antialias parseAntialias(const std::string& name) {
  if (name == "fxaa") return Antialias::Fxaa;
  if (name == "none") return Antialias::None;
  throw std::invalid_argument("expected \"fxaa\" or \"none\", got \"" + name + "\"");
}

const char* antialiasName(Antialias aa) { return aa == Antialias::Fxaa ? "fxaa" : "none"; }

}  // namespace marble

// The scene's enums by name (enum_choice.h): render mode, environment, subsurface resolution,
// antialiasing, light type.
#include <stdexcept>

#include "marble/scene/enum_choice.h"
#include "marble/scene/scene.h"

namespace marble {
namespace {

template <typename E>
constexpr int v(E e) {
  return static_cast<int>(e);
}

// In enum order (renderModeNames() and the shaders' MODE_* numbers rely on it).
constexpr EnumChoice kRenderModes[] = {
    {v(RenderMode::Paper), "paper", "paper"},
    {v(RenderMode::Marble), "marble", "marble"},
    {v(RenderMode::Phong), "phong", "phong"},
    {v(RenderMode::OrenNayar), "oren-nayar", "oren-nayar"},
    {v(RenderMode::Subsurface), "subsurface", "subsurface"},
    {v(RenderMode::Reflectance), "reflectance", "reflectance"},
    {v(RenderMode::Albedo), "albedo", "albedo"},
    {v(RenderMode::LightDepth), "light-depth", "light-depth"},
    {v(RenderMode::Thickness), "thickness", "thickness"},
    {v(RenderMode::Depth), "depth", "depth"},
    {v(RenderMode::Position), "position", "position"},
    {v(RenderMode::Normal), "normal", "normal"},
    {v(RenderMode::Floor), "floor", "floor"},
};
constexpr EnumChoice kEnvironments[] = {
    {v(Environment::Studio), "studio", "studio"},
    {v(Environment::None), "none", "none"},
    {v(Environment::Map), "map", "map"},
};
constexpr EnumChoice kSubsurfaceResolutions[] = {
    {v(SubsurfaceResolution::Half), "half", "half"},
    {v(SubsurfaceResolution::Full), "full", "full"},
};
constexpr EnumChoice kAntialias[] = {  // the default first, as messages offer it
    {v(Antialias::Fxaa), "fxaa", "FXAA"},
    {v(Antialias::None), "none", "none"},
};
constexpr EnumChoice kLightTypes[] = {
    {v(LightType::Point), "point", "point"},
    {v(LightType::Directional), "directional", "directional"},
};

constexpr bool inEnumOrder(std::span<const EnumChoice> t) {
  for (size_t i = 0; i < t.size(); ++i)
    if (t[i].value != static_cast<int>(i)) return false;
  return true;
}
static_assert(inEnumOrder(kRenderModes) && inEnumOrder(kEnvironments));

}  // namespace

std::span<const EnumChoice> renderModeChoices() { return kRenderModes; }
std::span<const EnumChoice> environmentChoices() { return kEnvironments; }
std::span<const EnumChoice> subsurfaceResolutionChoices() { return kSubsurfaceResolutions; }
std::span<const EnumChoice> antialiasChoices() { return kAntialias; }
std::span<const EnumChoice> lightTypeChoices() { return kLightTypes; }

const std::vector<std::string>& renderModeNames() {
  static const std::vector<std::string> names = choiceNames(kRenderModes);
  return names;
}

RenderMode parseRenderMode(const std::string& name) {
  if (const EnumChoice* e = findChoice(kRenderModes, name)) return static_cast<RenderMode>(e->value);
  std::string all;
  for (const auto& e : kRenderModes) all += (all.empty() ? "" : ", ") + std::string(e.name);
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

const std::vector<std::string>& environmentNames() {
  static const std::vector<std::string> names = choiceNames(kEnvironments);
  return names;
}

Environment parseEnvironment(const std::string& name) {
  if (const EnumChoice* e = findChoice(kEnvironments, name)) return static_cast<Environment>(e->value);
  throw std::invalid_argument("expected " + choiceAlternatives(kEnvironments) + ", got \"" + name + "\"");
}

Antialias parseAntialias(const std::string& name) {
  if (const EnumChoice* e = findChoice(kAntialias, name)) return static_cast<Antialias>(e->value);
  throw std::invalid_argument("expected " + choiceAlternatives(kAntialias) + ", got \"" + name + "\"");
}

const char* antialiasName(Antialias aa) { return choiceName(kAntialias, static_cast<int>(aa)); }

}  // namespace marble

#pragma once
// An equirectangular environment map made ready for shading, once per load: diffuse light as 9
// SH coefficients (sh_irradiance.h) and specular light as a GGX-prefiltered chain
// (ggx_prefilter.h). The GL side (render/environment_map.h) only uploads this.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "marble/core/image.h"
#include "marble/environment/sh_irradiance.h"
#include "marble/scene/scene.h"

namespace marble {

// Maps wider than this are averaged down to it first: reflections on a 2-unit statuette gain
// nothing from more (a texel is 0.18 degrees), and it bounds memory (21 MiB of RGBA16F with its
// levels) and the prefilter's time.
constexpr int kEnvironmentMaxWidth = 2048;

struct PrefilteredEnvironment {
  std::string source;                 // the file (or a label), for messages
  int sourceWidth = 0, sourceHeight = 0;
  std::vector<ImageRGBF> levels;      // level 0: the map; level k: GGX alpha_k (ggx_prefilter.h)
  float alpha1 = 0.0f;                // alpha of level 1
  ShCoefficients sh{};                // radiance projected on SH up to l = 2
  double seconds = 0.0;               // time spent reading and precomputing
};

// Precomputes everything from an equirectangular image (width = 2 x height).
PrefilteredEnvironment prefilterEnvironment(const ImageRGBF& equirect, const std::string& source);

// Reads a Radiance .hdr (core/hdr_image.h) and precomputes. An image that is not exactly twice
// as wide as high is refused: it is not equirectangular (a cube cross or a mirror ball, say),
// and stretching it would light the object from wrong directions. Throws InputError.
PrefilteredEnvironment loadEnvironmentMap(const std::filesystem::path& path);

// The scene's map when it asks for one (render.environment "map"), else nothing.
std::optional<PrefilteredEnvironment> loadSceneEnvironment(const Scene& scene);

}  // namespace marble

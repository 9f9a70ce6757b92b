#include "marble/environment/environment_lighting.h"

#include <chrono>

#include "marble/core/error.h"
#include "marble/core/hdr_image.h"
#include "marble/environment/equirect.h"
#include "marble/environment/ggx_prefilter.h"

namespace marble {

PrefilteredEnvironment prefilterEnvironment(const ImageRGBF& equirect, const std::string& source) {
  const auto start = std::chrono::steady_clock::now();
  PrefilteredEnvironment env;
  env.source = source;
  env.sourceWidth = equirect.width;
  env.sourceHeight = equirect.height;
  const ImageRGBF* base = &equirect;
  ImageRGBF reduced;
  if (equirect.width > kEnvironmentMaxWidth) {
    reduced = resampleEquirect(equirect, kEnvironmentMaxWidth, kEnvironmentMaxWidth / 2);
    base = &reduced;
  }
  env.sh = projectSh9(*base);
  env.levels = prefilterGgx(*base);
  env.alpha1 = prefilterAlpha1(base->width);
  env.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return env;
}

PrefilteredEnvironment loadEnvironmentMap(const std::filesystem::path& path) {
  const auto start = std::chrono::steady_clock::now();
  const std::string file = path.string();
  const HdrHeader header = readHdrHeader(path);  // the shape is known before any pixel is read
  if (header.width != 2 * header.height)
    throw InputError(file, "", "is " + std::to_string(header.width) + " x " + std::to_string(header.height) +
                                   " pixels; an equirectangular map is exactly twice as wide as high (e.g. 2048 x 1024)");
  const ImageRGBF image = readHdr(path);
  PrefilteredEnvironment env = prefilterEnvironment(image, file);
  env.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return env;
}

std::optional<PrefilteredEnvironment> loadSceneEnvironment(const Scene& scene) {
  if (scene.render.environment != Environment::Map) return std::nullopt;
  try {
    return loadEnvironmentMap(scene.render.environment_map);
  } catch (const InputError& e) {
    // A map the scene file named: the message names the scene too.
    if (!scene.origin.file.empty() && scene.origin.environmentMap == scene.render.environment_map)
      throw InputError(scene.origin.file, "render.environment_map", e.what());
    throw;
  }
}

}  // namespace marble

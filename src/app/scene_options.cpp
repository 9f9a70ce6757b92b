#include "scene_options.h"

#include <cmath>
#include <iostream>

#include "marble/core/error.h"
#include "marble/gl/program.h"
#include "marble/scene/material_io.h"

namespace marble {

void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool withSize) {
  cmd.add_option("input", o.input, "Scene (.json) or mesh (.obj .ply .stl .gltf .glb); default: the built-in scene");
  if (withSize) {
    cmd.add_option("--width", o.width, "Image width in pixels (default: the scene's, 800)")->check(CLI::Range(1, kMaxRenderSize));
    cmd.add_option("--height", o.height, "Image height in pixels (default: the scene's, 800)")->check(CLI::Range(1, kMaxRenderSize));
  }
  std::string modes;
  for (const auto& m : renderModeNames()) modes += (modes.empty() ? "" : ", ") + m;
  cmd.add_option("--mode", o.mode, "Render mode: " + modes);
  cmd.add_option("--preset", o.preset, "Material preset by name (see `marble presets`) or a preset .json file");
  cmd.add_option("--set", o.sets, "Override one material parameter, key=value (repeatable; keys as in preset files)");
  cmd.add_option("--up", o.up, "Which axis of the mesh file is up: y (default), z, x, -y, -z, -x");
  cmd.add_option("--subsurface-resolution", o.subsurfaceResolution,
                 "marble mode's subsurface blur: half (default, fast) or full (crisper)");
  cmd.add_option("--antialias", o.antialias, "Antialiasing of the picture: fxaa (default) or none");
  cmd.add_option("--environment", o.environment, "Light from around the object (marble mode): studio (default), none, map");
  cmd.add_option("--environment-map", o.environmentMap,
                 "An equirectangular Radiance .hdr (twice as wide as high) to light with; implies --environment map");
  cmd.add_option("--environment-rotation", o.environmentRotation, "Turn the environment map about the vertical axis, degrees")
      ->check(CLI::Range(-360.0f, 360.0f));
  cmd.add_option("--environment-intensity", o.environmentIntensity,
                 "Scale of the environment's light (default: the scene's, 0.6; a captured map is usually meant at 1)")
      ->check(CLI::Range(0.0f, 100.0f));
  addAllowOutsideFlag(cmd, o);
}

void addAllowOutsideFlag(CLI::App& cmd, SceneOptions& o) {
  cmd.add_flag("--allow-outside", o.allowOutside,
               "Let a glTF read buffer files outside its own folder (refused by default; see docs/reliability.md)");
}

Scene buildScene(const SceneOptions& o) {
  std::vector<std::string> warnings;
  Scene scene = sceneForInput(o.input, warnings);
  for (const auto& w : warnings) std::cerr << "warning: " << printable(w, kMessageLineLimit) << "\n";
  if (o.allowOutside) scene.allow_outside = true;
  if (o.width > 0) scene.render.width = o.width;
  if (o.height > 0) scene.render.height = o.height;
  if (!o.mode.empty()) {
    try {
      scene.render.mode = parseRenderMode(o.mode);
    } catch (const std::invalid_argument& e) {
      throw InputError("--mode", "", e.what());
    }
  }
  if (!o.antialias.empty()) {
    try {
      scene.render.antialias = parseAntialias(o.antialias);
    } catch (const std::invalid_argument& e) {
      throw InputError("--antialias", "", e.what());
    }
  }
  if (!o.up.empty()) {
    try {
      scene.up = parseUpAxis(o.up);
    } catch (const std::invalid_argument&) {
      throw InputError("--up", "", "expected one of y, z, x, -y, -z, -x, got \"" + o.up + "\"");
    }
  }
  if (o.subsurfaceResolution == "half") scene.render.subsurface_resolution = SubsurfaceResolution::Half;
  else if (o.subsurfaceResolution == "full") scene.render.subsurface_resolution = SubsurfaceResolution::Full;
  else if (!o.subsurfaceResolution.empty())
    throw InputError("--subsurface-resolution", "", "expected half or full, got \"" + o.subsurfaceResolution + "\"");
  if (!o.environmentMap.empty()) {
    scene.render.environment_map = o.environmentMap;
    scene.render.environment = Environment::Map;
  }
  if (!o.environment.empty()) {
    try {
      scene.render.environment = parseEnvironment(o.environment);
    } catch (const std::invalid_argument& e) {
      throw InputError("--environment", "", e.what());
    }
  }
  if (scene.render.environment == Environment::Map && scene.render.environment_map.empty())
    throw InputError("--environment", "", "\"map\" needs a file: add --environment-map FILE.hdr");
  if (o.environmentRotation) {
    // CLI::Range lets NaN through (every comparison with it is false).
    if (!std::isfinite(*o.environmentRotation))
      throw InputError("--environment-rotation", "", "expected a finite number of degrees in [-360, 360]");
    scene.render.environment_rotation_deg = *o.environmentRotation;
  }
  if (o.environmentIntensity) {
    if (!std::isfinite(*o.environmentIntensity))
      throw InputError("--environment-intensity", "", "expected a finite number in [0, 100]");
    scene.render.environment_intensity = *o.environmentIntensity;
  }
  if (!o.preset.empty()) scene.material = loadPreset(o.preset);
  for (const auto& kv : o.sets) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set", kv, "expected key=value");
    setMaterialKey(scene.material, kv.substr(0, eq), kv.substr(eq + 1));
  }
  return scene;
}

int reportErrors(const char* command, const std::function<int()>& body) {
  // InputError and EnvironmentError messages are printable already; anything else (a library's
  // exception) is made so here.
  const auto say = [&](const char* what) { std::cerr << "marble " << command << ": " << printable(what, kMessageLineLimit) << "\n"; };
  try {
    return body();
  } catch (const InputError& e) {
    say(e.what());
    return 2;
  } catch (const EnvironmentError& e) {
    say(e.what());
    return 1;
  } catch (const gl::ShaderError& e) {
    say(e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    say("out of memory");
    return 1;
  } catch (const std::exception& e) {
    say(e.what());
    return 1;
  }
}

}  // namespace marble

#include "scene_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "marble/core/error.h"
#include "marble/gl/program.h"
#include "marble/scene/enum_choice.h"
#include "marble/scene/material_io.h"
#include "marble/scene/material_params.h"
#include "marble/scene/orbit.h"
#include "marble/scene/showcase.h"

namespace marble {

void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool withSize) {
  cmd.add_option("input", o.input, "Scene (.json), a PNG marble rendered (its scene), or a mesh (.obj .ply .stl .gltf .glb); default: the built-in scene");
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
  cmd.add_option("--crease-angle", o.creaseAngle,
                 "For a mesh file without normals: edges whose faces meet at more than this many degrees are hard "
                 "(Blender's Auto Smooth angle; default 60, 180 = smooth everywhere). The file's own normals are used as given")
      ->check(CLI::Range(0.0f, 180.0f));
  cmd.add_option("--subsurface-resolution", o.subsurfaceResolution,
                 "marble mode's subsurface blur: half (default, fast) or full (crisper)");
  cmd.add_option("--antialias", o.antialias, "Antialiasing of the picture: fxaa (default) or none");
  cmd.add_option("--environment", o.environment,
                 "Light from around the object (marble mode): studio (default), none, or FILE.hdr (an equirectangular map)");
  cmd.add_option("--environment-map", o.environmentMap,
                 "An equirectangular Radiance .hdr (twice as wide as high) to light with; implies --environment map");
  cmd.add_option("--environment-rotation", o.environmentRotation, "Turn the environment map about the vertical axis, degrees")
      ->check(CLI::Range(-360.0f, 360.0f));
  cmd.add_option("--environment-intensity", o.environmentIntensity,
                 "Scale of the environment's light (default: the scene's, 0.6; a captured map is usually meant at 1)")
      ->check(CLI::Range(0.0f, 100.0f));
  cmd.add_option("--light", o.light,
                 "Where the light is, keeping its distance: front, side, back, top, or AZ,EL in degrees (azimuth from "
                 "the camera's side of the object, 180 = behind it; elevation above the horizon)");
  cmd.add_option("--light-position", o.lightPosition, "The light's position X,Y,Z (scene units; the object is 2 across, at the origin)");
  cmd.add_option("--camera", o.camera,
                 "Where the camera is: front, side, back, top, or AZ,EL[,DIST] in degrees about its target (0,0 = from +Z; "
                 "DIST in scene units, default: kept)");
  cmd.add_option("--camera-position", o.cameraPosition, "The camera's position X,Y,Z (scene units), looking at its target");
  cmd.add_option("--size-mm", o.sizeMm,
                 "The object's real size: its largest extent in millimetres (default 200; scattering lengths are in mm, "
                 "so a small object glows and a large one is opaque)");
  cmd.add_option("--exposure", o.exposure, "Exposure in stops (EV; +1 doubles the light; default: the scene's, 0)");
  cmd.add_option("--background", o.background, "Background colour R,G,B in [0, 1], as displayed (default: the scene's)");
  cmd.add_option("--backdrop", o.backdrop, "on: show the environment (studio or map) behind the object instead of the background colour (marble mode)");
  cmd.add_option("--backdrop-blur", o.backdropBlur, "Blur of the backdrop, 0 (sharp) to 1 (default 0.3); implies --backdrop on");
  cmd.add_option("--ground", o.ground, "on: a floor under the object receiving its shadow and a soft contact shadow (marble mode)");
  addAllowOutsideFlag(cmd, o);
}

void addAllowOutsideFlag(CLI::App& cmd, SceneOptions& o) {
  cmd.add_flag("--allow-outside", o.allowOutside,
               "Let a glTF read buffer files outside its own folder (refused by default; see docs/reliability.md)");
}

std::string ignoredKeyWarning(const std::string& key, const Material& m, RenderMode mode) {
  const ParamDesc* p = findParam(key);
  if (!p || p->modes == 0) return "";
  if (!modeReads(*p, mode))
    return "--set " + key + ": the '" + renderModeName(mode) + "' mode does not read " + key + " (used by: " +
           modeNames(p->modes) + ")";
  if (!paramActive(*p, m)) return "--set " + key + ": not used by this material: " + p->inactive;
  return "";
}

namespace {

// "1,2,3" -> {1, 2, 3}: `count` finite numbers (or `count - 1` when `optionalLast`), comma-separated.
std::optional<std::vector<float>> numberList(const std::string& text, size_t count, bool optionalLast = false) {
  std::vector<float> v;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    char* end = nullptr;
    const float f = std::strtof(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(f)) return std::nullopt;
    v.push_back(f);
    start = comma + 1;
  }
  if (v.size() == count || (optionalLast && v.size() + 1 == count)) return v;
  return std::nullopt;
}

std::string presetNames(const std::vector<Placement>& presets) {
  std::string s;
  for (const auto& p : presets) s += std::string(p.name) + ", ";
  return s;
}

glm::vec3 positionOption(const char* flag, const std::string& text) {
  const auto v = numberList(text, 3);
  if (!v || std::any_of(v->begin(), v->end(), [](float f) { return std::abs(f) > 1e4f; }))
    throw InputError(flag, "", "expected X,Y,Z (three numbers in [-10000, 10000]), got \"" + text + "\"");
  return {(*v)[0], (*v)[1], (*v)[2]};
}

void applyCamera(const SceneOptions& o, Scene& scene) {
  if (!o.camera.empty()) {
    if (const auto p = findPreset(cameraPresets(), o.camera)) {
      placeCamera(scene, p->azimuthDeg, p->elevationDeg);
    } else {
      const auto v = numberList(o.camera, 3, true);
      const bool ok = v && std::abs((*v)[1]) < 90.0f &&
                      (v->size() == 2 || ((*v)[2] >= Orbit::kMinDistance && (*v)[2] <= Orbit::kMaxDistance));
      if (!ok)
        throw InputError("--camera", "", "expected " + presetNames(cameraPresets()) +
                                             "or AZ,EL[,DIST] (degrees, elevation in (-90, 90), distance in [0.2, 100]), got \"" +
                                             o.camera + "\"");
      placeCamera(scene, (*v)[0], (*v)[1], v->size() == 3 ? (*v)[2] : 0.0f);
    }
  }
  if (!o.cameraPosition.empty()) {
    const glm::vec3 p = positionOption("--camera-position", o.cameraPosition);
    const glm::vec3 d = p - scene.camera.target;
    if (glm::length(d) < 1e-6f) throw InputError("--camera-position", "", "must differ from the camera's target");
    if (glm::length(glm::cross(glm::normalize(d), glm::normalize(scene.camera.up))) < 1e-4f)
      throw InputError("--camera-position", "", "must not be straight above or below the target (the camera's up is +Y)");
    scene.camera.position = p;
  }
}

void applyLight(const SceneOptions& o, Scene& scene) {
  if (!o.light.empty()) {
    if (const auto p = findPreset(lightPresets(), o.light)) {
      placeLight(scene, p->azimuthDeg, p->elevationDeg);
    } else {
      const auto v = numberList(o.light, 2);
      if (!v || std::abs((*v)[1]) > 90.0f)
        throw InputError("--light", "", "expected " + presetNames(lightPresets()) +
                                            "or AZ,EL (degrees, elevation in [-90, 90]), got \"" + o.light + "\"");
      placeLight(scene, (*v)[0], (*v)[1]);
    }
  }
  if (!o.lightPosition.empty()) {
    const glm::vec3 p = positionOption("--light-position", o.lightPosition);
    if (glm::length(p) < 1e-3f) throw InputError("--light-position", "", "must not be at the origin (the object is there)");
    scene.light.position = p;
  }
}

void applyLook(const SceneOptions& o, Scene& scene) {
  if (o.sizeMm) {
    // The scene's mm_per_unit range, [0.001, 1e6], said as the object's extent (2 units).
    if (!std::isfinite(*o.sizeMm) || *o.sizeMm < 0.002f || *o.sizeMm > 2e6f)
      throw InputError("--size-mm", "", "expected the object's size in millimetres, in [0.002, 2000000]");
    setObjectSizeMm(scene, *o.sizeMm);
  }
  if (o.exposure) {
    if (!std::isfinite(*o.exposure) || std::abs(*o.exposure) > 10.0f)
      throw InputError("--exposure", "", "expected stops in [-10, 10]");
    scene.render.exposure = *o.exposure;
  }
  if (!o.background.empty()) {
    const auto v = numberList(o.background, 3);
    if (!v || std::any_of(v->begin(), v->end(), [](float f) { return f < 0.0f || f > 1.0f; }))
      throw InputError("--background", "", "expected R,G,B (three numbers in [0, 1]), got \"" + o.background + "\"");
    scene.render.background = {(*v)[0], (*v)[1], (*v)[2]};
  }
}

bool onOff(const char* flag, const std::string& value) {
  if (value == "on") return true;
  if (value == "off") return false;
  throw InputError(flag, "", "expected on or off, got \"" + value + "\"");
}

void applyStage(const SceneOptions& o, Scene& scene) {
  if (o.backdropBlur) {
    if (!std::isfinite(*o.backdropBlur) || *o.backdropBlur < 0.0f || *o.backdropBlur > 1.0f)
      throw InputError("--backdrop-blur", "", "expected a number in [0, 1]");
    scene.render.backdrop_blur = *o.backdropBlur;
    scene.render.backdrop = true;
  }
  if (!o.backdrop.empty()) scene.render.backdrop = onOff("--backdrop", o.backdrop);
  if (!o.ground.empty()) scene.render.ground = onOff("--ground", o.ground);
}

bool namesHdrFile(const std::string& s) {
  if (s.size() < 4) return false;
  std::string ext = s.substr(s.size() - 4);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".hdr";
}

}  // namespace

Scene buildScene(const SceneOptions& o) {
  std::vector<std::string> warnings;
  Scene scene = o.input.empty() && o.showcaseWhenEmpty ? showcaseScene() : sceneForInput(o.input, warnings);
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
  if (o.creaseAngle) {
    if (!std::isfinite(*o.creaseAngle)) throw InputError("--crease-angle", "", "expected a number of degrees in [0, 180]");
    scene.crease_angle_deg = *o.creaseAngle;
  }
  if (!o.subsurfaceResolution.empty()) {
    const EnumChoice* e = findChoice(subsurfaceResolutionChoices(), o.subsurfaceResolution);
    if (!e)
      throw InputError("--subsurface-resolution", "",
                       "expected " + choiceAlternatives(subsurfaceResolutionChoices(), false) + ", got \"" +
                           o.subsurfaceResolution + "\"");
    scene.render.subsurface_resolution = static_cast<SubsurfaceResolution>(e->value);
  }
  if (!o.environmentMap.empty()) {
    scene.render.environment_map = o.environmentMap;
    scene.render.environment = Environment::Map;
  }
  if (namesHdrFile(o.environment)) {
    scene.render.environment_map = o.environment;
    scene.render.environment = Environment::Map;
  } else if (!o.environment.empty()) {
    try {
      scene.render.environment = parseEnvironment(o.environment);
    } catch (const std::invalid_argument& e) {
      throw InputError("--environment", "", "expected \"studio\", \"none\", \"map\" or a FILE.hdr, got \"" + o.environment + "\"");
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
  applyCamera(o, scene);  // before the light: the light's azimuth is relative to the camera's
  applyLight(o, scene);
  applyLook(o, scene);
  applyStage(o, scene);
  if (!o.preset.empty()) scene.material = loadPreset(o.preset);
  for (const auto& kv : o.sets) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set", kv, "expected key=value");
    setMaterialKey(scene.material, kv.substr(0, eq), kv.substr(eq + 1));
  }
  // After every --set: `--set vein_spacing=... --set vein_model=network` uses the spacing.
  std::vector<std::string> warned;
  for (const auto& kv : o.sets) {
    const std::string key = kv.substr(0, kv.find('='));
    if (std::find(warned.begin(), warned.end(), key) != warned.end()) continue;
    warned.push_back(key);
    const std::string warning = ignoredKeyWarning(key, scene.material, scene.render.mode);
    if (!warning.empty()) std::cerr << "warning: " << printable(warning, kMessageLineLimit) << "\n";
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

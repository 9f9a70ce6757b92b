#include "marble/scene/scene_io.h"

#include <charconv>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "marble/core/atomic_file.h"
#include "marble/scene/enum_choice.h"
#include "marble/scene/material_io.h"

namespace marble {
namespace {

using ojson = nlohmann::ordered_json;

// The shortest decimal that reads back (through double, as the JSON reader stores it) as `f`.
ojson number(float f) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, f);
  if (ec == std::errc()) {
    const double d = std::strtod(std::string(buf, end).c_str(), nullptr);
    if (static_cast<float>(d) == f) return d;
  }
  return static_cast<double>(f);
}

ojson vec3(const glm::vec3& v) { return ojson::array({number(v.x), number(v.y), number(v.z)}); }

// loadScene resolves a relative path (mesh, environment map) against the scene file's folder.
std::string fileField(const std::string& file, const std::filesystem::path& scenePath) {
  std::error_code ec;
  const auto folder = std::filesystem::absolute(scenePath, ec).parent_path();
  const auto absFile = std::filesystem::absolute(file, ec);
  const auto rel = std::filesystem::proximate(absFile, folder, ec);
  return (ec || rel.empty()) ? absFile.string() : rel.generic_string();
}

std::string meshField(const std::string& mesh, const std::filesystem::path& scenePath) {
  return mesh.rfind("builtin:", 0) == 0 ? mesh : fileField(mesh, scenePath);
}

ojson renderObject(const RenderSettings& r, const std::filesystem::path& scenePath) {
  ojson j = {{"width", r.width},
             {"height", r.height},
             {"background", vec3(r.background)},
             {"mode", renderModeName(r.mode)},
             {"exposure", number(r.exposure)},
             {"environment", choiceName(environmentChoices(), static_cast<int>(r.environment))},
             {"environment_intensity", number(r.environment_intensity)},
             {"subsurface_resolution", choiceName(subsurfaceResolutionChoices(), static_cast<int>(r.subsurface_resolution))},
             {"antialias", antialiasName(r.antialias)}};
  // The map is kept while another environment is chosen, so switching back finds it.
  if (!r.environment_map.empty()) j["environment_map"] = fileField(r.environment_map, scenePath);
  j["environment_rotation_deg"] = number(r.environment_rotation_deg);
  j["backdrop"] = r.backdrop;
  j["backdrop_blur"] = number(r.backdrop_blur);
  j["ground"] = r.ground;
  return j;
}

}  // namespace

std::string sceneToJsonText(const Scene& scene, const std::filesystem::path& path) {
  ojson j;
  j["mesh"] = meshField(scene.mesh, path);
  j["up"] = std::string(upAxisName(scene.up));
  j["mm_per_unit"] = number(scene.mm_per_unit);
  j["crease_angle_deg"] = number(scene.crease_angle_deg);
  if (scene.allow_outside) j["allow_outside"] = true;
  j["camera"] = {{"position", vec3(scene.camera.position)},
                 {"target", vec3(scene.camera.target)},
                 {"up", vec3(scene.camera.up)},
                 {"fov_y_deg", number(scene.camera.fov_y_deg)}};
  j["light"] = {{"type", choiceName(lightTypeChoices(), static_cast<int>(scene.light.type))},
                {"position", vec3(scene.light.position)},
                {"color", vec3(scene.light.color)},
                {"intensity", number(scene.light.intensity)}};
  // materialToJson sorts its keys; re-order them as preset files have them.
  const nlohmann::json m = materialToJson(scene.material);
  ojson mat = ojson::object();
  for (const auto& key : materialKeys())
    if (m.contains(key)) mat[key] = ojson::parse(m[key].dump());
  j["material"] = mat;
  j["render"] = renderObject(scene.render, path);
  return j.dump(2) + "\n";
}

void saveScene(const std::filesystem::path& path, const Scene& scene) {
  writeFileAtomically(path, sceneToJsonText(scene, path));
}

}  // namespace marble

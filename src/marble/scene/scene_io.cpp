#include "marble/scene/scene_io.h"

#include <charconv>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "marble/core/atomic_file.h"
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

std::string meshField(const std::string& mesh, const std::filesystem::path& scenePath) {
  if (mesh.rfind("builtin:", 0) == 0) return mesh;
  // loadScene resolves a relative mesh path against the scene file's folder.
  std::error_code ec;
  const auto folder = std::filesystem::absolute(scenePath, ec).parent_path();
  const auto absMesh = std::filesystem::absolute(mesh, ec);
  const auto rel = std::filesystem::proximate(absMesh, folder, ec);
  return (ec || rel.empty()) ? absMesh.string() : rel.generic_string();
}

}  // namespace

std::string sceneToJsonText(const Scene& scene, const std::filesystem::path& path) {
  ojson j;
  j["mesh"] = meshField(scene.mesh, path);
  j["up"] = std::string(upAxisName(scene.up));
  j["camera"] = {{"position", vec3(scene.camera.position)},
                 {"target", vec3(scene.camera.target)},
                 {"up", vec3(scene.camera.up)},
                 {"fov_y_deg", number(scene.camera.fov_y_deg)}};
  j["light"] = {{"type", scene.light.type == LightType::Point ? "point" : "directional"},
                {"position", vec3(scene.light.position)},
                {"color", vec3(scene.light.color)},
                {"intensity", number(scene.light.intensity)}};
  // materialToJson sorts its keys; re-order them as preset files have them.
  const nlohmann::json m = materialToJson(scene.material);
  ojson mat = ojson::object();
  for (const auto& key : materialKeys())
    if (m.contains(key)) mat[key] = ojson::parse(m[key].dump());
  j["material"] = mat;
  j["render"] = {{"width", scene.render.width},
                 {"height", scene.render.height},
                 {"background", vec3(scene.render.background)},
                 {"mode", renderModeName(scene.render.mode)},
                 {"subsurface_resolution",
                  scene.render.subsurface_resolution == SubsurfaceResolution::Half ? "half" : "full"},
                 {"antialias", antialiasName(scene.render.antialias)}};
  return j.dump(2) + "\n";
}

void saveScene(const std::filesystem::path& path, const Scene& scene) {
  writeFileAtomically(path, sceneToJsonText(scene, path));
}

}  // namespace marble

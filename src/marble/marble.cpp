// The public interface (marble/marble.h) over marble's own parts: the scene as `marble render`
// builds it, the Renderer, the headless context and the bake job the CLI runs. Nothing here
// computes anything of its own; it translates marble's errors to the public ones.
#include "marble/marble.h"

#include <cstring>
#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "marble/bake/bake_job.h"
#include "marble/core/error.h"
#include "marble/environment/environment_lighting.h"
#include "marble/gl/headless_context.h"
#include "marble/render/renderer.h"
#include "marble/scene/material_io.h"
#include "marble/scene/scene.h"
#include "marble/scene/showcase.h"

namespace marble::api {

struct Stone::Data {
  Scene scene;
  Mesh mesh;
  std::optional<PrefilteredEnvironment> environment;
  std::vector<std::string> warnings;
};

namespace {

// marble's InputError becomes the public one (the same line); everything else passes unchanged.
template <typename F>
auto translated(F&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const marble::InputError& e) {
    throw api::InputError(e.what());
  }
}

Scene sceneFor(const StoneSource& source, std::vector<std::string>& warnings) {
  Scene scene = source.input.empty() ? showcaseScene() : sceneForInput(source.input, warnings);
  if (!source.up.empty()) {
    try {
      scene.up = parseUpAxis(source.up);
    } catch (const std::invalid_argument&) {
      throw marble::InputError("up", "", "expected one of y, z, x, -y, -z, -x, got \"" + source.up + "\"");
    }
  }
  if (!source.preset.empty()) scene.material = loadPreset(source.preset, &warnings);
  for (const auto& kv : source.sets) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw marble::InputError("set", kv, "expected key=value");
    setMaterialKey(scene.material, kv.substr(0, eq), kv.substr(eq + 1));
  }
  return scene;
}

BakeSummary bake(const Stone& stone, BakeOutput kind, const std::filesystem::path& output, const BakeSettings& settings) {
  return translated([&] {
    const BakeJob job{.kind = kind,
                      .output = output,
                      .size = settings.size,
                      .supersample = settings.supersample,
                      .uvSource = parseUvSource(settings.uvFrom)};
    const Stone::Data& d = stone.data();
    const BakeJobResult r = runBakeJob(d.scene, d.mesh, job, settings.progress);
    BakeSummary s;
    s.size = r.size;
    s.thicknessSize = r.thicknessSize;
    s.thicknessScaleMm = r.thicknessScaleMm;
    s.unwrapped = r.unwrapped;
    s.charts = r.stats.charts;
    s.packingEfficiency = r.stats.packingEfficiency;
    s.note = r.note;
    return s;
  });
}

}  // namespace

Stone::Stone(const StoneSource& source) : data_(std::make_unique<Data>()) {
  translated([&] {
    data_->scene = sceneFor(source, data_->warnings);
    data_->mesh = loadSceneMesh(data_->scene, &data_->warnings);
    if (data_->mesh.triangleCount() == 0) throw marble::InputError(data_->scene.mesh, "", "the mesh has no faces");
    data_->environment = loadSceneEnvironment(data_->scene);  // before any GL, as the CLI does
  });
}

Stone::~Stone() = default;
Stone::Stone(Stone&&) noexcept = default;
Stone& Stone::operator=(Stone&&) noexcept = default;

std::size_t Stone::triangleCount() const { return data_->mesh.triangleCount(); }
int Stone::width() const { return data_->scene.render.width; }
int Stone::height() const { return data_->scene.render.height; }
std::string Stone::designJson() const { return materialToJson(data_->scene.material).dump(2); }
const std::vector<std::string>& Stone::warnings() const { return data_->warnings; }

struct StoneRenderer::Impl {
  explicit Impl(const Stone::Data& s) : stone(s) {}
  const Stone::Data& stone;
  Renderer renderer;  // the embedded shaders
};

StoneRenderer::StoneRenderer(const Stone& stone) : impl_(std::make_unique<Impl>(stone.data())) {
  impl_->renderer.setMesh(stone.data().mesh);
  if (stone.data().environment) impl_->renderer.setEnvironmentMap(*stone.data().environment);
}

StoneRenderer::~StoneRenderer() = default;

void StoneRenderer::render(unsigned framebuffer, int width, int height, const float* model) {
  if (width < 1 || height < 1 || width > kMaxRenderSize || height > kMaxRenderSize)
    throw api::InputError("render: expected a size of 1 to " + std::to_string(kMaxRenderSize) + " pixels a side, got " +
                          std::to_string(width) + "x" + std::to_string(height));
  glm::mat4 m(1.0f);
  if (model) std::memcpy(&m[0][0], model, sizeof m);  // glm is column-major, as the header promises
  impl_->renderer.render(impl_->stone.scene, m, framebuffer, width, height);
}

struct OffscreenContext::Impl {
  HeadlessContext context;
};

OffscreenContext::OffscreenContext() : impl_(std::make_unique<Impl>()) {}
OffscreenContext::~OffscreenContext() = default;
std::string OffscreenContext::renderer() const { return impl_->context.renderer(); }

BakeSummary bakeTextureSet(const Stone& stone, const std::filesystem::path& folder, const BakeSettings& settings) {
  return bake(stone, BakeOutput::TextureSet, folder, settings);
}

BakeSummary exportGltf(const Stone& stone, const std::filesystem::path& file, const BakeSettings& settings) {
  return bake(stone, BakeOutput::Gltf, file, settings);
}

}  // namespace marble::api

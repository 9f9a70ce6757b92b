#include "marble/bake/background_export.h"

#include <exception>
#include <system_error>

#include "marble/bake/bake_mesh.h"
#include "marble/bake/gltf_export.h"
#include "marble/bake/texture_set_files.h"
#include "marble/core/error.h"

namespace marble {

BackgroundExport::~BackgroundExport() {
  cancel_ = true;
  wait();
}

void BackgroundExport::wait() {
  if (thread_.joinable()) thread_.join();
}

bool BackgroundExport::start(const Scene& scene, const ExportRequest& request) {
  if (running_) return false;
  wait();
  cancel_ = false;
  progress_ = 0;
  running_ = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outcome_.reset();
    stage_ = "loading";
  }
  thread_ = std::thread(&BackgroundExport::run, this, scene, request);
  return true;
}

std::string BackgroundExport::stage() {
  std::lock_guard<std::mutex> lock(mutex_);
  return stage_;
}

std::optional<ExportOutcome> BackgroundExport::takeOutcome() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(outcome_, std::nullopt);
}

void BackgroundExport::run(Scene scene, ExportRequest request) {
  ExportOutcome outcome;
  auto setStage = [&](const char* s) {
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = s;
  };
  try {
    // Everything checkable is checked before the bake, as on the command line.
    if (request.path.empty()) throw InputError("export", "path", "no path given");
    if (request.size < 16 || request.size > 8192)
      throw InputError("export", "size", "expected 16 to 8192 texels, got " + std::to_string(request.size));
    const std::filesystem::path out(request.path);
    if (request.textureSet) {
      checkOutputFolder(out);
    } else {
      gltfContainerFor(out);
      const auto folder = out.has_parent_path() ? out.parent_path() : std::filesystem::path(".");
      std::error_code ec;
      if (!std::filesystem::is_directory(folder, ec))
        throw InputError(request.path, "", "the folder " + folder.string() + " does not exist");
    }
    const Mesh loaded = loadSceneMesh(scene);
    BakeOptions options;
    options.size = request.size;
    const BakeMesh mesh = prepareBakeMesh(loaded, UvSource::Auto, request.size, options.dilationTexels, scene.mesh);
    options.progress = [&](double f, const char* stage) {
      progress_ = f;
      setStage(stage);
      return !cancel_.load();
    };
    const TextureSet set = bakeTextureSet(mesh.mesh, scene.material, options);
    if (cancel_) throw BakeCancelled();
    setStage("writing");
    if (request.textureSet) writeTextureSet(out, set, describeTextureSet(set, scene.material, scene.mm_per_unit, mesh));
    else writeGltf(out, {mesh.mesh, set, scene.material, scene.mm_per_unit});
    outcome.ok = true;
    outcome.message = "exported " + request.path + (mesh.unwrapped ? " (texture coordinates unwrapped)" : " (the file's texture coordinates)");
  } catch (const BakeCancelled&) {
    outcome.cancelled = true;
    outcome.message = "export cancelled; nothing was written";
  } catch (const std::exception& e) {
    outcome.message = e.what();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  outcome_ = outcome;
  stage_.clear();
  running_ = false;
}

}  // namespace marble

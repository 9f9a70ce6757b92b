#include "marble/bake/background_export.h"

#include <exception>
#include <system_error>
#include <utility>

#include "marble/bake/bake_job.h"
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
    if (request.path.empty()) throw InputError("export", "path", "no path given");
    BakeJob job;
    job.kind = request.textureSet ? BakeOutput::TextureSet : BakeOutput::Gltf;
    job.output = request.path;
    job.size = request.size;
    checkBakeJob(job);
    const BakeJobResult r = runBakeJob(scene, loadSceneMesh(scene), job, [&](double f, const char* stage) {
      progress_ = f;
      setStage(stage);
      return !cancel_.load();
    });
    outcome.ok = true;
    outcome.message = "exported " + request.path + (r.unwrapped ? " (texture coordinates unwrapped)" : " (the file's texture coordinates)");
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

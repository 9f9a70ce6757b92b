#pragma once
// An export (glTF file or texture-set folder) baked and written on a thread of its own, for a
// caller that must keep drawing (the viewer's Export section): progress and the outcome are
// polled, a cancel is honoured between rows of the bake. What is written is what `marble export`
// / `marble bake` write (docs/export.md), each file atomically, so a cancelled or failed export
// leaves old files as they were.
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "marble/scene/scene.h"

namespace marble {

struct ExportRequest {
  std::string path;         // model.glb / model.gltf, or a folder for a texture set
  int size = 1024;          // texels per side (16-8192)
  bool textureSet = false;  // a folder of PNGs and material.json instead of a glTF file
};

struct ExportOutcome {
  bool ok = false;
  bool cancelled = false;
  std::string message;  // "exported PATH (...)", or the one-line error
};

class BackgroundExport {
 public:
  BackgroundExport() = default;
  BackgroundExport(const BackgroundExport&) = delete;
  BackgroundExport& operator=(const BackgroundExport&) = delete;
  ~BackgroundExport();  // cancels and waits

  // Starts unless one is running (returns false then). The scene is copied.
  bool start(const Scene& scene, const ExportRequest& request);
  void cancel() { cancel_ = true; }
  bool running() const { return running_; }
  double progress() const { return progress_; }
  std::string stage();
  // The outcome of a finished export, once (then empty until the next one finishes).
  std::optional<ExportOutcome> takeOutcome();
  void wait();  // blocks until the running export (if any) has finished

 private:
  void run(Scene scene, ExportRequest request);

  std::thread thread_;
  std::atomic<bool> running_{false}, cancel_{false};
  std::atomic<double> progress_{0};
  std::mutex mutex_;  // guards stage_ and outcome_
  std::string stage_;
  std::optional<ExportOutcome> outcome_;
};

}  // namespace marble

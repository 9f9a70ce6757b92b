#pragma once
// The viewer's side of the Export section: passes the panel's requests to a BackgroundExport
// (bake/background_export.h, which bakes on its own thread so the window keeps drawing) and its
// progress and outcome back to the panel and the status line.
#include <utility>

#include "marble/bake/background_export.h"
#include "viewer_state.h"

namespace marble {

// Once per frame.
inline void updateExport(BackgroundExport& job, ViewerState& s) {
  ExportPanel& e = s.exportPanel;
  if (std::exchange(e.requestCancel, false)) job.cancel();
  if (std::exchange(e.requestStart, false)) job.start(s.scene, {e.path, e.size, e.textureSet});
  e.running = job.running();
  e.progress = static_cast<float>(job.progress());
  e.stage = job.stage();
  if (auto outcome = job.takeOutcome()) {
    if (outcome->ok || outcome->cancelled) s.setStatus(outcome->message);
    else s.setError(outcome->message);
  }
}

}  // namespace marble

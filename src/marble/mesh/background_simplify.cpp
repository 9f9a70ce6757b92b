#include "marble/mesh/background_simplify.h"

#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

namespace marble {

struct BackgroundSimplification::State {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  SimplifiedMesh result;
  std::exception_ptr error;
};

BackgroundSimplification::BackgroundSimplification(Mesh source, size_t targetTriangles, float maxErrorUnits)
    : state_(std::make_shared<State>()) {
  std::thread([state = state_, source = std::move(source), targetTriangles, maxErrorUnits]() mutable {
    SimplifiedMesh result;
    std::exception_ptr error;
    try {
      result = simplifiedMesh(source, targetTriangles, maxErrorUnits);
    } catch (...) {
      error = std::current_exception();
    }
    const std::lock_guard lock(state->mutex);
    state->result = std::move(result);
    state->error = error;
    state->done = true;
    state->finished.notify_all();
  }).detach();
}

bool BackgroundSimplification::ready() const {
  const std::lock_guard lock(state_->mutex);
  return state_->done;
}

SimplifiedMesh BackgroundSimplification::take() {
  std::unique_lock lock(state_->mutex);
  state_->finished.wait(lock, [&] { return state_->done; });
  if (state_->error) std::rethrow_exception(state_->error);
  return std::move(state_->result);
}

}  // namespace marble

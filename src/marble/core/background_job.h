#pragma once
// A value made on a worker thread while the caller goes on (the viewer keeps drawing): the light's
// proxy of a large scan (mesh/background_simplify.h), the further bounces' form factors
// (render/further_radiosity.h). The thread owns what the work captured and its result: dropping
// the handle before it finishes leaves the thread to finish and free them (nothing waits for an
// abandoned job).
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

namespace marble {

template <class T>
class BackgroundJob {
public:
  explicit BackgroundJob(std::function<T()> work) : state_(std::make_shared<State>()) {
    std::thread([state = state_, work = std::move(work)]() {
      T result{};
      std::exception_ptr error;
      try {
        result = work();
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
  // Whether the value is made (take() will not wait).
  bool ready() const {
    const std::lock_guard lock(state_->mutex);
    return state_->done;
  }
  // The value; waits for it when not ready. Rethrows what the work threw. Once only.
  T take() {
    std::unique_lock lock(state_->mutex);
    state_->finished.wait(lock, [&] { return state_->done; });
    if (state_->error) std::rethrow_exception(state_->error);
    return std::move(state_->result);
  }

private:
  struct State {
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    T result{};
    std::exception_ptr error;
  };
  std::shared_ptr<State> state_;
};

}  // namespace marble

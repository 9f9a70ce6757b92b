#include "marble/render/pass_timer.h"

#include <chrono>

namespace marble {

namespace {
bool serialized = false;
double nowMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

void PassTimer::setSerialized(bool on) { serialized = on; }

void PassTimer::begin() {
  if (serialized) {
    glFinish();
    serialStartMs_ = nowMs();
    return;
  }
  if (!queries_[0]) {
    queries_[0] = gl::TimerQuery::create();
    queries_[1] = gl::TimerQuery::create();
  }
  current_ ^= 1;
  if (pending_[current_]) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(queries_[current_].id(), GL_QUERY_RESULT, &ns);
    lastMs_ = static_cast<double>(ns) * 1e-6;
    pending_[current_] = false;
  }
  glBeginQuery(GL_TIME_ELAPSED, queries_[current_].id());
}

void PassTimer::end() {
  if (serialized) {
    glFinish();
    lastMs_ = nowMs() - serialStartMs_;
    return;
  }
  glEndQuery(GL_TIME_ELAPSED);
  pending_[current_] = true;
}

double PassTimer::milliseconds() {
  const int other = current_ ^ 1;
  if (pending_[other]) {
    GLint ready = 0;
    glGetQueryObjectiv(queries_[other].id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(queries_[other].id(), GL_QUERY_RESULT, &ns);
      lastMs_ = static_cast<double>(ns) * 1e-6;
      pending_[other] = false;
    }
  }
  return lastMs_;
}

double PassTimer::waitMilliseconds() {
  if (pending_[current_]) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(queries_[current_].id(), GL_QUERY_RESULT, &ns);
    lastMs_ = static_cast<double>(ns) * 1e-6;
    pending_[current_] = false;
  }
  return lastMs_;
}

}  // namespace marble

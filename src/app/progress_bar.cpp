#include "progress_bar.h"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace marble {

ProgressBar::ProgressBar(int total)
    : total_(total), enabled_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {
  draw();
}

ProgressBar::~ProgressBar() {
  if (enabled_) std::fputc('\n', stderr);
}

void ProgressBar::step() {
  ++done_;
  draw();
}

double ProgressBar::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBar::draw() const {
  if (!enabled_) return;
  constexpr int kWidth = 30;
  const int filled = total_ > 0 ? done_ * kWidth / total_ : kWidth;
  const std::string bar = std::string(static_cast<size_t>(filled), '#') + std::string(static_cast<size_t>(kWidth - filled), '.');
  const double s = elapsedSeconds();
  if (done_ > 0)
    std::fprintf(stderr, "\r[%s] %d/%d  %.2f s/frame, %.0f s left ", bar.c_str(), done_, total_, s / done_,
                 s / done_ * (total_ - done_));
  else
    std::fprintf(stderr, "\r[%s] %d/%d", bar.c_str(), done_, total_);
  std::fflush(stderr);
}

}  // namespace marble

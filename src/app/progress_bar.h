#pragma once
// A progress bar on stderr for batches (turntables): redrawn in place when stderr is a
// terminal, silent otherwise (a log file gets the summary line, not hundreds of redraws).
#include <chrono>

namespace marble {

class ProgressBar {
public:
  explicit ProgressBar(int total);
  ~ProgressBar();  // ends the bar's line
  void step();     // one more item done
  double elapsedSeconds() const;

private:
  void draw() const;
  int total_, done_ = 0;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace marble

#pragma once
// A one-line progress bar on stderr for long bakes ("bake  [########------]  57%  base colour"),
// redrawn in place at most every 1%; off when stderr is not a terminal unless asked for.
#include <cstdio>
#include <string>

namespace marble {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled) {}
  // Always returns true (a command line bake is cancelled with Ctrl+C).
  bool update(double fraction, const char* stage) {
    if (!enabled_) return true;
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == lastPercent_ && stage == lastStage_) return true;
    lastPercent_ = percent;
    lastStage_ = stage;
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\rbake [%s%s] %3d%%  %-12s", std::string(static_cast<size_t>(filled), '#').c_str(),
                 std::string(static_cast<size_t>(kWidth - filled), '-').c_str(), percent, stage);
    std::fflush(stderr);
    return true;
  }
  void finish() {
    if (enabled_ && lastPercent_ >= 0) std::fprintf(stderr, "\n");
  }

 private:
  bool enabled_;
  int lastPercent_ = -1;
  std::string lastStage_;
};

}  // namespace marble

#pragma once
// `marble texture -o DIR [--size N] [--preset P] [--set key=value ...]`: bakes the stages of the
// paper's marble texture (§3.1) to PNG: white_noise.png, smooth_noise.png, turbulence.png,
// sine.png (Figure 3 A-D: lattice, interpolated lattice, turbulence, sine of ramp + turbulence)
// and marble.png (Figure 4: the colour ramp applied). Multi-threaded on the CPU.
#include <filesystem>
#include <string>
#include <vector>

namespace marble {

struct TextureOptions {
  std::filesystem::path out_dir;
  int size = 512;
  std::string preset = "paper";
  std::vector<std::string> sets;
};

// Returns 0; on bad input prints the one-line error to stderr and returns 2.
int runTextureCommand(const TextureOptions& options);

}  // namespace marble

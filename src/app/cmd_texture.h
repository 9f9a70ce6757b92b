#pragma once
// `marble texture -o DIR [--size N] [--preset P] [--set key=value ...]`: bakes the stages of the
// paper's marble texture (§3.1) to PNG: white_noise.png, smooth_noise.png, turbulence.png,
// sine.png (Figure 3 A-D: lattice, interpolated lattice, turbulence, sine of ramp + turbulence)
// and marble.png (Figure 4: the colour ramp applied). Multi-threaded on the CPU.
// For the vein models (vein_model network | breccia, issue 16) it writes marble.png as a planar
// slice of the solid pattern (--slice AXIS=OFFSET, default z=0: what the mesh shows where that
// plane cuts it) and veins.png, the value before colour. --tile: a tile that repeats without a
// seam (the paper's texture does by construction; the slices cross-fade a band at two edges).
#include <filesystem>
#include <string>
#include <vector>

namespace marble {

struct TextureOptions {
  std::filesystem::path out_dir;
  int size = 512;
  std::string preset = "paper";
  std::vector<std::string> sets;
  std::string slice;  // "" = z=0; vein models only
  bool tile = false;
};

// Returns 0; on bad input prints the one-line error to stderr and returns 2.
int runTextureCommand(const TextureOptions& options);

}  // namespace marble

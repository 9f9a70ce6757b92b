// Writes the synthetic sky of hdr_support.h as a Radiance .hdr, for looking at environment
// lighting by eye (the project ships no .hdr files and downloads none):
//   build/tests/marble_synthetic_hdr sky.hdr [WIDTH]      (default 2048; height = WIDTH / 2)
#include <cstdlib>
#include <iostream>

#include "hdr_support.h"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: marble_synthetic_hdr OUT.hdr [WIDTH]\n";
    return 2;
  }
  const int width = argc == 3 ? std::atoi(argv[2]) : 2048;
  if (width < 8 || width > 8192 || width % 2) {
    std::cerr << "marble_synthetic_hdr: WIDTH must be even and in [8, 8192]\n";
    return 2;
  }
  marble::test::writeHdrFile(argv[1], marble::test::syntheticSky(width));
  std::cout << "wrote " << argv[1] << " (" << width << " x " << width / 2 << ")\n";
  return 0;
}

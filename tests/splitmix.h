#pragma once
// A small PRNG of the tests' own (splitmix64, Steele et al. 2014): a fixed seed gives the same
// numbers on every platform and standard library, which std::mt19937's distributions do not.
#include <cstdint>

namespace marble::test {

struct SplitMix {
  uint64_t state;
  double next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;  // [0, 1)
  }
};

}  // namespace marble::test

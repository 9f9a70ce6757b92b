#include "marble/gl/packed_float_pair.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

namespace marble {
namespace {

// What GLSL's unpackDouble2x32 hands the shader: (low 32 bits, high 32 bits).
uint32_t lowWord(double d) { return static_cast<uint32_t>(std::bit_cast<uint64_t>(d)); }
uint32_t highWord(double d) { return static_cast<uint32_t>(std::bit_cast<uint64_t>(d) >> 32); }

TEST(PackedFloatPair, TheFirstFloatIsTheLowWordAndBothKeepTheirBits) {
  const float values[] = {0.0f, -0.0f, 1.0f, -3.25f, 1e-40f /* denormal */, -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::max(), -12.3456789f};
  for (float a : values)
    for (float b : values) {
      const double d = gl::packFloatPair(a, b);
      EXPECT_EQ(lowWord(d), std::bit_cast<uint32_t>(a)) << a << ", " << b;
      EXPECT_EQ(highWord(d), std::bit_cast<uint32_t>(b)) << a << ", " << b;
    }
}

}  // namespace
}  // namespace marble

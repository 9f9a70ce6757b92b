// The corner angle's fast path (mesh/corner_angle.h) rounds to the float std::atan2 gives, bit
// for bit: random corners of every shape, and angles made to lie next to a float rounding
// boundary, where the fast path must step aside (the negative control: without its check it would
// round these by a value a few double ulps off).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <random>

#include "marble/mesh/corner_angle.h"

namespace marble::mesh_detail {
namespace {

TEST(CornerAngle, EqualsAtan2OnRandomCorners) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> exponent(-30.0, 30.0);
  size_t fast = 0;
  const size_t n = 2'000'000;
  for (size_t i = 0; i < n; ++i) {
    const double scale = std::exp2(exponent(rng));
    const double y = std::fabs(unit(rng)) * scale * (i % 7 == 0 ? 1e-6 : 1.0);  // thin corners too
    const double x = unit(rng) * scale;
    const float expected = static_cast<float>(std::atan2(y, x));
    ASSERT_EQ(std::bit_cast<uint32_t>(cornerAngle(y, x)), std::bit_cast<uint32_t>(expected)) << y << " " << x;
    fast += fastCornerAngle(y, x).has_value();
  }
  EXPECT_GT(fast, n * 999 / 1000);  // the fast path is the rule, not the exception
  // Right angles, straight and degenerate corners, infinities and NaN.
  for (auto [y, x] : {std::pair{1.0, 0.0}, {1.0, -0.0}, {0.0, 1.0}, {0.0, -1.0}, {0.0, 0.0}, {1.0, 1.0}, {1.0, -1.0},
                      {INFINITY, 1.0}, {1.0, -INFINITY}, {NAN, 1.0}, {1.0, NAN}, {1e-300, -1.0}, {1e300, 1e-300}})
    EXPECT_EQ(std::bit_cast<uint32_t>(cornerAngle(y, x)), std::bit_cast<uint32_t>(static_cast<float>(std::atan2(y, x))))
        << y << " " << x;
}

TEST(CornerAngle, StepsAsideNextToARoundingBoundary) {
  // Angles halfway between two neighbouring floats in (0, pi): cos and sin of the midpoint as x
  // and y give atan2 within about an ulp of it, far inside the fast path's 2^-40 margin.
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> angle(0.01f, 3.13f);
  for (int i = 0; i < 10000; ++i) {
    const float a = angle(rng);
    const double mid = (static_cast<double>(a) + static_cast<double>(std::nextafter(a, 4.0f))) / 2;
    const double y = std::sin(mid), x = std::cos(mid);
    EXPECT_FALSE(fastCornerAngle(y, x).has_value()) << mid;
    EXPECT_EQ(std::bit_cast<uint32_t>(cornerAngle(y, x)), std::bit_cast<uint32_t>(static_cast<float>(std::atan2(y, x))));
  }
}

}  // namespace
}  // namespace marble::mesh_detail

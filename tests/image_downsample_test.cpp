// Box-filter downsampling for `marble render --supersample` (src/marble/core/image_downsample.h):
// 8-bit sRGB is averaged in linear light, linear floats as they are.
#include <gtest/gtest.h>

#include <stdexcept>

#include "marble/core/image_downsample.h"

using namespace marble;

namespace {

ImageRGBA8 rgba(int w, int h, std::vector<uint8_t> px) { return ImageRGBA8{w, h, std::move(px)}; }

}  // namespace

TEST(ImageDownsample, SrgbBlocksAreAveragedInLinearLight) {
  // Half black, half white: linear 0.5, which sRGB encodes as 188 (not the bytes' mean, 128).
  const ImageRGBA8 bw = rgba(2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255});
  const ImageRGBA8 out = downsampleSrgb(bw, 2);
  ASSERT_EQ(out.width, 1);
  ASSERT_EQ(out.height, 1);
  EXPECT_EQ(out.at(0, 0), glm::u8vec4(188, 188, 188, 255));
  // A block of one colour stays exactly that colour, every byte value.
  for (int v = 0; v < 256; ++v) {
    const auto b = static_cast<uint8_t>(v);
    const ImageRGBA8 flat = rgba(2, 2, std::vector<uint8_t>(16, b));
    EXPECT_EQ(downsampleSrgb(flat, 2).at(0, 0), glm::u8vec4(b, b, b, b)) << v;
  }
}

TEST(ImageDownsample, KeepsBlocksInPlaceAndSizesDivide) {
  // 6 x 3 by 3: two output pixels, the left block red, the right block blue.
  std::vector<uint8_t> px;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 6; ++x) {
      const bool left = x < 3;
      px.insert(px.end(), {static_cast<uint8_t>(left ? 200 : 0), 0, static_cast<uint8_t>(left ? 0 : 90), 255});
    }
  const ImageRGBA8 out = downsampleSrgb(rgba(6, 3, px), 3);
  ASSERT_EQ(out.width, 2);
  ASSERT_EQ(out.height, 1);
  EXPECT_EQ(out.at(0, 0), glm::u8vec4(200, 0, 0, 255));
  EXPECT_EQ(out.at(1, 0), glm::u8vec4(0, 0, 90, 255));
  EXPECT_EQ(downsampleSrgb(rgba(6, 3, px), 1).pixels, px) << "factor 1 is the identity";
  EXPECT_THROW(downsampleSrgb(rgba(6, 3, px), 2), std::invalid_argument);
}

TEST(ImageDownsample, LinearImagesAreAveragedAsTheyAre) {
  const ImageRGBF hdr{2, 2, {0.0f, 1.0f, 8.0f, 4.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}};
  const ImageRGBF out = downsampleLinear(hdr, 2);
  ASSERT_EQ(out.width, 1);
  ASSERT_EQ(out.height, 1);
  EXPECT_FLOAT_EQ(out.pixels[0], 1.0f);
  EXPECT_FLOAT_EQ(out.pixels[1], 0.75f);
  EXPECT_FLOAT_EQ(out.pixels[2], 2.0f);
  EXPECT_THROW(downsampleLinear(ImageRGBF{3, 2, std::vector<float>(18)}, 2), std::invalid_argument);
}

TEST(ImageDownsample, CoverageIsAveragedWithTheLight) {
  ImageRGBF hdr{2, 2, std::vector<float>(12, 0.5f)};
  hdr.alpha = {1.0f, 1.0f, 0.0f, 1.0f};
  const ImageRGBF out = downsampleLinear(hdr, 2);
  ASSERT_EQ(out.alpha.size(), 1u);
  EXPECT_FLOAT_EQ(out.alpha[0], 0.75f);
  EXPECT_TRUE(downsampleLinear(ImageRGBF{2, 2, std::vector<float>(12)}, 2).alpha.empty()) << "no alpha in, none out";
}

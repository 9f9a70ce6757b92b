// PNG text chunks (the scene a marble PNG carries): what is inserted is found again, readers
// that ignore it still decode the image, and a damaged chunk is reported rather than trusted.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <iterator>
#include <stdexcept>

#include "marble/core/image.h"
#include "marble/core/png_text.h"

using namespace marble;

namespace {
std::filesystem::path tempPng(const char* name) {
  return std::filesystem::temp_directory_path() / (std::string(name) + "-" + std::to_string(::getpid()) + ".png");
}
}  // namespace

TEST(PngText, WrittenTextIsReadBackAndTheImageStillDecodes) {
  const auto path = tempPng("pngtext");
  const ImageRGBA8 img{2, 1, {255, 0, 0, 255, 0, 0, 255, 255}};
  const std::string text = "{\"mesh\": \"caf\xc3\xa9.obj\"}\n";  // UTF-8
  writePng(path, img, {{"marble.scene", text}});
  EXPECT_EQ(readPngText(path, "marble.scene"), text);
  EXPECT_EQ(readPngText(path, "other"), std::nullopt);
  const ImageRGBA8 back = readPng(path);
  EXPECT_EQ(back.pixels, img.pixels);
  std::filesystem::remove(path);
}

TEST(PngText, DamagedChunkIsAnErrorNotText) {
  const auto path = tempPng("pngtext-bad");
  writePng(path, ImageRGBA8{1, 1, {1, 2, 3, 255}}, {{"k", "hello"}});
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::filesystem::remove(path);
  ASSERT_EQ(findPngText(bytes, "k"), "hello");
  std::string flipped = bytes;
  flipped[flipped.find("hello")] = 'j';  // the CRC no longer matches
  EXPECT_THROW(findPngText(flipped, "k"), std::invalid_argument);
  EXPECT_THROW(findPngText(bytes.substr(0, 40), "k"), std::invalid_argument);  // cut inside a chunk
  EXPECT_THROW(findPngText("not a png", "k"), std::invalid_argument);
  EXPECT_THROW(insertPngText(bytes, "", "x"), std::invalid_argument);
}

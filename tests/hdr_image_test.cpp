// The Radiance .hdr reader (src/marble/core/hdr_image.h) on files the test writes: good files
// come back with their values, and every bad one is a one-line InputError naming the file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "hdr_support.h"
#include "marble/core/error.h"
#include "marble/core/hdr_image.h"
#include "marble/environment/environment_lighting.h"

using namespace marble;
using namespace marble::test;

namespace {

namespace fs = std::filesystem;

class HdrImage : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("marble-hdr-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path put(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

  // Reading `path` fails with a message that starts with the file and contains `expected`.
  template <typename Read>
  static void expectError(const fs::path& path, const std::string& expected, Read read) {
    try {
      read(path);
      ADD_FAILURE() << path << ": read without an error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(expected), std::string::npos) << "expected: " << expected << "\n     got: " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  static void expectReadError(const fs::path& path, const std::string& expected) {
    expectError(path, expected, [](const fs::path& p) { readHdr(p); });
  }

  fs::path dir_;
};

// Values RGBE holds exactly: 8-bit mantissas sharing one power-of-two exponent per pixel.
ImageRGBF exactImage(int width, int height) {
  ImageRGBF img{width, height, std::vector<float>(static_cast<size_t>(width) * height * 3)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = &img.pixels[(static_cast<size_t>(y) * width + x) * 3];
      const float scale = std::ldexp(1.0f, (x + 3 * y) % 20 - 10);  // 2^-10 .. 2^9
      p[0] = 200.0f / 256.0f * scale;
      p[1] = static_cast<float>((x * 7 + y) % 200) / 256.0f * scale;
      p[2] = (x == 0 && y == 0) ? 0.0f : 17.0f / 256.0f * scale;
    }
  return img;
}

void expectSamePixels(const ImageRGBF& a, const ImageRGBF& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  for (size_t i = 0; i < a.pixels.size(); ++i) ASSERT_EQ(a.pixels[i], b.pixels[i]) << "value " << i;
}

}  // namespace

TEST_F(HdrImage, FlatAndRunLengthEncodedFilesReadBackExactly) {
  const ImageRGBF img = exactImage(40, 20);
  expectSamePixels(readHdr(put("rle.hdr", encodeHdr(img, true))), img);
  expectSamePixels(readHdr(put("flat.hdr", encodeHdr(img, false))), img);
  const ImageRGBF tiny = exactImage(2, 1);  // narrower than 8: always flat
  expectSamePixels(readHdr(put("tiny.hdr", encodeHdr(tiny))), tiny);
  const HdrHeader h = readHdrHeader(dir_ / "rle.hdr");
  EXPECT_EQ(h.width, 40);
  EXPECT_EQ(h.height, 20);
  EXPECT_TRUE(h.runLengthEncoded);
  EXPECT_FALSE(readHdrHeader(dir_ / "flat.hdr").runLengthEncoded);
}

TEST_F(HdrImage, RowZeroIsTheTopRowOfTheFile) {
  ImageRGBF img = constantImage(8, 4, glm::vec3(0.0f));
  img.pixels[0] = 1.0f;  // red at the top left
  const ImageRGBF back = readHdr(put("top.hdr", encodeHdr(img)));
  EXPECT_EQ(back.pixels[0], 1.0f);
  EXPECT_EQ(back.pixels[back.pixels.size() - 3], 0.0f);
}

TEST_F(HdrImage, RgbeSignatureWithoutRadianceIsAccepted) {
  std::string bytes = encodeHdr(exactImage(16, 8));
  bytes.replace(0, 10, "#?RGBE");
  EXPECT_EQ(readHdr(put("rgbe.hdr", bytes)).width, 16);
}

TEST_F(HdrImage, MissingDirectoryEmptyAndDeviceAreRefusedByName) {
  expectReadError(dir_ / "missing.hdr", "file not found");
  fs::create_directories(dir_ / "folder.hdr");
  expectReadError(dir_ / "folder.hdr", "is a directory, not an image file");
  expectReadError(put("empty.hdr", ""), "file is empty");
  expectReadError("/dev/zero", "is a character device, not a regular file");
}

TEST_F(HdrImage, GarbageAndOtherFormatsAreNotRadiance) {
  expectReadError(put("garbage.hdr", std::string("\x7f" "ELF\x02\x01\x01\x00\xff\xfe", 10)), "not a Radiance .hdr file");
  expectReadError(put("png.hdr", std::string("\x89PNG\r\n\x1a\n", 8) + std::string(100, '\0')), "not a Radiance .hdr file");
  expectReadError(put("text.hdr", "hello\n"), "it must start with the line #?RADIANCE or #?RGBE");
}

TEST_F(HdrImage, HeaderProblemsNameTheLine) {
  expectReadError(put("xyze.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 2\n" + std::string(8, '\x80')),
                  "header line 2: \"FORMAT=32-bit_rle_xyze\" is not supported (only FORMAT=32-bit_rle_rgbe)");
  expectReadError(put("noformat.hdr", "#?RADIANCE\nEXPOSURE=1\n\n-Y 1 +X 2\n" + std::string(8, '\x80')),
                  "header: no FORMAT=32-bit_rle_rgbe line");
  expectReadError(put("flipped.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 1 +X 2\n" + std::string(8, '\x80')),
                  "header line 4: resolution \"+Y 1 +X 2\" is not supported (only \"-Y height +X width\", top row first)");
  expectReadError(put("words.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y tall +X wide\n"), "header line 4: resolution");
  expectReadError(put("zero.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 2\n" + std::string(8, '\x80')),
                  "header line 4: image is 2 x 0 pixels");
  expectReadError(put("noend.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"), "header: no end of header (an empty line)");
  expectReadError(put("nores.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"), "header: no resolution line after the header");
}

TEST_F(HdrImage, SizesOverTheLimitAreRefusedFromTheHeader) {
  expectReadError(put("huge.hdr", hdrHeader(20000, 10000) + std::string(64, '\x80')),
                  "header line 5: image is 20,000 x 10,000 pixels; the limit is 8,192 per side");
  expectReadError(put("overflow.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 99999999999 +X 2\n" + std::string(8, '\x80')),
                  "header line 4: resolution \"-Y 99999999999 +X 2\" is not supported");
}

TEST_F(HdrImage, TruncatedPixelDataIsAnErrorNotBlackPixels) {
  const std::string rle = encodeHdr(exactImage(64, 32), true);
  const std::string flat = encodeHdr(exactImage(64, 32), false);
  const size_t header = hdrHeader(64, 32).size();
  expectReadError(put("flat.hdr", flat.substr(0, flat.size() - 1)),
                  "truncated: 64 x 32 flat RGBE pixels need 8,192 bytes but 8,191 follow the header");
  // Cut in the middle: long enough for the least RLE data could take, but not for this one.
  // (stb_image itself would loop forever on these: it reads zeros past the end, and a zero
  // count never finishes a scanline.)
  expectReadError(put("rle.hdr", rle.substr(0, header + (rle.size() - header) * 3 / 4)),
                  "the file ends inside the scanline (truncated)");
  expectReadError(put("rle1.hdr", rle.substr(0, rle.size() - 1)),
                  "pixel data, row 31 of 32: the file ends inside the scanline (truncated)");
  expectReadError(put("nodata.hdr", hdrHeader(64, 32)), "no pixel data after the header (truncated?)");
  // A few bytes claiming 8192 x 4096 run-length encoded pixels: refused before the decoder
  // would allocate 384 MiB for them.
  expectReadError(put("lying.hdr", hdrHeader(8192, 4096) + std::string("\x02\x02\x20\x00", 4) + std::string(60, '\x01')),
                  "truncated: 8192 x 4096 run-length encoded pixels need at least 2,146,304 bytes but 64 follow the header");
}

TEST_F(HdrImage, CorruptRunLengthDataNamesTheRow) {
  const std::string good = encodeHdr(exactImage(64, 32), true);
  const size_t header = hdrHeader(64, 32).size();
  std::string bytes = good;
  bytes[header + 3] = 63;  // the first scanline's marker says 63 pixels, not 64
  expectReadError(put("width.hdr", bytes),
                  "pixel data, row 0 of 32: the scanline says it is 63 pixels wide, the image 64 (corrupt)");
  bytes = good;
  bytes[header + 4] = static_cast<char>(128 + 100);  // a run of 100 in a 64-pixel scanline
  expectReadError(put("run.hdr", bytes), "pixel data, row 0 of 32: a run of 100 pixels goes past the scanline's end (corrupt)");
  // The second scanline without its marker: stb_image would start over in flat mode.
  const std::string second = encodeHdr(exactImage(64, 1), true).substr(hdrHeader(64, 1).size());
  bytes = good;
  bytes[header + second.size()] = 'x';
  expectReadError(put("marker.hdr", bytes), "pixel data, row 1 of 32: no run-length marker (2 2 hi lo)");
}

TEST_F(HdrImage, EnvironmentMapsMustBeTwiceAsWideAsHigh) {
  const auto load = [](const fs::path& p) { loadEnvironmentMap(p); };
  expectError(put("square.hdr", encodeHdr(constantImage(16, 16, glm::vec3(1.0f)))),
              "is 16 x 16 pixels; an equirectangular map is exactly twice as wide as high (e.g. 2048 x 1024)", load);
  expectError(put("wide.hdr", encodeHdr(constantImage(34, 16, glm::vec3(1.0f)))), "is 34 x 16 pixels", load);
  expectError(dir_ / "missing.hdr", "file not found", load);
  EXPECT_NO_THROW(loadEnvironmentMap(put("good.hdr", encodeHdr(constantImage(32, 16, glm::vec3(1.0f))))));
}

#pragma once
// Radiance RGBE images (.hdr, Greg Ward's format): the header is read and checked here, the
// pixels are decoded by stb_image's stbi_loadf. Every problem is an InputError naming the file.
#include <filesystem>

#include "marble/core/image.h"

namespace marble {

// Largest side accepted. Checked from the header, before any pixel memory is allocated: a
// 8192 x 4096 map is 384 MiB as floats. (Environment maps are used at most 2048 wide.)
constexpr int kMaxHdrSide = 8192;

struct HdrHeader {
  int width = 0, height = 0;
  long long dataOffset = 0;       // first byte of the pixel data
  bool runLengthEncoded = false;  // the first scanline starts with the "2 2 hi lo" RLE marker
};

// Reads and checks the header only (signature, FORMAT=32-bit_rle_rgbe, "-Y H +X W", limits,
// and that the file holds at least the bytes its pixels need). Throws InputError.
HdrHeader readHdrHeader(const std::filesystem::path& path);

// Reads the whole image: linear RGB, row 0 the top row. Throws InputError (also for a file that
// ends inside its pixel data: stb_image would silently fill the rest with black).
ImageRGBF readHdr(const std::filesystem::path& path);

}  // namespace marble

#pragma once
// Box-filter downsampling by a whole factor, for supersampled renders (`marble render
// --supersample N`): every N x N block of the large image becomes one pixel.
#include "marble/core/image.h"

namespace marble {

// 8-bit sRGB-encoded images are averaged in linear light: each block is decoded (IEC 61966-2-1),
// averaged and encoded again. Averaging the bytes themselves would darken every edge (black and
// white half and half must give 188, not 128). Alpha is averaged as it is.
// The image's width and height must be multiples of `factor` (>= 1); throws std::invalid_argument.
ImageRGBA8 downsampleSrgb(const ImageRGBA8& image, int factor);

// Linear images (the HDR output) are averaged as they are.
ImageRGBF downsampleLinear(const ImageRGBF& image, int factor);

}  // namespace marble

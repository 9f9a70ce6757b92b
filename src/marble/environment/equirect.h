#pragma once
// Equirectangular (latitude-longitude) images on the CPU: the mapping between directions and
// image coordinates, the solid angle of a texel, filtered lookups and resampling.
//
// The mapping, the same in shaders/environment.glsl (world +Y is up):
//   u = 0.5 + atan2(d.x, -d.z) / 2pi   (the image centre looks along -Z, +X is to its right)
//   v = acos(d.y) / pi                 (row 0, v = 0, is straight up)
// Texel (x, y) has its centre at u = (x + 0.5) / W, v = (y + 0.5) / H.
#include <vector>

#include <glm/glm.hpp>

#include "marble/core/image.h"

namespace marble {

glm::vec3 equirectDirection(double u, double v);
glm::vec2 equirectUv(const glm::vec3& d);

// Solid angle of each texel of row y in a W x H map: (2pi / W) (cos theta0 - cos theta1), the
// exact integral of sin(theta) over the row; the whole map sums to 4pi.
double equirectTexelSolidAngle(int y, int width, int height);

inline glm::vec3 texelAt(const ImageRGBF& img, int x, int y) {
  const float* p = &img.pixels[(static_cast<size_t>(y) * static_cast<size_t>(img.width) + static_cast<size_t>(x)) * 3];
  return {p[0], p[1], p[2]};
}

// Bilinear lookup at (u, v): wraps around horizontally, clamps at the poles (the GL texture's
// GL_REPEAT / GL_CLAMP_TO_EDGE).
glm::vec3 sampleEquirect(const ImageRGBF& img, float u, float v);

// The map at a new size, each new texel the solid-angle-weighted average of the old texels it
// covers (fractional coverage at the edges), so the map's integral is kept.
ImageRGBF resampleEquirect(const ImageRGBF& src, int width, int height);

// level 0 = `base`, then 2x2 box averages down to 1 x 1: the sizes GL gives mip levels.
std::vector<ImageRGBF> equirectMipChain(const ImageRGBF& base);

// The solid-angle-weighted mean radiance over the sphere (the map's integral / 4pi).
glm::dvec3 equirectMean(const ImageRGBF& img);

}  // namespace marble

#include "marble/environment/sh_irradiance.h"

#include <cmath>
#include <vector>

#include "marble/environment/equirect.h"

namespace marble {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The real SH basis functions Y_lm up to l = 2 (Ramamoorthi and Hanrahan 2001, eq. 3).
std::array<double, 9> basis(double x, double y, double z) {
  return {0.282095,
          0.488603 * y,
          0.488603 * z,
          0.488603 * x,
          1.092548 * x * y,
          1.092548 * y * z,
          0.315392 * (3.0 * z * z - 1.0),
          1.092548 * x * z,
          0.546274 * (x * x - y * y)};
}

// The constants of eq. 13.
constexpr float c1 = 0.429043f, c2 = 0.511664f, c3 = 0.743125f, c4 = 0.886227f, c5 = 0.247708f;

}  // namespace

ShCoefficients projectSh9(const ImageRGBF& img) {
  std::array<glm::dvec3, 9> sum{};
  // Directions per column share sin/cos of the longitude.
  std::vector<double> sinPhi(static_cast<size_t>(img.width)), cosPhi(static_cast<size_t>(img.width));
  for (int x = 0; x < img.width; ++x) {
    const double phi = ((x + 0.5) / img.width - 0.5) * 2.0 * kPi;
    sinPhi[static_cast<size_t>(x)] = std::sin(phi);
    cosPhi[static_cast<size_t>(x)] = std::cos(phi);
  }
  for (int y = 0; y < img.height; ++y) {
    const double theta = (y + 0.5) / img.height * kPi;
    const double st = std::sin(theta), ct = std::cos(theta);
    const double dOmega = equirectTexelSolidAngle(y, img.width, img.height);
    std::array<glm::dvec3, 9> row{};
    for (int x = 0; x < img.width; ++x) {
      // equirectDirection(), with the trigonometry hoisted.
      const double dx = st * sinPhi[static_cast<size_t>(x)], dy = ct, dz = -st * cosPhi[static_cast<size_t>(x)];
      const glm::dvec3 L(texelAt(img, x, y));
      const auto Y = basis(dx, dy, dz);
      for (size_t i = 0; i < 9; ++i) row[i] += L * Y[i];
    }
    for (size_t i = 0; i < 9; ++i) sum[i] += row[i] * dOmega;
  }
  ShCoefficients out;
  for (size_t i = 0; i < 9; ++i) out[i] = glm::vec3(sum[i]);
  return out;
}

glm::vec3 shIrradiance(const ShCoefficients& L, const glm::vec3& n) {
  const float x = n.x, y = n.y, z = n.z;
  return c1 * L[8] * (x * x - y * y) + c3 * L[6] * z * z + c4 * L[0] - c5 * L[6] +
         2.0f * c1 * (L[4] * x * y + L[7] * x * z + L[5] * y * z) + 2.0f * c2 * (L[3] * x + L[1] * y + L[2] * z);
}

std::array<glm::vec3, 9> shDiffuseTerms(const ShCoefficients& L) {
  const float invPi = static_cast<float>(1.0 / kPi);
  return {invPi * (c4 * L[0] - c5 * L[6]),
          invPi * 2.0f * c2 * L[3],
          invPi * 2.0f * c2 * L[1],
          invPi * 2.0f * c2 * L[2],
          invPi * 2.0f * c1 * L[4],
          invPi * 2.0f * c1 * L[5],
          invPi * 2.0f * c1 * L[7],
          invPi * c3 * L[6],
          invPi * c1 * L[8]};
}

}  // namespace marble

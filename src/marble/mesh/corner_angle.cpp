#include "marble/mesh/corner_angle.h"

#include <array>
#include <cmath>
#include <numbers>

namespace marble::mesh_detail {
namespace {

constexpr int kSteps = 32;

const std::array<double, kSteps + 1>& atanTable() {
  static const std::array<double, kSteps + 1> table = [] {
    std::array<double, kSteps + 1> t{};
    for (int k = 0; k <= kSteps; ++k) t[k] = std::atan(static_cast<double>(k) / kSteps);
    return t;
  }();
  return table;
}

}  // namespace

std::optional<float> fastCornerAngle(double y, double x) {
  if (!(y > 0.0) || !std::isfinite(y) || !std::isfinite(x)) return std::nullopt;
  const double ax = std::fabs(x);
  const bool steep = y > ax;              // atan2 = pi/2 - atan(|x| / y)
  const double r = steep ? ax / y : y / ax;  // in [0, 1]
  // atan(r) = atan(c) + atan(t), c = k / 32 the nearest step, t = (r - c) / (1 + r c), |t| <= 1/64.
  const int k = static_cast<int>(r * kSteps + 0.5);
  const double c = static_cast<double>(k) / kSteps;
  const double t = (r - c) / (1.0 + r * c);
  const double t2 = t * t;
  const double series = t * (1.0 - t2 * (1.0 / 3 - t2 * (1.0 / 5 - t2 * (1.0 / 7 - t2 * (1.0 / 9)))));
  double a = atanTable()[k] + series;
  if (steep) a = std::numbers::pi / 2 - a;
  if (x < 0.0) a = std::numbers::pi - a;
  const double tolerance = a * 0x1p-40;
  const float f = static_cast<float>(a);
  if (static_cast<float>(a - tolerance) != f || static_cast<float>(a + tolerance) != f) return std::nullopt;
  return f;
}

float cornerAngle(double y, double x) {
  if (const std::optional<float> f = fastCornerAngle(y, x)) return *f;
  return static_cast<float>(std::atan2(y, x));
}

}  // namespace marble::mesh_detail

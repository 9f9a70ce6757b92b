#pragma once
// The angle of a triangle's corner, the weight of its face's normal in the vertex normal
// (vertex_normals.h): atan2(|e1 x e2|, e1 . e2) in double, with atan from its Maclaurin series
// instead of libm's atan2 (the load of a 1.6 M-triangle mesh takes 4.8 M of them; libm's was
// ~10 % of the crease pass's CPU, Sixteenth session in docs/performance.md).
//
// Error: after the reductions below the series' argument is |u| <= tan(pi/8) = 0.41421; the
// series alternates, so stopping after the u^17 term errs by at most the first omitted term,
// u^19 / 19 <= 2.9e-9 rad, plus a few double roundings (~1e-16). The result, rounded to float,
// is libm's float or one ulp away from it (test VertexNormalsTolerance.CornerAngleMatchesLibm).
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace marble {

// atan2(y, x) for y >= 0 (a length), in [0, pi].
inline double atan2OfLength(double y, double x) {
  constexpr double kPi = std::numbers::pi;
  constexpr double kTanPiOver8 = 0.41421356237309503;  // sqrt(2) - 1
  const double ax = std::fabs(x);
  if (!(y > 0.0 || ax > 0.0)) return x < 0.0 ? kPi : 0.0;  // both zero (atan2(0, -0) = pi); NaN -> 0
  // atan(t), t = min / max in [0, 1]; the angle is atan(t) or pi/2 - atan(t).
  const bool steep = y > ax;
  const double t = steep ? ax / y : y / ax;
  // t above tan(pi/8): atan(t) = pi/4 + atan((t - 1) / (t + 1)), whose argument is in [-tan(pi/8), 0].
  const bool high = t > kTanPiOver8;
  const double u = high ? (t - 1.0) / (t + 1.0) : t;
  const double s = u * u;
  // atan(u) = u (1 - s/3 + s^2/5 - ... + s^8/17)
  double p = 1.0 / 17.0;
  p = p * s - 1.0 / 15.0;
  p = p * s + 1.0 / 13.0;
  p = p * s - 1.0 / 11.0;
  p = p * s + 1.0 / 9.0;
  p = p * s - 1.0 / 7.0;
  p = p * s + 1.0 / 5.0;
  p = p * s - 1.0 / 3.0;
  p = p * s + 1.0;
  const double atanT = (high ? kPi / 4.0 : 0.0) + u * p;
  const double a = steep ? kPi / 2.0 - atanT : atanT;
  return x < 0.0 ? kPi - a : a;
}

// The angle at p0 between the edges to p1 and p2, in radians. (vertex_normals.cpp calls
// atan2OfLength with the face's cross length, the same |e1 x e2| for all three corners.)
inline float cornerAngleOf(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
  const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
  return static_cast<float>(atan2OfLength(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2)));
}

}  // namespace marble

#include "marble/render/screen_cull.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace marble {

namespace {

// The four 3 x 3 minors of the 3 x 4 matrix with rows a, b, c, column k left out.
glm::dvec4 minors(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
  auto det3 = [](double a0, double a1, double a2, double b0, double b1, double b2, double c0, double c1, double c2) {
    return a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0);
  };
  return {det3(a.y, a.z, a.w, b.y, b.z, b.w, c.y, c.z, c.w), det3(a.x, a.z, a.w, b.x, b.z, b.w, c.x, c.z, c.w),
          det3(a.x, a.y, a.w, b.x, b.y, b.w, c.x, c.y, c.w), det3(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z)};
}

}  // namespace

ScreenCullMesh::ScreenCullMesh(const Mesh& mesh) : indices(mesh.indices) {
  const size_t n = mesh.positions.size();
  x.resize(n);
  y.resize(n);
  z.resize(n);
  for (size_t i = 0; i < n; ++i) {
    x[i] = mesh.positions[i].x;
    y[i] = mesh.positions[i].y;
    z[i] = mesh.positions[i].z;
  }
  const size_t triangles = indices.size() / 3;
  planeX.resize(triangles);
  planeY.resize(triangles);
  planeZ.resize(triangles);
  planeW.resize(triangles);
  for (size_t t = 0; t < triangles; ++t) {
    const glm::vec3 &p0 = mesh.positions[indices[3 * t]], &p1 = mesh.positions[indices[3 * t + 1]],
                    &p2 = mesh.positions[indices[3 * t + 2]];
    const glm::dvec4 q = minors(glm::dvec4(p0, 1.0), glm::dvec4(p1, 1.0), glm::dvec4(p2, 1.0));
    planeX[t] = static_cast<float>(q.x);
    planeY[t] = static_cast<float>(q.y);
    planeZ[t] = static_cast<float>(q.z);
    planeW[t] = static_cast<float>(q.w);
  }
}

size_t trianglesGlMayDraw(const ScreenCullMesh& mesh, const glm::mat4& modelViewProj, int width, int height,
                          CulledSense culled, uint32_t* kept, std::vector<float>& scratch, double slackPixels) {
  // Window positions relative to the viewport's centre (a shift does not change an area), in pixels;
  // NaN for a corner outside the view volume (every comparison with it is false: its triangles stay).
  const size_t count = mesh.x.size(), triangles = mesh.indices.size() / 3;
  scratch.resize(2 * count + triangles);
  float* __restrict wx = scratch.data();
  float* __restrict wy = wx + count;
  float* __restrict facing = wy + count;  // per triangle: > 0 where it may be of the culled sense
  const float* __restrict px = mesh.x.data();
  const float* __restrict py = mesh.y.data();
  const float* __restrict pz = mesh.z.data();
  const float halfWidth = 0.5f * static_cast<float>(width), halfHeight = 0.5f * static_cast<float>(height);
  const glm::mat4 m = modelViewProj;
  const float m00 = m[0][0], m10 = m[1][0], m20 = m[2][0], m30 = m[3][0];
  const float m01 = m[0][1], m11 = m[1][1], m21 = m[2][1], m31 = m[3][1];
  const float m02 = m[0][2], m12 = m[1][2], m22 = m[2][2], m32 = m[3][2];
  const float m03 = m[0][3], m13 = m[1][3], m23 = m[2][3], m33 = m[3][3];
  // 0.999: a corner on a clip plane, within this code's rounding, may be clipped by GL.
  const float inside = 0.999f;
  for (size_t i = 0; i < count; ++i) {
    const float X = m00 * px[i] + m10 * py[i] + m20 * pz[i] + m30;
    const float Y = m01 * px[i] + m11 * py[i] + m21 * pz[i] + m31;
    const float Z = m02 * px[i] + m12 * py[i] + m22 * pz[i] + m32;
    const float W = m03 * px[i] + m13 * py[i] + m23 * pz[i] + m33;
    const float bound = inside * W;
    // std::max, not std::fmax (a call where a NaN is possible): a NaN corner is out of view too.
    const bool inView = std::max(std::max(std::fabs(X), std::fabs(Y)), std::fabs(Z)) < bound;  // so W > 0
    const float invW = 1.0f / W;
    // Out of view: x's bits or'ed with a quiet NaN's (a NaN whatever the rest); bits, not a select,
    // so that the loop is vectorized (64 instructions a vertex otherwise).
    const float x = X * invW * halfWidth;
    wx[i] = std::bit_cast<float>(std::bit_cast<uint32_t>(x) | (static_cast<uint32_t>(!inView) * 0x7fc00000u));
    wy[i] = Y * invW * halfHeight;
  }
  // The view's minors (rows x, y, w of modelViewProj): their product with a triangle's plane is
  // det[X; Y; W] of its corners, its doubled area in normalized device coordinates times
  // W0 W1 W2 (> 0 in view), positive for counter-clockwise on screen (Cauchy-Binet). Used only to
  // keep a triangle at once (its rounding can only send a triangle on to the exact test below).
  auto row = [&m](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  const glm::vec4 eye(minors(row(0), row(1), row(3)));
  // The culled sense's sign: counter-clockwise on screen (y up) is a positive doubled area.
  const float senseF = culled == CulledSense::Clockwise ? -1.0f : 1.0f;
  const glm::vec4 culledEye = senseF * eye;
  {
    const float* __restrict qx = mesh.planeX.data();
    const float* __restrict qy = mesh.planeY.data();
    const float* __restrict qz = mesh.planeZ.data();
    const float* __restrict qw = mesh.planeW.data();
    for (size_t t = 0; t < triangles; ++t)
      facing[t] = culledEye.x * qx[t] + culledEye.y * qy[t] + culledEye.z * qz[t] + culledEye.w * qw[t];
  }
  const double sense = senseF;
  const double slack2 = 2.0 * slackPixels, slackSquared8 = 8.0 * slackPixels * slackPixels;
  uint32_t* out = kept;
  const uint32_t* idx = mesh.indices.data();
  size_t written = 0;
  for (size_t t = 0; t < triangles; ++t) {
    const uint32_t i0 = idx[3 * t], i1 = idx[3 * t + 1], i2 = idx[3 * t + 2];
    out[written] = i0;
    out[written + 1] = i1;
    out[written + 2] = i2;
    if (!(facing[t] > 0.0f)) {
      written += 3;  // facing the eye, or nearly: kept
      continue;
    }
    // Doubles: the products of the float differences are exact there, so the only error is the
    // corners' own, which the slack covers.
    const double x0 = wx[i0], y0 = wy[i0];
    const double ax = wx[i1] - x0, ay = wy[i1] - y0;
    const double bx = wx[i2] - x0, by = wy[i2] - y0;
    const double area = sense * (ax * by - ay * bx);  // > 0: the culled sense
    const double change = slack2 * (std::fabs(ax) + std::fabs(ay) + std::fabs(bx) + std::fabs(by)) + slackSquared8;
    written += (area > change) ? 0 : 3;
  }
  return written / 3;
}

}  // namespace marble

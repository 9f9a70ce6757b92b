// The fold of the further bounces' tests (bounce_further_gl_test.cpp, the renderer's picture;
// further_radiosity_test.cpp, the radiosity alone): a lit plate (light straight down) and a wall
// standing on it, and the fold's analytic two-bounce integral. The wall's face toward the plate
// gets no direct light, only the plate's first bounce; the plate then gets that back: with the
// plate's direct irradiance E_d = PI (at normal incidence per unit of the light's radiance),
//   G_1(y) = PI f(y) on the wall, f(y) = ∫_plate cosθ_p cosθ_y / (π r²) dA_p,
//   G_2(x) = PI ∫_wall f(y) cosθ_y cosθ_x / (π r²) dA_y = PI twoBounceIntegral(d) on the plate,
// integrated here on the CPU (the wall's face on a 48 x 48 grid, f at each point on 100 x 200:
// converged to 1 %).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "box_mesh.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/vertex_normals.h"

namespace marble::test::fold {

// The wall: x in [-kWall, kWall], y in [kPlateTop, 1]; the plate: y in [kPlateTop - 0.2,
// kPlateTop], x in [kWall, 1]; both z in [-1, 1] (bounce_gl_test.cpp's corner).
constexpr float kWall = 0.1f, kPlateTop = -0.6f;
// A point on the plate's top, d from the wall's face.
inline glm::vec3 probe(float d) { return {kWall + d, kPlateTop, 0.0f}; }

inline Mesh foldMesh(bool withWall) {
  Mesh m;
  if (withWall) addBox(m, {-kWall, kPlateTop, -1.0f}, {kWall, 1.0f, 1.0f});
  addBox(m, {kWall, kPlateTop - 0.2f, -1.0f}, {1.0f, kPlateTop, 1.0f});
  computeVertexNormals(m, 60.0f);  // flat faces
  return m;
}

// f(y, z): the plate's top face's view factor from the wall's face at (kWall, y, z).
inline double plateSeenFromWall(double y, double z) {
  const int nx = 100, nz = 200;
  const double dx = (1.0 - kWall) / nx, dz = 2.0 / nz;
  double sum = 0.0;
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k) {
      const double ux = (i + 0.5) * dx, uy = kPlateTop - y, uz = -1.0 + (k + 0.5) * dz - z;  // wall -> plate
      const double r2 = ux * ux + uy * uy + uz * uz;
      sum += ux * -uy / (r2 * r2 * M_PI);  // cosθ_y cosθ_p / (π r²), the cosines as dots over r
    }
  return sum * dx * dz;
}

// ∫_wall f(y) cosθ_y cosθ_x / (π r²) dA_y at the plate's point d from the wall.
inline double twoBounceIntegral(float d) {
  const int ny = 48, nz = 48;
  const double dy = (1.0 - kPlateTop) / ny, dz = 2.0 / nz;
  double sum = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int k = 0; k < nz; ++k) {
      const double y = kPlateTop + (j + 0.5) * dy, z = -1.0 + (k + 0.5) * dz;
      const double ux = -d, uy = y - kPlateTop, uz = z;  // plate point -> wall point
      const double r2 = ux * ux + uy * uy + uz * uz;
      sum += plateSeenFromWall(y, z) * (-ux) * uy / (r2 * r2 * M_PI);
    }
  return sum * dy * dz;
}

}  // namespace marble::test::fold

// The `marble` mode's transmission through a curved thin part (docs/quality.md, "Eleventh session:
// the translucent shadow map's gather"): a long round rod, 10 mm across, lit from straight behind
// by a directional light and seen head-on from the other side. Its glow at the middle of the far
// side must have the colour that Cycles' random walk gives in that rod: the walk of
// tests/transmission_slab_gl_test.cpp (cosine-weighted entry with the Principled coupling,
// isotropic scattering, no reflection inside the boundary, dropped after 256 flights), run here in
// the rod's cross-section. In a rod the walk reaches the far side by paths round the curve and
// loses what wanders out of the sides, so its light is whiter than a flat slab's of the same
// chord: green / red 0.57 in the rod (this walk) against 0.49 for the straight chord's slab, and a
// third of the slab's red. The straight chord
// along the light (main before session 11) gives the slab's colour and fails; the gather over the
// light's map gives the rod's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

#include "gl_support.h"
#include "image_probe.h"
#include "principled_stone.h"
#include "splitmix.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 128;
constexpr float kRadius = 0.1f;      // scene units: the rod's radius
constexpr float kMmPerUnit = 50.0f;  // 5 mm: a 10 mm chord through the middle
constexpr int kSegments = 96;        // round enough: 3.75 degrees a facet, smooth normals

// A rod along x, from -1 to 1, capped (the caps split off by the crease angle).
Mesh rod() {
  Mesh m;
  for (int end = 0; end < 2; ++end)
    for (int i = 0; i < kSegments; ++i) {
      const float a = 2.0f * static_cast<float>(M_PI) * static_cast<float>(i) / kSegments;
      m.positions.push_back({end ? 1.0f : -1.0f, kRadius * std::cos(a), kRadius * std::sin(a)});
    }
  for (int i = 0; i < kSegments; ++i) {
    const auto a = static_cast<uint32_t>(i), b = static_cast<uint32_t>((i + 1) % kSegments);
    const auto n = static_cast<uint32_t>(kSegments);
    for (uint32_t v : {a, b, b + n, a, b + n, a + n}) m.indices.push_back(v);
  }
  for (int end = 0; end < 2; ++end)  // caps, fanned from the first vertex
    for (int i = 1; i + 1 < kSegments; ++i) {
      const auto o = static_cast<uint32_t>(end * kSegments);
      const auto j = static_cast<uint32_t>(i), k = static_cast<uint32_t>(i + 1);
      if (end) {
        for (uint32_t v : {o, o + j, o + k}) m.indices.push_back(v);
      } else {
        for (uint32_t v : {o, o + k, o + j}) m.indices.push_back(v);
      }
    }
  computeVertexNormals(m, 60.0f);
  return m;
}

Scene rodScene() { return test::backLitScene("test:rod", kMmPerUnit, kSize); }

// Exitance at the rod's far side per unit irradiance (perpendicular to the light), over the arc
// within kWindow of its middle: walks enter uniformly across the rod's width (its cross-section
// seen from the light) with the Principled weight 1 - (1 - cos)^5 / 2, start cosine-weighted about
// the inward normal, and are followed in the cross-section (the rod is long: x does not matter).
// Lengths in mean free paths (sigma_t = 1), the radius tau_r of them.
constexpr double kWindow = 0.2;  // radians either side of the middle: the probe's 3 x 3 pixels
double walkThroughRod(double tauR, double alpha, int walks, uint64_t seed) {
  SplitMix rng{seed};
  double tally = 0.0;
  for (int n = 0; n < walks; ++n) {
    const double y0 = tauR * (2.0 * rng.next() - 1.0);
    double py = y0, pz = -std::sqrt(tauR * tauR - y0 * y0);
    const double ny = py / tauR, nz = pz / tauR, cosIn = -nz;
    const double m = 1.0 - cosIn;
    double w = 1.0 - 0.5 * m * m * m * m * m;
    // Cosine-weighted about -n; the tangents: x, and (-nz, ny) in the cross-section.
    const double mu = std::sqrt(rng.next()), phi = 2.0 * M_PI * rng.next(), st = std::sqrt(1.0 - mu * mu);
    double dy = -mu * ny + st * std::sin(phi) * -nz, dz = -mu * nz + st * std::sin(phi) * ny;
    for (int flights = 1; flights <= 256; ++flights) {
      const double l = -std::log1p(-rng.next());
      const double qy = py + l * dy, qz = pz + l * dz;
      if (qy * qy + qz * qz > tauR * tauR) {
        // Where the flight crosses the circle: |p + t d| = r, t > 0.
        const double a = dy * dy + dz * dz, b = 2.0 * (py * dy + pz * dz), c = py * py + pz * pz - tauR * tauR;
        const double t = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
        if (std::abs(std::atan2(py + t * dy, pz + t * dz)) < kWindow) tally += w;
        break;
      }
      py = qy;
      pz = qz;
      if (flights == 256) break;  // Cycles' BSDF_MAX_BOUNCES
      w *= alpha;
      const double cz = 2.0 * rng.next() - 1.0, ph = 2.0 * M_PI * rng.next();
      dy = std::sqrt(1.0 - cz * cz) * std::cos(ph);
      dz = cz;
    }
  }
  // Flux per unit length through the window, E x width x tally / walks, over the window's arc.
  return (tally / walks) * (2.0 * tauR) / (2.0 * kWindow * tauR);
}

// What an infinitely thick slab reflects per unit entering (R_inf; the renderer's transport is
// relative to it, as in tests/transmission_slab_gl_test.cpp).
double reflectedByHalfSpace(double alpha, int walks, uint64_t seed) {
  SplitMix rng{seed};
  double back = 0.0;
  for (int n = 0; n < walks; ++n) {
    double z = 0.0, mu = std::sqrt(rng.next()), w = 1.0;
    for (int flights = 1; flights <= 256; ++flights) {
      z += mu * -std::log1p(-rng.next());
      if (z < 0.0) {
        back += w;
        break;
      }
      if (flights == 256) break;
      w *= alpha;
      mu = 2.0 * rng.next() - 1.0;
    }
  }
  return back / walks;
}

// The rod's glow per channel as the renderer should draw it: albedo x exitance / (E R_inf).
glm::vec3 walkedGlow(const Material& m) {
  glm::vec3 g;
  for (int c = 0; c < 3; ++c) {
    const double sigmaT = static_cast<double>(m.sigma_a_mm[c]) + m.sigma_s_mm[c];
    const double alpha = m.sigma_s_mm[c] / sigmaT;
    const double through = walkThroughRod(sigmaT * kRadius * kMmPerUnit, alpha, 400000, 31u + static_cast<uint64_t>(c));
    g[c] = static_cast<float>(m.base_color[c] * through / reflectedByHalfSpace(alpha, 50000, 23u + static_cast<uint64_t>(c)));
  }
  return g;
}

glm::vec3 renderedGlow(Renderer& renderer) {
  const Scene s = rodScene();
  renderer.setMesh(rod());
  renderImage(renderer, s);
  return linearRgbAround(renderer.readHdr(), s, {0, 0, kRadius});
}

// Measured on llvmpipe: the gather 0.88 / 1.01 / 1.00 of the walk (R G B), G/R 1.14x; the
// straight chord 2.5 / 2.2 / 1.8x, G/R 0.86x. The walk's own noise is about 1 % (400,000 walks).
constexpr float kTolerance = 0.2f;

// Green over red: the colour, which the walk's rod and slab differ in most.
float greenOverRed(const glm::vec3& c) { return c.g / c.r; }

}  // namespace

TEST(TransmissionCurved, RodGlowsWithTheRandomWalksColour) {
  glContext();
  Renderer renderer;
  const glm::vec3 glow = renderedGlow(renderer);
  const glm::vec3 walk = walkedGlow(rodScene().material);
  std::cout << "[          ] rod: render " << glow.r << " " << glow.g << " " << glow.b << " (G/R " << greenOverRed(glow)
            << "), walk " << walk.r << " " << walk.g << " " << walk.b << " (G/R " << greenOverRed(walk) << ")\n";
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(glow[c], walk[c], kTolerance * walk[c]) << "channel " << c;
  EXPECT_NEAR(greenOverRed(glow), greenOverRed(walk), kTolerance * greenOverRed(walk));
}

// The negative control: the transmission along the straight chord alone (the gather's blend
// removed from the shader) gives a 10 mm slab's colour, redder than the rod's walk.
TEST(TransmissionCurvedControl, TheStraightChordIsTooRed) {
  glContext();
  std::string text = embeddedShaders().at("lighting.frag.glsl");
  const std::string from = "float blend = smoothstep(GLOW_FROM_MM, 2.0 * GLOW_FROM_MM, s0 * mm);";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << "lighting.frag.glsl no longer has the line this control breaks";
  text.replace(at, from.size(), "float blend = 0.0;");
  const auto dir = std::filesystem::temp_directory_path() / ("marble-curved-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "lighting.frag.glsl") << text;
  Renderer renderer{ShaderLibrary(dir.string())};
  const glm::vec3 glow = renderedGlow(renderer);
  std::filesystem::remove_all(dir);
  const glm::vec3 walk = walkedGlow(rodScene().material);
  std::cout << "[          ] straight chord: render " << glow.r << " " << glow.g << " " << glow.b << " (G/R "
            << greenOverRed(glow) << ")\n";
  EXPECT_GT(glow.r, (1.0f + kTolerance) * walk.r) << "the straight chord's red was expected far above the rod's walk";
}

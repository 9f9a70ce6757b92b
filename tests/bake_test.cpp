// The texture bake's pieces without GL: UV scan conversion, the overlap check, the automatic
// unwrap, the file-UV checks and the baked textures against closed forms (bake/*.h).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "temp_dir.h"
#include "marble/bake/background_export.h"
#include "marble/bake/bake_mesh.h"
#include "marble/bake/ray_bvh.h"
#include "marble/bake/texture_bake.h"
#include "marble/bake/uv_raster.h"
#include "marble/bake/uv_unwrap.h"
#include "marble/core/error.h"
#include "marble/noise/marble_pattern.h"
#include "marble/scene/material_io.h"

using namespace marble;

namespace {

// Two triangles covering the unit square, in the plane z = 0 with uv = (x, y) / 2 + 0.5.
Mesh unitQuad() {
  Mesh m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.normals.assign(4, glm::vec3(0, 0, 1));
  m.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

}  // namespace

TEST(UvRaster, SharedEdgeSamplesBelongToOneTriangle) {
  // The diagonal passes through sample centres: the top-left rule gives each to one triangle.
  for (int res : {7, 16, 33}) {
    const UvOverlap o = measureUvOverlap(unitQuad(), res);
    EXPECT_EQ(o.coveredSamples, static_cast<uint64_t>(res) * res) << res;
    EXPECT_EQ(o.overlapSamples, 0u) << res;
  }
}

TEST(UvRaster, OverlapIsCounted) {  // negative control for the test above
  Mesh m = unitQuad();
  m.indices = {0, 1, 2, 0, 1, 2};  // the same triangle twice
  const UvOverlap o = measureUvOverlap(m, 16);
  EXPECT_GT(o.overlapSamples, 100u);
  EXPECT_EQ(o.overlapSamples, o.coveredSamples);
}

TEST(UvRaster, BarycentricsReproduceTheSample) {
  const glm::vec2 a(0.1f, 0.2f), b(0.9f, 0.3f), c(0.4f, 0.95f);
  int n = 0;
  rasterizeUvTriangle(a, b, c, 32, [&](int x, int y, glm::vec3 w) {
    const glm::vec2 uv = w.x * a + w.y * b + w.z * c;
    EXPECT_NEAR(uv.x, (x + 0.5f) / 32, 1e-5f);
    EXPECT_NEAR(uv.y, 1.0f - (y + 0.5f) / 32, 1e-5f);  // row 0 is the top (v = 1)
    ++n;
  });
  // About the triangle's area in samples.
  const float area = 0.5f * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) * 32 * 32;
  EXPECT_NEAR(n, area, 0.1f * area);
}

class UnwrapBuiltin : public ::testing::TestWithParam<const char*> {};

TEST_P(UnwrapBuiltin, ChartsInsideTheSquareWithoutOverlap) {
  Mesh mesh = builtinMesh(GetParam());
  mesh.texcoords.clear();
  const UvUnwrapResult r = unwrapUvs(mesh, {512, 2, 50.0f});
  ASSERT_EQ(r.mesh.indices.size(), mesh.indices.size());
  ASSERT_EQ(r.mesh.texcoords.size(), r.mesh.positions.size());
  ASSERT_EQ(r.sourceVertex.size(), r.mesh.positions.size());
  for (size_t v = 0; v < r.mesh.positions.size(); ++v) {
    EXPECT_EQ(r.mesh.positions[v], mesh.positions[r.sourceVertex[v]]);
    EXPECT_GE(r.mesh.texcoords[v].x, 0.0f);
    EXPECT_LE(r.mesh.texcoords[v].x, 1.0f);
    EXPECT_GE(r.mesh.texcoords[v].y, 0.0f);
    EXPECT_LE(r.mesh.texcoords[v].y, 1.0f);
  }
  // The same triangles, corner for corner.
  for (size_t i = 0; i < mesh.indices.size(); ++i) EXPECT_EQ(r.sourceVertex[r.mesh.indices[i]], mesh.indices[i]);
  const UvOverlap o = measureUvOverlap(r.mesh, 1024);
  EXPECT_EQ(o.overlapSamples, 0u);
  EXPECT_GT(r.stats.charts, 0);
  EXPECT_GT(r.stats.packingEfficiency, 0.15);
  // Projection along the seed normal within a 50 degree cone: density varies by at most 1/cos(50).
  EXPECT_GT(r.stats.densityP05, std::cos(glm::radians(50.0)) - 0.02);
  EXPECT_LT(r.stats.densityP95, 1.0 / std::cos(glm::radians(50.0)) + 0.02);
}

INSTANTIATE_TEST_SUITE_P(Meshes, UnwrapBuiltin, ::testing::Values("sculpture", "sphere", "cube", "torus", "slab"));

TEST(Unwrap, CubeHasOneChartPerFace) {
  Mesh mesh = builtinMesh("cube");
  const UvUnwrapResult r = unwrapUvs(mesh, {256, 2, 50.0f});
  EXPECT_EQ(r.stats.charts, 6);
  EXPECT_NEAR(r.stats.densityCv, 0.0, 1e-4);  // flat faces: every texel the same size on the surface
}

TEST(BakeMesh, FileUvsThatOverlapAreRefusedWhenAskedFor) {
  Mesh m = unitQuad();
  m.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 0}};  // the second triangle folds onto the first
  m.indices = {0, 1, 2, 1, 2, 3};
  try {
    prepareBakeMesh(m, UvSource::File, 256, 2, "quad.obj");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("overlap"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("quad.obj"), std::string::npos) << e.what();
  }
  // auto unwraps instead, and says why.
  const BakeMesh b = prepareBakeMesh(m, UvSource::Auto, 256, 2, "quad.obj");
  EXPECT_TRUE(b.unwrapped);
  EXPECT_NE(b.note.find("overlap"), std::string::npos);
}

TEST(BakeMesh, FileUvsAreKeptWhenUsable) {
  const BakeMesh b = prepareBakeMesh(unitQuad(), UvSource::Auto, 256, 2, "quad.obj");
  EXPECT_FALSE(b.unwrapped);
  EXPECT_EQ(b.mesh.texcoords, unitQuad().texcoords);
  EXPECT_NEAR(b.stats.packingEfficiency, 1.0, 1e-6);
  Mesh outside = unitQuad();
  outside.texcoords[2] = {2, 2};
  EXPECT_THROW(prepareBakeMesh(outside, UvSource::File, 256, 2, "quad.obj"), InputError);
  Mesh none = unitQuad();
  none.texcoords.clear();
  EXPECT_THROW(prepareBakeMesh(none, UvSource::File, 256, 2, "quad.obj"), InputError);
}

TEST(RayBvh, NearestHitMatchesASphere) {
  const Mesh sphere = builtinMesh("sphere");
  const RayBvh bvh(sphere);
  // From the centre every ray leaves at the (tessellated) radius, 1.
  for (glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 2, 3))}) {
    EXPECT_NEAR(bvh.nearestHit(glm::vec3(0), d, 10.0f), 1.0f, 0.01f);
  }
  EXPECT_LT(bvh.nearestHit(glm::vec3(0, 5, 0), glm::vec3(0, 1, 0), 10.0f), 0.0f);  // pointing away: no hit
}

TEST(TextureBake, BaseColourIsThePatternAtTheTexelsPoint) {
  const Material m = loadPreset("calacatta");
  BakeOptions o;
  o.size = 32;
  o.supersample = 1;
  o.thicknessSize = 16;
  o.thicknessRays = 4;
  const TextureSet set = bakeTextureSet(unitQuad(), m, o);
  ASSERT_EQ(set.baseColor.width, 32);
  EXPECT_NEAR(set.coverage, 1.0, 1e-9);
  auto srgb = [](float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; };
  for (int y = 0; y < 32; y += 5)
    for (int x = 0; x < 32; x += 3) {
      // Texel (x, y) is uv ((x + .5) / 32, 1 - (y + .5) / 32), the point (2u - 1, 2v - 1, 0).
      const glm::vec3 p(2.0f * (x + 0.5f) / 32 - 1, 2.0f * (1.0f - (y + 0.5f) / 32) - 1, 0);
      const glm::vec3 c = marbleAlbedo(m, p, glm::vec3(0, 0, 1));
      const glm::u8vec4 t = set.baseColor.at(x, y);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(t[k], std::lround(std::clamp(srgb(c[k]), 0.0f, 1.0f) * 255), 1) << x << "," << y;
    }
  // metallic-roughness: glTF's packing.
  EXPECT_EQ(set.metallicRoughness.at(3, 3).y, std::lround(m.roughness * 255));
  EXPECT_EQ(set.metallicRoughness.at(3, 3).z, std::lround(m.metalness * 255));
}

TEST(TextureBake, SphereThicknessIsFourThirdsOfTheRadius) {
  // A chord at angle t from the inward normal of a sphere of radius R is 2R cos t; over
  // cosine-distributed directions its mean is 2R * 2/3.
  Mesh sphere = builtinMesh("sphere");
  const UvUnwrapResult u = unwrapUvs(sphere, {128, 2, 50.0f});
  BakeOptions o;
  o.size = 128;
  o.supersample = 1;
  o.thicknessSize = 64;
  o.thicknessRays = 64;
  const TextureSet set = bakeTextureSet(u.mesh, Material{}, o);
  EXPECT_NEAR(set.thicknessScale, 4.0f / 3.0f, 0.04f);
  // Every texel, covered or filled, near the maximum: the sphere is equally thick everywhere.
  int low = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) low += set.thickness.at(x, y).x < 240;
  EXPECT_LT(low, 64 * 64 / 50);
}

TEST(TextureBake, SlabThicknessVariesAcrossItsParts) {  // negative control: not uniform
  Mesh slab = builtinMesh("slab");
  const UvUnwrapResult u = unwrapUvs(slab, {64, 2, 50.0f});
  BakeOptions o;
  o.size = 64;
  o.supersample = 1;
  o.thicknessRays = 16;
  const TextureSet set = bakeTextureSet(u.mesh, Material{}, o);
  int lo = 255, hi = 0;
  for (int y = 0; y < set.thickness.height; ++y)
    for (int x = 0; x < set.thickness.width; ++x) {
      lo = std::min<int>(lo, set.thickness.at(x, y).x);
      hi = std::max<int>(hi, set.thickness.at(x, y).x);
    }
  EXPECT_GT(hi - lo, 60);
}

TEST(TextureBake, CancelStopsTheBake) {
  BakeOptions o;
  o.size = 64;
  o.progress = [](double, const char*) { return false; };
  EXPECT_THROW(bakeTextureSet(unitQuad(), Material{}, o), BakeCancelled);
}

namespace {
marble::ExportOutcome finish(marble::BackgroundExport& job) {
  job.wait();
  auto outcome = job.takeOutcome();
  EXPECT_TRUE(outcome.has_value());
  return outcome.value_or(marble::ExportOutcome{});
}
}  // namespace

TEST(BackgroundExport, WritesWhatTheCommandWritesAndReportsOnce) {
  const marble::test::TempDir dir("bg-export");
  Scene scene;
  scene.mesh = "builtin:cube";
  BackgroundExport job;
  ASSERT_TRUE(job.start(scene, {(dir / "cube.glb").string(), 64, false}));
  const ExportOutcome o = finish(job);
  EXPECT_TRUE(o.ok) << o.message;
  EXPECT_TRUE(std::filesystem::exists(dir / "cube.glb"));
  EXPECT_FALSE(job.takeOutcome().has_value());  // once
  ASSERT_TRUE(job.start(scene, {(dir / "set").string(), 64, true}));
  EXPECT_TRUE(finish(job).ok);
  EXPECT_TRUE(std::filesystem::exists(dir / "set" / "material.json"));
  // A bad path: an error, nothing written.
  ASSERT_TRUE(job.start(scene, {(dir / "missing" / "cube.glb").string(), 64, false}));
  const ExportOutcome bad = finish(job);
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.message.find("does not exist"), std::string::npos) << bad.message;
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

TEST(BackgroundExport, CancelWritesNothing) {
  const marble::test::TempDir dir("bg-cancel");
  Scene scene;
  scene.mesh = "builtin:torus";
  BackgroundExport job;
  ASSERT_TRUE(job.start(scene, {(dir / "t.glb").string(), 2048, false}));
  EXPECT_FALSE(job.start(scene, {(dir / "u.glb").string(), 64, false}));  // one at a time
  job.cancel();
  const ExportOutcome o = finish(job);
  EXPECT_TRUE(o.cancelled) << o.message;
  EXPECT_FALSE(std::filesystem::exists(dir / "t.glb"));
}

// STL loading: ASCII, binary, binary that starts with "solid", welding, errors.
#include "fixtures/mesh/mesh_test_support.h"

namespace marble {
namespace {

// Loader tests check structure (welding, indices) on smooth shapes: normals without a crease
// (kNoCreaseDeg); the crease itself is tested in mesh_geometry_test.cpp.

using meshtest::Bytes;
using meshtest::fixture;
using meshtest::loadError;
using meshtest::TempDir;
using ::testing::HasSubstr;

void expectPyramid(const Mesh& m) {
  meshtest::expectWellFormed(m);
  EXPECT_EQ(m.positions.size(), 5u);  // 18 corners welded into 5 vertices
  EXPECT_EQ(m.triangleCount(), 6u);
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_TRUE(meshtest::closedAndConsistent(m));
  // Welded, so normals are smooth: the apex points straight up.
  size_t apex = 0;
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (m.positions[i].y > m.positions[apex].y) apex = i;
  EXPECT_NEAR(m.positions[apex].y, 0.5f, 1e-6f);  // y in [0, 1] before centring
  EXPECT_NEAR(m.normals[apex].y, 1.0f, 1e-5f);
}

// The pyramid's triangles, fanned from the fixture faces.
std::vector<std::array<glm::vec3, 3>> pyramidTriangles() {
  std::vector<std::array<glm::vec3, 3>> tris;
  const auto& v = meshtest::pyramidPositions();
  for (const auto& f : meshtest::pyramidFaces())
    for (size_t k = 1; k + 1 < f.size(); ++k) tris.push_back({v[f[0]], v[f[k]], v[f[k + 1]]});
  return tris;
}

std::string binaryStl(const std::string& header80, const std::vector<std::array<glm::vec3, 3>>& tris) {
  Bytes b;
  std::string header = header80;
  header.resize(80, ' ');
  b.text(header);
  b.put<uint32_t>(static_cast<uint32_t>(tris.size()));
  for (const auto& t : tris) {
    b.put<float>(0).put<float>(0).put<float>(0);  // facet normal: ignored
    for (const glm::vec3& p : t) b.put<float>(p.x).put<float>(p.y).put<float>(p.z);
    b.put<uint16_t>(0);
  }
  return b.data;
}

TEST(MeshStl, Ascii) { expectPyramid(loadMesh(fixture("pyramid_ascii.stl"), meshtest::noCrease())); }

TEST(MeshStl, Binary) {
  TempDir dir;
  expectPyramid(loadMesh(dir.write("pyramid.stl", binaryStl("binary pyramid", pyramidTriangles())), meshtest::noCrease()));
}

TEST(MeshStl, BinaryWhoseHeaderStartsWithSolid) {
  TempDir dir;
  expectPyramid(loadMesh(dir.write("solid.STL", binaryStl("solid pyramid exported by a CAD tool", pyramidTriangles())), meshtest::noCrease()));
}

TEST(MeshStl, WeldTreatsMinusZeroAsZero) {
  TempDir dir;
  auto tris = pyramidTriangles();
  for (auto& t : tris)
    for (glm::vec3& p : t)
      if (p.y == 0.0f && p.x < 0) p.y = -0.0f;
  expectPyramid(loadMesh(dir.write("negzero.stl", binaryStl("x", tris)), meshtest::noCrease()));
}

TEST(MeshStl, TruncatedBinary) {
  TempDir dir;
  std::string full = binaryStl("binary pyramid", pyramidTriangles());
  auto p = dir.write("cut.stl", full.substr(0, full.size() - 30));
  EXPECT_THAT(loadError(p), HasSubstr("cut.stl: byte 80: declares 6 triangles (384 bytes) but the file has only 354 bytes (truncated)"));
  auto q = dir.write("tiny.stl", std::string("\x01\x02\x03", 3));
  EXPECT_THAT(loadError(q), HasSubstr("tiny.stl: header: file is 3 bytes, too short for a binary STL"));
}

TEST(MeshStl, HugeDeclaredCount) {
  TempDir dir;
  Bytes b;
  b.text(std::string(80, 'x')).put<uint32_t>(4000000000u).text(std::string(50, '\0'));
  EXPECT_THAT(loadError(dir.write("huge.stl", b.data)),
              HasSubstr("huge.stl: byte 80: declares 4,000,000,000 triangles; the limit is 50,000,000"));
  Bytes c;
  c.text(std::string(80, 'x')).put<uint32_t>(1000).text(std::string(50, '\0'));
  EXPECT_THAT(loadError(dir.write("liar.stl", c.data)), HasSubstr("declares 1,000 triangles (50,084 bytes)"));
}

TEST(MeshStl, ZeroTriangles) {
  TempDir dir;
  EXPECT_THAT(loadError(dir.write("empty.stl", binaryStl("nothing", {}))), HasSubstr("empty.stl: byte 80: the triangle count is 0"));
  EXPECT_THAT(loadError(dir.write("empty_ascii.stl", "solid nothing\nendsolid nothing\n")),
              HasSubstr("empty_ascii.stl: no triangles"));
}

TEST(MeshStl, NanInBinary) {
  TempDir dir;
  auto tris = pyramidTriangles();
  tris[2][1].z = std::numeric_limits<float>::infinity();
  EXPECT_THAT(loadError(dir.write("inf.stl", binaryStl("x", tris))),
              HasSubstr("inf.stl: byte 208: triangle 2: coordinate is NaN or infinite"));
}

TEST(MeshStl, AsciiErrors) {
  TempDir dir;
  EXPECT_THAT(loadError(dir.write("word.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n")),
              HasSubstr("word.stl: line 4: 'vertex' needs 3 numbers, found 'zero'"));
  EXPECT_THAT(loadError(dir.write("open.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n")),
              HasSubstr("open.stl: line 3: file ends inside 'outer loop' (truncated)"));
  EXPECT_THAT(loadError(dir.write("nan.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 NaN 0\n")),
              HasSubstr("nan.stl: line 5: coordinate is NaN or infinite"));
  EXPECT_THAT(loadError(dir.write("two.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n")),
              HasSubstr("two.stl: line 3: loop has 2 vertices; a facet needs 3"));
}

}  // namespace
}  // namespace marble

// glTF 2.0 loading: .gltf with data: URI and external .bin, .glb, node transforms, accessor checks.
#include <nlohmann/json.hpp>

#include "fixtures/mesh/mesh_test_support.h"

namespace marble {
namespace {

// Loader tests check structure (welding, indices) on smooth shapes: normals without a crease
// (kNoCreaseDeg); the crease itself is tested in mesh_geometry_test.cpp.

using json = nlohmann::json;
using meshtest::bounds;
using meshtest::Bytes;
using meshtest::fixture;
using meshtest::loadError;
using meshtest::TempDir;
using ::testing::HasSubstr;

// A pyramid document: buffer 0 holds positions (accessor 0), normals (1), texcoords (2),
// unsigned short indices (3); the caller adds a "uri" or keeps buffer 0 for a GLB.
struct Doc {
  json gltf;
  std::string bin;
};

Doc pyramidDoc() {
  Bytes b;
  const auto& v = meshtest::pyramidPositions();
  for (const glm::vec3& p : v) b.put<float>(p.x).put<float>(p.y).put<float>(p.z);
  for (const glm::vec3& p : v) {
    glm::vec3 n = glm::normalize(p - glm::vec3(0, 0.3f, 0));
    b.put<float>(n.x).put<float>(n.y).put<float>(n.z);
  }
  for (const glm::vec3& p : v) b.put<float>(p.x * 0.5f + 0.5f).put<float>(p.z * 0.5f + 0.5f);
  size_t indexCount = 0;
  for (const auto& f : meshtest::pyramidFaces())
    for (size_t k = 1; k + 1 < f.size(); ++k) {
      b.put<uint16_t>(static_cast<uint16_t>(f[0])).put<uint16_t>(static_cast<uint16_t>(f[k])).put<uint16_t>(static_cast<uint16_t>(f[k + 1]));
      indexCount += 3;
    }
  while (b.data.size() % 4) b.data.push_back('\0');
  Doc d;
  d.bin = b.data;
  d.gltf = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", {0}}}})},
      {"nodes", json::array({{{"mesh", 0}}})},
      {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                                            {"indices", 3},
                                                            {"mode", 4}}})}}})},
      {"buffers", json::array({{{"byteLength", d.bin.size()}}})},
      {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 60}},
                                   {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 60}},
                                   {{"buffer", 0}, {"byteOffset", 120}, {"byteLength", 40}},
                                   {{"buffer", 0}, {"byteOffset", 160}, {"byteLength", indexCount * 2}}})},
      {"accessors", json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 5}, {"type", "VEC3"}},
                                 {{"bufferView", 1}, {"componentType", 5126}, {"count", 5}, {"type", "VEC3"}},
                                 {{"bufferView", 2}, {"componentType", 5126}, {"count", 5}, {"type", "VEC2"}},
                                 {{"bufferView", 3}, {"componentType", 5123}, {"count", indexCount}, {"type", "SCALAR"}}})},
  };
  return d;
}

std::string glb(const json& gltf, const std::string& bin) {
  std::string text = gltf.dump();
  while (text.size() % 4) text.push_back(' ');
  Bytes b;
  b.text("glTF").put<uint32_t>(2).put<uint32_t>(static_cast<uint32_t>(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size())));
  b.put<uint32_t>(static_cast<uint32_t>(text.size())).put<uint32_t>(0x4E4F534A).text(text);
  if (!bin.empty()) b.put<uint32_t>(static_cast<uint32_t>(bin.size())).put<uint32_t>(0x004E4942).text(bin);
  return b.data;
}

void expectPyramid(const Mesh& m) {
  meshtest::expectWellFormed(m);
  EXPECT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.triangleCount(), 6u);
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_TRUE(meshtest::closedAndConsistent(m));
}

TEST(MeshGltf, EmbeddedDataUriWithNodeHierarchy) {
  // Fixture: a parent node translated by 5, a child scaled (2, 1, 1): 4 x 1 x 2 before normalizing.
  Mesh m = loadMesh(fixture("pyramid_embedded.gltf"), meshtest::noCrease());
  expectPyramid(m);
  auto e = bounds(m).extent();
  EXPECT_NEAR(e.x, 2.0f, 1e-5f);
  EXPECT_NEAR(e.y, 0.5f, 1e-5f);
  EXPECT_NEAR(e.z, 1.0f, 1e-5f);
}

TEST(MeshGltf, ExternalBinWithNormalsAndTexcoords) {
  TempDir dir;
  Doc d = pyramidDoc();
  d.gltf["buffers"][0]["uri"] = "pyramid%20data.bin";
  dir.write("pyramid data.bin", d.bin);
  Mesh m = loadMesh(dir.write("pyramid.gltf", d.gltf.dump(2)));
  expectPyramid(m);
  ASSERT_EQ(m.texcoords.size(), 5u);
  EXPECT_EQ(m.texcoords[4], glm::vec2(0.5f, 0.5f));
  // glTF's v = 0 is the image's top row; the mesh keeps OBJ's convention (v = 0 at the bottom).
  const glm::vec3 p0 = meshtest::pyramidPositions()[0];
  EXPECT_NEAR(m.texcoords[0].x, p0.x * 0.5f + 0.5f, 1e-6f);
  EXPECT_NEAR(m.texcoords[0].y, 1.0f - (p0.z * 0.5f + 0.5f), 1e-6f);
  EXPECT_NEAR(m.normals[4].y, 1.0f, 1e-6f);  // the file's normal, not a computed one
  EXPECT_NEAR(m.normals[0].y, glm::normalize(glm::vec3(-1, -0.3f, -1)).y, 1e-6f);
}

TEST(MeshGltf, GlbBinaryContainer) {
  TempDir dir;
  Doc d = pyramidDoc();
  expectPyramid(loadMesh(dir.write("pyramid.glb", glb(d.gltf, d.bin))));
}

TEST(MeshGltf, RotationAndMirrorTransforms) {
  TempDir dir;
  Doc d = pyramidDoc();
  // 90 degrees about X: the apex (+Y) turns to +Z, and so do the normals.
  const float s = std::sqrt(0.5f);
  d.gltf["nodes"][0]["rotation"] = {s, 0, 0, s};
  Mesh m = loadMesh(dir.write("rotated.glb", glb(d.gltf, d.bin)));
  expectPyramid(m);
  EXPECT_NEAR(m.positions[4].z, 0.5f, 1e-5f);  // z in [0, 1] before centring
  EXPECT_NEAR(m.normals[4].z, 1.0f, 1e-5f);

  // A mirroring matrix (x -> -x) must flip the winding to stay outward.
  Doc mirrored = pyramidDoc();
  mirrored.gltf["nodes"][0]["matrix"] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  expectPyramid(loadMesh(dir.write("mirrored.glb", glb(mirrored.gltf, mirrored.bin))));
}

TEST(MeshGltf, ChildNodesAreInstanced) {
  TempDir dir;
  Doc d = pyramidDoc();
  d.gltf["nodes"] = json::array({{{"children", {1, 2}}}, {{"mesh", 0}, {"translation", {-3, 0, 0}}},
                                 {{"mesh", 0}, {"translation", {3, 0, 0}}}});
  Mesh m = loadMesh(dir.write("two.glb", glb(d.gltf, d.bin)));
  EXPECT_EQ(m.positions.size(), 10u);
  EXPECT_EQ(m.triangleCount(), 12u);
  EXPECT_NEAR(bounds(m).extent().x, 2.0f, 1e-5f);
  EXPECT_NEAR(bounds(m).extent().y, 2.0f / 8.0f, 1e-5f);  // 8 wide, 1 tall
}

TEST(MeshGltf, NonIndexedAndNoNormals) {
  TempDir dir;
  Doc d = pyramidDoc();
  Bytes b;
  const auto& v = meshtest::pyramidPositions();
  for (const auto& f : meshtest::pyramidFaces())
    for (size_t k = 1; k + 1 < f.size(); ++k)
      for (uint32_t i : {f[0], f[k], f[k + 1]}) b.put<float>(v[i].x).put<float>(v[i].y).put<float>(v[i].z);
  d.gltf["buffers"][0]["byteLength"] = b.data.size();
  d.gltf["bufferViews"][0]["byteLength"] = b.data.size();
  d.gltf["accessors"][0]["count"] = 18;
  d.gltf["meshes"][0]["primitives"][0] = {{"attributes", {{"POSITION", 0}}}};
  Mesh m = loadMesh(dir.write("soup.glb", glb(d.gltf, b.data)));
  meshtest::expectWellFormed(m);
  EXPECT_EQ(m.positions.size(), 18u);
  EXPECT_EQ(m.triangleCount(), 6u);
  EXPECT_GT(signedVolume(m), 0.0);
}

TEST(MeshGltf, AccessorPastBufferView) {
  TempDir dir;
  Doc d = pyramidDoc();
  d.gltf["accessors"][0]["count"] = 6;
  EXPECT_THAT(loadError(dir.write("long.glb", glb(d.gltf, d.bin))),
              HasSubstr("long.glb: accessor 0: 6 elements from offset 0 need 72 bytes but bufferView 0 has 60"));
  Doc e = pyramidDoc();
  e.gltf["bufferViews"][3]["byteLength"] = 4000;
  EXPECT_THAT(loadError(dir.write("view.glb", glb(e.gltf, e.bin))), HasSubstr("view.glb: bufferView 3: bytes 160..4160 run past the end of buffer 0"));
  Doc f = pyramidDoc();
  f.gltf["buffers"][0]["byteLength"] = 5000;
  EXPECT_THAT(loadError(dir.write("buffer.glb", glb(f.gltf, f.bin))),
              HasSubstr("buffer.glb: buffer 0: declares 5,000 bytes but the GLB binary chunk holds 196"));
}

TEST(MeshGltf, IndexOutOfRange) {
  TempDir dir;
  Doc d = pyramidDoc();
  d.bin[160] = 9;  // first index
  EXPECT_THAT(loadError(dir.write("index.glb", glb(d.gltf, d.bin))),
              HasSubstr("index.glb: accessor 3: index 9 (element 0) is out of range (POSITION has 5)"));
}

TEST(MeshGltf, NanPosition) {
  TempDir dir;
  Doc d = pyramidDoc();
  float nan = std::nanf("");
  std::memcpy(d.bin.data() + 12 * 2 + 4, &nan, 4);
  EXPECT_THAT(loadError(dir.write("nan.glb", glb(d.gltf, d.bin))),
              HasSubstr("nan.glb: mesh 0 primitive 0: POSITION element 2 is NaN or infinite"));
}

TEST(MeshGltf, TruncatedGlb) {
  TempDir dir;
  Doc d = pyramidDoc();
  std::string full = glb(d.gltf, d.bin);
  EXPECT_THAT(loadError(dir.write("cut.glb", full.substr(0, full.size() - 50))), HasSubstr("cut.glb: header: declares "));
  EXPECT_THAT(loadError(dir.write("tiny.glb", "glTF")), HasSubstr("tiny.glb: header: file is 4 bytes, too short for GLB"));
  EXPECT_THAT(loadError(dir.write("magic.glb", std::string(64, 'x'))), HasSubstr("magic.glb: header: not a GLB file"));
}

TEST(MeshGltf, BadJsonAndUnsupportedFeatures) {
  TempDir dir;
  EXPECT_THAT(loadError(dir.write("bad.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"meshes\": [ }")),
              HasSubstr("bad.gltf: byte "));
  EXPECT_THAT(loadError(dir.write("bad.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"meshes\": [ }")), HasSubstr("invalid JSON"));
  Doc d = pyramidDoc();
  d.gltf["asset"]["version"] = "1.0";
  EXPECT_THAT(loadError(dir.write("v1.glb", glb(d.gltf, d.bin))), HasSubstr("v1.glb: asset: glTF version \"1.0\" is not supported"));
  Doc e = pyramidDoc();
  e.gltf["accessors"][0]["sparse"] = json::object();
  EXPECT_THAT(loadError(dir.write("sparse.glb", glb(e.gltf, e.bin))), HasSubstr("sparse.glb: accessor 0: sparse accessors are not supported"));
  Doc f = pyramidDoc();
  f.gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  EXPECT_THAT(loadError(dir.write("draco.glb", glb(f.gltf, f.bin))), HasSubstr("requires extension \"KHR_draco_mesh_compression\""));
  Doc g = pyramidDoc();
  g.gltf["buffers"][0]["uri"] = "missing.bin";
  EXPECT_THAT(loadError(dir.write("missing.gltf", g.gltf.dump())), HasSubstr("missing.gltf: buffer 0: cannot read 'missing.bin'"));
  Doc h = pyramidDoc();
  h.gltf["nodes"] = json::array({{{"children", {1}}}, {{"children", {0}}}});
  h.gltf["scenes"][0]["nodes"] = {0};
  EXPECT_THAT(loadError(dir.write("cycle.glb", glb(h.gltf, h.bin))), HasSubstr("cycle.glb: node 0: the node hierarchy has a cycle"));
  Doc i = pyramidDoc();
  i.gltf["meshes"][0]["primitives"][0]["mode"] = 1;  // lines only
  EXPECT_THAT(loadError(dir.write("lines.glb", glb(i.gltf, i.bin))), HasSubstr("lines.glb: scene: no triangles"));
}

}  // namespace
}  // namespace marble

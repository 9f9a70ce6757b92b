// PLY loading: ascii and both binary byte orders, property types, skipped elements, errors.
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
  EXPECT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.triangleCount(), 6u);  // the base quad is two triangles
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_TRUE(meshtest::closedAndConsistent(m));
}

TEST(MeshPly, AsciiSkipsUnknownElementsAndProperties) {
  Mesh m = loadMesh(fixture("pyramid_ascii.ply"), meshtest::noCrease());
  expectPyramid(m);
  ASSERT_EQ(m.texcoords.size(), 5u);
  EXPECT_EQ(m.texcoords[4], glm::vec2(0.5f, 0.5f));
  // No normals in the file: smooth ones, the apex's pointing straight up.
  EXPECT_NEAR(m.normals[4].y, 1.0f, 1e-5f);
}

// The pyramid in binary, with a mix of property types, an extra element before the faces and a
// list property after the indices.
std::string binaryPyramid(bool bigEndian, bool withNormals) {
  Bytes b;
  b.bigEndian = bigEndian;
  b.text("ply\nformat ");
  b.text(bigEndian ? "binary_big_endian" : "binary_little_endian");
  b.text(" 1.0\ncomment made by mesh_ply_test\n");
  b.text("element vertex 5\nproperty double x\nproperty float32 y\nproperty float z\nproperty uchar alpha\n");
  if (withNormals) b.text("property float nx\nproperty float ny\nproperty float nz\n");
  b.text("property list uint8 int16 junk\n");
  b.text("element material 2\nproperty int16 id\nproperty list ushort char name\n");
  b.text("element face 5\nproperty int8 flag\nproperty list ushort uint vertex_index\nproperty list uchar double extra\n");
  b.text("end_header\n");
  const auto& v = meshtest::pyramidPositions();
  for (size_t i = 0; i < v.size(); ++i) {
    b.put<double>(v[i].x).put<float>(v[i].y).put<float>(v[i].z).put<uint8_t>(200);
    if (withNormals) {
      glm::vec3 n = glm::normalize(v[i] - glm::vec3(0, 0.3f, 0));
      b.put<float>(n.x).put<float>(n.y).put<float>(n.z);
    }
    b.put<uint8_t>(2).put<int16_t>(-1).put<int16_t>(300);
  }
  b.put<int16_t>(1).put<uint16_t>(3).put<int8_t>('a').put<int8_t>('b').put<int8_t>('c');
  b.put<int16_t>(2).put<uint16_t>(0);
  for (const auto& f : meshtest::pyramidFaces()) {
    b.put<int8_t>(-5).put<uint16_t>(static_cast<uint16_t>(f.size()));
    for (uint32_t i : f) b.put<uint32_t>(i);
    b.put<uint8_t>(1).put<double>(3.5);
  }
  return b.data;
}

TEST(MeshPly, BinaryLittleEndian) {
  TempDir dir;
  Mesh m = loadMesh(dir.write("le.ply", binaryPyramid(false, false)), meshtest::noCrease());
  expectPyramid(m);
  EXPECT_TRUE(m.texcoords.empty());
}

TEST(MeshPly, BinaryBigEndianWithNormals) {
  TempDir dir;
  Mesh m = loadMesh(dir.write("be.ply", binaryPyramid(true, true)));
  expectPyramid(m);
  // File normals are kept (normalized): vertex 4 is the apex, its normal straight up.
  EXPECT_NEAR(m.normals[4].y, 1.0f, 1e-5f);
  EXPECT_NEAR(m.normals[0].x, glm::normalize(glm::vec3(-1, -0.3f, -1)).x, 1e-5f);
}

TEST(MeshPly, TruncatedBinaryNamesTheByte) {
  TempDir dir;
  std::string full = binaryPyramid(false, false);
  // Cut inside the last face: the header's minimum-size check passes, reading runs out.
  auto p = dir.write("cut.ply", full.substr(0, full.size() - 12));
  EXPECT_THAT(loadError(p), HasSubstr("cut.ply: byte "));
  EXPECT_THAT(loadError(p), HasSubstr("file ends inside face 4 of 5 (truncated)"));
}

TEST(MeshPly, DeclaredCountLargerThanFileIsCaughtBeforeAllocating) {
  TempDir dir;
  auto p = dir.write("liar.ply",
                     "ply\nformat binary_little_endian 1.0\nelement vertex 40000000\nproperty float x\n"
                     "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "end_header\n" + std::string(100, '\0'));
  EXPECT_THAT(loadError(p), HasSubstr("liar.ply: header line 3: declares 40,000,000 vertex elements (at least 480,000,000 bytes) "
                                      "but only 100 bytes follow the header (truncated file?)"));
  auto q = dir.write("liar_ascii.ply",
                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 1000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_THAT(loadError(q), HasSubstr("liar_ascii.ply: header line 7: declares 1,000 face elements"));
}

TEST(MeshPly, HardCapOnVertices) {
  TempDir dir;
  auto p = dir.write("huge.ply",
                     "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                     "property float y\nproperty float z\nend_header\n");
  EXPECT_THAT(loadError(p), HasSubstr("huge.ply: header line 3: declares 4,000,000,000 vertices; the limit is 50,000,000"));
}

TEST(MeshPly, IndexOutOfRange) {
  TempDir dir;
  auto p = dir.write("range.ply",
                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_THAT(loadError(p), HasSubstr("range.ply: line 13: face 0: vertex index 3 is out of range (the file has 3 vertices)"));
  auto q = dir.write("negative.ply",
                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n");
  EXPECT_THAT(loadError(q), HasSubstr("vertex index -1 is out of range"));
}

TEST(MeshPly, BadHeaders) {
  TempDir dir;
  EXPECT_THAT(loadError(dir.write("magic.ply", "plyx\nformat ascii 1.0\nend_header\n")),
              HasSubstr("magic.ply: header: not a PLY file"));
  EXPECT_THAT(loadError(dir.write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\n")),
              HasSubstr("noend.ply: header: no 'end_header' line"));
  EXPECT_THAT(loadError(dir.write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n")),
              HasSubstr("type.ply: header line 4: unknown property type 'float128'"));
  EXPECT_THAT(loadError(dir.write("noxyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n")),
              HasSubstr("noxyz.ply: header line 3: the vertex element needs properties x, y and z"));
  EXPECT_THAT(loadError(dir.write("cloud.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                  "property float z\nend_header\n0 0 0\n")),
              HasSubstr("cloud.ply: header: no face element"));
}

TEST(MeshPly, NanInBinary) {
  TempDir dir;
  Bytes b;
  b.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
  b.put<float>(0).put<float>(0).put<float>(0);
  b.put<float>(1).put<float>(std::nanf("")).put<float>(0);
  b.put<float>(0).put<float>(1).put<float>(0);
  b.put<uint8_t>(3).put<int32_t>(0).put<int32_t>(1).put<int32_t>(2);
  EXPECT_THAT(loadError(dir.write("nan.ply", b.data)), HasSubstr("nan.ply: byte "));
  EXPECT_THAT(loadError(dir.write("nan.ply", b.data)), HasSubstr("vertex 1: coordinate is NaN or infinite"));
}

}  // namespace
}  // namespace marble

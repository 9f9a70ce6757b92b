// Bad input every format shares: missing file, directory, empty file, garbage, unknown extension.
#include "fixtures/mesh/mesh_test_support.h"

namespace marble {
namespace {

using meshtest::loadError;
using meshtest::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(MeshErrors, MissingFile) {
  TempDir dir;
  auto p = dir.path() / "nope.obj";
  EXPECT_EQ(loadError(p), p.string() + ": file not found");
}

TEST(MeshErrors, Directory) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "folder.obj");
  EXPECT_EQ(loadError(dir.path() / "folder.obj"), (dir.path() / "folder.obj").string() + ": is a directory, not a mesh file");
}

TEST(MeshErrors, EmptyFileInEveryFormat) {
  TempDir dir;
  for (const char* name : {"e.obj", "e.ply", "e.stl", "e.gltf", "e.glb"}) {
    auto p = dir.write(name, "");
    EXPECT_EQ(loadError(p), p.string() + ": file is empty") << name;
  }
}

TEST(MeshErrors, UnknownExtension) {
  TempDir dir;
  auto p = dir.write("model.fbx", "Kaydara FBX Binary");
  EXPECT_EQ(loadError(p), p.string() + ": unknown mesh format '.fbx' (expected .obj, .ply, .stl, .gltf or .glb)");
  auto q = dir.write("model", "v 0 0 0");
  EXPECT_THAT(loadError(q), HasSubstr("unknown mesh format '(no extension)'"));
}

TEST(MeshErrors, ExtensionIsCaseInsensitive) {
  TempDir dir;
  auto p = dir.write("UPPER.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(loadMesh(p).triangleCount(), 1u);
}

TEST(MeshErrors, BinaryGarbageInEveryFormat) {
  TempDir dir;
  std::string garbage;
  std::mt19937 rng(1234);
  for (int i = 0; i < 1000; ++i) garbage.push_back(static_cast<char>(rng() & 0xFF));
  garbage[10] = '\0';
  for (const char* name : {"g.obj", "g.ply", "g.stl", "g.gltf", "g.glb"}) {
    auto p = dir.write(name, garbage);
    std::string message = loadError(p);
    EXPECT_THAT(message, StartsWith(p.string() + ": ")) << name;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find("WRONG EXCEPTION"), std::string::npos) << message;
    EXPECT_EQ(message.find("NO ERROR"), std::string::npos) << name;
  }
  EXPECT_THAT(loadError(dir.path() / "g.obj"), HasSubstr("g.obj: byte 10: binary data (NUL byte) in what should be a text OBJ file"));
  EXPECT_THAT(loadError(dir.path() / "g.ply"), HasSubstr("g.ply: header: not a PLY file"));
  EXPECT_THAT(loadError(dir.path() / "g.glb"), HasSubstr("g.glb: header: not a GLB file"));
}

TEST(MeshErrors, GarbageWithoutNulBytes) {
  TempDir dir;
  std::string garbage;
  std::mt19937 rng(99);
  for (int i = 0; i < 500; ++i) garbage.push_back(static_cast<char>(0x80 + (rng() & 0x7F)));
  EXPECT_THAT(loadError(dir.write("g.obj", garbage)), HasSubstr("g.obj: line 1: unexpected binary data"));
}

TEST(MeshErrors, AllPointsEqualIsABoundsError) {
  TempDir dir;
  auto p = dir.write("point.obj", "v 1 2 3\nv 1 2 3\nv 1 2 3\nf 1 2 3\n");
  EXPECT_EQ(loadError(p), p.string() + ": bounds: all vertices are at the same point (zero extent); cannot normalize");
}

TEST(MeshErrors, MessagesAreOneLine) {
  TempDir dir;
  // A sample across the loaders: every message is a single line starting with the file name.
  std::vector<std::filesystem::path> files = {
      dir.write("a.obj", "v 0 0 0\nf 1 2 3\n"),
      dir.write("b.ply", "ply\nformat ascii 1.0\nelement vertex x\n"),
      dir.write("c.stl", "solid\nfacet\nouter loop\nvertex 1 2\n"),
      dir.write("d.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": []}"),
      dir.write("e.gltf", "[1, 2, 3]"),
  };
  for (const auto& f : files) {
    std::string message = loadError(f);
    EXPECT_THAT(message, StartsWith(f.string() + ": "));
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find("WRONG EXCEPTION"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace marble

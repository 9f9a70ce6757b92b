// Issue 18's classes at the library level: bounded work and depth in the parsers and the glTF
// node walk, what a glTF may pull in, duplicate triangles, and messages that never echo a
// whole value. The CLI side (one line, exit code, no file touched) is tests/bad_inputs_cli.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "error_text.h"
#include "marble/core/error.h"
#include "marble/core/json_limits.h"
#include "marble/mesh/duplicate_triangles.h"
#include "marble/mesh/mesh.h"
#include "marble/scene/material_io.h"
#include "marble/scene/scene.h"

using namespace marble;
using marble::test::errorOf;
namespace fs = std::filesystem;

namespace {

struct HostileInputs : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("marble-hostile-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir / "models"); }
  void TearDown() override { fs::remove_all(dir); }
  fs::path put(const std::string& name, const std::string& bytes) {
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
};

// One triangle: three float positions and the indices 0 1 2 (base64 of 42 bytes).
const std::string kTriangleBuffer =
    "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA";

std::string gltfWithNodes(const std::string& nodes, const std::string& scenes, const std::string& bufferUri = kTriangleBuffer) {
  return R"({"asset":{"version":"2.0"},"buffers":[{"uri":")" + bufferUri + R"(","byteLength":42}],)"
         R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
         R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"nodes":)" + nodes + scenes + "}";
}

}  // namespace

// ---- glTF node hierarchy ----------------------------------------------------------------------

TEST_F(HostileInputs, AGltfDagIsAClearErrorNotTwoToTheFortyWalks) {
  // 41 nodes, each listing the next one twice: a recursive walk visits the last one 2^40 times.
  std::string nodes = "[";
  for (int i = 0; i < 40; ++i) nodes += "{\"children\":[" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
  nodes += "{\"mesh\":0}]";
  const auto p = put("dag.gltf", gltfWithNodes(nodes, R"(,"scenes":[{"nodes":[0]}])"));
  EXPECT_EQ(errorOf([&] { loadMesh(p); }),
            p.string() + ": node 40: is reached twice (from node 39 and from node 39); glTF requires each node to have at most one parent");
}

TEST_F(HostileInputs, AGltfNodeWithTwoParentsOrACycleIsAnError) {
  const auto two = put("two.gltf", gltfWithNodes(R"([{"children":[2]},{"children":[2]},{"mesh":0}])", ""));
  EXPECT_NE(errorOf([&] { loadMesh(two); }).find("node 2: is reached twice (from node 0 and from node 1)"), std::string::npos);
  const auto cycle = put("cycle.gltf", gltfWithNodes(R"([{"children":[1],"mesh":0},{"children":[0]}])", R"(,"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(errorOf([&] { loadMesh(cycle); }).find("node 0: the node hierarchy has a cycle"), std::string::npos);
  // Negative control: a proper tree with the mesh on two leaves loads both instances.
  const auto tree = put("tree.gltf", gltfWithNodes(
      R"([{"children":[1,2]},{"mesh":0,"translation":[5,0,0]},{"mesh":0}])", R"(,"scenes":[{"nodes":[0]}])"));
  EXPECT_EQ(loadMesh(tree).triangleCount(), 2u);
}

TEST_F(HostileInputs, AGltfNodeChain100000DeepLoadsWithoutRecursion) {
  // A recursive walk overflowed the stack at 20,000. The chain is flat in the JSON.
  constexpr int kDepth = 100'000;
  std::string nodes = "[";
  nodes.reserve(kDepth * 20);
  for (int i = 0; i + 1 < kDepth; ++i) nodes += "{\"children\":[" + std::to_string(i + 1) + "]},";
  nodes += "{\"mesh\":0}]";
  const auto p = put("chain.gltf", gltfWithNodes(nodes, R"(,"scenes":[{"nodes":[0]}])"));
  EXPECT_EQ(loadMesh(p).triangleCount(), 1u);
}

// ---- JSON nesting and values in messages ------------------------------------------------------

TEST_F(HostileInputs, DeeplyNestedJsonIsRefusedBeforeParsing) {
  const std::string deep = std::string(100'000, '[') + std::string(100'000, ']');
  const auto scene = put("deep.json", "{\"camera\": " + deep + "}");
  std::vector<std::string> warnings;
  EXPECT_EQ(errorOf([&] { loadScene(scene, warnings); }),
            scene.string() + ": line 1, column 75: JSON nested deeper than 64 levels (arrays and objects); no scene, preset or glTF needs that many");
  const auto preset = put("deep_preset.json", "{\"turb_power\": " + deep + "}");
  EXPECT_NE(errorOf([&] { loadPreset(preset.string()); }).find("JSON nested deeper than 64 levels"), std::string::npos);
  const auto gltf = put("deep.gltf", R"({"asset":{"version":"2.0"},"extras":)" + deep + "}");
  EXPECT_NE(errorOf([&] { loadMesh(gltf); }).find("JSON nested deeper than 64 levels"), std::string::npos);
  // Negative control: brackets inside strings do not count, and 64 levels are allowed.
  const auto ok = put("ok.json", "{\"camera\": {\"fov_y_deg\": 40}, \"x\": [\"" + std::string(1000, '[') + "\", " +
                                 std::string(62, '[') + std::string(62, ']') + "]}");
  EXPECT_NO_THROW(loadScene(ok, warnings));
  EXPECT_NO_THROW(checkJsonNesting(std::string(64, '[') + std::string(64, ']'), "f"));
  EXPECT_THROW(checkJsonNesting(std::string(65, '[') + std::string(65, ']'), "f"), InputError);
}

TEST_F(HostileInputs, AHugeValueIsNeverEchoedWhole) {
  const std::string huge(10'000'000, 'A');
  const auto scene = put("huge.json", "{\"camera\": {\"fov_y_deg\": \"" + huge + "\"}}");
  std::vector<std::string> warnings;
  const std::string e = errorOf([&] { loadScene(scene, warnings); });
  EXPECT_LT(e.size(), 300u) << e.substr(0, 300);
  EXPECT_NE(e.find("camera.fov_y_deg: expected a number, got string \"AAAA"), std::string::npos) << e.substr(0, 300);
  // An array of a million numbers where one number belongs.
  std::string big = "[";
  for (int i = 0; i < 1'000'000; ++i) big += "1,";
  big += "1]";
  const auto preset = put("big_preset.json", "{\"turb_power\": " + big + "}");
  const std::string p = errorOf([&] { loadPreset(preset.string()); });
  EXPECT_LT(p.size(), 300u) << p.substr(0, 300);
  EXPECT_NE(p.find("got array [1,1,1"), std::string::npos) << p;
}

TEST_F(HostileInputs, APresetThatIsASymlinkLoopSaysSo) {
  fs::create_symlink("b.json", dir / "a.json");
  fs::create_symlink("a.json", dir / "b.json");
  EXPECT_EQ(errorOf([&] { loadPreset((dir / "a.json").string()); }),
            (dir / "a.json").string() + ": too many levels of symbolic links (a symbolic link loop?)");
}

TEST_F(HostileInputs, AFileThatIsNotJsonIsNotEchoed) {
  const auto p = put("credentials.json", "root:$6$secretHASH:19000:0:99999:7:::\n");
  const std::string e = errorOf([&] { loadPreset(p.string()); });
  EXPECT_NE(e.find(p.string() + ": invalid JSON: parse error at line 1, column 1"), std::string::npos) << e;
  EXPECT_EQ(e.find("secret"), std::string::npos) << e;
  EXPECT_EQ(e.find("root"), std::string::npos) << e;
}

// ---- what a glTF may pull in ------------------------------------------------------------------

TEST_F(HostileInputs, GltfBuffersOutsideTheirFolderAreRefusedUnlessAllowed) {
  std::ofstream(dir / "outside.bin", std::ios::binary)
      << std::string("\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\x01\0\x02\0", 42);
  const auto up = put("models/up.gltf", gltfWithNodes("[{\"mesh\":0}]", "", "../outside.bin"));
  const std::string e = errorOf([&] { loadMesh(up); });
  EXPECT_EQ(e, up.string() + ": buffer 0: 'uri' \"../outside.bin\" is outside the glTF's folder; marble reads buffers only "
                             "from there unless told otherwise (--allow-outside, or \"allow_outside\": true in a scene)");
  const auto abs = put("models/abs.gltf", gltfWithNodes("[{\"mesh\":0}]", "", "/etc/passwd"));
  EXPECT_NE(errorOf([&] { loadMesh(abs); }).find("is outside the glTF's folder"), std::string::npos);
  const auto deep = put("models/deep.gltf", gltfWithNodes("[{\"mesh\":0}]", "", "../../../../etc/passwd"));
  EXPECT_NE(errorOf([&] { loadMesh(deep); }).find("is outside the glTF's folder"), std::string::npos);
  // A symbolic link inside the folder that points out of it counts as outside.
  fs::create_symlink("../outside.bin", dir / "models" / "link.bin");
  const auto link = put("models/link.gltf", gltfWithNodes("[{\"mesh\":0}]", "", "link.bin"));
  EXPECT_NE(errorOf([&] { loadMesh(link); }).find("is outside the glTF's folder"), std::string::npos);
  // Allowed: the file loads.
  MeshLoadOptions allow;
  allow.allowOutside = true;
  EXPECT_EQ(loadMesh(up, allow).triangleCount(), 1u);
  EXPECT_EQ(loadMesh(link, allow).triangleCount(), 1u);
  // Negative control: a buffer beside the glTF loads without permission.
  fs::copy_file(dir / "outside.bin", dir / "models" / "inside.bin");
  EXPECT_EQ(loadMesh(put("models/in.gltf", gltfWithNodes("[{\"mesh\":0}]", "", "inside.bin"))).triangleCount(), 1u);
}

TEST_F(HostileInputs, ASceneCanAllowOutsideBuffersAndNamesItselfInErrors) {
  std::ofstream(dir / "outside.bin", std::ios::binary)
      << std::string("\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\x01\0\x02\0", 42);
  put("models/up.gltf", gltfWithNodes("[{\"mesh\":0}]", "", "../outside.bin"));
  std::vector<std::string> warnings;
  const auto refused = put("refused.json", R"({"mesh": "models/up.gltf"})");
  const Scene a = loadScene(refused, warnings);
  EXPECT_NE(errorOf([&] { loadSceneMesh(a); }).find(refused.string() + ": mesh: " + (dir / "models/up.gltf").string() +
                                                    ": buffer 0: 'uri' \"../outside.bin\" is outside"),
            std::string::npos)
      << errorOf([&] { loadSceneMesh(a); });
  const auto allowed = put("allowed.json", R"({"mesh": "models/up.gltf", "allow_outside": true})");
  const Scene b = loadScene(allowed, warnings);
  EXPECT_TRUE(b.allow_outside);
  EXPECT_EQ(loadSceneMesh(b).triangleCount(), 1u);
  const auto wrongType = put("wrong.json", R"({"allow_outside": "yes"})");
  EXPECT_EQ(errorOf([&] { loadScene(wrongType, warnings); }), wrongType.string() + ": allow_outside: expected true or false, got string \"yes\"");
}

TEST_F(HostileInputs, AnErrorInAMeshASceneNamesCarriesTheScenesName) {
  put("models/two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
  const auto scene = put("s.json", R"({"mesh": "models/two.obj"})");
  std::vector<std::string> warnings;
  const Scene s = loadScene(scene, warnings);
  EXPECT_EQ(errorOf([&] { loadSceneMesh(s); }),
            scene.string() + ": mesh: " + (dir / "models/two.obj").string() + ": line 4: face has 2 vertices; a face needs at least 3");
  // Negative control: the same mesh named on the command line (no scene file) is not blamed on one.
  Scene direct;
  direct.mesh = (dir / "models/two.obj").string();
  EXPECT_EQ(errorOf([&] { loadSceneMesh(direct); }).rfind((dir / "models/two.obj").string(), 0), 0u);
}

// ---- duplicate triangles ----------------------------------------------------------------------

TEST(DuplicateTriangles, AHundredThousandCopiesOfOneTriangleLoadAsOne) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (int i = 0; i < 100'000; ++i) m.indices.insert(m.indices.end(), {0, 1, 2});
  EXPECT_EQ(removeDuplicateTriangles(m), 99'999u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(DuplicateTriangles, RotationsAreTheSameTriangleTheReversedWindingIsNot) {
  Mesh m;
  // Two copies of the corner positions under different indices (as STL/OBJ files may have).
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0f, 0, 0}};
  m.indices = {0, 1, 2,   // kept
               4, 5, 3,   // rotation, by other indices: dropped
               2, 0, 1,   // rotation: dropped
               0, 2, 1,   // reversed winding: kept
               6, 1, 2};  // -0 is +0: dropped
  EXPECT_EQ(removeDuplicateTriangles(m), 3u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 1}));
}

TEST(DuplicateTriangles, ARepeatedCornerDoesNotHideARotation) {
  // (a, b, a), (a, a, b) and (b, a, a) are one triangle (zero area, but drawn as any other); the
  // lowest-corner-first key once made (a, b, a) and (a, a, b) two. (b, a, b) is another triangle.
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}};
  m.indices = {0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0, 1};
  EXPECT_EQ(removeDuplicateTriangles(m), 2u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 0, 1, 0, 1}));
}

TEST(DuplicateTriangles, DistinctTrianglesAreAllKeptInOrder) {
  // Negative control: a strip of 1,000 distinct triangles loses nothing.
  Mesh m;
  for (int i = 0; i < 1002; ++i) m.positions.push_back({static_cast<float>(i), static_cast<float>(i % 2), 0.0f});
  for (uint32_t i = 0; i < 1000; ++i) m.indices.insert(m.indices.end(), {i, i + 1, i + 2});
  const auto before = m.indices;
  EXPECT_EQ(removeDuplicateTriangles(m), 0u);
  EXPECT_EQ(m.indices, before);
}

TEST_F(HostileInputs, LoadMeshDropsDuplicatesWithOneWarning) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  for (int i = 0; i < 100'000; ++i) obj += "f 1 2 3\n";
  obj += "f 1 2 4\n";
  const auto p = put("copies.obj", obj);
  std::vector<std::string> warnings;
  MeshLoadOptions options;
  options.warnings = &warnings;
  EXPECT_EQ(loadMesh(p, options).triangleCount(), 2u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], p.string() + ": dropped 99,999 duplicate triangles (the same three corners as an earlier triangle, same winding)");
}

// ---- STL: sizes from the header ---------------------------------------------------------------

TEST_F(HostileInputs, ASparseStlIsJudgedByItsHeader) {
  // 3.9 GB, all zeros but a header: count 0. Sparse, so it takes no disk.
  const fs::path p = dir / "sparse.stl";
  { std::ofstream(p, std::ios::binary) << std::string(84, '\0'); }
  fs::resize_file(p, 3'900'000'000ull);
  EXPECT_EQ(errorOf([&] { loadMesh(p); }), p.string() + ": byte 80: the triangle count is 0: no triangles");
  // One triangle and 3.9 GB of padding: only the 134 bytes it declares are read.
  std::string one(80, 'h');
  one += std::string("\x01\0\0\0", 4) + std::string(12, '\0');
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) one.append(reinterpret_cast<const char*>(&v), 4);
  one += std::string(2, '\0');
  const fs::path q = dir / "padded.stl";
  { std::ofstream(q, std::ios::binary) << one; }
  fs::resize_file(q, 3'900'000'000ull);
  EXPECT_EQ(loadMesh(q).triangleCount(), 1u);
}

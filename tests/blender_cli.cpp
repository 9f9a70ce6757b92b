// Blender imports marble's .glb with its own glTF importer and the bridge (tools/blender_marble.py)
// rebuilds the Principled material from the design the file carries. Skipped with a message where
// Blender is not installed (it is not in tools/deps.txt: a large optional tool).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cli_support.h"

TEST(Blender, ImportsTheExportAndBuildsTheMaterial) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) GTEST_SKIP() << "Blender is not installed (apt-get install blender python3-numpy)";
  namespace fs = std::filesystem;
  const auto dir = marble::test::tempDir("blender");
  std::ofstream(dir / "scene.json") << R"({"mesh": "builtin:cube", "material": {"preset": "carrara"}})";
  const auto e = marble::test::runMarble("export " + (dir / "scene.json").string() + " --size 64 -o " + (dir / "m.glb").string());
  ASSERT_EQ(e.exitCode, 0) << e.output;
  const std::string cmd = "blender -b --factory-startup -P " + (fs::path(MARBLE_SOURCE_DIR) / "tools" / "blender_marble.py").string() +
                          " -- " + (dir / "m.glb").string() + " --save " + (dir / "m.blend").string() + " > " +
                          (dir / "log.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream log(dir / "log.txt");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("blender_marble: imported 1 mesh(es), 12 triangles, material 'carrara'"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(dir / "m.blend")) << text;
}

// tools/cycles_reference.py renders a veined stone through the bridge: `marble export` bakes the
// veins, Blender's importer reads the .glb, the texture becomes the Principled's colours. (The
// flat path, for marble scenes with one colour, is what docs/quality.md's references use.)
TEST(Blender, CyclesReferenceKeepsTheVeins) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) GTEST_SKIP() << "Blender is not installed (apt-get install blender python3-numpy)";
  namespace fs = std::filesystem;
  const auto dir = marble::test::tempDir("cycles-veins");
  std::ofstream(dir / "scene.json") << R"({"mesh": "builtin:sphere", "material": {"preset": "carrara"}, "render": {"environment": "none"}})";
  const std::string cmd = "nice -n 19 blender -b --factory-startup -P " +
                          (fs::path(MARBLE_SOURCE_DIR) / "tools" / "cycles_reference.py").string() + " -- " +
                          (dir / "scene.json").string() + " " + (dir / "ref.exr").string() +
                          " --samples 1 --width 24 --height 24 --bake-size 64 --marble " MARBLE_BINARY " > " +
                          (dir / "log.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream log(dir / "log.txt");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("cycles_reference: veins baked by marble export (64x64) onto 1 mesh(es)"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(dir / "ref.exr")) << text;
}

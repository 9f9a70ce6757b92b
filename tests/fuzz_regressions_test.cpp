// Every input a fuzzer (tests/fuzz/) ever crashed on, kept in tests/fixtures/regressions/ and
// loaded again here, with the node-graph and nesting inputs of issue 18 (the DAG glTF, values
// nested 4,000 deep): each must now end in a one-line InputError, nothing else. The file name says
// which reader: scene-*.json -> loadScene, preset-*.json -> loadPreset, *.hdr -> readHdr, anything
// else -> loadMesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <typeinfo>
#include <vector>

#include "marble/core/error.h"
#include "marble/core/hdr_image.h"
#include "marble/mesh/mesh.h"
#include "marble/scene/material_io.h"
#include "marble/scene/scene.h"

namespace {

namespace fs = std::filesystem;

void load(const fs::path& p) {
  const std::string name = p.filename().string();
  std::vector<std::string> warnings;
  if (name.rfind("scene-", 0) == 0) marble::loadScene(p, warnings);
  else if (name.rfind("preset-", 0) == 0) marble::loadPreset(p.string(), &warnings);
  else if (p.extension() == ".hdr") marble::readHdr(p);
  else marble::loadMesh(p);
}

TEST(FuzzRegressions, EveryFoundCrashIsNowAnInputError) {
  const fs::path dir = fs::path(MARBLE_TEST_FIXTURES) / "regressions";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    const fs::path& p = entry.path();
    try {
      load(p);
      ADD_FAILURE() << p.filename() << ": loaded without an error";
    } catch (const marble::InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << p.filename() << ": message is not one line: " << what;
      EXPECT_NE(what.find(p.filename().string()), std::string::npos) << p.filename() << ": message does not name the file: " << what;
    } catch (const std::exception& e) {
      ADD_FAILURE() << p.filename() << ": escaped as " << typeid(e).name() << ": " << e.what();
    }
  }
  EXPECT_GT(files, 0) << "no files in " << dir;
}

}  // namespace

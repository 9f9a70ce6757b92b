// `marble params` and the `--set` warning for keys the chosen render mode does not read.
#include <gtest/gtest.h>

#include "cli_support.h"

using namespace marble::test;

namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(CliParams, ListsEveryGroupWithDefaultsAndModes) {
  const auto r = runMarble("params");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("Scattering (marble)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("k_schlick"), std::string::npos);
  EXPECT_NE(r.output.find("default 0.12; read by marble"), std::string::npos) << r.output;  // roughness
}

TEST(CliParams, SetOfAKeyTheModeIgnoresWarnsOnceAndStillRenders) {
  const auto dir = tempDir("params-warning");
  const std::string out = (dir / "x.png").string();
  const auto r = runMarble("render -o " + out + " --width 32 --height 32 --mode marble --set k_schlick=0.9 --set roughness=0.3");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(count(r.output, "warning:"), 1u) << r.output;
  EXPECT_NE(r.output.find("--set k_schlick: the 'marble' mode does not read k_schlick (used by: paper)"), std::string::npos)
      << r.output;
  // A key the mode reads: no warning (negative control of the line above).
  const auto quiet = runMarble("render -o " + out + " --width 32 --height 32 --mode paper --set k_schlick=0.9");
  EXPECT_EQ(quiet.exitCode, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("warning:"), std::string::npos) << quiet.output;
}

TEST(CliParams, UpdateDocOfAFileWithoutMarkersExitsTwo) {
  const auto dir = tempDir("params-doc");
  const auto r = runMarble("params --update-doc " + (dir / "missing.md").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("missing.md"), std::string::npos) << r.output;
}

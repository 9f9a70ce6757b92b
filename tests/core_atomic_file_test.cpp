#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"

using namespace marble;

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
size_t entries(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}
struct AtomicFile : ::testing::Test {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("marble-atomic-" + std::to_string(::getpid()));
  void SetUp() override { std::filesystem::create_directories(dir); }
  void TearDown() override {
    setAtomicWriteFaultHookForTesting(nullptr);
    std::filesystem::remove_all(dir);
  }
};
}  // namespace

TEST_F(AtomicFile, WritesAndReplaces) {
  writeFileAtomically(dir / "a.txt", "first");
  EXPECT_EQ(slurp(dir / "a.txt"), "first");
  writeFileAtomically(dir / "a.txt", "second");
  EXPECT_EQ(slurp(dir / "a.txt"), "second");
  EXPECT_EQ(entries(dir), 1u);
}

TEST_F(AtomicFile, FailureMidWriteLeavesOldFileAndNoTemporary) {
  writeFileAtomically(dir / "preset.json", "{\"old\": true}");
  setAtomicWriteFaultHookForTesting([] { throw std::runtime_error("simulated disk full"); });
  EXPECT_THROW(writeFileAtomically(dir / "preset.json", "{\"new\": tr"), InputError);
  EXPECT_EQ(slurp(dir / "preset.json"), "{\"old\": true}");
  EXPECT_EQ(entries(dir), 1u) << "no temporary may be left behind";
}

TEST_F(AtomicFile, UnwritableFolderIsAnInputErrorNamingThePath) {
  try {
    writeFileAtomically(dir / "no-such-folder" / "x.png", "x");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-folder/x.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(writeFileAtomically(dir, "x"), InputError);
}

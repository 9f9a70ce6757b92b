// The test suite's scratch folders (tests/temp_dir.h): each one fresh, and gone with everything
// in it when its owner goes, so a run leaves nothing in the temporary folder.
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using marble::test::TempDir;

TEST(TempDirTest, RemovedWithWhatItHoldsWhenItGoes) {
  fs::path kept;
  {
    const TempDir dir("tempdir-test");
    kept = dir.path();
    ASSERT_TRUE(fs::is_directory(kept));
    dir.write("a.txt", "x");
    fs::create_directories(dir / "sub" / "deeper");
    dir.write("sub/deeper/b.bin", std::string(1000, '\0'));
    EXPECT_TRUE(fs::exists(dir / "sub" / "deeper" / "b.bin"));
    EXPECT_EQ(kept.filename().string().rfind("marble-test-tempdir-test-", 0), 0u) << kept;
  }
  EXPECT_FALSE(fs::exists(kept)) << kept;
}

TEST(TempDirTest, TheSameNameTwiceGivesTwoFreshFolders) {
  const TempDir a("tempdir-twice"), b("tempdir-twice");
  EXPECT_NE(a.path(), b.path());
  EXPECT_TRUE(fs::is_empty(a.path()));
  EXPECT_TRUE(fs::is_empty(b.path()));
}

TEST(TempDirTest, AFolderTheTestRemovedItselfIsNoError) {
  const TempDir dir("tempdir-gone");
  fs::remove_all(dir.path());
  SUCCEED();  // the destructor's remove_all must not throw on a missing folder
}

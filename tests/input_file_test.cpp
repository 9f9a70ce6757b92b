// The one way marble opens a file it reads (core/input_file.h): regular files only, true
// messages for everything else, and never a block on a FIFO.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "marble/core/error.h"
#include "marble/core/input_file.h"

using namespace marble;
namespace fs = std::filesystem;

namespace {

std::string openError(const fs::path& p) {
  try {
    InputFile f(p, p.string(), "a mesh file");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(opened)";
}

struct InputFileTest : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("marble-input-file-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }
};

}  // namespace

TEST_F(InputFileTest, ARegularFileIsReadWholeOrInPart) {
  std::ofstream(dir / "a.obj") << "v 0 0 0\n";
  InputFile f(dir / "a.obj", "a.obj");
  EXPECT_EQ(f.size(), 8u);
  EXPECT_EQ(f.readPrefix(3), "v 0");
  EXPECT_EQ(f.readPrefix(100), "v 0 0 0\n");
  EXPECT_EQ(f.readAll(8), "v 0 0 0\n");
  try {
    (void)f.readAll(7);
    FAIL() << "a file over the limit must be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "a.obj: file is 8 bytes; the limit is 7");
  }
}

TEST_F(InputFileTest, ReadLargeGivesTheBytesReadGives) {
  // 40 MB of bytes that differ from place to place (so a range read at the wrong offset is seen):
  // several ranges read by threads at once where there are cores; and the small file above, whole
  // and in part; and the limit.
  std::string big(40u << 20, '\0');
  for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>((i * 2654435761u) >> 13);
  std::ofstream(dir / "big.bin", std::ios::binary).write(big.data(), static_cast<std::streamsize>(big.size()));
  InputFile f(dir / "big.bin", "big.bin");
  const FileBytes whole = f.readLarge(f.size(), f.size());
  EXPECT_TRUE(whole.view() == big);
  EXPECT_TRUE(f.readLarge(UINT64_MAX, f.size()).view() == big);
  EXPECT_TRUE(f.readLarge(20'000'001, f.size()).view() == std::string_view(big).substr(0, 20'000'001));
  std::ofstream(dir / "a.obj") << "v 0 0 0\n";
  InputFile small(dir / "a.obj", "a.obj");
  EXPECT_EQ(small.readLarge(3, 8).view(), "v 0");
  EXPECT_EQ(small.readLarge(100, 8).view(), "v 0 0 0\n");
  EXPECT_THROW((void)small.readLarge(8, 7), InputError);
}

TEST_F(InputFileTest, AFifoIsRefusedAtOnceInsteadOfBlocking) {
  ASSERT_EQ(::mkfifo((dir / "pipe.obj").c_str(), 0644), 0);
  // Opening a FIFO for reading blocks until a writer comes; a hang here fails by the test's timeout.
  EXPECT_EQ(openError(dir / "pipe.obj"),
            (dir / "pipe.obj").string() + ": is a named pipe (FIFO), not a regular file; marble reads only regular files");
}

TEST_F(InputFileTest, DevicesAreRefusedWithWhatTheyAre) {
  EXPECT_EQ(openError("/dev/zero"), "/dev/zero: is a character device, not a regular file; marble reads only regular files");
  EXPECT_EQ(openError("/dev/null"), "/dev/null: is a character device, not a regular file; marble reads only regular files");
}

TEST_F(InputFileTest, SymlinkLoopsAndDanglingLinksSayWhatTheyAre) {
  fs::create_symlink("loop2.obj", dir / "loop1.obj");
  fs::create_symlink("loop1.obj", dir / "loop2.obj");
  EXPECT_EQ(openError(dir / "loop1.obj"), (dir / "loop1.obj").string() + ": too many levels of symbolic links (a symbolic link loop?)");
  fs::create_symlink("gone.obj", dir / "dangling.obj");
  EXPECT_EQ(openError(dir / "dangling.obj"), (dir / "dangling.obj").string() + ": is a symbolic link to a file that does not exist");
  // Negative control: a link to a real file opens.
  std::ofstream(dir / "real.obj") << "x";
  fs::create_symlink("real.obj", dir / "good.obj");
  EXPECT_EQ(openError(dir / "good.obj"), "(opened)");
}

TEST_F(InputFileTest, MissingFilesFoldersAndPathsThroughFiles) {
  EXPECT_EQ(openError(dir / "missing.obj"), (dir / "missing.obj").string() + ": file not found");
  EXPECT_EQ(openError(dir), dir.string() + ": is a directory, not a mesh file");
  std::ofstream(dir / "afile") << "x";
  EXPECT_EQ(openError(dir / "afile" / "x.obj"),
            (dir / "afile" / "x.obj").string() + ": file not found (a part of the path is a file, not a folder)");
}

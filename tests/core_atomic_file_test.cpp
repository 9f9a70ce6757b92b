#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/core/live_temporaries.h"

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

// ---- issue 18: the routine's rules, one test each -------------------------------------------

namespace {
mode_t modeOf(const std::filesystem::path& p) {
  struct stat st {};
  ::stat(p.c_str(), &st);
  return st.st_mode & 07777;
}
std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST_F(AtomicFile, ALongTargetNameGetsATemporaryThatFitsNameMax) {
  const std::string name = std::string(246, 'n') + ".png";  // 250 characters, a valid name
  writeFileAtomically(dir / name, "ok");
  EXPECT_EQ(slurp(dir / name), "ok");
  EXPECT_EQ(entries(dir), 1u);
  // Negative control: a name past NAME_MAX is refused by the system, and says so.
  EXPECT_NE(messageOf([&] { writeFileAtomically(dir / std::string(300, 'n'), "x"); }).find("cannot write"), std::string::npos);
}

TEST_F(AtomicFile, AReplacedFileKeepsItsMode) {
  writeFileAtomically(dir / "secret.json", "old");
  ::chmod((dir / "secret.json").c_str(), 0600);
  writeFileAtomically(dir / "secret.json", "new");
  EXPECT_EQ(modeOf(dir / "secret.json"), 0600u);
  ::chmod((dir / "secret.json").c_str(), 0755);
  writeFileAtomically(dir / "secret.json", "newer");
  EXPECT_EQ(modeOf(dir / "secret.json"), 0755u);
  EXPECT_EQ(slurp(dir / "secret.json"), "newer");
}

TEST_F(AtomicFile, ANewFileGetsTheUmasksMode) {
  const mode_t old = ::umask(027);
  writeFileAtomically(dir / "fresh.png", "x");
  ::umask(old);
  EXPECT_EQ(modeOf(dir / "fresh.png"), 0640u);
}

TEST_F(AtomicFile, DevicesAndFifosAreRefusedNotReplaced) {
  const std::string null = messageOf([] { writeFileAtomically("/dev/null", "x"); });
  EXPECT_EQ(null, "/dev/null: is a character device, not a regular file; refusing to replace it");
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null must still be the device";
  ASSERT_EQ(::mkfifo((dir / "pipe.png").c_str(), 0644), 0);
  EXPECT_NE(messageOf([&] { writeFileAtomically(dir / "pipe.png", "x"); }).find("is a named pipe (FIFO), not a regular file"),
            std::string::npos);
  ASSERT_EQ(::lstat((dir / "pipe.png").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(entries(dir), 1u) << "no temporary may be left behind";
}

TEST_F(AtomicFile, ASymlinkTargetReplacesTheFileItPointsTo) {
  std::filesystem::create_directories(dir / "real");
  writeFileAtomically(dir / "real" / "out.png", "old");
  std::filesystem::create_symlink("real/out.png", dir / "link.png");
  writeFileAtomically(dir / "link.png", "new");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.png"));
  EXPECT_EQ(slurp(dir / "real" / "out.png"), "new");
  EXPECT_EQ(entries(dir / "real"), 1u);
  // A link to nothing is not written through.
  std::filesystem::create_symlink("nowhere/x.png", dir / "dangling.png");
  EXPECT_NE(messageOf([&] { writeFileAtomically(dir / "dangling.png", "x"); }).find("symbolic link to nothing"), std::string::npos);
}

TEST_F(AtomicFile, TemporariesAreUniqueSoConcurrentWritersNeverBlend) {
  // Two sets staging the same target at once get two temporaries; the later commit wins whole.
  AtomicFileSet a, b;
  a.add(dir / "x.exr", std::string(1000, 'a'));
  b.add(dir / "x.exr", std::string(10, 'b'));
  EXPECT_EQ(entries(dir), 2u);
  a.commit();
  b.commit();
  EXPECT_EQ(slurp(dir / "x.exr"), std::string(10, 'b'));
  EXPECT_EQ(entries(dir), 1u);
}

TEST_F(AtomicFile, ASetIsWrittenWholeOrNotAtAll) {
  writeFileAtomically(dir / "a.png", "old a");
  writeFileAtomically(dir / "b.exr", "old b");
  int calls = 0;
  setAtomicWriteFaultHookForTesting([&] {
    if (++calls == 2) throw std::runtime_error("simulated disk full");
  });
  {
    AtomicFileSet set;
    set.add(dir / "a.png", "new a");
    EXPECT_THROW(set.add(dir / "b.exr", "new b"), InputError);
  }  // not committed: the first temporary goes too
  EXPECT_EQ(slurp(dir / "a.png"), "old a");
  EXPECT_EQ(slurp(dir / "b.exr"), "old b");
  EXPECT_EQ(entries(dir), 2u);
  setAtomicWriteFaultHookForTesting(nullptr);
  AtomicFileSet set;
  set.add(dir / "a.png", "new a");
  set.add(dir / "b.exr", "new b");
  EXPECT_EQ(slurp(dir / "a.png"), "old a") << "nothing is in place before commit()";
  set.commit();
  EXPECT_EQ(slurp(dir / "a.png"), "new a");
  EXPECT_EQ(slurp(dir / "b.exr"), "new b");
  EXPECT_EQ(liveTemporaryCount(), 0);
}

// SIGTERM (and SIGINT) while a temporary exists: the handler removes it and the process still
// ends by the signal. The fault hook raises the signal at the worst moment: written, not renamed.
TEST_F(AtomicFile, ASignalMidWriteRemovesTheTemporary) {
  for (int sig : {SIGTERM, SIGINT}) {
    writeFileAtomically(dir / "render.png", "old");
    EXPECT_EXIT(
        {
          setAtomicWriteFaultHookForTesting([sig] { ::raise(sig); });
          writeFileAtomically(dir / "render.png", "new");
          std::_Exit(0);  // not reached
        },
        ::testing::KilledBySignal(sig), "");
    EXPECT_EQ(slurp(dir / "render.png"), "old");
    EXPECT_EQ(entries(dir), 1u) << "signal " << sig << ": the temporary was left behind";
  }
}

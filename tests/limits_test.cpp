// A file whose header lies about its size is caught before anything of that size is allocated
// (issue 7, "Limits"). Each load runs in a forked child whose address space is capped a little
// above what the process already uses: had the loader trusted the header and reserved gigabytes,
// the child would die of bad_alloc (or ASan's out-of-memory report) instead of answering with the
// one-line InputError checked here. (OBJ is absent on purpose: it has no header that declares sizes.)
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <string>

#include "marble/core/error.h"
#include "marble/core/hdr_image.h"
#include "marble/mesh/mesh.h"

namespace {

namespace fs = std::filesystem;

// What the child reports through its exit code.
enum ChildResult { kExpectedError = 0, kWrongMessage = 3, kNoError = 4, kOutOfMemory = 5, kOtherException = 6 };

class LimitsTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("marble-limits-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

  // Loads `path` in a child limited to its current address space + 256 MiB and expects an
  // InputError whose message contains `expected`.
  static void expectCaughtBeforeAllocating(const fs::path& path, const std::string& expected,
                                           void (*load)(const fs::path&) = [](const fs::path& p) { marble::loadMesh(p); }) {
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0) << std::strerror(errno);
    if (pid == 0) ::_exit(loadInCappedChild(path, expected, load));
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status)) << path.filename() << ": the child died (signal " << WTERMSIG(status)
                                   << "); an allocation sized by the header is the likely cause";
    EXPECT_EQ(WEXITSTATUS(status), kExpectedError) << path.filename() << ": see the child's message above";
  }

private:
  static int loadInCappedChild(const fs::path& path, const std::string& expected, void (*load)(const fs::path&)) {
    // statm's first field: the whole address space in pages (ASan's shadow included).
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t cap = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + (256u << 20);
    const rlimit limit{cap, cap};
    if (::setrlimit(RLIMIT_AS, &limit) != 0) return kOtherException;
    try {
      load(path);
      std::cerr << path.filename() << ": loaded without an error\n";
      return kNoError;
    } catch (const marble::InputError& e) {
      if (std::string(e.what()).find(expected) != std::string::npos) return kExpectedError;
      std::cerr << "message: " << e.what() << "\nexpected it to contain: " << expected << "\n";
      return kWrongMessage;
    } catch (const std::bad_alloc&) {
      std::cerr << path.filename() << ": bad_alloc: the loader allocated what the header declared\n";
      return kOutOfMemory;
    } catch (const std::exception& e) {
      std::cerr << path.filename() << ": " << e.what() << "\n";
      return kOtherException;
    }
  }

  fs::path dir_;
};

std::string u32le(uint32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[static_cast<size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
  return s;
}

std::string plyHeader(const std::string& format, const std::string& vertices, const std::string& faces) {
  return "ply\nformat " + format + " 1.0\nelement vertex " + vertices +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

// A minimal valid GLB around `json` (padded to 4 bytes), with no BIN chunk.
std::string glb(std::string json, uint32_t jsonLengthField = 0) {
  while (json.size() % 4) json += ' ';
  const uint32_t jsonLength = jsonLengthField ? jsonLengthField : static_cast<uint32_t>(json.size());
  const std::string body = u32le(jsonLength) + u32le(0x4E4F534Au) + json;
  return "glTF" + u32le(2) + u32le(static_cast<uint32_t>(12 + body.size())) + body;
}

TEST_F(LimitsTest, PlyDeclaringTwoToThe31VerticesIsRejectedByTheCap) {
  const std::string n = "2147483648";
  expectCaughtBeforeAllocating(write("binary.ply", plyHeader("binary_little_endian", n, "1") + std::string(64, '\0')),
                               "header line 3: declares 2,147,483,648 vertices; the limit is 50,000,000");
  expectCaughtBeforeAllocating(write("ascii.ply", plyHeader("ascii", n, "1") + "0 0 0\n"),
                               "declares 2,147,483,648 vertices; the limit is 50,000,000");
}

TEST_F(LimitsTest, PlyDeclaringTwoToThe31FacesIsRejectedByTheCap) {
  expectCaughtBeforeAllocating(write("faces.ply", plyHeader("binary_little_endian", "3", "2147483648") + std::string(64, '\0')),
                               "declares 2,147,483,648 faces; the limit is 50,000,000");
}

TEST_F(LimitsTest, PlyUnderTheCapButLongerThanTheFileIsCaughtByItsSize) {
  // 49 million vertices and faces are allowed, but cannot fit in the 64 bytes that follow.
  expectCaughtBeforeAllocating(write("lying.ply", plyHeader("binary_little_endian", "49000000", "49000000") + std::string(64, '\0')),
                               "declares 49,000,000 vertex elements (at least 588,000,000 bytes) but only 64 bytes follow the header");
}

TEST_F(LimitsTest, BinaryStlDeclaringABillionTrianglesIsRejectedByTheCap) {
  expectCaughtBeforeAllocating(write("billion.stl", std::string(80, 'x') + u32le(1'000'000'000) + std::string(50, '\0')),
                               "byte 80: declares 1,000,000,000 triangles; the limit is 50,000,000");
}

TEST_F(LimitsTest, BinaryStlUnderTheCapButLongerThanTheFileIsCaughtByItsSize) {
  expectCaughtBeforeAllocating(write("lying.stl", std::string(80, 'x') + u32le(49'000'000) + std::string(50, '\0')),
                               "declares 49,000,000 triangles (2,450,000,084 bytes) but the file has only 134 bytes (truncated)");
}

TEST_F(LimitsTest, GlbDeclaringAHugeTotalLength) {
  std::string file = glb(R"({"asset":{"version":"2.0"}})");
  file.replace(8, 4, u32le(0xFFFFFFFFu));
  expectCaughtBeforeAllocating(write("length.glb", file), "header: declares 4,294,967,295 bytes but the file has");
}

TEST_F(LimitsTest, GlbWithAHugeJsonChunkLength) {
  expectCaughtBeforeAllocating(write("json.glb", glb(R"({"asset":{"version":"2.0"}})", 0xFFFFFFF0u)),
                               "byte 12: JSON chunk of 4,294,967,280 bytes runs past the end of the file (truncated)");
}

TEST_F(LimitsTest, GlbWithAHugeBinChunkLength) {
  std::string file = glb(R"({"asset":{"version":"2.0"}})");
  const std::string bin = u32le(0xFFFFFF00u) + u32le(0x004E4942u) + std::string(16, '\0');
  file += bin;
  file.replace(8, 4, u32le(static_cast<uint32_t>(file.size())));
  expectCaughtBeforeAllocating(write("bin.glb", file), "BIN chunk of 4,294,967,040 bytes runs past the end of the file (truncated)");
}

TEST_F(LimitsTest, HdrDeclaringTheLargestMapInAFewBytes) {
  // 8192 x 4096 is within the limit (384 MiB as floats, over this child's cap); the file cannot
  // hold it, flat or run-length encoded, which is noticed before stb_image allocates.
  const auto header = [](const std::string& size) { return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n" + size + "\n"; };
  const auto read = [](const fs::path& p) { marble::readHdr(p); };
  expectCaughtBeforeAllocating(write("flat.hdr", header("-Y 4096 +X 8192") + std::string(64, '\x80')),
                               "truncated: 8192 x 4096 flat RGBE pixels need 134,217,728 bytes but 64 follow the header", read);
  expectCaughtBeforeAllocating(write("rle.hdr", header("-Y 4096 +X 8192") + std::string("\x02\x02\x20\x00", 4) + std::string(60, '\x81')),
                               "run-length encoded pixels need at least 2,146,304 bytes", read);
  expectCaughtBeforeAllocating(write("huge.hdr", header("-Y 1000000 +X 2000000") + std::string(64, '\x80')),
                               "image is 2,000,000 x 1,000,000 pixels; the limit is 8,192 per side", read);
}

TEST_F(LimitsTest, GltfAccessorCountsBeyondTheirBufferOrTheCap) {
  // Three vertices' worth of data; the accessor claims far more.
  const auto doc = [](const std::string& count) {
    return R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" + std::string(48, 'A') + R"("}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"type":"VEC3","count":)" + count + "}]}";
  };
  expectCaughtBeforeAllocating(write("count.gltf", doc("49000000")), "49,000,000 elements from offset 0 need 588,000,000 bytes but bufferView 0 has 36");
  expectCaughtBeforeAllocating(write("cap.gltf", doc("4000000000")), "count 4,000,000,000 is over the limit of 50,000,000");
}

}  // namespace

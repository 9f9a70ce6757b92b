// PageBuffer (core/page_buffer.h): resizing keeps the bytes it had (within the mapping and across
// an mremap that may move it), moves hand the pages over, and a released mapping is taken again
// by the next buffer (what lets a later load's file and records reuse pages faulted in already),
// unless it is larger than the heap keeps free.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <utility>

#include "marble/core/allocator_tuning.h"
#include "marble/core/page_buffer.h"

namespace marble {
namespace {

void fill(char* p, size_t n, uint32_t seed) {
  for (size_t i = 0; i < n; ++i) p[i] = static_cast<char>((i * 2654435761u + seed) >> 13);
}
bool holds(const char* p, size_t n, uint32_t seed) {
  for (size_t i = 0; i < n; ++i)
    if (p[i] != static_cast<char>((i * 2654435761u + seed) >> 13)) return false;
  return true;
}

TEST(PageBuffer, ResizeKeepsTheBytesItHad) {
  releaseKeptPages();
  PageBuffer b(10'000);
  ASSERT_EQ(b.size(), 10'000u);
  fill(b.data(), b.size(), 1);
  b.resize(10'100);  // within the mapping's last page
  EXPECT_TRUE(holds(b.data(), 10'000, 1));
  b.resize(40u << 20);  // far larger: a new mapping (mremap), the bytes carried over
  ASSERT_EQ(b.size(), 40u << 20);
  EXPECT_TRUE(holds(b.data(), 10'000, 1));
  fill(b.data(), b.size(), 2);
  b.resize(3'000);  // smaller: the front kept
  EXPECT_TRUE(holds(b.data(), 3'000, 2));
  b.resize(50u << 20);
  EXPECT_TRUE(holds(b.data(), 3'000, 2));
  b.resize(0);
  EXPECT_EQ(b.size(), 0u);
  releaseKeptPages();
}

TEST(PageBuffer, MovesHandThePagesOver) {
  PageBuffer a(5'000);
  fill(a.data(), a.size(), 3);
  const char* at = a.data();
  PageBuffer b = std::move(a);
  EXPECT_EQ(a.data(), nullptr);
  EXPECT_EQ(a.size(), 0u);
  EXPECT_EQ(b.data(), at);
  PageBuffer c(100);
  c = std::move(b);
  EXPECT_EQ(c.data(), at);
  EXPECT_TRUE(holds(c.data(), 5'000, 3));
}

TEST(PageBuffer, AReleasedMappingIsTakenByTheNextBuffer) {
  releaseKeptPages();
  const char* at = nullptr;
  {
    PageBuffer a(8u << 20);
    fill(a.data(), a.size(), 4);
    at = a.data();
  }
  PageBuffer b(6u << 20);  // fits the kept mapping: the same pages, no new mapping
  EXPECT_EQ(b.data(), at);
  PageBuffer c(1u << 20);  // none kept now: a mapping of its own
  EXPECT_NE(c.data(), at);
  releaseKeptPages();
}

TEST(PageBuffer, AMappingOverTheHeapsKeptSizeIsGivenBack) {
  releaseKeptPages();
  const char* at = nullptr;
  {
    PageBuffer a(static_cast<size_t>(kTrimThresholdBytes) + 4096);  // mapped, never touched: no memory used
    at = a.data();
  }
  PageBuffer b(1u << 20);
  EXPECT_NE(b.data(), at);
  releaseKeptPages();
}

}  // namespace
}  // namespace marble

// The loaders' short-decimal path (parseShortDecimal in mesh_internal.h) gives std::from_chars's
// float and double, bit for bit, and stops at the same character, wherever it answers: checked on 2 million
// decimals of the forms mesh files hold (printf's %g and %f of floats of every magnitude, and
// random digit strings with a point, a sign and a following character), with a negative control.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <type_traits>

#include "marble/mesh/mesh_internal.h"

namespace marble {
namespace {

// Both readers on `text`; false (and a message) when the short path answered differently.
template <class T>
bool agreesAs(const std::string& text, size_t& shortPathUsed) {
  using Bits = std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>;
  const char* b = text.data();
  const char* e = b + text.size();
  T fast = 0;
  const char* after = mesh_detail::parseShortDecimal(b, e, fast);
  if (!after) return true;  // from_chars reads it
  ++shortPathUsed;
  T reference = 0;
  const auto [ptr, ec] = std::from_chars(b, e, reference);
  if (ec != std::errc{} || ptr != after || std::bit_cast<Bits>(reference) != std::bit_cast<Bits>(fast)) {
    ADD_FAILURE() << "'" << text << "': short path " << fast << " (" << (after - b) << " chars), from_chars " << reference
                  << " (" << (ptr - b) << " chars)";
    return false;
  }
  return true;
}
bool agrees(const std::string& text, size_t& shortPathUsed) {
  size_t asDouble = 0;
  return agreesAs<float>(text, shortPathUsed) && agreesAs<double>(text, asDouble);
}

std::string randomDecimal(std::mt19937& rng) {
  std::uniform_int_distribution<int> pick(0, 5);
  char buf[64];
  const float f = std::ldexp(std::uniform_real_distribution<float>(-1.0f, 1.0f)(rng),
                             std::uniform_int_distribution<int>(-30, 30)(rng));
  switch (pick(rng)) {
    case 0: std::snprintf(buf, sizeof buf, "%.7g", static_cast<double>(f)); break;
    case 1: std::snprintf(buf, sizeof buf, "%.*g", 1 + static_cast<int>(rng() % 9), static_cast<double>(f)); break;
    case 2: std::snprintf(buf, sizeof buf, "%.*f", static_cast<int>(rng() % 11), static_cast<double>(f)); break;
    case 3: std::snprintf(buf, sizeof buf, "%.6f", static_cast<double>(f)); break;
    default: {  // digits with a point somewhere (or none), a sign, leading zeros
      std::string s = rng() % 3 == 0 ? "-" : "";
      const int n = 1 + static_cast<int>(rng() % 17);
      const int point = static_cast<int>(rng() % (n + 2)) - 1;
      for (int i = 0; i < n; ++i) {
        if (i == point) s += '.';
        s += static_cast<char>('0' + rng() % 10);
      }
      if (point == n) s += '.';
      return s + " /\ne.5x"[rng() % 8];
    }
  }
  return std::string(buf) + " /\ne.5x"[rng() % 8];
}

TEST(MeshParseFloat, ShortDecimalsEqualFromChars) {
  std::mt19937 rng(7);
  size_t used = 0, total = 0;
  for (int i = 0; i < 2'000'000; ++i, ++total)
    if (!agrees(randomDecimal(rng), used)) break;
  // The extremes of the path: 2^24 and 2^24 + 1, ten fraction digits, nine digits, -0, "5.", ".5".
  for (const char* s : {"16777216", "16777217", "1677721.6", "0.0000000001", "-0.0000016777", "123456789", "-0",
                        "-0.0", "5.", ".5", "-.5", "0.1", "0.3", "1.0000001", "3.4028235", "0.99999994", "16777215.",
                        "1e5", "1.5e-3", "00000000001", "nan", "-", ".", "999999999999999", "0.000000000000001",
                        "-123456789.012345", "9007199254740993", "0.1000000000000000055511151231257827"}) {
    ++total;
    EXPECT_TRUE(agrees(s, used)) << s;
  }
  // A good share took the short path (47 % of these forms: the comparison is not vacuous).
  EXPECT_GT(used, total / 3) << used << " of " << total;
}

// leadingDigits (the OBJ face indices' word-at-a-time digits) against a loop over the bytes: 2
// million 8-byte strings of digits and the bytes beside them in ASCII ('/' and ':'), separators,
// and bytes with the top bit set (0xB0-0xB9 are digits but for that bit), every digit count.
TEST(MeshParseDigits, LeadingDigitsEqualTheLoop) {
  std::mt19937 rng(20);
  const char others[] = {'/', ':', ' ', '\n', '\r', '\t', '-', '.', 'e', '\0', '\x7f', '\xb0', '\xb9', '\xff', '\xca'};
  for (int trial = 0; trial < 2'000'000; ++trial) {
    char bytes[8];
    const int digitsFirst = static_cast<int>(rng() % 9);  // the length the loop should find
    for (int i = 0; i < 8; ++i)
      bytes[i] = i < digitsFirst || rng() % 3 == 0 ? static_cast<char>('0' + rng() % 10) : others[rng() % sizeof(others)];
    int expectedCount = 0;
    uint64_t expectedValue = 0;
    while (expectedCount < 8 && bytes[expectedCount] >= '0' && bytes[expectedCount] <= '9')
      expectedValue = expectedValue * 10 + static_cast<uint64_t>(bytes[expectedCount++] - '0');
    uint64_t value = 12345;
    const int count = mesh_detail::leadingDigits(bytes, value);
    ASSERT_EQ(count, expectedCount) << std::string(bytes, 8);
    if (count < 8) {
      ASSERT_EQ(value, expectedValue) << std::string(bytes, 8);
    }
  }
}

// Negative control: multiplying by the reciprocal power of ten instead of dividing by the power
// (both inexact for 10^-k) gives another float for some of the same decimals, and the comparison
// sees it.
TEST(MeshParseFloat, ComparisonNoticesAnInexactReading) {
  std::mt19937 rng(7);
  int differing = 0;
  for (int i = 0; i < 200'000 && differing == 0; ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.7f", static_cast<double>(std::uniform_real_distribution<float>(0.0f, 1.0f)(rng)));
    uint32_t m = 0;
    int fraction = -1;
    for (const char* c = buf; *c; ++c) {
      if (*c == '.') fraction = 0;
      else {
        m = m * 10 + static_cast<uint32_t>(*c - '0');
        if (fraction >= 0) ++fraction;
      }
    }
    const float inexact = static_cast<float>(m) * (1.0f / 1e7f);
    float exact = 0.0f;
    std::from_chars(buf, buf + std::strlen(buf), exact);
    differing += std::bit_cast<uint32_t>(inexact) != std::bit_cast<uint32_t>(exact);
  }
  EXPECT_GT(differing, 0);
}

}  // namespace
}  // namespace marble

// The one message sanitizer (core/message_text.h) and InputError's use of it.
#include <gtest/gtest.h>

#include <string>

#include "marble/core/error.h"
#include "marble/core/message_text.h"

using namespace marble;

TEST(MessageText, EscapesLineBreaksTerminalEscapesAndNul) {
  EXPECT_EQ(printable("a\nb\rc\td"), "a\\nb\\rc\\td");
  EXPECT_EQ(printable("\x1b[31mred\x1b[0m"), "\\x1b[31mred\\x1b[0m");
  EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\0b");
  EXPECT_EQ(printable("\x7f\x01"), "\\x7f\\x01");
  // C1 controls as UTF-8 (U+009B is the 8-bit CSI) and invalid UTF-8 bytes are escaped too.
  EXPECT_EQ(printable("\xc2\x9b" "2J"), "\\xc2\\x9b2J");
  EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");
  // Negative control: ordinary text, a backslash and well-formed UTF-8 pass unchanged.
  EXPECT_EQ(printable("W\xc3\xbcrfel.obj: line 3: a\\b"), "W\xc3\xbcrfel.obj: line 3: a\\b");
}

TEST(MessageText, CutsLongValuesAndSaysHowLongTheyWere) {
  const std::string big(10'000'000, 'x');
  const std::string out = printable(big, 100);
  EXPECT_LE(out.size(), 100u);
  EXPECT_NE(out.find("(10000000 bytes in all)"), std::string::npos) << out;
  EXPECT_EQ(printable(std::string(100, 'x'), 100), std::string(100, 'x')) << "exactly at the limit: not cut";
  // A cut never splits an escape or a UTF-8 character.
  const std::string escapes = printable(std::string(200, '\n'), 50);
  EXPECT_EQ(escapes.substr(0, escapes.find(' ')).size() % 2, 0u) << escapes;
  const std::string utf8 = printable(std::string(60, '\xc3') + std::string(1, '\xbc'), 20);
  EXPECT_EQ(printable(utf8, 1000), utf8) << "the result is itself printable";
}

TEST(MessageText, IsIdempotent) {
  for (const std::string& s : {std::string("a\nb"), std::string(5000, 'q'), std::string("\x1b\0\xff", 3)}) {
    const std::string once = printable(s);
    EXPECT_EQ(printable(once), once);
  }
}

TEST(MessageText, InputErrorIsOneLineWholeAndBounded) {
  const InputError e(std::string("evil\nname\0.obj", 14), "line 3", "unexpected '\x1b]0;pwned\x07'");
  EXPECT_EQ(std::string(e.what()), "evil\\nname\\0.obj: line 3: unexpected '\\x1b]0;pwned\\x07'");
  const InputError big("file.json", "key", "got string \"" + std::string(10'000'000, 'a') + "\"");
  EXPECT_LE(std::string(big.what()).size(), kMessagePartLimit + kMessageLineLimit + 10);
  // A nested message (a scene naming a mesh) keeps the inner message whole when it is short.
  const InputError inner("model.obj", "line 3", "face has 2 vertices");
  const InputError outer("scene.json", "mesh", inner.what());
  EXPECT_EQ(std::string(outer.what()), "scene.json: mesh: model.obj: line 3: face has 2 vertices");
}

TEST(MessageText, QuotedExcerptIsShortAndEscaped) {
  EXPECT_EQ(quotedExcerpt("root:x:0:0\nroot", 6), "\"root:x...\"");
  EXPECT_EQ(quotedExcerpt("ab", 6), "\"ab\"");
}

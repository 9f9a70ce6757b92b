// The OBJ loader's parallel path (chunks scanned on several threads, joined in file order) gives the
// sequential scan's mesh, and on bad input its exact error message, wherever the chunk boundaries
// fall: every input below is loaded with 1 chunk (the sequential scan) and with 2, 3 and 7.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <variant>

#include "loader_parts.h"
#include "marble/core/error.h"
#include "marble/mesh/mesh_internal.h"

namespace marble {
namespace {

using loader_parts::Outcome;
using loader_parts::sameMesh;
using loader_parts::withLineAt;

Outcome load(const std::string& text, unsigned chunks, bool* joined = nullptr) {
  return loader_parts::load(
      [](const std::string& t, unsigned n, bool* j) { return mesh_detail::loadObjInChunks("chunks.obj", t, n, j); }, text,
      chunks, joined);
}

// A grid of quads (v, vt, vn, f with every corner form), comments and CRLF lines mixed in, about
// `rows` * 60 lines. `face` writes one face's corners given the four 1-based vertex indices.
std::string grid(int rows, bool withAttributes) {
  std::string s = "# a grid\r\no grid\n";
  const int n = 8;
  for (int y = 0; y <= rows; ++y)
    for (int x = 0; x <= n; ++x) {
      s += "v " + std::to_string(x * 0.25) + " " + std::to_string(y * 0.125) + " " + std::to_string((x * y) % 3 * 0.1) + "\n";
      if (withAttributes) s += "vt " + std::to_string(x / 8.0) + " " + std::to_string(y / 8.0) + "\r\nvn 0 0 1\n";
    }
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
      if (withAttributes)
        s += "f " + std::to_string(a) + "/" + std::to_string(a) + "/" + std::to_string(a) + " " + std::to_string(b) + "/" +
             std::to_string(b) + "/" + std::to_string(b) + " " + std::to_string(c) + "/" + std::to_string(c) + "/" +
             std::to_string(c) + " " + std::to_string(d) + "/" + std::to_string(d) + "/" + std::to_string(d) + "\n";
      else
        s += "f " + std::to_string(a) + " " + std::to_string(b) + "\t" + std::to_string(c) + " " + std::to_string(d) + "  # quad\n";
    }
  return s;
}

void expectSameForEveryChunking(const std::string& text, const std::string& what, bool parallel = false) {
  loader_parts::expectSameForEveryPartCount(
      [](const std::string& t, unsigned n, bool* j) { return mesh_detail::loadObjInChunks("chunks.obj", t, n, j); }, text,
      what, parallel);
}

TEST(MeshObjChunks, ValidFilesGiveTheSequentialMesh) {
  expectSameForEveryChunking(grid(20, false), "positions only", true);
  expectSameForEveryChunking(grid(20, true), "v/vt/vn corners", true);
  expectSameForEveryChunking("\xEF\xBB\xBF" + grid(5, false), "byte order mark", true);
  // A face before the vertices it names (resolved at the end), across chunks.
  expectSameForEveryChunking("f 1 2 3\nf 2 3 4\n" + grid(10, false), "forward references", true);
  // Relative indices in a late chunk (their meaning needs the counts before it).
  expectSameForEveryChunking(grid(10, false) + "f -1 -2 -3\n", "relative indices");
  // Mixed corner forms: some faces without texture coordinates (then none are used).
  expectSameForEveryChunking(withLineAt(grid(10, true), 0.8, "f 1 2 3\n"), "mixed forms", true);
  expectSameForEveryChunking(withLineAt(grid(10, false), 0.7, "f 00000000001 2 3\n"), "leading zeros", true);
  expectSameForEveryChunking("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3", "no final newline");
}

TEST(MeshObjChunks, BadFilesGiveTheSequentialError) {
  const std::string base = grid(20, false);
  for (double at : {0.1, 0.5, 0.9}) {
    const std::string where = " at " + std::to_string(at);
    expectSameForEveryChunking(withLineAt(base, at, "v 1 nan 0\n"), "NaN" + where);
    expectSameForEveryChunking(withLineAt(base, at, "v 1 x 0\n"), "not a number" + where);
    expectSameForEveryChunking(withLineAt(base, at, "f 1 2\n"), "two corners" + where);
    expectSameForEveryChunking(withLineAt(base, at, "f 1 0 2\n"), "index 0" + where);
    expectSameForEveryChunking(withLineAt(base, at, "f 1 2 99999\n"), "out of range" + where);
    expectSameForEveryChunking(withLineAt(base, at, "f 1 2 -99999\n"), "relative out of range" + where);
    expectSameForEveryChunking(withLineAt(base, at, "f 1 2 12345678901\n"), "too large" + where);
    expectSameForEveryChunking(withLineAt(base, at, "f 1 2 3x\n"), "bad corner" + where);
    expectSameForEveryChunking(withLineAt(base, at, "\x01\x02\n"), "binary" + where);
    expectSameForEveryChunking(withLineAt(base, at, "\xEF\xBB\xBFv 0 0 0\n"), "byte order mark inside" + where);
  }
  // A NUL byte where the scanner would not look (a comment): each chunk checks its own bytes, and
  // the sequential path names the file's first NUL, wherever the chunks fall.
  constexpr char kNulComment[] = "# a NUL \0 in a comment\n";
  const std::string nulComment(kNulComment, sizeof kNulComment - 1);
  for (double at : {0.05, 0.5, 0.95}) {
    const std::string where = " at " + std::to_string(at);
    const std::string text = withLineAt(base, at, nulComment);
    expectSameForEveryChunking(text, "NUL in a comment" + where);
    EXPECT_NE(std::get<std::string>(load(text, 7)).find("binary data (NUL byte)"), std::string::npos) << where;
    expectSameForEveryChunking(withLineAt(withLineAt(base, 0.9, nulComment), at, nulComment), "two NULs" + where);
  }
  // The first of two errors is the one named, whichever chunks they fall in.
  expectSameForEveryChunking(withLineAt(withLineAt(base, 0.8, "f 1 0 2\n"), 0.2, "v 1 x 0\n"), "two errors");
}

// Negative control: the comparison notices a different mesh and a different message.
TEST(MeshObjChunks, ComparisonNoticesDifferences) {
  const Outcome a = load(grid(3, false), 2), b = load(grid(4, false), 2);
  EXPECT_FALSE(sameMesh(std::get<Mesh>(a), std::get<Mesh>(b)));
  const Outcome e1 = load("v 1 x 0\n", 2), e2 = load("v 1 0\nv 1 x 0\n", 2);
  EXPECT_NE(std::get<std::string>(e1), std::get<std::string>(e2));
}

}  // namespace
}  // namespace marble

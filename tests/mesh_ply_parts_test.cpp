// The PLY loader's parallel path (the vertex and face elements read in parts on several threads)
// gives the front-to-back read's mesh, and on bad input its exact error message, wherever the part
// boundaries fall: every file below is loaded in 1 part and in 2, 3 and 7 (loader_parts.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "loader_parts.h"
#include "marble/mesh/mesh_internal.h"

namespace marble {
namespace {

using loader_parts::Outcome;

Mesh loadParts(const std::string& text, unsigned parts, bool* parallel) {
  return mesh_detail::loadPlyInParts("parts.ply", text, parts, parallel);
}
void expectSame(const std::string& text, const std::string& what, bool parallel = false) {
  loader_parts::expectSameForEveryPartCount(loadParts, text, what, parallel);
}

// A grid of (rows + 1) x 9 vertices and rows x 8 quads (or two triangles each), with optional
// normals and texture coordinates, an extra scalar after the face list, and an element the loader
// skips.
struct Grid {
  int rows = 12;
  bool quads = false, attributes = false, extraFaceProperty = false, skippedElement = false;
  int vertexCount() const { return (rows + 1) * 9; }
  int faceCount() const { return rows * 8 * (quads ? 1 : 2); }
  std::vector<float> vertex(int i) const {
    const int x = i % 9, y = i / 9;
    std::vector<float> v{x * 0.25f, y * 0.125f, static_cast<float>((x * y) % 3) * 0.1f};
    if (attributes) v.insert(v.end(), {0.0f, 0.6f, 0.8f, x / 8.0f, y / 8.0f});
    return v;
  }
  std::vector<int> face(int f) const {
    const int q = quads ? f : f / 2, y = q / 8, x = q % 8;
    const int a = y * 9 + x, b = a + 1, c = a + 10, d = a + 9;
    if (quads) return {a, b, c, d};
    return f % 2 ? std::vector<int>{a, c, d} : std::vector<int>{a, b, c};
  }
  std::string header(const char* format) const {
    std::string h = std::string("ply\nformat ") + format + " 1.0\ncomment a grid\nelement vertex " +
                    std::to_string(vertexCount()) + "\nproperty float x\nproperty float y\nproperty float z\n";
    if (attributes) h += "property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n";
    if (skippedElement) h += "element material 2\nproperty uchar red\nproperty list uchar float weights\n";
    h += "element face " + std::to_string(faceCount()) + "\nproperty list uchar int vertex_indices\n";
    if (extraFaceProperty) h += "property uchar flags\n";
    return h + "end_header\n";
  }
  // One line per vertex and face (`lines[0]` is the header).
  std::vector<std::string> asciiLines() const {
    std::vector<std::string> lines{header("ascii")};
    for (int i = 0; i < vertexCount(); ++i) {
      std::string s;
      for (float x : vertex(i)) s += (s.empty() ? "" : " ") + std::to_string(x);
      lines.push_back(s + "\n");
    }
    if (skippedElement) lines.insert(lines.end(), {"7 2 0.5 0.25\n", "9 0\n"});
    for (int f = 0; f < faceCount(); ++f) {
      const std::vector<int> c = face(f);
      std::string s = std::to_string(c.size());
      for (int k : c) s += " " + std::to_string(k);
      lines.push_back(s + (extraFaceProperty ? " 1" : "") + (f % 5 == 0 ? "\r\n" : "\n"));
    }
    return lines;
  }
  std::string ascii() const {
    std::string s;
    for (const std::string& line : asciiLines()) s += line;
    return s;
  }
  std::string binary(bool bigEndian) const {
    std::string s = header(bigEndian ? "binary_big_endian" : "binary_little_endian");
    auto put = [&](const void* p, size_t n) {
      const auto* b = static_cast<const char*>(p);
      for (size_t k = 0; k < n; ++k) s += b[bigEndian ? n - 1 - k : k];
    };
    for (int i = 0; i < vertexCount(); ++i)
      for (float x : vertex(i)) put(&x, 4);
    if (skippedElement) {
      for (int m = 0; m < 2; ++m) {
        const unsigned char red = 7, n = static_cast<unsigned char>(m);
        put(&red, 1);
        put(&n, 1);
        for (int k = 0; k < m; ++k) {
          const float w = 0.5f;
          put(&w, 4);
        }
      }
    }
    for (int f = 0; f < faceCount(); ++f) {
      const std::vector<int> c = face(f);
      const auto n = static_cast<unsigned char>(c.size());
      put(&n, 1);
      for (int k : c) put(&k, 4);
      if (extraFaceProperty) {
        const unsigned char flags = 1;
        put(&flags, 1);
      }
    }
    return s;
  }
  // Byte offsets of vertex i's first value and face f's list count in binary().
  size_t vertexOffset(int i) const { return header("binary_little_endian").size() + static_cast<size_t>(i) * vertex(0).size() * 4; }
  size_t faceOffset(int f) const {
    const size_t faceBytes = 1 + (quads ? 16 : 12) + (extraFaceProperty ? 1 : 0);
    return vertexOffset(vertexCount()) + (skippedElement ? 2 + 6 : 0) + static_cast<size_t>(f) * faceBytes;
  }
};

std::string withLine(std::vector<std::string> lines, size_t index, const std::string& line) {
  lines[index] = line;
  std::string s;
  for (const std::string& l : lines) s += l;
  return s;
}

TEST(MeshPlyParts, ValidAsciiFilesGiveTheSequentialMesh) {
  Grid g;
  expectSame(g.ascii(), "triangles", true);
  g.quads = true;
  g.attributes = true;
  expectSame(g.ascii(), "quads, normals and texture coordinates", true);
  g.extraFaceProperty = true;
  g.skippedElement = true;
  expectSame(g.ascii(), "a skipped element and a property after the list", true);
  std::string noFinalNewline = g.ascii();
  noFinalNewline.pop_back();
  expectSame(noFinalNewline, "no final newline", true);
  expectSame(g.ascii() + "\n\n  \n", "blank lines after the last face", true);
}

TEST(MeshPlyParts, UnusualAsciiLayoutsGiveTheSequentialMesh) {
  Grid g;
  const std::vector<std::string> lines = g.asciiLines();
  // Two vertices on one line, and a vertex over two lines: legal PLY, read front to back.
  std::vector<std::string> joined = lines;
  joined[5].back() = ' ';
  expectSame(withLine(joined, 6, lines[6]), "two vertices on one line");
  expectSame(withLine(lines, 40, "1 2\n3\n"), "a vertex over two lines");
  expectSame(withLine(lines, 30, "\n" + lines[30]), "a blank line among the vertices");
}

TEST(MeshPlyParts, ValidBinaryFilesGiveTheSequentialMesh) {
  Grid g;
  expectSame(g.binary(false), "little-endian triangles", true);
  g.quads = true;
  g.attributes = true;
  expectSame(g.binary(true), "big-endian quads with normals", true);
  g.extraFaceProperty = true;
  g.skippedElement = true;
  expectSame(g.binary(false), "a skipped element and a property after the list", true);
  expectSame(g.binary(false) + "padding", "bytes after the body", true);
  // A triangle among quads (lists of another length): read front to back, the same mesh.
  std::string mixed = g.binary(false);
  const size_t f = g.faceOffset(5);
  mixed[f] = 3;
  mixed.erase(f + 13, 4);
  expectSame(mixed, "one triangle among quads");
}

TEST(MeshPlyParts, BadAsciiFilesGiveTheSequentialError) {
  Grid g;
  const std::vector<std::string> lines = g.asciiLines();
  const size_t vertices = static_cast<size_t>(g.vertexCount()), faces = static_cast<size_t>(g.faceCount());
  for (double at : {0.1, 0.5, 0.9}) {
    const std::string where = " at " + std::to_string(at);
    const size_t v = 1 + static_cast<size_t>(at * static_cast<double>(vertices));
    const size_t f = 1 + vertices + static_cast<size_t>(at * static_cast<double>(faces));
    expectSame(withLine(lines, v, "1 nan 0\n"), "NaN" + where);
    expectSame(withLine(lines, v, "1 1e999 0\n"), "out of range" + where);
    expectSame(withLine(lines, v, "1 x 0\n"), "not a number" + where);
    expectSame(withLine(lines, v, "1 2 3 4\n"), "a value too many" + where);
    expectSame(withLine(lines, f, "2 0 1\n"), "two corners" + where);
    expectSame(withLine(lines, f, "3 0 1 99999\n"), "index out of range" + where);
    expectSame(withLine(lines, f, "3 0 -1 2\n"), "negative index" + where);
    expectSame(withLine(lines, f, "3.5 0 1 2\n"), "bad list length" + where);
    expectSame(withLine(lines, f, "3 0 1\n"), "list too short" + where);
    const std::string text = g.ascii();
    expectSame(text.substr(0, static_cast<size_t>(static_cast<double>(text.size()) * at)), "truncated" + where);
  }
  // The first of two errors is the one named, whichever parts they fall in.
  std::vector<std::string> two = lines;
  two[1 + vertices + 3] = "3 0 1 99999\n";
  two[1 + vertices + faces - 2] = "2 0 1\n";
  expectSame(withLine(two, 1, lines[1]), "two errors");
}

TEST(MeshPlyParts, BadBinaryFilesGiveTheSequentialError) {
  Grid g;
  g.quads = true;
  const std::string base = g.binary(false);
  for (double at : {0.1, 0.5, 0.9}) {
    const std::string where = " at " + std::to_string(at);
    const size_t v = g.vertexOffset(static_cast<int>(at * g.vertexCount()));
    const size_t f = g.faceOffset(static_cast<int>(at * g.faceCount()));
    std::string nan = base;
    const float qnan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&nan[v + 4], &qnan, 4);
    expectSame(nan, "NaN" + where);
    std::string range = base;
    const int big = 99999;
    std::memcpy(&range[f + 5], &big, 4);
    expectSame(range, "index out of range" + where);
    std::string two = base;
    two[f] = 2;
    expectSame(two, "two corners" + where);
    expectSame(base.substr(0, static_cast<size_t>(static_cast<double>(base.size()) * at)), "truncated" + where);
  }
}

// Negative control: the comparison notices a different mesh and a different message.
TEST(MeshPlyParts, ComparisonNoticesDifferences) {
  Grid a, b;
  b.rows = 13;
  const Outcome ma = loader_parts::load(loadParts, a.ascii(), 2), mb = loader_parts::load(loadParts, b.ascii(), 2);
  EXPECT_FALSE(loader_parts::sameMesh(std::get<Mesh>(ma), std::get<Mesh>(mb)));
  const std::vector<std::string> lines = a.asciiLines();
  const Outcome e1 = loader_parts::load(loadParts, withLine(lines, 2, "1 x 0\n"), 2);
  const Outcome e2 = loader_parts::load(loadParts, withLine(lines, 3, "1 x 0\n"), 2);
  EXPECT_NE(std::get<std::string>(e1), std::get<std::string>(e2));
}

}  // namespace
}  // namespace marble

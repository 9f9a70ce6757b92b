// The STL loader's parallel paths give the one-pass read's mesh, and on bad input its exact error
// message, for any chunk count: an ASCII file cut into chunks at 'facet' lines, the corners welded
// after the join (loader_parts.h); and the weld of a whole soup (prefetching ahead) equals
// inserting the corners one by one into a map.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "loader_parts.h"
#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/weld_corners.h"

namespace marble {
namespace {

using loader_parts::Outcome;

Mesh loadAsciiParts(const std::string& text, unsigned parts, bool* joined) {
  return mesh_detail::loadStlAsciiInChunks("parts.stl", text, parts, joined);
}
// A wavy grid's triangles, every corner written out as STL stores it (so neighbours share corners
// only through welding), with -0 among the coordinates.
std::vector<glm::vec3> gridCorners(int rows) {
  std::vector<glm::vec3> corners;
  auto at = [](int x, int y) { return glm::vec3(x * 0.25f, y * 0.125f, x == 0 ? -0.0f : ((x * y) % 3) * 0.1f); };
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < 8; ++x)
      for (glm::vec3 p : {at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y), at(x + 1, y + 1), at(x, y + 1)})
        corners.push_back(p);
  return corners;
}

std::vector<std::string> asciiLines(const std::vector<glm::vec3>& corners) {
  std::vector<std::string> lines{"solid grid\n"};
  for (size_t c = 0; c < corners.size(); c += 3) {
    lines.push_back(c % 9 == 0 ? "  facet normal 0 0 1\r\n" : "facet normal 0 0 1\n");
    lines.push_back("    outer loop\n");
    for (size_t k = 0; k < 3; ++k) {
      const glm::vec3& p = corners[c + k];
      lines.push_back("      vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " +
                      std::to_string(p.z) + "\n");
    }
    lines.push_back("    endloop\n");
    lines.push_back("  endfacet\n");
  }
  lines.push_back("endsolid grid\n");
  return lines;
}
std::string joinLines(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l;
  return s;
}

TEST(MeshStlParts, AsciiChunksGiveTheOnePassMesh) {
  const std::vector<std::string> lines = asciiLines(gridCorners(12));
  loader_parts::expectSameForEveryPartCount(loadAsciiParts, joinLines(lines), "grid", true);
  // A quad loop (a fan of two triangles), and a loop whose vertices are never closed by a facet
  // but which the next 'outer loop' replaces (its vertices still welded, as the one-pass read does).
  std::vector<std::string> quad = lines;
  quad.insert(quad.begin() + 40, "      vertex 9 9 9\n");
  loader_parts::expectSameForEveryPartCount(loadAsciiParts, joinLines(quad), "a quad loop", true);
  std::vector<std::string> reopened = lines;
  reopened.insert(reopened.begin() + 60, "    outer loop\n      vertex 5 5 5\n");
  loader_parts::expectSameForEveryPartCount(loadAsciiParts, joinLines(reopened), "a loop reopened", true);
  std::string noFinalNewline = joinLines(lines);
  noFinalNewline.pop_back();
  loader_parts::expectSameForEveryPartCount(loadAsciiParts, noFinalNewline, "no final newline", true);
  // 'outer' with its 'loop' on the next line, which starts with "facet": one token to the one-pass
  // read; a chunk boundary there must not change the meaning.
  std::vector<std::string> split = lines;
  split[2] = "    outer\nfacet\n";
  loader_parts::expectSameForEveryPartCount(loadAsciiParts, joinLines(split), "'loop' spelled 'facet'");
}

TEST(MeshStlParts, AsciiChunksGiveTheOnePassError) {
  const std::vector<std::string> lines = asciiLines(gridCorners(12));
  for (double at : {0.1, 0.5, 0.9}) {
    const std::string where = " at " + std::to_string(at);
    // A vertex line near `at` (every 7 lines from line 3 on are vertex lines 3-5 of a facet).
    const size_t v = 3 + 7 * static_cast<size_t>(at * static_cast<double>(lines.size() - 2) / 7);
    auto with = [&](const std::string& line) {
      std::vector<std::string> l = lines;
      l[v] = line;
      return joinLines(l);
    };
    for (const char* bad : {"vertex 1 nan 0\n", "vertex 1 x 0\n", "vertex 1 2\n", "endloop\n", "vertex 1 1e99 0\n",
                            "bogus\n", "endfacet\nvertex 1 2 3\n"})
      loader_parts::expectSameForEveryPartCount(loadAsciiParts, with(bad), std::string(bad) + where);
    const std::string text = joinLines(lines);
    loader_parts::expectSameForEveryPartCount(loadAsciiParts, text.substr(0, static_cast<size_t>(static_cast<double>(text.size()) * at)),
                                              "truncated" + where);
  }
  std::string nul = joinLines(lines);
  nul[nul.size() / 2] = '\0';
  loader_parts::expectSameForEveryPartCount(loadAsciiParts, nul, "a NUL byte");
}

// The reference: corners inserted one by one into a map from bit patterns (-0 as +0).
mesh_detail::WeldedCorners weldByMap(const std::vector<glm::vec3>& corners) {
  std::map<std::tuple<uint32_t, uint32_t, uint32_t>, uint32_t> seen;
  mesh_detail::WeldedCorners out;
  for (glm::vec3 p : corners) {
    for (int k = 0; k < 3; ++k)
      if (p[k] == 0.0f) p[k] = 0.0f;
    const auto key = std::make_tuple(std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z));
    const auto [it, fresh] = seen.emplace(key, static_cast<uint32_t>(out.positions.size()));
    if (fresh) out.positions.push_back(p);
    out.indices.push_back(it->second);
  }
  return out;
}

bool sameWeld(const mesh_detail::WeldedCorners& a, const mesh_detail::WeldedCorners& b) {
  return a.indices == b.indices && a.positions.size() == b.positions.size() &&
         std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)) == 0;
}

TEST(MeshStlParts, WeldEqualsOneByOneInsertion) {
  std::vector<glm::vec3> corners = gridCorners(30);
  // Many corners on few positions (long probe runs), and positions differing only in -0.
  for (int i = 0; i < 3000; ++i) corners.push_back(glm::vec3(static_cast<float>(i % 7), -0.0f, static_cast<float>(i % 5)));
  const mesh_detail::WeldedCorners reference = weldByMap(corners);
  EXPECT_TRUE(sameWeld(reference, mesh_detail::weldCorners(corners)));
  // Negative control: one corner moved changes the weld.
  std::vector<glm::vec3> moved = corners;
  moved[5].x += 1.0f;
  EXPECT_FALSE(sameWeld(reference, mesh_detail::weldCorners(moved)));
}

}  // namespace
}  // namespace marble

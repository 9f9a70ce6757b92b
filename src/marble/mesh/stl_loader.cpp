// STL, ASCII and binary. Binary: 80-byte header, uint32 triangle count, 50 bytes per triangle
// (normal, three vertices, uint16 attribute). A file whose size is exactly 84 + 50 * count is
// binary even when its header starts with "solid" (many exporters write that). Otherwise a file
// starting with "solid" is ASCII.
//
// STL stores every triangle's corners separately; identical positions (bit-exact) are welded into
// one vertex so that smooth normals see the neighbours. Facet normals are ignored.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <vector>

#include "marble/core/parallel_for.h"
#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/weld_corners.h"

namespace marble::mesh_detail {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

float loadFloatLE(const unsigned char* p) {
  uint32_t bits;
  std::memcpy(&bits, p, 4);
  if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
  return std::bit_cast<float>(bits);
}

// Checks a binary STL's 84-byte header against the file's size; returns the triangle count.
// `head` holds at least the file's first 84 bytes when the file has them.
uint32_t checkBinaryHeader(const std::string& file, std::string_view head, uint64_t fileSize) {
  if (fileSize < 84)
    throw InputError(file, "header", "file is " + std::to_string(fileSize) +
                                         " bytes, too short for a binary STL (at least 84) and not ASCII STL ('solid ...')");
  uint32_t count;
  std::memcpy(&count, head.data() + 80, 4);
  if constexpr (std::endian::native == std::endian::big) count = __builtin_bswap32(count);
  if (count == 0) throw InputError(file, "byte 80", "the triangle count is 0: no triangles");
  if (count > kMaxTriangles)
    throw InputError(file, "byte 80", "declares " + withThousands(count) + " triangles; the limit is " + withThousands(kMaxTriangles));
  const uint64_t needed = 84 + 50ull * count;
  if (fileSize < needed)
    throw InputError(file, "byte 80", "declares " + withThousands(count) + " triangles (" + withThousands(needed) +
                                          " bytes) but the file has only " + withThousands(fileSize) + " bytes (truncated)");
  return count;
}

Mesh loadBinary(const std::string& file, std::string_view data) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const uint32_t count = checkBinaryHeader(file, data, data.size());
  // Extra bytes after the last triangle are tolerated (some exporters pad).
  // One pass, welding as it reads: the weld's table probes (cache misses) are the cost. Tried and
  // dropped (1.6 M triangles, ≈ 125 ms of CPU): decoding on threads into an array first (+45 ms:
  // the array's 57 MB of fresh pages), a table per thread over a split of the hash space (2.7x
  // the CPU: two tables' misses), prefetching the slot of the corner 8 ahead (no gain).
  Mesh mesh;
  mesh.indices.reserve(3ull * count);
  Welder welder(count / 2);
  for (uint32_t t = 0; t < count; ++t) {
    const unsigned char* tri = bytes + 84 + 50ull * t;
    for (int k = 0; k < 3; ++k) {
      const unsigned char* v = tri + 12 + 12 * k;
      const glm::vec3 p(loadFloatLE(v), loadFloatLE(v + 4), loadFloatLE(v + 8));
      if (!finite(p))
        throw InputError(file, byteAt(static_cast<size_t>(v - bytes)),
                         "triangle " + std::to_string(t) + ": coordinate is NaN or infinite");
      mesh.indices.push_back(welder.add(p, mesh.positions));
    }
  }
  return mesh;
}

// The ASCII grammar, for the whole file or one chunk of it. `sink.vertex(p, line)` returns the id a
// loop refers to (the welded vertex, or a chunk's corner number); triangles are appended to
// `indices` as fans of those ids. Throws InputError at the first problem.
template <class Sink>
void scanAscii(const std::string& file, std::string_view data, Sink& sink, std::vector<uint32_t>& indices) {
  TextCursor c{data.data(), data.data() + data.size(), 1};
  std::vector<uint32_t> loop;
  bool inLoop = false;
  size_t loopLine = 0;
  for (;;) {
    std::string_view tok = c.token();
    if (tok.empty()) break;
    if (equalsIgnoreCase(tok, "vertex")) {
      if (!inLoop) throw InputError(file, lineAt(c.line), "'vertex' outside 'outer loop'");
      glm::vec3 p;
      for (int k = 0; k < 3; ++k) {
        std::string_view num = c.token();
        float x = 0;
        const char* after = num.empty() ? nullptr : parseFloat(num.data(), num.data() + num.size(), x);
        if (!after || after != num.data() + num.size())
          throw InputError(file, lineAt(c.line), "'vertex' needs 3 numbers, found '" + std::string(num.substr(0, 24)) + "'");
        if (!std::isfinite(x)) throw InputError(file, lineAt(c.line), "coordinate is NaN or infinite");
        p[k] = x;
      }
      loop.push_back(sink.vertex(p, c.line));
    } else if (equalsIgnoreCase(tok, "outer")) {
      c.token();  // "loop"
      inLoop = true;
      loopLine = c.line;
      loop.clear();
    } else if (equalsIgnoreCase(tok, "endloop")) {
      if (loop.size() < 3)
        throw InputError(file, lineAt(loopLine), "loop has " + std::to_string(loop.size()) + " vertices; a facet needs 3");
      if (indices.size() / 3 + loop.size() - 2 > kMaxTriangles)
        throw InputError(file, lineAt(c.line), "more than " + withThousands(kMaxTriangles) + " triangles (the limit)");
      for (size_t k = 1; k + 1 < loop.size(); ++k) {
        indices.push_back(loop[0]);
        indices.push_back(loop[k]);
        indices.push_back(loop[k + 1]);
      }
      inLoop = false;
    } else if (equalsIgnoreCase(tok, "solid") || equalsIgnoreCase(tok, "endsolid")) {
      c.restOfLine();  // the solid's name
    } else if (equalsIgnoreCase(tok, "facet")) {
      c.restOfLine();  // "normal nx ny nz": ignored, normals are recomputed
    } else if (equalsIgnoreCase(tok, "endfacet")) {
      // nothing
    } else {
      throw InputError(file, lineAt(c.line), "unexpected '" + std::string(tok.substr(0, 24)) + "' in ASCII STL");
    }
  }
  if (inLoop) throw InputError(file, lineAt(loopLine), "file ends inside 'outer loop' (truncated)");
}

// The whole file in one pass, welding as it goes: the reference for every message.
Mesh loadAsciiSequential(const std::string& file, std::string_view data) {
  rejectBinary(file, data, "ASCII STL");
  struct WeldingSink {
    const std::string& file;
    Mesh& mesh;
    Welder welder;
    uint32_t vertex(const glm::vec3& p, size_t line) {
      if (mesh.positions.size() >= kMaxVertices)
        throw InputError(file, lineAt(line), "more than " + withThousands(kMaxVertices) + " vertices (the limit)");
      return welder.add(p, mesh.positions);
    }
  };
  Mesh mesh;
  WeldingSink sink{file, mesh, Welder(data.size() / 512)};  // ~250 bytes of text per facet; grows if needed
  scanAscii(file, data, sink, mesh.indices);
  return mesh;
}

// Chunk boundaries at the starts of lines whose first word is "facet", near equal sizes (fewer
// chunks when the file has few such lines).
std::vector<std::string_view> facetChunks(std::string_view data, unsigned chunks) {
  std::vector<std::string_view> parts;
  size_t begin = 0;
  for (unsigned i = 1; i <= chunks && begin < data.size(); ++i) {
    size_t end = data.size();
    for (size_t at = std::max(begin, data.size() * i / chunks); i < chunks && at < data.size();) {
      const size_t nl = data.find('\n', at);
      if (nl == std::string_view::npos) break;
      size_t word = nl + 1;
      while (word < data.size() && isSpace(data[word])) ++word;
      if (data.size() - word > 5 && equalsIgnoreCase(data.substr(word, 5), "facet") && isSpace(data[word + 5])) {
        end = nl + 1;
        break;
      }
      at = nl + 1;
    }
    parts.push_back(data.substr(begin, end - begin));
    begin = end;
  }
  return parts;
}

}  // namespace

Mesh loadStlAsciiInChunks(const std::string& file, std::string_view data, unsigned chunks, bool* joined) {
  if (joined) *joined = false;
  rejectBinary(file, data, "ASCII STL");
  const std::vector<std::string_view> parts = facetChunks(data, chunks);
  if (parts.size() > 1) {
    // Each chunk numbers its corners (every 'vertex') and refers to them; after the join the
    // corners are welded in file order, which numbers the vertices as the one-pass welder does.
    // A chunk with any problem (or that ends inside a loop), or a total that could pass a limit,
    // sends the whole file through the one-pass scan for its message.
    struct CornerSink {
      std::vector<glm::vec3> corners;
      uint32_t vertex(const glm::vec3& p, size_t) {
        corners.push_back(p);
        return static_cast<uint32_t>(corners.size() - 1);
      }
    };
    std::vector<CornerSink> sinks(parts.size());
    std::vector<std::vector<uint32_t>> indices(parts.size());
    std::vector<char> ok(parts.size(), 0);
    parallelFor(parts.size(), 1, [&](size_t first, size_t last) {
      for (size_t i = first; i < last; ++i) {
        try {
          sinks[i].corners.reserve(parts[i].size() / 80);
          scanAscii(file, parts[i], sinks[i], indices[i]);
          ok[i] = 1;
        } catch (const InputError&) {
        }
      }
    });
    size_t corners = 0, corners3 = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
      corners += sinks[i].corners.size();
      corners3 += indices[i].size();
    }
    if (std::find(ok.begin(), ok.end(), 0) == ok.end() && corners <= kMaxVertices && corners3 / 3 <= kMaxTriangles) {
      std::vector<glm::vec3> soup;
      soup.reserve(corners);
      std::vector<uint32_t> cornerIndices;
      cornerIndices.reserve(corners3);
      for (size_t i = 0; i < parts.size(); ++i) {
        const auto base = static_cast<uint32_t>(soup.size());
        for (uint32_t id : indices[i]) cornerIndices.push_back(base + id);
        soup.insert(soup.end(), sinks[i].corners.begin(), sinks[i].corners.end());
        std::vector<glm::vec3>().swap(sinks[i].corners);
      }
      const WeldedCorners welded = weldCorners(soup);
      Mesh mesh;
      mesh.positions = welded.positions;
      mesh.indices.resize(cornerIndices.size());
      for (size_t k = 0; k < cornerIndices.size(); ++k) mesh.indices[k] = welded.indices[cornerIndices[k]];
      if (joined) *joined = true;
      return mesh;
    }
  }
  return loadAsciiSequential(file, data);
}

namespace {

bool startsWithSolid(std::string_view data) {
  size_t i = 0;
  while (i < data.size() && i < 256 && isSpace(data[i])) ++i;
  return data.size() - i >= 5 && equalsIgnoreCase(data.substr(i, 5), "solid");
}

// Whether an STL of `fileSize` bytes starting with `head` (its first kStlProbeBytes) is ASCII.
bool isAsciiStl(std::string_view head, uint64_t fileSize) {
  if (fileSize >= 84 && head.size() >= 84) {
    uint32_t count;
    std::memcpy(&count, head.data() + 80, 4);
    if constexpr (std::endian::native == std::endian::big) count = __builtin_bswap32(count);
    if (84 + 50ull * count == fileSize) return false;
  }
  // "solid" but binary after all (a size that matches no count): an ASCII file has no NULs in
  // its first bytes, a binary one nearly always does.
  return startsWithSolid(head) && std::memchr(head.data(), '\0', std::min<size_t>(head.size(), kStlProbeBytes)) == nullptr;
}

}  // namespace

uint64_t stlBytesToRead(const std::string& file, std::string_view head, uint64_t fileSize) {
  if (isAsciiStl(head, fileSize)) return fileSize;
  const uint32_t count = checkBinaryHeader(file, head, fileSize);
  return 84 + 50ull * count;  // padding after the last triangle is not read
}

Mesh loadStl(const std::string& file, std::string_view data) {
  if (isAsciiStl(data.substr(0, kStlProbeBytes), data.size())) {
    const unsigned chunks = workerThreadCount(data.size(), kTextBytesPerChunk);
    return chunks > 1 ? loadStlAsciiInChunks(file, data, chunks) : loadAsciiSequential(file, data);
  }
  return loadBinary(file, data);
}

}  // namespace marble::mesh_detail

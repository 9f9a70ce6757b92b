// STL, ASCII and binary. Binary: 80-byte header, uint32 triangle count, 50 bytes per triangle
// (normal, three vertices, uint16 attribute). A file whose size is exactly 84 + 50 * count is
// binary even when its header starts with "solid" (many exporters write that). Otherwise a file
// starting with "solid" is ASCII.
//
// STL stores every triangle's corners separately; identical positions (bit-exact) are welded into
// one vertex so that smooth normals see the neighbours. Facet normals are ignored.
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

#include "marble/mesh/mesh_internal.h"

namespace marble::mesh_detail {
namespace {

// Welds bit-identical positions (with -0 == +0) into shared vertices.
class Welder {
public:
  // Starts small (a closed mesh has about half as many vertices as triangles) and doubles as
  // needed, keeping the load factor <= 1/2.
  explicit Welder(size_t expectedVertices) {
    size_t capacity = 16;
    while (capacity < expectedVertices * 2) capacity *= 2;
    slots_.assign(capacity, kEmpty);
    mask_ = capacity - 1;
  }

  uint32_t add(glm::vec3 p, Mesh& mesh) {
    if (p.x == 0.0f) p.x = 0.0f;  // -0 -> +0
    if (p.y == 0.0f) p.y = 0.0f;
    if (p.z == 0.0f) p.z = 0.0f;
    const uint32_t bx = std::bit_cast<uint32_t>(p.x), by = std::bit_cast<uint32_t>(p.y), bz = std::bit_cast<uint32_t>(p.z);
    size_t slot = hash(p) & mask_;
    for (;;) {
      uint32_t v = slots_[slot];
      if (v == kEmpty) {
        if (mesh.positions.size() * 2 >= slots_.size()) grow(mesh);
        return insertNew(p, mesh);
      }
      const glm::vec3& q = mesh.positions[v];
      if (std::bit_cast<uint32_t>(q.x) == bx && std::bit_cast<uint32_t>(q.y) == by && std::bit_cast<uint32_t>(q.z) == bz)
        return v;
      slot = (slot + 1) & mask_;
    }
  }

private:
  static constexpr uint32_t kEmpty = 0xFFFFFFFFu;

  static size_t hash(const glm::vec3& p) {
    const uint64_t bx = std::bit_cast<uint32_t>(p.x), by = std::bit_cast<uint32_t>(p.y), bz = std::bit_cast<uint32_t>(p.z);
    uint64_t h = bx * 0x9E3779B97F4A7C15ull ^ by * 0xC2B2AE3D27D4EB4Full ^ bz * 0x165667B19E3779F9ull;
    return static_cast<size_t>(h ^ (h >> 31));
  }
  size_t slotFor(const glm::vec3& p) const {
    size_t slot = hash(p) & mask_;
    while (slots_[slot] != kEmpty) slot = (slot + 1) & mask_;
    return slot;
  }
  uint32_t insertNew(const glm::vec3& p, Mesh& mesh) {
    const uint32_t index = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(p);
    slots_[slotFor(p)] = index;
    return index;
  }
  void grow(const Mesh& mesh) {
    slots_.assign(slots_.size() * 2, kEmpty);
    mask_ = slots_.size() - 1;
    for (uint32_t i = 0; i < mesh.positions.size(); ++i) slots_[slotFor(mesh.positions[i])] = i;
  }

  std::vector<uint32_t> slots_;
  size_t mask_ = 0;
};

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
  Mesh mesh;
  mesh.indices.reserve(3ull * count);
  Welder welder(count / 2);
  for (uint32_t t = 0; t < count; ++t) {
    const unsigned char* tri = bytes + 84 + 50ull * t;
    for (int k = 0; k < 3; ++k) {
      const unsigned char* v = tri + 12 + 12 * k;
      glm::vec3 p(loadFloatLE(v), loadFloatLE(v + 4), loadFloatLE(v + 8));
      if (!finite(p))
        throw InputError(file, byteAt(static_cast<size_t>(v - bytes)),
                         "triangle " + std::to_string(t) + ": coordinate is NaN or infinite");
      mesh.indices.push_back(welder.add(p, mesh));
    }
  }
  return mesh;
}

Mesh loadAscii(const std::string& file, std::string_view data) {
  rejectBinary(file, data, "ASCII STL");
  TextCursor c{data.data(), data.data() + data.size(), 1};
  Mesh mesh;
  Welder welder(data.size() / 512);  // ~250 bytes of text per facet; grows if needed
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
      if (mesh.positions.size() >= kMaxVertices)
        throw InputError(file, lineAt(c.line), "more than " + withThousands(kMaxVertices) + " vertices (the limit)");
      loop.push_back(welder.add(p, mesh));
    } else if (equalsIgnoreCase(tok, "outer")) {
      c.token();  // "loop"
      inLoop = true;
      loopLine = c.line;
      loop.clear();
    } else if (equalsIgnoreCase(tok, "endloop")) {
      if (loop.size() < 3)
        throw InputError(file, lineAt(loopLine), "loop has " + std::to_string(loop.size()) + " vertices; a facet needs 3");
      if (mesh.indices.size() / 3 + loop.size() - 2 > kMaxTriangles)
        throw InputError(file, lineAt(c.line), "more than " + withThousands(kMaxTriangles) + " triangles (the limit)");
      for (size_t k = 1; k + 1 < loop.size(); ++k) {
        mesh.indices.push_back(loop[0]);
        mesh.indices.push_back(loop[k]);
        mesh.indices.push_back(loop[k + 1]);
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
  return mesh;
}

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
  return isAsciiStl(data.substr(0, kStlProbeBytes), data.size()) ? loadAscii(file, data) : loadBinary(file, data);
}

}  // namespace marble::mesh_detail

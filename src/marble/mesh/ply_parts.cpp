#include "marble/mesh/ply_parts.h"

#include <algorithm>
#include <cstring>

#include "marble/core/parallel_for.h"

namespace marble::mesh_detail::ply {
namespace {

// Runs part(k, first, last) for the `parts` ranges of [0, count) on threads; true when every part
// returned true.
template <class Part>
bool inParts(uint64_t count, unsigned parts, Part&& part) {
  std::vector<char> ok(parts, 0);
  parallelFor(parts, 1, [&](size_t firstPart, size_t lastPart) {
    for (size_t k = firstPart; k < lastPart; ++k)
      ok[k] = part(k, count * k / parts, count * (k + 1) / parts) ? 1 : 0;
  });
  return std::find(ok.begin(), ok.end(), 0) == ok.end();
}

// ---- ASCII: one element per line ---------------------------------------------------------------

// Tokens of one line.
struct LineCursor {
  const char* p;
  const char* end;  // the line's '\n' (or the data's end)

  bool number(double& v) {
    while (p < end && isSpace(*p)) ++p;
    const char* s = p;
    while (p < end && !isSpace(*p)) ++p;
    return p > s && asciiNumber(std::string_view(s, static_cast<size_t>(p - s)), v);
  }
  bool onlySpaceLeft() {
    while (p < end && isSpace(*p)) ++p;
    return p == end;
  }
};

// The starts of the lines that begin each part of `count` lines from `p` (starts[k], k < parts) and
// the end of the last line (starts[parts]: after its '\n', or the data's end when the last line has
// none); `newlines` = the '\n's passed. Empty when the data has fewer lines. (memchr line by line:
// counting '\n's in blocks first, portable SWAR or std::count, cost 13-20 % more of the parse.)
std::vector<const char*> partLines(const char* p, const char* end, uint64_t count, unsigned parts, uint64_t& newlines) {
  std::vector<const char*> starts{p};
  uint64_t line = 0;  // the line `p` starts
  newlines = 0;
  for (unsigned k = 1; k <= parts; ++k) {
    const uint64_t target = count * k / parts;
    while (line < target) {
      if (const void* nl = std::memchr(p, '\n', static_cast<size_t>(end - p))) {
        p = static_cast<const char*>(nl) + 1;
        ++line;
        ++newlines;
      } else if (line + 1 == count && p < end) {  // the last line, without a '\n'
        p = end;
        line = count;
      } else {
        return {};
      }
    }
    starts.push_back(p);
  }
  return starts;
}

// Reads the element's lines in parts: record(i, cursor, part) for element i on its line's cursor,
// false at anything unusual. Moves `text` past the element when every record read and then
// accept() said yes.
template <class Record, class Accept>
bool asciiInParts(TextCursor& text, const Element& e, unsigned parts, Record&& record, Accept&& accept) {
  if (e.count == 0) return true;
  if (!text.skipWhitespace()) return false;  // the front-to-back read says where the data ended
  uint64_t newlines = 0;
  const std::vector<const char*> starts = partLines(text.p, text.end, e.count, parts, newlines);
  if (starts.empty()) return false;
  const bool ok = inParts(e.count, parts, [&](size_t k, uint64_t first, uint64_t last) {
    const char* p = starts[k];
    const char* partEnd = starts[k + 1];
    for (uint64_t i = first; i < last; ++i) {
      const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(partEnd - p)));
      LineCursor line{p, nl ? nl : partEnd};
      if (!record(i, line, k) || !line.onlySpaceLeft()) return false;
      p = nl ? nl + 1 : partEnd;
    }
    return true;
  });
  if (!ok || !accept()) return false;
  text.p = starts.back();
  text.line += static_cast<size_t>(newlines);
  return true;
}

bool skipAsciiList(LineCursor& line) {
  double n = 0;
  if (!line.number(n) || !goodListCount(n)) return false;
  for (double j = 0; j < n; ++j)
    if (double x = 0; !line.number(x)) return false;
  return true;
}

// Appends the fan of `polygon` to `out`.
void appendFan(const uint32_t* polygon, size_t n, std::vector<uint32_t>& out) {
  for (size_t j = 1; j + 1 < n; ++j) {
    out.push_back(polygon[0]);
    out.push_back(polygon[j]);
    out.push_back(polygon[j + 1]);
  }
}

// Joins the parts' triangles after `indices`, within the triangle limit.
bool joinTriangles(std::vector<std::vector<uint32_t>>& partIndices, std::vector<uint32_t>& indices) {
  size_t total = indices.size();
  for (const auto& v : partIndices) total += v.size();
  if (total / 3 > kMaxTriangles) return false;
  indices.reserve(total);
  for (auto& v : partIndices) {
    indices.insert(indices.end(), v.begin(), v.end());
    std::vector<uint32_t>().swap(v);
  }
  return true;
}

}  // namespace

bool readAsciiVerticesInParts(TextCursor& text, const Element& e, const VertexLayout& layout, Mesh& mesh, unsigned parts) {
  return asciiInParts(text, e, parts, [&](uint64_t i, LineCursor& line, size_t) {
    double v[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (size_t k = 0; k < e.properties.size(); ++k) {
      if (e.properties[k].isList) {
        if (!skipAsciiList(line)) return false;
        continue;
      }
      double x = 0;
      if (!line.number(x)) return false;
      if (layout.roles[k] != kNone) v[layout.roles[k]] = x;
    }
    return storeVertex(v, static_cast<size_t>(i), layout, mesh);
  }, [] { return true; });
}

bool readAsciiFacesInParts(TextCursor& text, const Element& e, size_t list, uint64_t vertexCount,
                           std::vector<uint32_t>& indices, unsigned parts) {
  std::vector<std::vector<uint32_t>> partIndices(parts);
  std::vector<std::vector<uint32_t>> polygons(parts);
  return asciiInParts(text, e, parts, [&](uint64_t, LineCursor& line, size_t part) {
    for (size_t k = 0; k < e.properties.size(); ++k) {
      if (k != list) {
        if (e.properties[k].isList) {
          if (!skipAsciiList(line)) return false;
        } else if (double x = 0; !line.number(x)) {
          return false;
        }
        continue;
      }
      double n = 0;
      if (!line.number(n) || !goodListCount(n) || n < 3) return false;
      std::vector<uint32_t>& polygon = polygons[part];
      polygon.clear();
      for (double j = 0; j < n; ++j) {
        double x = 0;
        if (!line.number(x) || !goodIndex(x, vertexCount)) return false;
        polygon.push_back(static_cast<uint32_t>(x));
      }
      appendFan(polygon.data(), polygon.size(), partIndices[part]);
    }
    return true;
  }, [&] { return joinTriangles(partIndices, indices); });
}

// ---- binary ------------------------------------------------------------------------------------

bool readBinaryVerticesInParts(std::string_view body, const Element& e, const VertexLayout& layout, bool swap, Mesh& mesh,
                               unsigned parts, size_t& pos) {
  uint64_t stride = 0;
  for (const Property& p : e.properties) {
    if (p.isList) return false;
    stride += typeSize(p.type);
  }
  if (stride == 0 || e.count > body.size() / stride) return false;
  const auto* bytes = reinterpret_cast<const unsigned char*>(body.data());
  const bool ok = inParts(e.count, parts, [&](size_t, uint64_t first, uint64_t last) {
    for (uint64_t i = first; i < last; ++i) {
      const unsigned char* q = bytes + i * stride;
      double v[8] = {0, 0, 0, 0, 0, 0, 0, 0};
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Type t = e.properties[k].type;
        if (layout.roles[k] != kNone) v[layout.roles[k]] = loadValue(t, q, swap);
        q += typeSize(t);
      }
      if (!storeVertex(v, static_cast<size_t>(i), layout, mesh)) return false;
    }
    return true;
  });
  if (ok) pos += static_cast<size_t>(e.count * stride);
  return ok;
}

bool readBinaryFacesInParts(std::string_view body, const Element& e, size_t list, uint64_t vertexCount, bool swap,
                            std::vector<uint32_t>& indices, unsigned parts, size_t& pos) {
  if (e.count == 0) return true;
  // The layout of every face, from the first: scalars, then the one list with the first face's length.
  uint64_t before = 0, after = 0;
  for (size_t k = 0; k < e.properties.size(); ++k) {
    const Property& p = e.properties[k];
    if (k == list) continue;
    if (p.isList) return false;
    (k < list ? before : after) += typeSize(p.type);
  }
  const Property& lp = e.properties[list];
  const uint64_t countSize = typeSize(lp.countType), itemSize = typeSize(lp.type);
  if (body.size() < before + countSize) return false;
  const auto* bytes = reinterpret_cast<const unsigned char*>(body.data());
  const double n0 = loadValue(lp.countType, bytes + before, swap);
  if (!goodListCount(n0) || n0 < 3 || n0 > 64) return false;
  const auto n = static_cast<uint64_t>(n0);
  const uint64_t stride = before + countSize + n * itemSize + after;
  if (e.count > body.size() / stride) return false;
  const uint64_t perFace = 3 * (n - 2);
  if (indices.size() / 3 + e.count * (n - 2) > kMaxTriangles) return false;
  const size_t base = indices.size();
  indices.resize(base + static_cast<size_t>(e.count * perFace));
  const bool ok = inParts(e.count, parts, [&](size_t, uint64_t first, uint64_t last) {
    uint32_t polygon[64];
    for (uint64_t i = first; i < last; ++i) {
      const unsigned char* q = bytes + i * stride + before;
      if (loadValue(lp.countType, q, swap) != n0) return false;
      q += countSize;
      for (uint64_t j = 0; j < n; ++j, q += itemSize) {
        const double x = loadValue(lp.type, q, swap);
        if (!goodIndex(x, vertexCount)) return false;
        polygon[j] = static_cast<uint32_t>(x);
      }
      uint32_t* out = indices.data() + base + i * perFace;
      for (uint64_t j = 1; j + 1 < n; ++j) {
        *out++ = polygon[0];
        *out++ = polygon[j];
        *out++ = polygon[j + 1];
      }
    }
    return true;
  });
  if (!ok) {
    indices.resize(base);
    return false;
  }
  pos += static_cast<size_t>(e.count * stride);
  return true;
}

}  // namespace marble::mesh_detail::ply

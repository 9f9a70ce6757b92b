// PLY (Stanford polygon file): ascii, binary_little_endian and binary_big_endian.
// Reads the vertex element (x, y, z; optional nx, ny, nz and s/t, u/v, texture_u/texture_v) and
// the face element's vertex_indices / vertex_index list (any count and index type, polygons as
// fans); every other element and property is read past and ignored.
//
// Before anything is allocated, the counts in the header are checked against the hard caps and
// against the least number of bytes the declared elements need.
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/ply_format.h"
#include "marble/mesh/ply_parts.h"
#include "marble/core/parallel_for.h"

namespace marble::mesh_detail {
namespace {

using namespace ply;

// An index as the file gave it, for a message. Float properties can hold anything: a cast of
// inf, nan or 1e30 to an integer is undefined (fuzz_ply found "inf" here), so those are printed
// as the number they are.
std::string indexText(double x) {
  if (std::isfinite(x) && std::abs(x) < 9e15 && x == std::floor(x)) return std::to_string(static_cast<long long>(x));
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

class PlyParser {
public:
  // `parts` > 1: the vertex and face elements are first tried in that many parts (ply_parts.h);
  // anything unusual there and the element is read front to back, which gives every message.
  PlyParser(const std::string& file, std::string_view data, unsigned parts = 1)
      : file_(file), data_(data), parts_(parts) {}

  // Whether every vertex and face element was read in parts (tests).
  bool allInParts() const { return inParts_ && partsTried_; }

  Mesh parse() {
    parseHeader();
    checkCountsBeforeAllocating();
    if (format_ == Format::Ascii) {
      rejectBinary(file_, data_.substr(bodyStart_), "ASCII PLY");
      text_ = TextCursor{data_.data() + bodyStart_, data_.data() + data_.size(), bodyLine_};
    } else {
      pos_ = bodyStart_;
      swap_ = (format_ == Format::BinaryLE) != (std::endian::native == std::endian::little);
    }
    for (const Element& e : elements_) readElement(e);
    if (!sawFaces_) throw InputError(file_, "header", "no face element (point clouds are not supported)");
    return std::move(mesh_);
  }

private:
  [[noreturn]] void headerFail(size_t line, const std::string& problem) const {
    throw InputError(file_, "header line " + std::to_string(line), problem);
  }
  [[noreturn]] void bodyFail(const std::string& problem) const {
    if (format_ == Format::Ascii) throw InputError(file_, lineAt(text_.line), problem);
    throw InputError(file_, byteAt(pos_), problem);
  }

  void parseHeader() {
    TextCursor c{data_.data(), data_.data() + data_.size(), 1};
    // The first line must be exactly "ply".
    if (data_.size() < 4 || data_.substr(0, 3) != "ply" || (data_[3] != '\n' && data_[3] != '\r'))
      throw InputError(file_, "header", "not a PLY file (it must start with a line 'ply')");
    c.restOfLine();
    bool sawFormat = false;
    for (;;) {
      if (c.p >= c.end) throw InputError(file_, "header", "no 'end_header' line (truncated or not a PLY file)");
      const size_t line = c.line;
      std::string_view text = c.restOfLine();
      // Split into words.
      std::vector<std::string_view> w;
      size_t i = 0;
      while (i < text.size()) {
        while (i < text.size() && isSpace(text[i])) ++i;
        size_t s = i;
        while (i < text.size() && !isSpace(text[i])) ++i;
        if (i > s) w.push_back(text.substr(s, i - s));
      }
      if (w.empty()) continue;
      if (w[0] == "end_header") break;
      if (w[0] == "comment" || w[0] == "obj_info") continue;
      if (w[0] == "format") {
        if (w.size() < 2) headerFail(line, "'format' needs a value");
        if (w[1] == "ascii") format_ = Format::Ascii;
        else if (w[1] == "binary_little_endian") format_ = Format::BinaryLE;
        else if (w[1] == "binary_big_endian") format_ = Format::BinaryBE;
        else headerFail(line, "unknown format '" + std::string(w[1]) + "'");
        sawFormat = true;
      } else if (w[0] == "element") {
        if (w.size() < 3) headerFail(line, "'element' needs a name and a count");
        Element e;
        e.name = std::string(w[1]);
        e.headerLine = line;
        auto r = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
        if (r.ec != std::errc{} || r.ptr != w[2].data() + w[2].size())
          headerFail(line, "bad element count '" + std::string(w[2]) + "'");
        elements_.push_back(std::move(e));
      } else if (w[0] == "property") {
        if (elements_.empty()) headerFail(line, "'property' before any 'element'");
        Property p;
        if (w.size() >= 2 && w[1] == "list") {
          if (w.size() < 5) headerFail(line, "'property list' needs a count type, an item type and a name");
          auto ct = parseType(w[2]);
          auto it = parseType(w[3]);
          if (!ct || !it) headerFail(line, "unknown property type '" + std::string(ct ? w[3] : w[2]) + "'");
          if (!isIntegral(*ct)) headerFail(line, "list count type must be an integer type");
          p.isList = true;
          p.countType = *ct;
          p.type = *it;
          p.name = std::string(w[4]);
        } else {
          if (w.size() < 3) headerFail(line, "'property' needs a type and a name");
          auto t = parseType(w[1]);
          if (!t) headerFail(line, "unknown property type '" + std::string(w[1]) + "'");
          p.type = *t;
          p.name = std::string(w[2]);
        }
        elements_.back().properties.push_back(std::move(p));
      } else {
        headerFail(line, "unknown header keyword '" + std::string(w[0]) + "'");
      }
    }
    if (!sawFormat) throw InputError(file_, "header", "no 'format' line");
    bodyStart_ = static_cast<size_t>(c.p - data_.data());
    bodyLine_ = c.line;
  }

  void checkCountsBeforeAllocating() {
    const Element* vertex = nullptr;
    for (const Element& e : elements_) {
      if (e.name == "vertex") {
        vertex = &e;
        if (e.count > kMaxVertices)
          headerFail(e.headerLine, "declares " + withThousands(e.count) + " vertices; the limit is " + withThousands(kMaxVertices));
      } else if (e.name == "face" && e.count > kMaxTriangles) {
        headerFail(e.headerLine, "declares " + withThousands(e.count) + " faces; the limit is " + withThousands(kMaxTriangles));
      }
    }
    if (!vertex) throw InputError(file_, "header", "no 'vertex' element");
    bool hasX = false, hasY = false, hasZ = false;
    for (const Property& p : vertex->properties) {
      if (p.isList) continue;
      hasX |= p.name == "x";
      hasY |= p.name == "y";
      hasZ |= p.name == "z";
    }
    if (!hasX || !hasY || !hasZ) headerFail(vertex->headerLine, "the vertex element needs properties x, y and z");
    vertexCount_ = vertex->count;

    // The least room the declared elements need: binary, the fixed-size properties plus each
    // list's count; ASCII, one character and one separator per value.
    const uint64_t available = data_.size() - bodyStart_;
    uint64_t needed = 0;
    for (const Element& e : elements_) {
      uint64_t per = 0;
      for (const Property& p : e.properties) {
        if (format_ == Format::Ascii) per += 2;
        else per += p.isList ? typeSize(p.countType) : typeSize(p.type);
      }
      if (per == 0) continue;
      const uint64_t room = format_ == Format::Ascii ? available + 1 : available;
      if (e.count > (room - std::min(room, needed)) / per)
        headerFail(e.headerLine, "declares " + withThousands(e.count) + " " + e.name + " elements (at least " +
                                     withThousands(e.count * per) + " bytes) but only " + withThousands(available) +
                                     " bytes follow the header (truncated file?)");
      needed += e.count * per;
    }
  }

  // ---- reading values ------------------------------------------------------------------------

  double binaryValue(Type t, const Element& e, uint64_t index) {
    const size_t size = typeSize(t);
    if (data_.size() - pos_ < size)
      bodyFail("file ends inside " + e.name + " " + std::to_string(index) + " of " + withThousands(e.count) + " (truncated)");
    double v = loadValue(t, reinterpret_cast<const unsigned char*>(data_.data()) + pos_, swap_);
    pos_ += size;
    return v;
  }

  double asciiValue(const Element& e, uint64_t index) {
    std::string_view tok = text_.token();
    if (tok.empty())
      bodyFail("file ends inside " + e.name + " " + std::to_string(index) + " of " + withThousands(e.count) + " (truncated)");
    double v = 0;
    if (!asciiNumber(tok, v))
      bodyFail("expected a number in " + e.name + " " + std::to_string(index) + ", found '" +
               std::string(tok.substr(0, 24)) + "'");
    return v;
  }

  double value(Type t, const Element& e, uint64_t index) {
    return format_ == Format::Ascii ? asciiValue(e, index) : binaryValue(t, e, index);
  }

  uint64_t listCount(const Property& p, const Element& e, uint64_t index) {
    double n = value(p.countType, e, index);
    if (!goodListCount(n))
      bodyFail("bad list length " + std::to_string(n) + " in " + e.name + " " + std::to_string(index));
    return static_cast<uint64_t>(n);
  }

  void skipList(const Property& p, const Element& e, uint64_t index) {
    uint64_t n = listCount(p, e, index);
    if (format_ == Format::Ascii) {
      for (uint64_t k = 0; k < n; ++k) asciiValue(e, index);
    } else {
      const uint64_t bytes = n * typeSize(p.type);
      if (data_.size() - pos_ < bytes)
        bodyFail("file ends inside " + e.name + " " + std::to_string(index) + " of " + withThousands(e.count) + " (truncated)");
      pos_ += static_cast<size_t>(bytes);
    }
  }

  void readElement(const Element& e) {
    if (e.name == "vertex") readVertices(e);
    else if (e.name == "face") readFaces(e);
    else skipElement(e);
  }

  void skipElement(const Element& e) {
    // An element without properties takes no room, whatever its count (the fuzzer's
    // "element x 2147483648" with nothing after it looped two billion times).
    if (e.properties.empty()) return;
    // Fast path: a binary element of fixed-size properties is skipped in one step.
    bool fixed = format_ != Format::Ascii;
    uint64_t size = 0;
    for (const Property& p : e.properties) {
      fixed = fixed && !p.isList;
      size += typeSize(p.type);
    }
    if (fixed) {
      pos_ += static_cast<size_t>(e.count * size);  // room checked before allocating
      return;
    }
    for (uint64_t i = 0; i < e.count; ++i)
      for (const Property& p : e.properties) {
        if (p.isList) skipList(p, e, i);
        else value(p.type, e, i);
      }
  }

  void readVertices(const Element& e) {
    const VertexLayout layout = vertexLayout(e);
    const size_t n = static_cast<size_t>(e.count);
    mesh_.positions.resize(n);
    if (layout.normals) mesh_.normals.resize(n);
    if (layout.uvs) mesh_.texcoords.resize(n);
    if (tryInParts([&] {
          return format_ == Format::Ascii ? readAsciiVerticesInParts(text_, e, layout, mesh_, parts_)
                                          : readBinaryVerticesInParts(binaryBody(), e, layout, swap_, mesh_, parts_, pos_);
        }))
      return;
    for (size_t i = 0; i < n; ++i) {
      double v[8] = {0, 0, 0, 0, 0, 0, 0, 0};
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (p.isList) {
          skipList(p, e, i);
          continue;
        }
        double x = value(p.type, e, i);
        if (layout.roles[k] != kNone) v[layout.roles[k]] = x;
      }
      if (!storeVertex(v, i, layout, mesh_)) bodyFail("vertex " + std::to_string(i) + ": coordinate is NaN or infinite");
    }
  }

  // The body from the read position on (binary).
  std::string_view binaryBody() const { return data_.substr(pos_); }

  // Runs a reader in parts when there are parts to use; true when it read the element (and moved
  // the position past it), false when the element must be read front to back from where it starts.
  template <class Read>
  bool tryInParts(Read&& read) {
    if (parts_ <= 1) return false;
    partsTried_ = true;
    const bool ok = read();
    inParts_ = inParts_ && ok;
    return ok;
  }

  void readFaces(const Element& e) {
    sawFaces_ = true;
    int listIndex = -1;
    for (size_t k = 0; k < e.properties.size(); ++k) {
      const Property& p = e.properties[k];
      if (p.isList && (p.name == "vertex_indices" || p.name == "vertex_index")) listIndex = static_cast<int>(k);
    }
    if (listIndex < 0) headerFail(e.headerLine, "the face element has no 'vertex_indices' list");
    if (!isIntegral(e.properties[static_cast<size_t>(listIndex)].type))
      headerFail(e.headerLine, "face indices must be an integer type");
    const auto list = static_cast<size_t>(listIndex);
    if (tryInParts([&] {
          return format_ == Format::Ascii ? readAsciiFacesInParts(text_, e, list, vertexCount_, mesh_.indices, parts_)
                                          : readBinaryFacesInParts(binaryBody(), e, list, vertexCount_, swap_, mesh_.indices,
                                                                   parts_, pos_);
        }))
      return;
    mesh_.indices.reserve(static_cast<size_t>(std::min<uint64_t>(e.count * 3, kMaxTriangles * 3)));
    std::vector<uint32_t> polygon;
    for (uint64_t i = 0; i < e.count; ++i) {
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (static_cast<int>(k) != listIndex) {
          if (p.isList) skipList(p, e, i);
          else value(p.type, e, i);
          continue;
        }
        const uint64_t n = listCount(p, e, i);
        if (n < 3) bodyFail("face " + std::to_string(i) + " has " + std::to_string(n) + " vertices; a face needs at least 3");
        if (mesh_.indices.size() / 3 + (n - 2) > kMaxTriangles)
          bodyFail("more than " + withThousands(kMaxTriangles) + " triangles (the limit)");
        polygon.clear();
        for (uint64_t j = 0; j < n; ++j) {
          double x = value(p.type, e, i);
          if (!goodIndex(x, vertexCount_))
            bodyFail("face " + std::to_string(i) + ": vertex index " + indexText(x) + " is out of range (the file has " +
                     withThousands(vertexCount_) + " vertices)");
          polygon.push_back(static_cast<uint32_t>(x));
        }
        for (size_t j = 1; j + 1 < polygon.size(); ++j) {
          mesh_.indices.push_back(polygon[0]);
          mesh_.indices.push_back(polygon[j]);
          mesh_.indices.push_back(polygon[j + 1]);
        }
      }
    }
  }

  const std::string& file_;
  std::string_view data_;
  Format format_ = Format::Ascii;
  std::vector<Element> elements_;
  size_t bodyStart_ = 0;
  size_t bodyLine_ = 1;
  uint64_t vertexCount_ = 0;
  TextCursor text_{nullptr, nullptr, 1};
  size_t pos_ = 0;
  bool swap_ = false;
  bool sawFaces_ = false;
  unsigned parts_ = 1;
  bool partsTried_ = false, inParts_ = true;
  Mesh mesh_;
};

}  // namespace

Mesh loadPlyInParts(const std::string& file, std::string_view data, unsigned parts, bool* parallel) {
  PlyParser parser(file, data, parts);
  Mesh mesh = parser.parse();
  if (parallel) *parallel = parser.allInParts();
  return mesh;
}

Mesh loadPly(const std::string& file, std::string_view data) {
  return loadPlyInParts(file, data, workerThreadCount(data.size(), kTextBytesPerChunk));
}

}  // namespace marble::mesh_detail

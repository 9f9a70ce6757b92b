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

namespace marble::mesh_detail {
namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<Type> parseType(std::string_view s) {
  if (s == "char" || s == "int8") return Type::Int8;
  if (s == "uchar" || s == "uint8") return Type::UInt8;
  if (s == "short" || s == "int16") return Type::Int16;
  if (s == "ushort" || s == "uint16") return Type::UInt16;
  if (s == "int" || s == "int32") return Type::Int32;
  if (s == "uint" || s == "uint32") return Type::UInt32;
  if (s == "float" || s == "float32") return Type::Float32;
  if (s == "double" || s == "float64") return Type::Float64;
  return std::nullopt;
}

size_t typeSize(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::UInt8: return 1;
    case Type::Int16:
    case Type::UInt16: return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 1;
}

bool isIntegral(Type t) { return t != Type::Float32 && t != Type::Float64; }

struct Property {
  std::string name;
  Type type = Type::Float32;
  bool isList = false;
  Type countType = Type::UInt8;
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
  size_t headerLine = 0;
};

enum class Format { Ascii, BinaryLE, BinaryBE };

// Roles of vertex properties.
enum Role { kX, kY, kZ, kNX, kNY, kNZ, kU, kV, kNone };

Role vertexRole(std::string_view n) {
  if (n == "x") return kX;
  if (n == "y") return kY;
  if (n == "z") return kZ;
  if (n == "nx") return kNX;
  if (n == "ny") return kNY;
  if (n == "nz") return kNZ;
  if (n == "s" || n == "u" || n == "texture_u" || n == "texture_s") return kU;
  if (n == "t" || n == "v" || n == "texture_v" || n == "texture_t") return kV;
  return kNone;
}

template <typename T>
T loadRaw(const unsigned char* p, bool swap) {
  T v;
  if constexpr (sizeof(T) == 1) {
    std::memcpy(&v, p, 1);
  } else {
    unsigned char b[sizeof(T)];
    std::memcpy(b, p, sizeof(T));
    if (swap)
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    std::memcpy(&v, b, sizeof(T));
  }
  return v;
}

double loadValue(Type t, const unsigned char* p, bool swap) {
  switch (t) {
    case Type::Int8: return loadRaw<int8_t>(p, swap);
    case Type::UInt8: return loadRaw<uint8_t>(p, swap);
    case Type::Int16: return loadRaw<int16_t>(p, swap);
    case Type::UInt16: return loadRaw<uint16_t>(p, swap);
    case Type::Int32: return loadRaw<int32_t>(p, swap);
    case Type::UInt32: return loadRaw<uint32_t>(p, swap);
    case Type::Float32: return loadRaw<float>(p, swap);
    case Type::Float64: return loadRaw<double>(p, swap);
  }
  return 0.0;
}

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
  PlyParser(const std::string& file, std::string_view data) : file_(file), data_(data) {}

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
    const char* b = tok.data();
    if (*b == '+') ++b;
    auto r = std::from_chars(b, tok.data() + tok.size(), v);
    if (r.ec == std::errc::result_out_of_range) {
      v = HUGE_VAL;  // reported as non-finite where it matters
    } else if (r.ec != std::errc{} || r.ptr != tok.data() + tok.size()) {
      bodyFail("expected a number in " + e.name + " " + std::to_string(index) + ", found '" +
               std::string(tok.substr(0, 24)) + "'");
    }
    return v;
  }

  double value(Type t, const Element& e, uint64_t index) {
    return format_ == Format::Ascii ? asciiValue(e, index) : binaryValue(t, e, index);
  }

  uint64_t listCount(const Property& p, const Element& e, uint64_t index) {
    double n = value(p.countType, e, index);
    if (!(n >= 0) || n != std::floor(n) || n > 1e9)
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
    std::vector<Role> roles;
    bool hasNormal[3] = {false, false, false}, hasUv[2] = {false, false};
    for (const Property& p : e.properties) {
      Role r = p.isList ? kNone : vertexRole(p.name);
      roles.push_back(r);
      if (r >= kNX && r <= kNZ) hasNormal[r - kNX] = true;
      if (r == kU || r == kV) hasUv[r - kU] = true;
    }
    const bool normals = hasNormal[0] && hasNormal[1] && hasNormal[2];
    const bool uvs = hasUv[0] && hasUv[1];
    const size_t n = static_cast<size_t>(e.count);
    mesh_.positions.resize(n);
    if (normals) mesh_.normals.resize(n);
    if (uvs) mesh_.texcoords.resize(n);
    for (size_t i = 0; i < n; ++i) {
      double v[8] = {0, 0, 0, 0, 0, 0, 0, 0};
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (p.isList) {
          skipList(p, e, i);
          continue;
        }
        double x = value(p.type, e, i);
        if (roles[k] != kNone) v[roles[k]] = x;
      }
      glm::vec3 pos(static_cast<float>(v[kX]), static_cast<float>(v[kY]), static_cast<float>(v[kZ]));
      if (!std::isfinite(pos.x) || !std::isfinite(pos.y) || !std::isfinite(pos.z))
        bodyFail("vertex " + std::to_string(i) + ": coordinate is NaN or infinite");
      mesh_.positions[i] = pos;
      if (normals)
        mesh_.normals[i] = glm::vec3(static_cast<float>(v[kNX]), static_cast<float>(v[kNY]), static_cast<float>(v[kNZ]));
      if (uvs) mesh_.texcoords[i] = glm::vec2(static_cast<float>(v[kU]), static_cast<float>(v[kV]));
    }
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
          if (!(x >= 0) || x >= static_cast<double>(vertexCount_))
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
  Mesh mesh_;
};

}  // namespace

Mesh loadPly(const std::string& file, std::string_view data) { return PlyParser(file, data).parse(); }

}  // namespace marble::mesh_detail

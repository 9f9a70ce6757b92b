#pragma once
// The PLY body's types and values, shared by the front-to-back reader (ply_loader.cpp) and the
// readers in parts (ply_parts.cpp).
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "marble/mesh/mesh.h"
#include "marble/mesh/mesh_internal.h"

namespace marble::mesh_detail::ply {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

inline std::optional<Type> parseType(std::string_view s) {
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

inline size_t typeSize(Type t) {
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

inline bool isIntegral(Type t) { return t != Type::Float32 && t != Type::Float64; }

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

inline Role vertexRole(std::string_view n) {
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

inline double loadValue(Type t, const unsigned char* p, bool swap) {
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

// Which vertex properties are read into what (repeated names: the last one wins, as in the file).
struct VertexLayout {
  std::vector<Role> roles;  // per property; kNone for lists and unknown names
  bool normals = false, uvs = false;
};

inline VertexLayout vertexLayout(const Element& e) {
  VertexLayout layout;
  bool hasNormal[3] = {false, false, false}, hasUv[2] = {false, false};
  for (const Property& p : e.properties) {
    const Role r = p.isList ? kNone : vertexRole(p.name);
    layout.roles.push_back(r);
    if (r >= kNX && r <= kNZ) hasNormal[r - kNX] = true;
    if (r == kU || r == kV) hasUv[r - kU] = true;
  }
  layout.normals = hasNormal[0] && hasNormal[1] && hasNormal[2];
  layout.uvs = hasUv[0] && hasUv[1];
  return layout;
}

// Stores vertex i from its values by role (the mesh's arrays sized already); false when the
// position is not finite (nothing stored then).
inline bool storeVertex(const double (&v)[8], size_t i, const VertexLayout& layout, Mesh& mesh) {
  const glm::vec3 pos(static_cast<float>(v[kX]), static_cast<float>(v[kY]), static_cast<float>(v[kZ]));
  if (!std::isfinite(pos.x) || !std::isfinite(pos.y) || !std::isfinite(pos.z)) return false;
  mesh.positions[i] = pos;
  if (layout.normals)
    mesh.normals[i] = glm::vec3(static_cast<float>(v[kNX]), static_cast<float>(v[kNY]), static_cast<float>(v[kNZ]));
  if (layout.uvs) mesh.texcoords[i] = glm::vec2(static_cast<float>(v[kU]), static_cast<float>(v[kV]));
  return true;
}

// An ASCII value: an optional '+', then std::from_chars as a double over the whole token; out of
// range reads as HUGE_VAL (reported as non-finite where it matters). False: not a number.
inline bool asciiNumber(std::string_view tok, double& v) {
  const char* b = tok.data();
  const char* e = tok.data() + tok.size();
  if (b < e && *b == '+') ++b;
  if (mesh_detail::parseShortDecimal(b, e, v) == e) return true;
  const auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc::result_out_of_range) {
    v = HUGE_VAL;
    return true;
  }
  return r.ec == std::errc{} && r.ptr == e;
}

// Whether a list count read as `n` is one the reader accepts (a whole number, 0 to 10^9).
inline bool goodListCount(double n) { return n >= 0 && n == std::floor(n) && n <= 1e9; }
// Whether a face index read as `x` names one of `vertexCount` vertices.
inline bool goodIndex(double x, uint64_t vertexCount) { return x >= 0 && x < static_cast<double>(vertexCount); }

}  // namespace marble::mesh_detail::ply

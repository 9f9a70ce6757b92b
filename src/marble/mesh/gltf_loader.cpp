// glTF 2.0: .gltf (JSON; buffers as data: URIs or external files relative to the .gltf) and .glb
// (12-byte header, JSON chunk, optional BIN chunk).
//
// Reads the meshes of the default scene's nodes (recursively, with node matrix or TRS transforms);
// primitives of mode 4 (triangles, the default), 5 (strip) and 6 (fan) with POSITION and optional
// NORMAL / TEXCOORD_0, indexed (unsigned byte/short/int) or not. Every accessor is checked against
// its bufferView and buffer before it is read. glTF is +Y up by its specification.
#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "marble/core/json_limits.h"
#include "marble/mesh/mesh_internal.h"

namespace marble::mesh_detail {
namespace {

using json = nlohmann::json;

constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;

size_t componentSize(int type) {
  switch (type) {
    case kByte:
    case kUnsignedByte: return 1;
    case kShort:
    case kUnsignedShort: return 2;
    case kUnsignedInt:
    case kFloat: return 4;
    default: return 0;
  }
}

int componentCount(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  if (type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

template <typename T>
T loadLE(const unsigned char* p) {
  T v;
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(&v, p, sizeof(T));
  } else {
    unsigned char b[sizeof(T)];
    for (size_t i = 0; i < sizeof(T); ++i) b[i] = p[sizeof(T) - 1 - i];
    std::memcpy(&v, b, sizeof(T));
  }
  return v;
}

int base64Value(unsigned char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;
  if (c == '/' || c == '_') return 63;
  return -1;
}

// Returns false on a character outside the base64 alphabet.
bool decodeBase64(std::string_view in, std::string& out) {
  out.clear();
  out.reserve(in.size() / 4 * 3);
  uint32_t acc = 0;
  int bits = 0;
  for (char ch : in) {
    if (ch == '=') break;
    if (ch == '\n' || ch == '\r' || ch == ' ') continue;
    int v = base64Value(static_cast<unsigned char>(ch));
    if (v < 0) return false;
    acc = (acc << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xFF));
    }
  }
  return true;
}

std::string percentDecode(std::string_view s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size()) {
      auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
      };
      int a = hex(s[i + 1]), b = hex(s[i + 2]);
      if (a >= 0 && b >= 0) {
        out.push_back(static_cast<char>(a * 16 + b));
        i += 2;
        continue;
      }
    }
    out.push_back(s[i]);
  }
  return out;
}

// A checked view of one accessor's elements.
struct AccessorView {
  const unsigned char* base = nullptr;  // nullptr: no bufferView, all zeros
  size_t stride = 0;
  size_t count = 0;
  int componentType = 0;
  int components = 0;
  bool normalized = false;

  float component(size_t i, int c) const {
    if (!base) return 0.0f;
    const unsigned char* p = base + i * stride + static_cast<size_t>(c) * componentSize(componentType);
    switch (componentType) {
      case kFloat: return loadLE<float>(p);
      case kUnsignedByte: return normalized ? loadLE<uint8_t>(p) / 255.0f : loadLE<uint8_t>(p);
      case kUnsignedShort: return normalized ? loadLE<uint16_t>(p) / 65535.0f : loadLE<uint16_t>(p);
      case kByte: return normalized ? std::max(loadLE<int8_t>(p) / 127.0f, -1.0f) : loadLE<int8_t>(p);
      case kShort: return normalized ? std::max(loadLE<int16_t>(p) / 32767.0f, -1.0f) : loadLE<int16_t>(p);
      case kUnsignedInt: return static_cast<float>(loadLE<uint32_t>(p));
      default: return 0.0f;
    }
  }
  uint32_t index(size_t i) const {
    if (!base) return 0;
    const unsigned char* p = base + i * stride;
    switch (componentType) {
      case kUnsignedByte: return loadLE<uint8_t>(p);
      case kUnsignedShort: return loadLE<uint16_t>(p);
      default: return loadLE<uint32_t>(p);
    }
  }
};

// Whether `path` lies inside `folder` once both are resolved (symbolic links followed, so a link
// inside the folder that points out of it counts as outside).
bool isInsideFolder(const std::filesystem::path& path, const std::filesystem::path& folder) {
  std::error_code ec;
  const auto resolved = [&](const std::filesystem::path& p) {
    auto r = std::filesystem::weakly_canonical(std::filesystem::absolute(p.empty() ? "." : p, ec), ec).lexically_normal();
    if (!r.has_filename()) r = r.parent_path();  // "dir/" -> "dir"
    return r;
  };
  const auto base = resolved(folder);
  if (ec) return false;
  const auto target = resolved(path);
  if (ec) return false;
  auto b = base.begin(), t = target.begin();
  for (; b != base.end(); ++b, ++t)
    if (t == target.end() || *b != *t) return false;
  return t != target.end();
}

class GltfReader {
public:
  GltfReader(const std::string& file, const std::filesystem::path& baseDir, bool allowOutside)
      : file_(file), baseDir_(baseDir), allowOutside_(allowOutside) {}

  void setJson(std::string_view text, size_t byteOffset) {
    checkJsonNesting(text, file_);
    try {
      doc_ = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
      // "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..."
      const std::string what = jsonErrorText(e.what());
      size_t colon = what.find(": ");
      std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
      throw InputError(file_, byteAt(byteOffset + (e.byte > 0 ? e.byte - 1 : 0)), "invalid JSON: " + detail);
    } catch (const json::exception& e) {  // out_of_range: a number such as 1e400 beyond double
      throw InputError(file_, "json", "invalid JSON: " + jsonErrorText(e.what()));
    }
    if (!doc_.is_object()) throw InputError(file_, "json", "the top level is not a JSON object");
  }
  void setBinChunk(std::string_view bin) { bin_ = bin; }

  Mesh read() {
    try {
      return readDocument();
    } catch (const json::exception& e) {
      // A value of the wrong JSON type somewhere the checks above did not look.
      std::string what = e.what();
      size_t bracket = what.find("] ");
      throw InputError(file_, "json", "unexpected JSON structure: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
  }

private:
  Mesh readDocument() {
    const json& asset = field(doc_, "asset", "json");
    if (!asset.is_object()) fail("json", "'asset' must be an object");
    if (asset.contains("version")) {
      const json& v = asset["version"];
      if (!v.is_string() || v.get<std::string>().rfind("2.", 0) != 0)
        fail("asset", "glTF version " + jsonExcerpt(v) + " is not supported (need 2.x)");
    }
    if (doc_.contains("extensionsRequired")) {
      for (const json& ext : array(doc_, "extensionsRequired", "json"))
        fail("json", "requires extension " + jsonExcerpt(ext) + ", which is not supported");
    }
    const size_t meshCount = doc_.contains("meshes") ? array(doc_, "meshes", "json").size() : 0;
    if (meshCount == 0) fail("json", "no meshes");
    nodeCount_ = doc_.contains("nodes") ? array(doc_, "nodes", "json").size() : 0;
    buffers_.resize(doc_.contains("buffers") ? array(doc_, "buffers", "json").size() : 0);

    std::vector<size_t> roots;
    const size_t sceneCount = doc_.contains("scenes") ? array(doc_, "scenes", "json").size() : 0;
    if (sceneCount > 0) {
      size_t scene = doc_.contains("scene") ? index(doc_, "scene", sceneCount, "json") : 0;
      const json& s = doc_["scenes"][scene];
      const std::string place = "scene " + std::to_string(scene);
      if (s.contains("nodes"))
        for (size_t i = 0; i < array(s, "nodes", place).size(); ++i) roots.push_back(indexValue(s["nodes"][i], nodeCount_, place, "node"));
    } else if (nodeCount_ > 0) {
      // No scene: every node that is nobody's child.
      std::vector<bool> isChild(nodeCount_, false);
      for (size_t n = 0; n < nodeCount_; ++n) {
        const json& node = doc_["nodes"][n];
        if (node.is_object() && node.contains("children"))
          for (const json& c : array(node, "children", "node " + std::to_string(n)))
            isChild[indexValue(c, nodeCount_, "node " + std::to_string(n), "node")] = true;
      }
      for (size_t n = 0; n < nodeCount_; ++n)
        if (!isChild[n]) roots.push_back(n);
    }
    if (nodeCount_ == 0) {
      for (size_t m = 0; m < meshCount; ++m) addMesh(m, glm::dmat4(1.0));
    } else {
      visitTrees(roots);
    }
    if (mesh_.indices.empty()) fail("scene", "no triangles (no mesh in the scene has a triangle primitive)");
    if (!allNormals_) mesh_.normals.clear();
    if (!allTexcoords_) mesh_.texcoords.clear();
    return std::move(mesh_);
  }

  [[noreturn]] void fail(const std::string& place, const std::string& problem) const {
    throw InputError(file_, place, problem);
  }

  const json& field(const json& obj, const char* key, const std::string& place) const {
    if (!obj.is_object() || !obj.contains(key)) fail(place, std::string("missing '") + key + "'");
    return obj[key];
  }
  const json& array(const json& obj, const char* key, const std::string& place) const {
    const json& a = field(obj, key, place);
    if (!a.is_array()) fail(place, std::string("'") + key + "' must be an array");
    return a;
  }
  uint64_t uint(const json& obj, const char* key, const std::string& place, std::optional<uint64_t> fallback = {}) const {
    if (!obj.contains(key)) {
      if (fallback) return *fallback;
      fail(place, std::string("missing '") + key + "'");
    }
    const json& v = obj[key];
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<int64_t>() >= 0))
      fail(place, std::string("'") + key + "' must be a non-negative integer, not " + jsonExcerpt(v));
    return v.get<uint64_t>();
  }
  size_t indexValue(const json& v, size_t count, const std::string& place, const char* what) const {
    if (!v.is_number_integer() || v.get<int64_t>() < 0 || static_cast<uint64_t>(v.get<int64_t>()) >= count)
      fail(place, std::string(what) + " index " + jsonExcerpt(v) + " is out of range (there are " + std::to_string(count) + ")");
    return static_cast<size_t>(v.get<int64_t>());
  }
  size_t index(const json& obj, const char* key, size_t count, const std::string& place) const {
    return indexValue(field(obj, key, place), count, place, key);
  }
  glm::dvec3 vec3(const json& obj, const char* key, glm::dvec3 fallback, const std::string& place) const {
    if (!obj.contains(key)) return fallback;
    const json& a = obj[key];
    if (!a.is_array() || a.size() != 3) fail(place, std::string("'") + key + "' must be an array of 3 numbers");
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) v[i] = number(a[static_cast<size_t>(i)], place, key);
    return v;
  }
  double number(const json& v, const std::string& place, const char* key) const {
    if (!v.is_number()) fail(place, std::string("'") + key + "' must hold numbers, found " + jsonExcerpt(v));
    double d = v.get<double>();
    if (!std::isfinite(d)) fail(place, std::string("'") + key + "' holds a non-finite number");
    return d;
  }

  // ---- buffers, views, accessors -------------------------------------------------------------

  std::string_view buffer(size_t i) {
    if (i >= buffers_.size()) fail("buffer " + std::to_string(i), "no such buffer");
    if (buffers_[i]) return *buffers_[i];
    const std::string place = "buffer " + std::to_string(i);
    const json& b = doc_["buffers"][i];
    const uint64_t declared = uint(b, "byteLength", place);
    std::string bytes;
    if (!b.contains("uri")) {
      if (i != 0 || !bin_) fail(place, "has no 'uri' and there is no GLB binary chunk");
      if (bin_->size() < declared)
        fail(place, "declares " + withThousands(declared) + " bytes but the GLB binary chunk holds " + withThousands(bin_->size()));
      buffers_[i] = std::string(bin_->substr(0, static_cast<size_t>(declared)));
      return *buffers_[i];
    }
    if (!b["uri"].is_string()) fail(place, "'uri' must be a string");
    const std::string uri = b["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) {
      size_t comma = uri.find(',');
      if (comma == std::string::npos || uri.substr(0, comma).find(";base64") == std::string::npos)
        fail(place, "only base64 data: URIs are supported");
      if (!decodeBase64(std::string_view(uri).substr(comma + 1), bytes)) fail(place, "invalid base64 in data: URI");
    } else {
      if (uri.find("://") != std::string::npos) fail(place, "external URL '" + uri.substr(0, 64) + "' is not supported (only files)");
      const std::filesystem::path p = baseDir_ / percentDecode(uri);
      if (!allowOutside_ && !isInsideFolder(p, baseDir_))
        fail(place, "'uri' \"" + uri + "\" is outside the glTF's folder; marble reads buffers only from there unless "
                    "told otherwise (--allow-outside, or \"allow_outside\": true in a scene)");
      try {
        bytes = readWholeFile(p, p.string());
      } catch (const InputError& e) {
        fail(place, std::string("cannot read '") + uri + "': " + e.what());
      }
    }
    if (bytes.size() < declared)
      fail(place, "declares " + withThousands(declared) + " bytes but its data holds only " + withThousands(bytes.size()) +
                      " (truncated)");
    bytes.resize(static_cast<size_t>(declared));
    buffers_[i] = std::move(bytes);
    return *buffers_[i];
  }

  AccessorView accessor(size_t a, int wantComponents, const char* role) {
    const size_t accessorCount = doc_.contains("accessors") ? array(doc_, "accessors", "json").size() : 0;
    if (a >= accessorCount) fail("accessor " + std::to_string(a), "no such accessor");
    const std::string place = "accessor " + std::to_string(a);
    const json& acc = doc_["accessors"][a];
    if (!acc.is_object()) fail(place, "must be an object");
    if (acc.contains("sparse")) fail(place, "sparse accessors are not supported");
    AccessorView view;
    view.componentType = static_cast<int>(uint(acc, "componentType", place));
    const std::string type = field(acc, "type", place).is_string() ? acc["type"].get<std::string>() : "";
    view.components = componentCount(type);
    view.count = static_cast<size_t>(std::min<uint64_t>(uint(acc, "count", place), ~uint64_t{0} >> 8));
    view.normalized = acc.contains("normalized") && acc["normalized"].is_boolean() && acc["normalized"].get<bool>();
    const size_t csize = componentSize(view.componentType);
    if (csize == 0) fail(place, "unknown componentType " + std::to_string(view.componentType));
    if (view.components != wantComponents)
      fail(place, std::string(role) + " must be " + (wantComponents == 1 ? "SCALAR" : "VEC" + std::to_string(wantComponents)) +
                      ", not " + (type.empty() ? "(missing)" : type));
    if (view.count == 0) fail(place, "count is 0");
    const uint64_t limit = wantComponents == 1 ? 3 * kMaxTriangles : kMaxVertices;
    if (view.count > limit) fail(place, "count " + withThousands(view.count) + " is over the limit of " + withThousands(limit));
    const size_t elementSize = csize * static_cast<size_t>(view.components);
    if (!acc.contains("bufferView")) return view;  // all zeros, per the specification

    const size_t viewCount = doc_.contains("bufferViews") ? array(doc_, "bufferViews", "json").size() : 0;
    const size_t v = index(acc, "bufferView", viewCount, place);
    const std::string viewPlace = "bufferView " + std::to_string(v);
    const json& bv = doc_["bufferViews"][v];
    const size_t bufferIndex = index(bv, "buffer", buffers_.size(), viewPlace);
    const uint64_t viewOffset = uint(bv, "byteOffset", viewPlace, 0);
    const uint64_t viewLength = uint(bv, "byteLength", viewPlace);
    const uint64_t stride = uint(bv, "byteStride", viewPlace, elementSize);
    if (stride < elementSize) fail(viewPlace, "byteStride " + std::to_string(stride) + " is smaller than the element (" +
                                                  std::to_string(elementSize) + " bytes)");
    if (stride > 252) fail(viewPlace, "byteStride " + std::to_string(stride) + " is over 252");
    std::string_view buf = buffer(bufferIndex);
    if (viewOffset > buf.size() || viewLength > buf.size() - viewOffset)
      fail(viewPlace, "bytes " + std::to_string(viewOffset) + ".." + std::to_string(viewOffset + viewLength) +
                          " run past the end of buffer " + std::to_string(bufferIndex) + " (" + withThousands(buf.size()) +
                          " bytes)");
    const uint64_t accOffset = uint(acc, "byteOffset", place, 0);
    const uint64_t span = accOffset + stride * (view.count - 1) + elementSize;  // count <= 150M, stride <= 252: no overflow
    if (span > viewLength)
      fail(place, withThousands(view.count) + " elements from offset " + std::to_string(accOffset) + " need " +
                      withThousands(span) + " bytes but bufferView " + std::to_string(v) + " has " + withThousands(viewLength));
    view.base = reinterpret_cast<const unsigned char*>(buf.data()) + viewOffset + accOffset;
    view.stride = static_cast<size_t>(stride);
    return view;
  }

  // ---- scene traversal -----------------------------------------------------------------------

  glm::dmat4 localMatrix(const json& node, const std::string& place) const {
    if (node.contains("matrix")) {
      const json& m = node["matrix"];
      if (!m.is_array() || m.size() != 16) fail(place, "'matrix' must be an array of 16 numbers");
      glm::dmat4 out;
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out[c][r] = number(m[static_cast<size_t>(c * 4 + r)], place, "matrix");
      return out;
    }
    glm::dvec3 t = vec3(node, "translation", glm::dvec3(0.0), place);
    glm::dvec3 s = vec3(node, "scale", glm::dvec3(1.0), place);
    glm::dquat q(1.0, 0.0, 0.0, 0.0);
    if (node.contains("rotation")) {
      const json& r = node["rotation"];
      if (!r.is_array() || r.size() != 4) fail(place, "'rotation' must be an array of 4 numbers (x, y, z, w)");
      q = glm::dquat(number(r[3], place, "rotation"), number(r[0], place, "rotation"), number(r[1], place, "rotation"),
                     number(r[2], place, "rotation"));
      double len = glm::length(q);
      q = len > 0.0 ? q / len : glm::dquat(1.0, 0.0, 0.0, 0.0);
    }
    glm::dmat4 m = glm::mat4_cast(q);
    m[0] *= s.x;
    m[1] *= s.y;
    m[2] *= s.z;
    m[3] = glm::dvec4(t, 1.0);
    return m;
  }

  // Depth-first over the node hierarchy with an explicit stack (a chain 100,000 nodes deep must
  // not overflow the call stack), in the order a recursive walk would take. glTF 2.0 requires
  // the hierarchy to be disjoint strict trees: no cycles, at most one parent per node (spec
  // section 3.5.2, "Nodes and Hierarchy"). A node reached a second time is therefore an error,
  // not a second instance: that also bounds the work by the number of nodes (a chain in which
  // every node lists the next one twice would otherwise be walked 2^n times).
  void visitTrees(const std::vector<size_t>& roots) {
    constexpr size_t kNone = static_cast<size_t>(-1);
    std::vector<size_t> parentOf(nodeCount_, kNone);
    std::vector<bool> reached(nodeCount_, false);
    struct Pending {
      size_t node, parent;
      glm::dmat4 parentWorld;
    };
    std::vector<Pending> stack;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, kNone, glm::dmat4(1.0)});
    while (!stack.empty()) {
      const Pending at = stack.back();
      stack.pop_back();
      const size_t n = at.node;
      const std::string place = "node " + std::to_string(n);
      if (reached[n]) {
        bool cycle = false;
        for (size_t a = at.parent; a != kNone; a = parentOf[a])
          if (a == n) {
            cycle = true;
            break;
          }
        if (cycle) fail(place, "the node hierarchy has a cycle");
        const std::string first = parentOf[n] == kNone ? "the scene" : "node " + std::to_string(parentOf[n]);
        const std::string second = at.parent == kNone ? "the scene" : "node " + std::to_string(at.parent);
        fail(place, "is reached twice (from " + first + " and from " + second +
                        "); glTF requires each node to have at most one parent");
      }
      reached[n] = true;
      parentOf[n] = at.parent;
      const json& node = doc_["nodes"][n];
      if (!node.is_object()) fail(place, "must be an object");
      const glm::dmat4 world = at.parentWorld * localMatrix(node, place);
      if (node.contains("mesh")) {
        const size_t meshCount = array(doc_, "meshes", "json").size();
        addMesh(index(node, "mesh", meshCount, place), world);
      }
      if (node.contains("children")) {
        const json& children = array(node, "children", place);
        for (size_t c = children.size(); c-- > 0;)
          stack.push_back({indexValue(children[c], nodeCount_, place, "child node"), n, world});
      }
    }
  }

  void addMesh(size_t m, const glm::dmat4& world) {
    const std::string place = "mesh " + std::to_string(m);
    const json& mesh = doc_["meshes"][m];
    const json& prims = array(mesh, "primitives", place);
    for (size_t p = 0; p < prims.size(); ++p) addPrimitive(prims[p], place + " primitive " + std::to_string(p), world);
  }

  void addPrimitive(const json& prim, const std::string& place, const glm::dmat4& world) {
    if (!prim.is_object()) fail(place, "must be an object");
    const uint64_t mode = uint(prim, "mode", place, 4);
    if (mode < 4) return;  // points and lines have no surface
    if (mode > 6) fail(place, "unknown mode " + std::to_string(mode));
    const json& attrs = field(prim, "attributes", place);
    if (!attrs.is_object()) fail(place, "'attributes' must be an object");
    if (!attrs.contains("POSITION")) fail(place, "no POSITION attribute");
    const size_t accessorCount = doc_.contains("accessors") ? array(doc_, "accessors", "json").size() : 0;
    const AccessorView pos = accessor(index(attrs, "POSITION", accessorCount, place), 3, "POSITION");
    if (pos.componentType != kFloat) fail(place, "POSITION must be float");
    std::optional<AccessorView> nrm, uv;
    if (attrs.contains("NORMAL")) {
      nrm = accessor(index(attrs, "NORMAL", accessorCount, place), 3, "NORMAL");
      if (nrm->count != pos.count) fail(place, "NORMAL and POSITION counts differ");
    }
    if (attrs.contains("TEXCOORD_0")) {
      uv = accessor(index(attrs, "TEXCOORD_0", accessorCount, place), 2, "TEXCOORD_0");
      if (uv->count != pos.count) fail(place, "TEXCOORD_0 and POSITION counts differ");
    }
    std::vector<uint32_t> idx;
    if (prim.contains("indices")) {
      const size_t a = index(prim, "indices", accessorCount, place);
      const AccessorView iv = accessor(a, 1, "indices");
      if (iv.componentType != kUnsignedByte && iv.componentType != kUnsignedShort && iv.componentType != kUnsignedInt)
        fail("accessor " + std::to_string(a), "indices must be unsigned byte, short or int");
      idx.resize(iv.count);
      for (size_t i = 0; i < iv.count; ++i) {
        idx[i] = iv.index(i);
        if (idx[i] >= pos.count)
          fail("accessor " + std::to_string(a), "index " + std::to_string(idx[i]) + " (element " + std::to_string(i) +
                                                     ") is out of range (POSITION has " + withThousands(pos.count) + ")");
      }
    } else {
      idx.resize(pos.count);
      for (size_t i = 0; i < pos.count; ++i) idx[i] = static_cast<uint32_t>(i);
    }
    std::vector<uint32_t> tris;
    if (mode == 4) {
      if (idx.size() % 3 != 0) fail(place, "triangle list with " + std::to_string(idx.size()) + " indices (not a multiple of 3)");
      tris = std::move(idx);
    } else {
      for (size_t i = 0; i + 2 < idx.size(); ++i) {
        if (mode == 5) {  // strip: every other triangle flips to keep the winding
          tris.insert(tris.end(), {idx[i + (i & 1)], idx[i + 1 - (i & 1)], idx[i + 2]});
        } else {  // fan
          tris.insert(tris.end(), {idx[0], idx[i + 1], idx[i + 2]});
        }
      }
    }
    if (mesh_.positions.size() + pos.count > kMaxVertices)
      fail(place, "more than " + withThousands(kMaxVertices) + " vertices in all (the limit)");
    if (mesh_.indices.size() / 3 + tris.size() / 3 > kMaxTriangles)
      fail(place, "more than " + withThousands(kMaxTriangles) + " triangles in all (the limit)");

    const glm::dmat3 linear(world);
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirror = glm::determinant(linear) < 0.0;
    const uint32_t base = static_cast<uint32_t>(mesh_.positions.size());
    for (size_t i = 0; i < pos.count; ++i) {
      glm::dvec3 p(pos.component(i, 0), pos.component(i, 1), pos.component(i, 2));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(place, "POSITION element " + std::to_string(i) + " is NaN or infinite");
      mesh_.positions.push_back(glm::vec3(world * glm::dvec4(p, 1.0)));
      if (nrm) {
        glm::dvec3 n = normalMatrix * glm::dvec3(nrm->component(i, 0), nrm->component(i, 1), nrm->component(i, 2));
        double len = glm::length(n);
        mesh_.normals.push_back(len > 0.0 && std::isfinite(len) ? glm::vec3(n / len) : glm::vec3(0.0f));
      }
      // glTF's v runs down the image, the mesh's up (mesh.h).
      if (uv) mesh_.texcoords.emplace_back(uv->component(i, 0), 1.0f - uv->component(i, 1));
    }
    allNormals_ = allNormals_ && nrm.has_value();
    allTexcoords_ = allTexcoords_ && uv.has_value();
    for (size_t t = 0; t + 2 < tris.size(); t += 3) {
      mesh_.indices.push_back(base + tris[t]);
      mesh_.indices.push_back(base + tris[t + (mirror ? 2 : 1)]);
      mesh_.indices.push_back(base + tris[t + (mirror ? 1 : 2)]);
    }
  }

  const std::string& file_;
  std::filesystem::path baseDir_;
  bool allowOutside_ = false;
  json doc_;
  std::optional<std::string_view> bin_;
  std::vector<std::optional<std::string>> buffers_;
  size_t nodeCount_ = 0;
  bool allNormals_ = true, allTexcoords_ = true;
  Mesh mesh_;
};

}  // namespace

Mesh loadGltf(const std::string& file, std::string_view data, const std::filesystem::path& baseDir, bool allowOutside) {
  if (data.size() >= 4 && data.substr(0, 4) == "glTF") return loadGlb(file, data, baseDir, allowOutside);  // misnamed .glb
  GltfReader reader(file, baseDir, allowOutside);
  size_t skip = data.size() >= 3 && data.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  reader.setJson(data.substr(skip), skip);
  return reader.read();
}

Mesh loadGlb(const std::string& file, std::string_view data, const std::filesystem::path& baseDir, bool allowOutside) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  if (data.size() < 12) throw InputError(file, "header", "file is " + std::to_string(data.size()) + " bytes, too short for GLB (12-byte header)");
  if (data.substr(0, 4) != "glTF") throw InputError(file, "header", "not a GLB file (it must start with 'glTF')");
  const uint32_t version = loadLE<uint32_t>(bytes + 4);
  const uint32_t length = loadLE<uint32_t>(bytes + 8);
  if (version != 2) throw InputError(file, "header", "GLB version " + std::to_string(version) + " is not supported (need 2)");
  if (length > data.size())
    throw InputError(file, "header", "declares " + withThousands(length) + " bytes but the file has " + withThousands(data.size()) +
                                         " (truncated)");
  if (length < 20) throw InputError(file, "header", "declared length " + std::to_string(length) + " leaves no room for a JSON chunk");
  const uint32_t jsonLength = loadLE<uint32_t>(bytes + 12);
  const uint32_t jsonType = loadLE<uint32_t>(bytes + 16);
  if (jsonType != 0x4E4F534Au) throw InputError(file, "byte 16", "the first chunk is not JSON");
  if (jsonLength > length - 20)
    throw InputError(file, "byte 12", "JSON chunk of " + withThousands(jsonLength) + " bytes runs past the end of the file (truncated)");
  GltfReader reader(file, baseDir, allowOutside);
  reader.setJson(data.substr(20, jsonLength), 20);
  size_t at = 20 + static_cast<size_t>(jsonLength);
  at = (at + 3) & ~size_t{3};
  if (at + 8 <= length) {
    const uint32_t binLength = loadLE<uint32_t>(bytes + at);
    const uint32_t binType = loadLE<uint32_t>(bytes + at + 4);
    if (binType == 0x004E4942u) {
      if (binLength > length - at - 8)
        throw InputError(file, byteAt(at), "BIN chunk of " + withThousands(binLength) + " bytes runs past the end of the file (truncated)");
      reader.setBinChunk(data.substr(at + 8, binLength));
    }
  }
  return reader.read();
}

}  // namespace marble::mesh_detail

// loadMesh (dispatch and the steps every loaded mesh goes through), up axis, normals, normalization.
#include "marble/mesh/mesh.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "marble/core/error.h"
#include "marble/core/input_file.h"
#include "marble/core/parallel_for.h"
#include "marble/mesh/duplicate_triangles.h"
#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/point_ids.h"
#include "marble/mesh/vertex_normals.h"

namespace marble {

namespace mesh_detail {

std::string withThousands(uint64_t n) {
  std::string digits = std::to_string(n);
  std::string out;
  out.reserve(digits.size() + digits.size() / 3);
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string readWholeFile(const std::filesystem::path& path, const std::string& label) {
  InputFile in(path, label, "a mesh file");
  return readMeshBytes(in, in.size());
}

std::string readMeshBytes(const InputFile& in, uint64_t bytes) {
  if (in.size() == 0) throw InputError(in.label(), "", "file is empty");
  return in.read(bytes, kMaxFileBytes);
}

void rejectBinary(const std::string& file, std::string_view data, std::string_view format) {
  const void* nul = std::memchr(data.data(), '\0', data.size());
  if (nul) {
    size_t at = static_cast<size_t>(static_cast<const char*>(nul) - data.data());
    throw InputError(file, byteAt(at), "binary data (NUL byte) in what should be a text " + std::string(format) + " file");
  }
}

}  // namespace mesh_detail

using namespace mesh_detail;

UpAxis parseUpAxis(std::string_view text) {
  std::string t;
  for (char c : text) {
    if (c == ' ' || c == '\t') continue;
    t += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  if (!t.empty() && t[0] == '+') t.erase(0, 1);
  if (t == "y") return UpAxis::Y;
  if (t == "z") return UpAxis::Z;
  if (t == "x") return UpAxis::X;
  if (t == "-y") return UpAxis::NegY;
  if (t == "-z") return UpAxis::NegZ;
  if (t == "-x") return UpAxis::NegX;
  throw std::invalid_argument("unknown up axis '" + std::string(text) + "' (expected y, z, x, -y, -z or -x)");
}

std::string_view upAxisName(UpAxis axis) {
  switch (axis) {
    case UpAxis::Y: return "y";
    case UpAxis::Z: return "z";
    case UpAxis::X: return "x";
    case UpAxis::NegY: return "-y";
    case UpAxis::NegZ: return "-z";
    case UpAxis::NegX: return "-x";
  }
  return "y";
}

namespace {

// Below this many vertices (or indices) per thread the steps over all of them run on one: a
// thread's start (≈ 20-50 µs) would cost more than it saves.
constexpr size_t kPositionsPerThread = 100000;

// Proper rotations (det +1) that take the named file axis to +Y.
glm::vec3 rotateUp(glm::vec3 v, UpAxis up) {
  switch (up) {
    case UpAxis::Y: return v;
    case UpAxis::Z: return {v.x, v.z, -v.y};     // -90 deg about X
    case UpAxis::NegZ: return {v.x, -v.z, v.y};  // +90 deg about X
    case UpAxis::X: return {-v.y, v.x, v.z};     // +90 deg about Z
    case UpAxis::NegX: return {v.y, -v.x, v.z};  // -90 deg about Z
    case UpAxis::NegY: return {v.x, -v.y, -v.z}; // 180 deg about X
  }
  return v;
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The first i in [0, count) where `is(i)` holds, or `count`: over threads, each range's first, the least.
template <class Predicate>
size_t firstWhere(size_t count, Predicate is) {
  std::vector<size_t> first(workerThreadCount(count, kPositionsPerThread), count);
  parallelFor(first.size(), 1, [&](size_t a, size_t b) {
    for (size_t r = a; r < b; ++r)
      for (size_t i = count * r / first.size(), end = count * (r + 1) / first.size(); i < end; ++i)
        if (is(i)) {
          first[r] = i;
          break;
        }
  });
  return *std::min_element(first.begin(), first.end());
}

// Final checks on what a loader returned; fixes up optional attributes.
void validateLoaded(Mesh& mesh, const std::string& file) {
  if (mesh.indices.empty())
    throw InputError(file, "", "no triangles: the file has " + withThousands(mesh.positions.size()) +
                                   " vertices but no faces");
  if (mesh.indices.size() % 3 != 0) throw InputError(file, "", "internal: index count is not a multiple of 3");
  // Both checks over threads (a large mesh's 5 M indices); each names the first fault in order.
  const uint32_t n = static_cast<uint32_t>(mesh.positions.size());
  const size_t outOfRange = firstWhere(mesh.indices.size(), [&](size_t i) { return mesh.indices[i] >= n; });
  if (outOfRange < mesh.indices.size())
    throw InputError(file, "", "vertex index " + std::to_string(mesh.indices[outOfRange]) + " out of range");
  const size_t notFinite = firstWhere(mesh.positions.size(), [&](size_t i) { return !finite(mesh.positions[i]); });
  if (notFinite < mesh.positions.size())
    throw InputError(file, "vertex " + std::to_string(notFinite), "coordinate is NaN or infinite");
  if (!mesh.texcoords.empty() && mesh.texcoords.size() != mesh.positions.size()) mesh.texcoords.clear();
  if (mesh.normals.size() != mesh.positions.size()) {
    mesh.normals.clear();
  } else {
    // File normals are made unit length; if any is unusable, all are recomputed (mixing file and
    // computed normals would look patchy).
    for (glm::vec3& v : mesh.normals) {
      float len = glm::length(v);
      if (!std::isfinite(len) || len < 1e-20f) {
        mesh.normals.clear();
        break;
      }
      v /= len;
    }
  }
}

}  // namespace

void applyUpAxis(Mesh& mesh, UpAxis up) {
  if (up == UpAxis::Y) return;
  for (std::vector<glm::vec3>* v : {&mesh.positions, &mesh.normals})
    parallelFor(v->size(), kPositionsPerThread, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) (*v)[i] = rotateUp((*v)[i], up);
    });
}

void normalizeMesh(Mesh& mesh) { normalizeMesh(mesh, "mesh"); }

void normalizeMesh(Mesh& mesh, const std::string& source) {
  if (mesh.positions.empty()) throw InputError(source, "bounds", "mesh has no vertices");
  // The bounds per range over threads, then the least and greatest of them (min and max are exact:
  // the same bounds in any order).
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const unsigned ranges = workerThreadCount(mesh.positions.size(), kPositionsPerThread);
  std::vector<glm::vec3> los(ranges, glm::vec3(kInf)), his(ranges, glm::vec3(-kInf));
  parallelFor(ranges, 1, [&](size_t a, size_t b) {
    for (size_t r = a; r < b; ++r) {
      glm::vec3 lo(kInf), hi(-kInf);
      const size_t n = mesh.positions.size();
      for (size_t i = n * r / ranges, end = n * (r + 1) / ranges; i < end; ++i) {
        lo = glm::min(lo, mesh.positions[i]);
        hi = glm::max(hi, mesh.positions[i]);
      }
      los[r] = lo;
      his[r] = hi;
    }
  });
  glm::vec3 lo(kInf), hi(-kInf);
  for (unsigned r = 0; r < ranges; ++r) {
    lo = glm::min(lo, los[r]);
    hi = glm::max(hi, his[r]);
  }
  if (!finite(lo) || !finite(hi)) throw InputError(source, "bounds", "coordinates are NaN or infinite");
  // Extents in double: hi - lo can overflow float for coordinates near FLT_MAX.
  glm::dvec3 centre = (glm::dvec3(lo) + glm::dvec3(hi)) * 0.5;
  glm::dvec3 extent = glm::dvec3(hi) - glm::dvec3(lo);
  double largest = std::max({extent.x, extent.y, extent.z});
  double scale = 2.0 / largest;
  if (!(largest > 0.0) || !std::isfinite(scale))
    throw InputError(source, "bounds", "all vertices are at the same point (zero extent); cannot normalize");
  parallelFor(mesh.positions.size(), kPositionsPerThread, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) mesh.positions[i] = glm::vec3((glm::dvec3(mesh.positions[i]) - centre) * scale);
  });
}

double signedVolume(const Mesh& mesh) {
  double v = 0.0;
  const size_t n = mesh.positions.size();
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    if (a >= n || b >= n || c >= n) continue;
    glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), pc(mesh.positions[c]);
    v += glm::dot(pa, glm::cross(pb, pc));
  }
  return v / 6.0;
}

namespace {

// Says once how many exact duplicate triangles were dropped (mesh/duplicate_triangles.h).
void warnOfDroppedDuplicates(size_t dropped, const std::string& file, std::vector<std::string>* warnings) {
  if (dropped == 0) return;
  const std::string warning = file + ": dropped " + withThousands(dropped) +
                              " duplicate triangles (the same three corners as an earlier triangle, same winding)";
  if (warnings) warnings->push_back(warning);
  else std::cerr << "warning: " << printable(warning, kMessageLineLimit) << "\n";
}

Mesh loadOpenedMesh(const std::filesystem::path& path, const std::string& ext, const InputFile& in,
                    const MeshLoadOptions& options) {
  const std::string& file = in.label();
  // A binary STL's 84-byte header says how much of the file there is to read.
  const uint64_t bytes = ext == ".stl" ? stlBytesToRead(file, in.readPrefix(kStlProbeBytes), in.size()) : in.size();
  // Read by threads into memory left unset (the file's emptiness was checked by loadMesh).
  FileBytes bytesRead = in.readLarge(bytes, kMaxFileBytes);
  const std::string_view data = bytesRead.view();
  Mesh mesh;
  if (ext == ".obj") {
    mesh = loadObj(file, data);
  } else if (ext == ".ply") {
    mesh = loadPly(file, data);
  } else if (ext == ".stl") {
    mesh = loadStl(file, data);
  } else if (ext == ".gltf") {
    mesh = loadGltf(file, data, path.parent_path(), options.allowOutside);
  } else {
    mesh = loadGlb(file, data, path.parent_path(), options.allowOutside);
  }
  // The file's pages, faulted in by the read, become the normals' records (page_buffer.h) when
  // the normals are computed; otherwise they are freed before the heavier steps.
  PageBuffer recycled = std::move(bytesRead.pages);
  validateLoaded(mesh, file);
  if (!mesh.normals.empty()) recycled = {};
  applyUpAxis(mesh, options.up);
  // Normalizing first and computing normals second gives the same normals as the other order
  // (normalization is a uniform scale and a shift) but keeps cross products in float range.
  normalizeMesh(mesh, file);
  // The points (equal positions) found once for both steps below. Duplicates are judged on the
  // positions that will be drawn (after normalization), as the normals' points are: two corners
  // that the scale rounds to one position are one point to both.
  // Without file normals the normals' pass drops the duplicates as it goes (the same triangles,
  // found point by point: vertex_normals.h).
  const std::vector<uint32_t> points = pointIds(mesh.positions);
  const size_t dropped = mesh.normals.empty()
                             ? removeDuplicatesAndComputeNormals(mesh, options.creaseAngleDeg, points, &recycled)
                             : removeDuplicateTriangles(mesh, points);
  warnOfDroppedDuplicates(dropped, file, options.warnings);
  return mesh;
}

}  // namespace

Mesh loadMesh(const std::filesystem::path& path, UpAxis up) { return loadMesh(path, MeshLoadOptions{up}); }

Mesh loadMesh(const std::filesystem::path& path, const MeshLoadOptions& options) {
  const std::string file = path.string();
  std::string ext = path.extension().string();
  for (char& c : ext) c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  // The file must exist before its extension matters (a typo'd path is the commoner mistake).
  const InputFile in(path, file, "a mesh file");
  if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".gltf" && ext != ".glb")
    throw InputError(file, "", "unknown mesh format '" + (ext.empty() ? std::string("(no extension)") : ext) +
                                   "' (expected .obj, .ply, .stl, .gltf or .glb)");
  if (in.size() == 0) throw InputError(file, "", "file is empty");
  try {
    return loadOpenedMesh(path, ext, in, options);
  } catch (const std::bad_alloc&) {
    // Out of memory is the machine's limit, not a fault in the file (exit 1), but the user
    // needs to know which file asked for it.
    throw EnvironmentError(file + ": out of memory while loading this " + withThousands(in.size()) + "-byte mesh");
  }
}

}  // namespace marble

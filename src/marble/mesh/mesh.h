#pragma once
// A triangle mesh as the renderer consumes it: indexed triangles with one normal per vertex.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace marble {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // empty until computed, then one per position
  // Texture coordinates: empty when the file has none, else one per position. OBJ's convention
  // (and OpenGL's): v = 0 is the image's bottom row. glTF's v (0 = top row) is flipped on load
  // and on export (bake/gltf_export.cpp).
  std::vector<glm::vec2> texcoords;
  std::vector<uint32_t> indices;     // three per triangle

  size_t triangleCount() const { return indices.size() / 3; }
};

// Which axis of a file points up. The mesh is turned so that axis becomes +Y;
// nothing is ever guessed (design.md, Conventions).
enum class UpAxis { Y, Z, X, NegY, NegZ, NegX };
UpAxis parseUpAxis(std::string_view text);  // "y", "z", "x", "-y", ...; throws std::invalid_argument
std::string_view upAxisName(UpAxis axis);

// How a mesh file is loaded.
struct MeshLoadOptions {
  UpAxis up = UpAxis::Y;
  // glTF buffers may be read from outside the glTF's folder (--allow-outside, or a scene's
  // "allow_outside"); by default a buffer uri such as ../../etc/passwd is refused
  // (docs/reliability.md, "What a file may pull in").
  bool allowOutside = false;
  // Warnings about the file (duplicate triangles dropped) are appended here; when null they are
  // printed to stderr as "warning: ...".
  std::vector<std::string>* warnings = nullptr;
};

// Loads OBJ, PLY (ASCII/binary), STL (ASCII/binary) or glTF 2.0 (.gltf/.glb) by extension
// (content sniffing for STL). Throws InputError "<file>: <place>: <problem>".
// The result is turned to +Y up, has smooth normals when the file had none, and is normalized.
// Exact duplicate triangles are dropped with one warning (mesh/duplicate_triangles.h).
// Running out of memory is an EnvironmentError naming the file.
Mesh loadMesh(const std::filesystem::path& path, UpAxis up = UpAxis::Y);
Mesh loadMesh(const std::filesystem::path& path, const MeshLoadOptions& options);

// Area-weighted smooth normals; degenerate triangles contribute nothing, and a vertex with
// no usable neighbour gets +Y rather than NaN.
void computeSmoothNormals(Mesh& mesh);

// Bounding-box centre to the origin, then a uniform scale so the largest extent is 2.0.
// A mesh with no positions or zero extent throws InputError(source, "bounds", ...); the
// one-argument form names the source "mesh".
void normalizeMesh(Mesh& mesh);
void normalizeMesh(Mesh& mesh, const std::string& source);

// Signed volume enclosed by the triangles (divergence theorem); > 0 for a closed mesh wound
// counter-clockwise seen from outside. Meaningful only for closed meshes.
double signedVolume(const Mesh& mesh);

// Rotates positions and normals so that `up` becomes +Y.
void applyUpAxis(Mesh& mesh, UpAxis up);

// Meshes compiled into the binary, by name ("sculpture" is the default).
std::vector<std::string> builtinMeshNames();
Mesh builtinMesh(std::string_view name);  // throws InputError for an unknown name
constexpr std::string_view kDefaultBuiltinMesh = "sculpture";

}  // namespace marble

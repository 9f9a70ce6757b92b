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

// The crease angle used when neither the scene nor the command line gives one. 60 degrees splits
// the cube's edges (90) and the dodecahedron's (63.4), as a user expects of them; on the shared
// decimated scans it splits 3.3 % (dragon), 8.4 % (buddha), 0.6 % (bunny) of the edges, all on
// tiny folded triangles where it changes no visible shading (docs/meshes.md, "Normals", measured).
inline constexpr float kDefaultCreaseAngleDeg = 60.0f;
// 180 (or more) is "no crease": one normal per point, as Blender's Shade Smooth without Auto Smooth.
inline constexpr float kNoCreaseDeg = 180.0f;

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
  // For a file without normals: edges whose faces' normals are more than this many degrees apart
  // are hard (computeVertexNormals in vertex_normals.h). The file's own normals are used as given.
  float creaseAngleDeg = kDefaultCreaseAngleDeg;
};

// Loads OBJ, PLY (ASCII/binary), STL (ASCII/binary) or glTF 2.0 (.gltf/.glb) by extension
// (content sniffing for STL). Throws InputError "<file>: <place>: <problem>".
// The result is turned to +Y up and normalized. The file's own normals are used as given; when it
// has none, they are computed as Blender does (angle-weighted, hard edges split at
// options.creaseAngleDeg: computeVertexNormals in vertex_normals.h). Exact duplicate triangles (judged
// after normalization) are dropped with one warning (mesh/duplicate_triangles.h).
// Running out of memory is an EnvironmentError naming the file.
Mesh loadMesh(const std::filesystem::path& path, UpAxis up = UpAxis::Y);
Mesh loadMesh(const std::filesystem::path& path, const MeshLoadOptions& options);

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

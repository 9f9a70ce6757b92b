#pragma once
// Automatic texture coordinates for meshes that have none (docs/export.md, "Unwrap"):
// charts grown over shared edges while the face normal stays within a cone around the chart's
// seed normal, each chart projected orthographically along that seed normal (so no triangle
// flips, and a triangle's area shrinks by at most cos(cone)), turned to its principal axis, then
// all charts packed at one common scale (equal texel density) into the unit square by shelves,
// with a gap of 2 x padding texels between charts for the bake's edge dilation.
//
// No Debian package provides an unwrapper (xatlas, UVAtlas are not packaged), so this is marble's own.
#include <cstdint>
#include <string>
#include <vector>

#include "marble/mesh/mesh.h"

namespace marble {

struct UvUnwrapOptions {
  int textureSize = 2048;       // the texture the charts are packed for (padding is in its texels)
  int paddingTexels = 4;        // empty texels kept on every side of a chart
  float coneAngleDeg = 50.0f;   // largest angle between a face normal and its chart's seed normal
  std::string source = "mesh";  // names the mesh in errors (its file)
};

struct UvUnwrapStats {
  int charts = 0;
  double packingEfficiency = 0;  // texture area covered by triangles / the whole unit square
  // Texel density (texels per object unit, sqrt(uv area / surface area) per triangle): the
  // area-weighted coefficient of variation, and the 5th/95th percentile ratio to the median.
  double densityCv = 0;
  double densityP05 = 0, densityP95 = 0;
};

struct UvUnwrapResult {
  Mesh mesh;                          // vertices split at chart borders; texcoords set
  std::vector<uint32_t> sourceVertex; // for each new vertex, the input vertex it copies
  UvUnwrapStats stats;
};

// Throws InputError("mesh", "unwrap", ...) when the mesh has no triangles.
UvUnwrapResult unwrapUvs(const Mesh& mesh, const UvUnwrapOptions& options = {});

// Texel density statistics of any mesh with texcoords (used on the file's UVs too).
UvUnwrapStats measureUvLayout(const Mesh& mesh);

}  // namespace marble

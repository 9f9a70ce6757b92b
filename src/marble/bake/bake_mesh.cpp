#include "marble/bake/bake_mesh.h"

#include <algorithm>
#include <cstdio>

#include "marble/bake/uv_raster.h"
#include "marble/core/error.h"

namespace marble {

UvSource parseUvSource(const std::string& name) {
  if (name == "auto") return UvSource::Auto;
  if (name == "file") return UvSource::File;
  if (name == "unwrap") return UvSource::Unwrap;
  throw InputError("--uv-from", "", "expected auto, file or unwrap, got '" + name + "'");
}

namespace {

// Why the file's texcoords cannot be baked onto, or empty when they can. Overlap is measured on
// a grid as fine as the texture (at most 2048): a texel covered by two triangles would hold
// the colour of only one of the two places on the surface.
std::string fileUvProblem(const Mesh& mesh, int textureSize) {
  if (mesh.texcoords.empty()) return "the file has no texture coordinates";
  const UvOverlap o = measureUvOverlap(mesh, std::min(textureSize, 2048));
  if (o.outsideTriangles > 0)
    return std::to_string(o.outsideTriangles) + " triangles have texture coordinates outside [0,1] (tiling UVs cannot be baked)";
  if (o.coveredSamples == 0) return "the texture coordinates cover no texel (all triangles are degenerate in UV space)";
  // A few texels on chart borders can be claimed twice by rounding; more than 0.1% is overlap.
  if (o.overlapSamples * 1000 > o.coveredSamples) {
    char pct[32];
    std::snprintf(pct, sizeof pct, "%.2f%%", 100.0 * static_cast<double>(o.overlapSamples) / static_cast<double>(o.coveredSamples));
    return std::string("the texture coordinates overlap: ") + pct + " of the covered texels belong to two or more triangles";
  }
  return {};
}

}  // namespace

BakeMesh prepareBakeMesh(const Mesh& loaded, UvSource source, int textureSize, int paddingTexels, const std::string& file) {
  if (loaded.triangleCount() == 0) throw InputError(file, "", "no triangles to bake onto");
  BakeMesh out;
  if (source != UvSource::Unwrap) {
    const std::string problem = fileUvProblem(loaded, textureSize);
    if (problem.empty()) {
      out.mesh = loaded;
      out.stats = measureUvLayout(out.mesh);
      return out;
    }
    if (source == UvSource::File) throw InputError(file, "texcoords", problem + " (--uv-from file)");
    if (!loaded.texcoords.empty()) out.note = problem + "; unwrapping instead";
  }
  UvUnwrapOptions options;
  options.textureSize = textureSize;
  options.paddingTexels = paddingTexels;
  options.source = file;
  UvUnwrapResult r = unwrapUvs(loaded, options);
  out.mesh = std::move(r.mesh);
  out.stats = r.stats;
  out.unwrapped = true;
  return out;
}

}  // namespace marble

#pragma once
// The mesh a bake works on: the loaded (normalized) mesh with texture coordinates, either the
// file's (checked: inside [0,1], no texel covered twice) or a fresh unwrap (bake/uv_unwrap.h).
#include <string>

#include "marble/bake/uv_unwrap.h"
#include "marble/mesh/mesh.h"

namespace marble {

// "auto": the file's texcoords when it has usable ones, else an unwrap; "file": the file's or an
// error; "unwrap": always unwrap.
enum class UvSource { Auto, File, Unwrap };
UvSource parseUvSource(const std::string& name);  // throws InputError("--uv-from", ...)

struct BakeMesh {
  Mesh mesh;
  bool unwrapped = false;
  UvUnwrapStats stats;
  std::string note;  // why auto did not keep the file's texcoords (empty otherwise)
};

// `file` names the source in messages. Throws InputError: no triangles; with "file", missing,
// out-of-range or overlapping texcoords.
BakeMesh prepareBakeMesh(const Mesh& loaded, UvSource source, int textureSize, int paddingTexels, const std::string& file);

}  // namespace marble

#pragma once
// glTF 2.0 export (`marble export`, docs/export.md): the mesh with its normals and texture
// coordinates, the baked texture set, PBR metallic-roughness and the stone's light transport in
// KHR_materials_volume, KHR_materials_diffuse_transmission, KHR_materials_ior and
// KHR_materials_specular (bake/gltf_material.h has the mapping). Positions are in metres
// (mm_per_unit / 1000 per unit of the normalized mesh), as glTF specifies. The bytes depend on the
// input only (sorted JSON keys, shortest round-trip floats, deterministic PNGs): the same input
// gives the same file.
#include <filesystem>
#include <string>

#include "marble/bake/texture_bake.h"
#include "marble/mesh/mesh.h"
#include "marble/scene/material.h"

namespace marble {

struct GltfExportInput {
  const Mesh& mesh;  // with normals and texcoords (one per position)
  const TextureSet& textures;
  const Material& material;
  float mmPerUnit = 100.0f;
};

enum class GltfContainer { Glb, Gltf };  // binary, or JSON with the buffer and images as data: URIs

std::string encodeGltf(const GltfExportInput& in, GltfContainer container);

// By the extension of `path` (.glb or .gltf; anything else is an InputError), written atomically.
void writeGltf(const std::filesystem::path& path, const GltfExportInput& in);
GltfContainer gltfContainerFor(const std::filesystem::path& path);  // throws InputError

}  // namespace marble

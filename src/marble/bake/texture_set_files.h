#pragma once
// A baked texture set on disk (`marble bake -o DIR`): base_color.png, metallic_roughness.png,
// thickness.png (and thickness.exr, unquantized in millimetres) and material.json, which says what each file holds, the thickness's scale, the
// texture coordinates' provenance and the glTF parameters (docs/export.md).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "marble/bake/bake_mesh.h"
#include "marble/bake/texture_bake.h"

namespace marble {

inline constexpr const char* kBaseColorFile = "base_color.png";
inline constexpr const char* kMetallicRoughnessFile = "metallic_roughness.png";
inline constexpr const char* kThicknessFile = "thickness.png";
inline constexpr const char* kThicknessExrFile = "thickness.exr";  // the same map in millimetres, half float (OpenEXR)
inline constexpr const char* kMaterialFile = "material.json";

nlohmann::json describeTextureSet(const TextureSet& set, const Material& m, float mmPerUnit, const BakeMesh& mesh);

// Checks, creating nothing, that `dir` is or can be made a writable folder: the nearest part of
// the path that exists must be a folder marble may write in. Throws InputError(dir, "", problem).
void checkOutputFolder(const std::filesystem::path& dir);

// Creates `dir` if needed, encodes every file, then writes each atomically (core/atomic_file.h).
// mmPerUnit: the scene's, for thickness.exr's millimetres.
void writeTextureSet(const std::filesystem::path& dir, const TextureSet& set, float mmPerUnit, const nlohmann::json& description);

}  // namespace marble

#include "marble/bake/texture_set_files.h"

#include <unistd.h>

#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "marble/bake/gltf_material.h"
#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/scene/material_io.h"

namespace marble {

using json = nlohmann::json;

json describeTextureSet(const TextureSet& set, const Material& m, float mmPerUnit, const BakeMesh& mesh) {
  const GltfMaterialParams g = gltfMaterialFor(m, mmPerUnit);
  json uv = {{"source", mesh.unwrapped ? "unwrap" : "file"},
             {"packing_efficiency", mesh.stats.packingEfficiency},
             {"texel_density_cv", mesh.stats.densityCv},
             {"texel_density_p05_over_median", mesh.stats.densityP05},
             {"texel_density_p95_over_median", mesh.stats.densityP95}};
  if (mesh.unwrapped) uv["charts"] = mesh.stats.charts;
  return {
      {"generator", "marble bake"},
      {"mm_per_unit", mmPerUnit},
      {"uv", uv},
      {"textures",
       {{"base_color", {{"file", kBaseColorFile}, {"size", set.baseColor.width}, {"encoding", "sRGB"}, {"coverage", set.coverage}}},
        {"metallic_roughness",
         {{"file", kMetallicRoughnessFile}, {"size", set.metallicRoughness.width}, {"encoding", "linear"},
          {"channels", {{"G", "roughness"}, {"B", "metalness"}}}}},
        {"thickness",
         {{"file", kThicknessFile}, {"size", set.thickness.width}, {"encoding", "linear"},
          {"convention", "local thickness (mean distance along rays cast inward around the normal to where they leave the mesh), "
                         "normalized: value / 255 * scale"},
          {"scale_units", set.thicknessScale},
          {"scale_mm", set.thicknessScale * mmPerUnit}}},
        {"thickness_mm",
         {{"file", kThicknessExrFile}, {"size", set.thickness.width}, {"encoding", "linear, 16-bit half float, R = G = B"},
          {"convention", "the same local thickness, unquantized, in millimetres"}}}}},
      {"gltf",
       {{"roughnessFactor", g.roughness},
        {"metallicFactor", g.metallic},
        {"ior", g.ior},
        {"specularFactor", g.specular},
        {"attenuationColor", {g.attenuationColor.x, g.attenuationColor.y, g.attenuationColor.z}},
        {"attenuationDistance_m", g.attenuationDistance},
        {"diffuseTransmissionFactor", g.diffuseTransmission},
        {"thicknessFactor_m", set.thicknessScale * g.metresPerUnit}}},
      {"material", materialToJson(m)},
  };
}

void checkOutputFolder(const std::filesystem::path& dir) {
  if (dir.empty()) throw InputError("-o", "", "an output folder is required (e.g. -o textures)");
  std::error_code ec;
  std::filesystem::path existing = std::filesystem::absolute(dir, ec);
  while (!existing.empty() && !std::filesystem::exists(existing, ec) && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!std::filesystem::is_directory(existing, ec))
    throw InputError(dir.string(), "", "cannot create folder: " + existing.string() + " is not a folder");
  if (::access(existing.c_str(), W_OK) != 0)
    throw InputError(dir.string(), "", "cannot create or write the folder: " + existing.string() + " is not writable");
}

namespace {

// The thickness in millimetres (the normalized values times the scale) as a float EXR.
std::string encodeThicknessMm(const TextureSet& set, float mmPerUnit) {
  ImageRGBF img;
  img.width = set.thickness.width;
  img.height = set.thickness.height;
  img.pixels.resize(set.thicknessValues.size() * 3);
  const float scaleMm = set.thicknessScale * mmPerUnit;
  for (size_t i = 0; i < set.thicknessValues.size(); ++i) img.pixels[i * 3] = img.pixels[i * 3 + 1] = img.pixels[i * 3 + 2] = set.thicknessValues[i] * scaleMm;
  return encodeExr(img);
}

}  // namespace

void writeTextureSet(const std::filesystem::path& dir, const TextureSet& set, float mmPerUnit, const json& description) {
  std::vector<std::pair<std::string, std::string>> files = {{kBaseColorFile, encodePng(set.baseColor)},
                                                            {kMetallicRoughnessFile, encodePng(set.metallicRoughness)},
                                                            {kThicknessFile, encodePng(set.thickness)},
                                                            {kThicknessExrFile, encodeThicknessMm(set, mmPerUnit)},
                                                            {kMaterialFile, description.dump(2) + "\n"}};
  for (const auto& [name, bytes] : files)
    if (bytes.empty()) throw InputError((dir / name).string(), "", "encoding failed");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir.string(), "", "cannot create folder" + (ec ? ": " + ec.message() : std::string()));
  // The set appears whole or not at all: every file is staged first, then all are renamed
  // (AtomicFileSet, core/atomic_file.h; docs/reliability.md, "Files written together").
  AtomicFileSet staged;
  for (const auto& [name, bytes] : files) staged.add(dir / name, bytes);
  staged.commit();
}

}  // namespace marble

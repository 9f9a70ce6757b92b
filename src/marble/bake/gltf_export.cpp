#include "marble/bake/gltf_export.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "marble/bake/gltf_material.h"
#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/scene/material_io.h"

namespace marble {
namespace {

using json = nlohmann::json;

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The binary buffer and the bufferViews into it, each view 4-byte aligned.
struct BinaryBuilder {
  std::string bytes;
  json views = json::array();

  int add(const void* data, size_t size, int target) {
    while (bytes.size() % 4) bytes.push_back('\0');
    json view = {{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", size}};
    if (target) view["target"] = target;
    bytes.append(static_cast<const char*>(data), size);
    views.push_back(view);
    return static_cast<int>(views.size()) - 1;
  }
};

std::string base64(const std::string& in) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const uint32_t v = (uint32_t{static_cast<uint8_t>(in[i])} << 16) | (uint32_t{static_cast<uint8_t>(in[i + 1])} << 8) |
                       static_cast<uint8_t>(in[i + 2]);
    out += k[v >> 18];
    out += k[(v >> 12) & 63];
    out += k[(v >> 6) & 63];
    out += k[v & 63];
  }
  if (i < in.size()) {
    uint32_t v = uint32_t{static_cast<uint8_t>(in[i])} << 16;
    if (i + 1 < in.size()) v |= uint32_t{static_cast<uint8_t>(in[i + 1])} << 8;
    out += k[v >> 18];
    out += k[(v >> 12) & 63];
    out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

json vec3Json(glm::vec3 v) { return json::array({v.x, v.y, v.z}); }

}  // namespace

GltfContainer gltfContainerFor(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".glb") return GltfContainer::Glb;
  if (ext == ".gltf") return GltfContainer::Gltf;
  throw InputError(path.string(), "", "expected a .glb or .gltf file name");
}

std::string encodeGltf(const GltfExportInput& in, GltfContainer container) {
  const Mesh& mesh = in.mesh;
  const GltfMaterialParams g = gltfMaterialFor(in.material, in.mmPerUnit);
  const size_t n = mesh.positions.size();

  // Vertex data in metres; normals re-normalized (the validator checks unit length); v flipped
  // (glTF's v runs down the image, the mesh's up: mesh.h).
  std::vector<float> positions(n * 3), normals(n * 3), uvs(n * 2);
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 p = mesh.positions[i] * g.metresPerUnit;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    glm::vec3 nn = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0);
    const float len = glm::length(nn);
    nn = len > 0 && std::isfinite(len) ? nn / len : glm::vec3(0, 1, 0);
    for (int k = 0; k < 3; ++k) {
      positions[i * 3 + k] = p[k];
      normals[i * 3 + k] = nn[k];
    }
    uvs[i * 2] = mesh.texcoords[i].x;
    uvs[i * 2 + 1] = 1.0f - mesh.texcoords[i].y;
  }

  BinaryBuilder bin;
  const int posView = bin.add(positions.data(), positions.size() * sizeof(float), kArrayBuffer);
  const int nrmView = bin.add(normals.data(), normals.size() * sizeof(float), kArrayBuffer);
  const int uvView = bin.add(uvs.data(), uvs.size() * sizeof(float), kArrayBuffer);
  const int idxView = bin.add(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t), kElementArrayBuffer);
  const std::string pngs[3] = {encodePng(in.textures.baseColor), encodePng(in.textures.metallicRoughness),
                               encodePng(in.textures.thickness)};
  const char* imageNames[3] = {"base_color", "metallic_roughness", "thickness"};
  json images = json::array();
  for (int i = 0; i < 3; ++i) {
    if (pngs[i].empty()) throw InputError("export", imageNames[i], "PNG encoding failed");
    if (container == GltfContainer::Glb)
      images.push_back({{"name", imageNames[i]}, {"mimeType", "image/png"}, {"bufferView", bin.add(pngs[i].data(), pngs[i].size(), 0)}});
    else
      images.push_back({{"name", imageNames[i]}, {"uri", "data:image/png;base64," + base64(pngs[i])}});
  }
  while (bin.bytes.size() % 4) bin.bytes.push_back('\0');

  json accessors = json::array({
      {{"bufferView", posView}, {"componentType", kFloat}, {"count", n}, {"type", "VEC3"}, {"min", vec3Json(lo)}, {"max", vec3Json(hi)}},
      {{"bufferView", nrmView}, {"componentType", kFloat}, {"count", n}, {"type", "VEC3"}},
      {{"bufferView", uvView}, {"componentType", kFloat}, {"count", n}, {"type", "VEC2"}},
      {{"bufferView", idxView}, {"componentType", kUnsignedInt}, {"count", mesh.indices.size()}, {"type", "SCALAR"}},
  });
  const std::string name = in.material.name.empty() ? "marble" : in.material.name;
  json material = {
      {"name", name},
      // The design itself, for tools that read it back (tools/blender_marble.py): every key of a preset file.
      {"extras", {{"marble", materialToJson(in.material)}, {"mm_per_unit", in.mmPerUnit}}},
      {"pbrMetallicRoughness",
       {{"baseColorTexture", {{"index", 0}}},
        {"metallicRoughnessTexture", {{"index", 1}}},
        {"metallicFactor", 1.0},
        {"roughnessFactor", 1.0}}},
      {"extensions",
       {{"KHR_materials_ior", {{"ior", g.ior}}},
        {"KHR_materials_specular", {{"specularFactor", g.specular}}},
        {"KHR_materials_diffuse_transmission",
         {{"diffuseTransmissionFactor", g.diffuseTransmission}, {"diffuseTransmissionColorTexture", {{"index", 0}}}}},
        {"KHR_materials_volume",
         {{"thicknessFactor", in.textures.thicknessScale * g.metresPerUnit},
          {"thicknessTexture", {{"index", 2}}},
          {"attenuationDistance", g.attenuationDistance},
          {"attenuationColor", vec3Json(g.attenuationColor)}}}}},
  };
  json doc = {
      {"asset", {{"version", "2.0"}, {"generator", "marble export"}}},
      {"extensionsUsed", json::array({"KHR_materials_diffuse_transmission", "KHR_materials_ior", "KHR_materials_specular",
                                      "KHR_materials_volume"})},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", json::array({0})}}})},
      {"nodes", json::array({{{"mesh", 0}, {"name", name}}})},
      {"meshes", json::array({{{"name", name},
                               {"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                                            {"indices", 3},
                                                            {"material", 0}}})}}})},
      {"materials", json::array({material})},
      // Linear filtering with trilinear mips: the bake's padding keeps mip levels free of seams.
      {"samplers", json::array({{{"magFilter", 9729}, {"minFilter", 9987}}})},
      {"textures", json::array({{{"sampler", 0}, {"source", 0}}, {{"sampler", 0}, {"source", 1}}, {{"sampler", 0}, {"source", 2}}})},
      {"images", images},
      {"accessors", accessors},
      {"bufferViews", bin.views},
  };
  if (container == GltfContainer::Gltf) {
    doc["buffers"] = json::array({{{"byteLength", bin.bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin.bytes)}}});
    return doc.dump(1) + "\n";
  }
  doc["buffers"] = json::array({{{"byteLength", bin.bytes.size()}}});
  std::string text = doc.dump();
  while (text.size() % 4) text.push_back(' ');
  auto u32 = [](std::string& s, uint32_t v) {
    for (int k = 0; k < 4; ++k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
  };
  std::string out;
  const uint64_t total = 12 + 8 + text.size() + 8 + bin.bytes.size();
  if (total > std::numeric_limits<uint32_t>::max()) throw InputError("export", "", "the .glb would exceed 4 GiB; use a smaller --size");
  out.reserve(static_cast<size_t>(total));
  u32(out, 0x46546C67u);  // "glTF"
  u32(out, 2);
  u32(out, static_cast<uint32_t>(total));
  u32(out, static_cast<uint32_t>(text.size()));
  u32(out, 0x4E4F534Au);  // "JSON"
  out += text;
  u32(out, static_cast<uint32_t>(bin.bytes.size()));
  u32(out, 0x004E4942u);  // "BIN\0"
  out += bin.bytes;
  return out;
}

void writeGltf(const std::filesystem::path& path, const GltfExportInput& in) {
  writeFileAtomically(path, encodeGltf(in, gltfContainerFor(path)));
}

}  // namespace marble

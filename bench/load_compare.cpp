// marble_load_compare: marble's mesh loaders side by side with assimp's on the same files (issue
// 20, deliverable 4). Every run loads every file with every loader in turn (interleaved, so a
// shared machine's drift hits all columns alike); the table gives medians of wall time and of the
// process's CPU time (all threads), and the triangle count each loader ended with.
//
//   marble_load_compare [--runs N] [--up z] [--no-assimp] FILE...      (.obj .ply .stl)
//
// Columns:
//   marble parse  - the file read and parsed (mesh_detail::loadObj/Ply/Stl): the work assimp's
//                   importer does, parallel where it pays (files >= 4 MB: one part per core)
//   parse 1 part  - the same read front to back on one thread (loadObjInChunks(1),
//                   loadPlyInParts(1), loadStlAsciiInChunks(1); a binary STL is one pass anyway); before the
//                   timed runs, each file's mesh from both is compared byte for byte
//   marble load   - loadMesh: parse, duplicate triangles dropped, up axis, normalization,
//                   angle-weighted normals with the 60-degree crease (what `marble` runs)
//   assimp read   - Importer::ReadFile with aiProcess_Triangulate | aiProcess_JoinIdenticalVertices
//                   (indexed triangles with shared vertices, as marble's parse gives)
//   assimp +norm  - the same plus aiProcess_GenSmoothNormals at a 60-degree smoothing angle
//                   (AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE), the nearest to marble load
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "marble/core/allocator_tuning.h"
#include "marble/core/error.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/mesh_internal.h"

#include "load_timing.h"

namespace {

using load_timing::cpuMs;
using load_timing::median;
using load_timing::wallMs;

struct Loader {
  const char* name;
  std::function<size_t(const std::filesystem::path&)> load;  // returns the triangle count
};

size_t marbleParse(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string data = marble::mesh_detail::readWholeFile(path, file);
  if (ext == ".obj") return marble::mesh_detail::loadObj(file, data).triangleCount();
  if (ext == ".ply") return marble::mesh_detail::loadPly(file, data).triangleCount();
  return marble::mesh_detail::loadStl(file, data).triangleCount();
}

marble::Mesh parseInParts(const std::filesystem::path& path, unsigned parts) {
  const std::string file = path.string();
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string data = marble::mesh_detail::readWholeFile(path, file);
  namespace md = marble::mesh_detail;
  if (ext == ".obj") return parts == 0 ? md::loadObj(file, data) : md::loadObjInChunks(file, data, parts);
  if (ext == ".ply") return parts == 0 ? md::loadPly(file, data) : md::loadPlyInParts(file, data, parts);
  uint32_t count = 0;
  if (data.size() >= 84) std::memcpy(&count, data.data() + 80, 4);
  const bool binary = data.size() == 84 + 50ull * count;  // read in one pass either way
  return parts == 0 || binary ? md::loadStl(file, data) : md::loadStlAsciiInChunks(file, data, parts);
}

bool sameMesh(const marble::Mesh& a, const marble::Mesh& b) {
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.positions, b.positions) && same(a.normals, b.normals) && same(a.texcoords, b.texcoords) &&
         same(a.indices, b.indices);
}

size_t assimpRead(const std::filesystem::path& path, bool normals) {
  Assimp::Importer importer;
  importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 60.0f);
  unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
  if (normals) flags |= aiProcess_GenSmoothNormals;
  const aiScene* scene = importer.ReadFile(path.string(), flags);
  if (!scene) throw marble::InputError(path.string(), "", std::string("assimp: ") + importer.GetErrorString());
  size_t triangles = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) triangles += scene->mMeshes[i]->mNumFaces;
  return triangles;
}

}  // namespace

int main(int argc, char** argv) {
  marble::keepFreedMemoryForReuse();  // as `marble` runs
  int runs = 5;
  bool withAssimp = true;
  marble::UpAxis up = marble::UpAxis::Y;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--up" && i + 1 < argc) up = marble::parseUpAxis(argv[++i]);
    else if (a == "--no-assimp") withAssimp = false;
    else files.emplace_back(a);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: marble_load_compare [--runs N] [--up AXIS] [--no-assimp] FILE...\n");
    return 2;
  }
  std::vector<Loader> loaders = {
      {"marble parse", marbleParse},
      {"parse 1 part", [](const std::filesystem::path& p) { return parseInParts(p, 1).triangleCount(); }},
      {"marble load", [up](const std::filesystem::path& p) { return marble::loadMesh(p, up).triangleCount(); }},
  };
  if (withAssimp) {
    loaders.push_back({"assimp read", [](const std::filesystem::path& p) { return assimpRead(p, false); }});
    loaders.push_back({"assimp +norm", [](const std::filesystem::path& p) { return assimpRead(p, true); }});
  }
  // [file][loader] -> samples
  std::vector<std::vector<std::vector<double>>> wall(files.size(), std::vector<std::vector<double>>(loaders.size()));
  auto cpu = wall;
  std::vector<std::vector<size_t>> triangles(files.size(), std::vector<size_t>(loaders.size()));
  try {
    for (const auto& f : files)
      if (!sameMesh(parseInParts(f, 0), parseInParts(f, 1))) {
        std::fprintf(stderr, "marble_load_compare: %s: the parallel parse differs from the one-part parse\n",
                     f.string().c_str());
        return 1;
      }
    for (int r = 0; r < runs; ++r)
      for (size_t f = 0; f < files.size(); ++f)
        for (size_t l = 0; l < loaders.size(); ++l) {
          const double w0 = wallMs(), c0 = cpuMs();
          triangles[f][l] = loaders[l].load(files[f]);
          wall[f][l].push_back(wallMs() - w0);
          cpu[f][l].push_back(cpuMs() - c0);
        }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "marble_load_compare: %s\n", e.what());
    return 2;
  }
  std::printf("median of %d interleaved runs; ms wall / ms CPU (all threads); triangles in brackets\n\n", runs);
  std::printf("| file | MB |");
  for (const Loader& l : loaders) std::printf(" %s |", l.name);
  if (withAssimp) std::printf(" assimp read / marble parse (wall) |");
  std::printf("\n| --- | ---: |");
  for (size_t l = 0; l < loaders.size() + (withAssimp ? 1 : 0); ++l) std::printf(" ---: |");
  std::printf("\n");
  for (size_t f = 0; f < files.size(); ++f) {
    std::printf("| %s | %.1f |", files[f].filename().string().c_str(),
                static_cast<double>(std::filesystem::file_size(files[f])) / 1e6);
    for (size_t l = 0; l < loaders.size(); ++l)
      std::printf(" %.0f / %.0f (%zu) |", median(wall[f][l]), median(cpu[f][l]), triangles[f][l]);
    if (withAssimp) std::printf(" %.1f× |", median(wall[f][3]) / median(wall[f][0]));
    std::printf("\n");
  }
  return 0;
}

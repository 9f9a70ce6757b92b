#pragma once
// Shared by the libFuzzer targets. marble's readers take a path and choose the format by its
// extension, so each input is first written to a file with the right extension, in a folder of
// this process's own (several fuzzers may run at once).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "marble/core/error.h"
#include "marble/mesh/mesh.h"

namespace marble::fuzz {

class InputFile {
public:
  explicit InputFile(const char* extension)
      : dir_(std::filesystem::temp_directory_path() / ("marble-fuzz-" + std::to_string(::getpid()))),
        path_(dir_ / (std::string("input") + extension)) {
    std::filesystem::create_directories(dir_);
  }
  // libFuzzer ends a normal run with exit(), which runs this; after a crash the folder is kept.
  ~InputFile() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::filesystem::path& write(const uint8_t* data, size_t size) {
    std::FILE* f = std::fopen(path_.c_str(), "wb");
    if (!f) std::abort();  // the harness itself is broken: stop loudly rather than fuzz nothing
    if (size && std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);
    return path_;
  }

private:
  std::filesystem::path dir_, path_;
};

// A loader's outcome as bytes, for the differential checks (parallel path against the
// front-to-back read): the mesh's arrays, or the error's message.
template <class Load>
std::string meshOutcome(Load&& load) {
  try {
    const Mesh m = load();
    std::string bytes(reinterpret_cast<const char*>(m.positions.data()), m.positions.size() * sizeof(glm::vec3));
    bytes.append(reinterpret_cast<const char*>(m.texcoords.data()), m.texcoords.size() * sizeof(glm::vec2));
    bytes.append(reinterpret_cast<const char*>(m.normals.data()), m.normals.size() * sizeof(glm::vec3));
    bytes.append(reinterpret_cast<const char*>(m.indices.data()), m.indices.size() * sizeof(uint32_t));
    return "mesh " + std::to_string(m.positions.size()) + " " + std::to_string(m.indices.size()) + " " + bytes;
  } catch (const InputError& e) {
    return std::string("error ") + e.what();
  }
}

}  // namespace marble::fuzz

#pragma once
// Shared by the loaders' parallel-path tests (OBJ, PLY, STL): a file loaded in 1 part (the
// front-to-back read that defines every message) and in 2, 3 and 7 parts must give the same mesh,
// bit for bit, or the same error message.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <string>
#include <variant>

#include "marble/core/error.h"
#include "marble/mesh/mesh.h"

namespace marble::loader_parts {

using Outcome = std::variant<Mesh, std::string>;  // the mesh, or the error's message
// Loads `text` in `parts` parts; sets `parallel` to whether the parts' reads were used.
using PartsLoader = std::function<Mesh(const std::string& text, unsigned parts, bool* parallel)>;

inline Outcome load(const PartsLoader& loader, const std::string& text, unsigned parts, bool* parallel = nullptr) {
  try {
    return loader(text, parts, parallel);
  } catch (const InputError& e) {
    return std::string(e.what());
  }
}

inline bool sameMesh(const Mesh& a, const Mesh& b) {
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.positions, b.positions) && same(a.normals, b.normals) && same(a.texcoords, b.texcoords) &&
         a.indices == b.indices;
}

// `parallel`: the parts' own reads must be the ones used (not the front-to-back fallback), so that
// the comparison tests the parallel path.
inline void expectSameForEveryPartCount(const PartsLoader& loader, const std::string& text, const std::string& what,
                                        bool parallel = false) {
  const Outcome sequential = load(loader, text, 1);
  for (unsigned parts : {2u, 3u, 7u}) {
    bool used = false;
    const Outcome split = load(loader, text, parts, &used);
    if (parallel) {
      EXPECT_TRUE(used) << what << ", " << parts << " parts";
    }
    ASSERT_EQ(sequential.index(), split.index()) << what << ", " << parts << " parts";
    if (const auto* message = std::get_if<std::string>(&sequential))
      EXPECT_EQ(*message, std::get<std::string>(split)) << what << ", " << parts << " parts";
    else
      EXPECT_TRUE(sameMesh(std::get<Mesh>(sequential), std::get<Mesh>(split))) << what << ", " << parts << " parts";
  }
}

// Inserts `line` (with its newline) at about `fraction` of the text, at a line start (after
// `from`, e.g. a header's end).
inline std::string withLineAt(std::string text, double fraction, const std::string& line, size_t from = 0) {
  const size_t target = from + static_cast<size_t>(static_cast<double>(text.size() - from) * fraction);
  size_t at = text.find('\n', target);
  at = at == std::string::npos ? text.size() : at + 1;
  return text.insert(at, line);
}

}  // namespace marble::loader_parts

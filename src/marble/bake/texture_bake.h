#pragma once
// Bakes the marble onto a mesh's texture coordinates (`marble bake`, `marble export`;
// docs/export.md): every texel's sub-samples are mapped through the triangle that covers them to
// the object-space point, where the solid pattern (shaders/pattern_core.glsl compiled as C++,
// noise/marble_pattern.h) gives the colour; texels no triangle covers are filled from their
// neighbours (dilation, then pull-push), so bilinear reads and mip levels never pull in a colour
// from outside the charts.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "marble/core/image.h"
#include "marble/mesh/mesh.h"
#include "marble/scene/material.h"

namespace marble {

struct BakeOptions {
  int size = 2048;          // base colour and metallic-roughness: size x size texels
  int supersample = 2;      // N x N colour samples per texel, averaged in linear light
  int thicknessSize = 0;    // 0: size / 4, at least 64 (thickness changes slowly over a surface)
  int thicknessRays = 16;   // rays per thickness texel
  int dilationTexels = 4;   // rings grown from the charts by averaging neighbours (then pull-push)
  // Called from the baking thread with the fraction done (0..1) and the stage; returning false
  // cancels the bake (BakeCancelled is thrown).
  std::function<bool(double fraction, const char* stage)> progress;
};

struct TextureSet {
  ImageRGBA8 baseColor;          // sRGB-encoded, alpha 255
  ImageRGBA8 metallicRoughness;  // glTF's packing (linear): G roughness, B metalness, R 255
  ImageRGBA8 thickness;          // R = G = B = local thickness / thicknessScale (linear), alpha 255
  float thicknessScale = 0;      // object units (the normalized mesh) that 255 stands for
  std::vector<float> thicknessValues;  // the same map unquantized: local thickness / thicknessScale, row 0 on top
  double coverage = 0;           // fraction of base-colour texels some triangle covers
};

struct BakeCancelled : std::runtime_error {
  BakeCancelled() : std::runtime_error("bake cancelled") {}
};

// The mesh must have texcoords in [0,1] (unwrapped or the file's). Local thickness at a surface
// point is the mean distance, over `thicknessRays` cosine-distributed rays into the object around
// the inward normal, to where each ray leaves the mesh (rays that never leave are left out).
TextureSet bakeTextureSet(const Mesh& mesh, const Material& material, const BakeOptions& options);

}  // namespace marble

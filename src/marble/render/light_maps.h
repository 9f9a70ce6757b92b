#pragma once
// The light-depth pass's render targets at one size (LightDepthPass): the distance and depth maps,
// the reflective shadow map at an eighth of the size with mipmaps, the entry and exit layers at a
// quarter, and their framebuffers. The pass keeps one set at its full size and, for interaction
// detail, one at a reduced size (LightDepthPass::setMapSize).
#include <cstddef>

#include "marble/gl/handles.h"

namespace marble {

struct LightMaps {
  explicit LightMaps(int size);
  int size;
  // RG32F: the distance, and the cosine at which the light enters there (light_depth.frag.glsl).
  gl::Texture distance, depth;  // depth: compare mode on, for sampler2DShadow
  int bounceSize;               // the reflective shadow map's finest width
  gl::Texture bouncePosition, bounceNormal, bounceDepth;
  int layersSize;
  gl::Texture layers;
  gl::Framebuffer fbo, bounceFbo, layersFbo;
  // distance 8 + depth 4 bytes a texel; the reflective shadow map's position 16 + normal 16 (its
  // mipmaps a third more) + depth 4 at its own size; the layers 8 at theirs.
  size_t bytes() const {
    return static_cast<size_t>(size) * size * 12 + static_cast<size_t>(bounceSize) * bounceSize * (4 + 32 * 4 / 3) +
           static_cast<size_t>(layersSize) * layersSize * 8;
  }
};

}  // namespace marble

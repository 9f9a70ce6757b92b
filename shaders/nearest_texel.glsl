// One texel of a GL_NEAREST texture (one level, clamped to the edge) read through its sampler
// instead of texelFetch: the same texel and the same value, bit for bit, for fewer instructions on
// llvmpipe, whose texelFetch selects a level and tests the bounds per lane (robust access) where
// the sampler's nearest read only scales, floors and clamps: -3.15 M instructions of the dragon's
// 800^2 camera frame for one read per bounce sample (docs/performance.md, "Twenty-third session:
// byte-equal savings"). The texel's centre, (texel + 0.5) / size, is scaled back by the sampler
// to within an ulp of texel + 0.5, whose floor is `texel`. Only for textures whose filter is
// GL_NEAREST and texels inside the texture (texelFetch reads 0 outside; this clamps).
#ifndef NEAREST_TEXEL_GLSL
#define NEAREST_TEXEL_GLSL  // included by several files one program may hold
vec4 nearest_texel(sampler2D s, ivec2 texel) {
  return textureLod(s, (vec2(texel) + 0.5) / vec2(textureSize(s, 0)), 0.0);
}
#endif

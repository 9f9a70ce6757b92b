#pragma once
// The numbers that C++ and the shaders in shaders/ must agree on, each written once, here.
// ShaderLibrary puts all of them after every shader's #version line as #defines
// (sharedShaderDefines()), so a shader says `layout(binding = UNIT_LIGHTING_ALBEDO)` or
// `u_mode == MODE_MARBLE` and the C++ side says shader::UNIT_LIGHTING_ALBEDO: one name, one
// value, nothing copied by hand. The render modes' numbers come from the RenderMode enum itself
// (MODE_PAPER, MODE_OREN_NAYAR, ...: renderModeNames() upper-cased, '-' as '_').
// pattern_core.glsl keeps its own PAT_* numbers: it is also compiled as C++ (noise/marble_pattern.cpp).
#include <string>
#include <vector>

// X(NAME, value) for each constant. Texture units: a pass that binds several with one
// glBindTextures call from the first relies on them being consecutive (checked below).
#define MARBLE_SHADER_CONSTANTS(X)                                                                      \
  /* environment.glsl: the kind of environment light (the ENV_KIND variant define) */                 \
  X(ENV_STUDIO, 0)                                                                                      \
  X(ENV_MAP, 1)                                                                                         \
  /* subsurface_blur.frag.glsl: taps per side at most (its weight array's size) */                     \
  X(MAX_TAPS, 9)                                                                                        \
  /* texture units of files included by several programs */                                            \
  X(UNIT_ENV_MAP, 7)          /* environment.glsl */                                                    \
  X(UNIT_TURBULENCE_GRID, 8)  /* marble_pattern.glsl */                                                 \
  X(UNIT_SURFACE_DEPTH, 1)    /* subsurface_common.glsl, post.frag.glsl, stage.frag.glsl: G-buffer's */ \
  X(UNIT_SCREEN_INPUT, 0)     /* the one input of blur_depth, fxaa, subsurface_blur */                  \
  X(UNIT_SCREEN_INPUT_TEXELS, 2) /* subsurface_blur: the same input through a GL_NEAREST sampler */     \
  X(UNIT_SCREEN_INPUT_OWN, 3) /* subsurface_blur: the lighting pass's texels, for the kernel's core */   \
  /* albedo.frag.glsl */                                                                                \
  X(UNIT_ALBEDO_DEPTH, 0)                                                                               \
  X(UNIT_ALBEDO_NORMAL, 1)                                                                              \
  /* lighting.frag.glsl */                                                                              \
  X(UNIT_LIGHTING_ALBEDO, 0)                                                                            \
  X(UNIT_LIGHTING_NORMAL, 1)                                                                            \
  X(UNIT_LIGHTING_DEPTH, 2)                                                                             \
  X(UNIT_LIGHTING_LIGHT_DISTANCE, 3)                                                                    \
  X(UNIT_LIGHTING_LIGHT_SHADOW, 4)                                                                      \
  X(UNIT_LIGHTING_BOUNCE_POSITION, 5) /* bounce.glsl, in bounce_gather.frag.glsl (its units 1, 2 above) */  \
  X(UNIT_LIGHTING_BOUNCE_NORMAL, 6)                                                                     \
  X(UNIT_LIGHTING_BOUNCE, 9)  /* bounce_upsample.glsl: the bounce pass's output (7: the environment's) */  \
  X(UNIT_LIGHTING_BOUNCE_FURTHER, 10) /* bounce_merge.glsl: the further bounces' 3D grid */           \
  X(UNIT_LIGHTING_BOUNCE_ENTRY, 11)   /* bounce_entry.glsl: the bounce at the light's entries */         \
  X(UNIT_LIGHTING_LIGHT_LAYERS, 12)   /* hidden_mirror.glsl, bounce_through_stone.glsl: the light's layers */ \
  /* bounce_refine_*.comp.glsl: the refined texels' list, its images, the workgroups' sizes */          \
  X(BUFFER_BOUNCE_REFINE_LIST, 0)                                                                       \
  X(IMAGE_BOUNCE_REFINED, 0)       /* the lighting pass's bounce texture (the coarse grid and the fine) */ \
  X(IMAGE_BOUNCE_REFINED_FIRST, 1) /* the refined texels' first bounce, before the merge */             \
  X(BOUNCE_MARK_GROUP, 8)          /* coarse texels per side of the mark's workgroup */                 \
  X(BOUNCE_REFINE_GROUP, 64)       /* list entries per workgroup of the gather and the merge */         \
  /* post.frag.glsl (its depth: UNIT_SURFACE_DEPTH) */                                                  \
  X(UNIT_POST_HDR, 0)                                                                                   \
  X(UNIT_POST_BLURRED, 2)                                                                               \
  X(UNIT_POST_DIFFUSE, 3)                                                                               \
  X(UNIT_POST_ALBEDO, 4)                                                                                \
  X(UNIT_POST_NORMAL, 5)                                                                                \
  X(UNIT_POST_LIGHT_SHADOW, 6)                                                                          \
  X(UNIT_POST_SURFACE_LIGHT, 9)      /* SURFACE_REUSE 2: the stored upsampled light */                  \
  X(UNIT_POST_SURFACE_REFLECTED, 10) /* SURFACE_REUSE 2: the stored reflected light */                  \
  X(UNIT_POST_MIRROR_HIT, 11)        /* marble: where the lighting pass's mirror rays meet the object */ \
  /* stage.frag.glsl (its depth: UNIT_SURFACE_DEPTH) */                                                 \
  X(UNIT_STAGE_LIGHT_SHADOW, 6)                                                                         \
  X(UNIT_STAGE_BOTTOM_DISTANCE, 8)

namespace marble::shader {

#define MARBLE_SHADER_CONSTANT_ENUM(name, value) name = value,
enum : int { MARBLE_SHADER_CONSTANTS(MARBLE_SHADER_CONSTANT_ENUM) };
#undef MARBLE_SHADER_CONSTANT_ENUM

// The binding orders the passes' glBindTextures calls use.
static_assert(UNIT_ALBEDO_NORMAL == UNIT_ALBEDO_DEPTH + 1);
static_assert(UNIT_LIGHTING_NORMAL == UNIT_LIGHTING_ALBEDO + 1 && UNIT_LIGHTING_DEPTH == UNIT_LIGHTING_ALBEDO + 2 &&
              UNIT_LIGHTING_LIGHT_DISTANCE == UNIT_LIGHTING_ALBEDO + 3 &&
              UNIT_LIGHTING_LIGHT_SHADOW == UNIT_LIGHTING_ALBEDO + 4);
static_assert(UNIT_SURFACE_DEPTH == UNIT_POST_HDR + 1 && UNIT_POST_BLURRED == UNIT_POST_HDR + 2 &&
              UNIT_POST_DIFFUSE == UNIT_POST_HDR + 3 && UNIT_POST_ALBEDO == UNIT_POST_HDR + 4 &&
              UNIT_POST_NORMAL == UNIT_POST_HDR + 5 && UNIT_POST_LIGHT_SHADOW == UNIT_POST_HDR + 6);

// "NAME VALUE" for every constant above and every render mode, as ShaderLibrary::assemble
// takes defines.
const std::vector<std::string>& sharedShaderDefines();

}  // namespace marble::shader

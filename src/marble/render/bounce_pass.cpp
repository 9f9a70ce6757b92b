#include "marble/render/bounce_pass.h"

#include <algorithm>

#include "marble/gl/checked_calls.h"
#include "marble/render/frame_uniforms.h"
#include "marble/render/material_uniforms.h"
#include "marble/render/shader_constants.h"

namespace marble {
namespace {
// Outside the rectangle there is no surface: alpha -1, which the upsamples leave out (alpha >= 0
// is a surface's, bounce_gather.frag.glsl).
constexpr float kNone[4] = {0, 0, 0, -1};
// The entry draw's grid: this level of the reflective shadow map (64² of the 1024² light map's
// 128²). Its gather costs as much per texel as the camera-side first bounce's (21.6 M instructions
// for the dragon's 100² texels at 800²), and it runs on every light move: at level 0 (128²) it
// would cost ~35 M a light frame (~9 %), at level 1 ~9 M. The light it carries is smooth over
// a thin part's width on the lit side (tens of millimetres), which level 1's texels (~25 mm on the
// teapot) resolve as coarsely as the camera-side gather's grid.
constexpr int kEntryLevel = 1;
}  // namespace

void setBounceGridUniforms(const gl::Program& program, const BounceGridLayout& grid) {
  program.set("u_bounce_scale", grid.scale);
  glProgramUniform2i(program.id(), program.location("u_bounce_coarse_size"), grid.coarseSize.x, grid.coarseSize.y);
  glProgramUniform2i(program.id(), program.location("u_bounce_fine_size"), grid.fineSize.x, grid.fineSize.y);
}

BouncePass::BouncePass(const ShaderLibrary& shaders)
    : gatherPrograms_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "bounce_gather.frag.glsl"}}),
      deinterleaveProgram_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "bounce_deinterleave.frag.glsl"}}),
      mergeProgram_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "bounce_merge.frag.glsl"}}),
      entryProgram_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "bounce_entry.frag.glsl"}}),
      gridDepthProgram_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "bounce_grid_depth.frag.glsl"}}),
      markProgram_(shaders, {{GL_COMPUTE_SHADER, "bounce_refine_mark.comp.glsl"}}),
      refineMergeProgram_(shaders, {{GL_COMPUTE_SHADER, "bounce_refine_merge.comp.glsl"}}),
      refinePrograms_(shaders, {{GL_COMPUTE_SHADER, "bounce_refine_gather.comp.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {
  // The default light's, so a broken shader shows at once.
  const bool directional = Light{}.type == LightType::Directional;
  gatherProgram(directional);
  refineProgram(directional);
  clearFurtherGrid();
}

const gl::Program& BouncePass::gatherProgram(bool directional) {
  return gatherPrograms_.get(directional ? 1u : 0u, [&] {
    return std::vector<std::string>{lightKindDefine(directional)};
  });
}

const gl::Program& BouncePass::refineProgram(bool directional) {
  return refinePrograms_.get(directional ? 1u : 0u, [&] {
    return std::vector<std::string>{lightKindDefine(directional)};
  });
}

void BouncePass::clearFurtherGrid() {
  // A grid of zero weight: the merge reads no further bounces.
  FurtherGrid none;
  none.cells = 2;
  none.cellSize = 1.0f;
  none.values.assign(8, glm::vec4(0.0f));
  setFurtherGrid(none, glm::mat4(1.0f));
}

void BouncePass::resize(int width, int height, int lightingScale) {
  const int scale = bounceScale(lightingScale);
  const int w = (width + scale - 1) / scale, h = (height + scale - 1) / scale;  // rounded up: every pixel has one
  if (w == width_ && h == height_ && scale == scale_ && fbo_) return;
  width_ = w;
  height_ = h;
  scale_ = scale;
  // Nearest: the upsamples read texels by index and weigh them themselves.
  first_ = gl::makeTexture2D(GL_RGBA16F, w, h, GL_NEAREST);
  firstFbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(firstFbo_.id(), GL_COLOR_ATTACHMENT0, first_.id(), 0);
  evened_ = gl::makeTexture2D(GL_RGBA16F, w, h, GL_NEAREST);
  evenedFbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(evenedFbo_.id(), GL_COLOR_ATTACHMENT0, evened_.id(), 0);
  // The refined grid at half the scale, beside the coarse one in the output (bounce_refined_grid.glsl).
  const int fine = scale / 2;
  fineWidth_ = (width + fine - 1) / fine;
  fineHeight_ = (height + fine - 1) / fine;
  bounce_ = gl::makeTexture2D(GL_RGBA16F, w + fineWidth_, std::max(h, fineHeight_), GL_NEAREST);
  refinedFirst_ = gl::makeTexture2D(GL_RGBA16F, fineWidth_, fineHeight_, GL_NEAREST);
  refineList_ = gl::Buffer::create();
  glNamedBufferStorage(refineList_.id(), static_cast<GLsizeiptr>(16 + 4 * static_cast<size_t>(fineWidth_) * fineHeight_),
                       nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, bounce_.id(), 0);
  firstDepth_.resize(w + fineWidth_, std::max(h, fineHeight_));
  firstDepth_.attachTo(firstFbo_.id());
  firstDepth_.attachTo(fbo_.id());
  firstDepth_.attachTo(evenedFbo_.id());
  gridDepthsStale_ = true;
}

void BouncePass::run(const BounceInputs& in, const CameraMatrices& camera, const LightMatrices& lightM,
                     const Light& light, const Material& material, float lightTexelWorld, const ScreenRect& rect,
                     bool gather) {
  timer_.begin();
  glBindTextureUnit(shader::UNIT_LIGHTING_NORMAL, in.normal);
  glBindTextureUnit(shader::UNIT_LIGHTING_DEPTH, in.depth);
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE_POSITION, in.bouncePosition);
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE_NORMAL, in.bounceNormal);
  // The first bounce's visibility through the stone (bounce_through_stone.glsl): the layers, and
  // their texel at the object for its tolerance (they span the bounding sphere's diameter, as the
  // light's map: view_setup.h).
  glBindTextureUnit(shader::UNIT_LIGHTING_LIGHT_LAYERS, in.lightLayers);
  const float layerTexel = 2.0f * kBoundingRadius / static_cast<float>(std::max(in.lightLayersSize, 1));
  for (const gl::Program* p :
       std::initializer_list<const gl::Program*>{&gatherProgram(lightM.directional), &refineProgram(lightM.directional), &entryProgram_})
    p->set("u_light_layer_texel_world", layerTexel);
  // A run without the gather has the last gather's view (only the material changed since).
  if (gather || gridDepthsStale_) {
    fillGridDepths(rect);
    gridDepthsStale_ = false;
  }
  if (gather) {
    gatherBounces(camera, lightM, light, lightTexelWorld, rect);
  }
  if (entriesStale_ || !gather) {
    gatherEntries(camera, lightM, light, material, lightTexelWorld, in.bounceMapSize);
    entriesStale_ = false;
  }
  // Both, with the emitters' albedo and Fresnel factors, on the first bounce's grid: the
  // background's texels keep the clear's -1, which the draw copies from the first bounce there.
  setGridDrawState();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::clearFramebuffer(fbo_.id(), GL_COLOR, 0, kNone);
  scissorTo(scaledDown(rect, scale_));
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE, evened_.id());
  bindFurtherGrid(mergeProgram_);
  setFrameUniforms(mergeProgram_, camera, lightM, light, lightTexelWorld);
  uploadMaterialUniforms(mergeProgram_, material);
  mergeProgram_.set("u_scale", scale_);
  gl::drawFullscreenTriangle(mergeProgram_.id(), emptyVao_.id());
  scissorOff();
  // The refinement: marked again on every run (the coarse clear above may have cleared its flags),
  // gathered with the coarse gather, merged with the coarse merge.
  markRefined(camera, lightM, light, lightTexelWorld, rect);
  if (gather) gatherRefined(camera, lightM, light, lightTexelWorld);
  mergeRefined(camera, lightM, light, material, lightTexelWorld);
  timer_.end();
}

void BouncePass::markRefined(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
                             float lightTexelWorld, const ScreenRect& rect) {
  // The refined grid's texels read -1 (not gathered; the even ones' flags: none refined) where the
  // lighting pass can read them: the object's rectangle and the upsample's one texel beyond it.
  // This runs after the coarse grid's clear, which may cover the whole texture.
  const ScreenRect cells = scaledDown(rect, scale_);
  const int fx0 = std::max(2 * cells.x - 1, 0), fy0 = std::max(2 * cells.y - 1, 0);
  const int fx1 = std::min(2 * (cells.x + cells.width) + 1, fineWidth_), fy1 = std::min(2 * (cells.y + cells.height) + 1, fineHeight_);
  if (fx1 > fx0 && fy1 > fy0)
    glClearTexSubImage(bounce_.id(), 0, width_ + fx0, fy0, 0, fx1 - fx0, fy1 - fy0, 1, GL_RGBA, GL_FLOAT, kNone);
  // The list's header: the gather's dispatch of {0, 1, 1} workgroups, no texel yet.
  constexpr GLuint kEmptyList[4] = {0, 1, 1, 0};
  glNamedBufferSubData(refineList_.id(), 0, sizeof(kEmptyList), kEmptyList);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader::BUFFER_BOUNCE_REFINE_LIST, refineList_.id());
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE, first_.id());
  glBindImageTexture(shader::IMAGE_BOUNCE_REFINED, bounce_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  setFrameUniforms(markProgram_, camera, lightM, light, lightTexelWorld);
  setBounceGridUniforms(markProgram_, gridLayout());
  glProgramUniform2i(markProgram_.id(), markProgram_.location("u_cell_origin"), cells.x, cells.y);
  glUseProgram(markProgram_.id());
  // The mark, the gather and the merge store into textures the last frame's passes fetched from
  // (bounce_: the lighting pass; refinedFirst_: the merge): an image store after a texture fetch of
  // an earlier command is ordered only by this bit (OpenGL 4.5, 7.13.2, SHADER_IMAGE_ACCESS: "image
  // stores ... issued after the barrier will not execute until all memory accesses ... initiated
  // prior to the barrier complete").
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  const int groups = shader::BOUNCE_MARK_GROUP;
  if (!cells.empty())
    gl::dispatchCompute(static_cast<GLuint>((cells.width + groups - 1) / groups),
                        static_cast<GLuint>((cells.height + groups - 1) / groups), 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void BouncePass::gatherRefined(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
                               float lightTexelWorld) {
  glBindImageTexture(shader::IMAGE_BOUNCE_REFINED_FIRST, refinedFirst_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  const gl::Program& refine = refineProgram(lightM.directional);
  setFrameUniforms(refine, camera, lightM, light, lightTexelWorld);
  refine.set("u_scale", scale_ / 2);
  glUseProgram(refine.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, refineList_.id());
  gl::dispatchComputeIndirect(0);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void BouncePass::mergeRefined(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
                              const Material& material, float lightTexelWorld) {
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE, refinedFirst_.id());
  bindFurtherGrid(refineMergeProgram_);
  glBindImageTexture(shader::IMAGE_BOUNCE_REFINED, bounce_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  setFrameUniforms(refineMergeProgram_, camera, lightM, light, lightTexelWorld);
  uploadMaterialUniforms(refineMergeProgram_, material);
  setBounceGridUniforms(refineMergeProgram_, gridLayout());
  glUseProgram(refineMergeProgram_.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, refineList_.id());
  gl::dispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  // The mark's and the merge's stores into bounce_: fetched by the lighting pass, then (the next
  // frame) overwritten by the coarse merge's clear and draw (framebuffer) and the mark's
  // glClearTexSubImage, which wait for earlier image stores only with the last two bits (7.13.2).
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

int BouncePass::refinedTexelCount() const {
  GLuint count = 0;
  glGetNamedBufferSubData(refineList_.id(), 12, sizeof(count), &count);
  return static_cast<int>(count);
}

void BouncePass::gatherEntries(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
                               const Material& material, float lightTexelWorld, int mapSize) {
  const int size = std::max(mapSize >> kEntryLevel, 1);
  if (size != entrySize_ || !entryFbo_) {
    entrySize_ = size;
    // Linear: the lighting pass reads it bilinearly (bounce_entry.glsl), averaging the four turns.
    entry_ = gl::makeTexture2D(GL_RGBA16F, size, size, GL_LINEAR);
    entryFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(entryFbo_.id(), GL_COLOR_ATTACHMENT0, entry_.id(), 0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, entryFbo_.id());
  glViewport(0, 0, entrySize_, entrySize_);
  gl::setScreenPassState();  // the whole map, no depth: the camera's rectangle does not apply
  setFrameUniforms(entryProgram_, camera, lightM, light, lightTexelWorld);
  uploadMaterialUniforms(entryProgram_, material);
  entryProgram_.set("u_level", kEntryLevel);
  gl::drawFullscreenTriangle(entryProgram_.id(), emptyVao_.id());
}

void BouncePass::setFurtherGrid(const FurtherGrid& grid, const glm::mat4& model) {
  if (grid.cells != furtherCells_ || !furtherGrid_) {
    furtherCells_ = grid.cells;
    furtherGrid_ = gl::Texture::create(GL_TEXTURE_3D);
    glTextureStorage3D(furtherGrid_.id(), 1, GL_RGBA32F, grid.cells, grid.cells, grid.cells);
    // Linear: the merge's trilinear read, divided by the interpolated weight (bounce_merge.glsl).
    glTextureParameteri(furtherGrid_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(furtherGrid_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTextureParameteri(furtherGrid_.id(), wrap, GL_CLAMP_TO_EDGE);
  }
  glTextureSubImage3D(furtherGrid_.id(), 0, 0, 0, 0, grid.cells, grid.cells, grid.cells, GL_RGBA, GL_FLOAT,
                      grid.values.data());
  furtherFromWorld_ = grid.textureFromModel() * glm::inverse(model);
}

void BouncePass::bindFurtherGrid(const gl::Program& program) const {
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE_FURTHER, furtherGrid_.id());
  glProgramUniformMatrix4fv(program.id(), program.location("u_further_from_world"), 1, GL_FALSE, &furtherFromWorld_[0][0]);
}

void BouncePass::fillGridDepths(const ScreenRect& rect) {
  firstDepth_.fill(gridDepthProgram_, emptyVao_.id(), scale_, width_, height_, scaledDown(rect, scale_));
}

void BouncePass::setGridDrawState() const {
  if (skipsBackground_)
    gl::setSurfaceOnlyScreenPassState();
  else
    gl::setScreenPassState();
}

void BouncePass::gatherBounces(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
                               float lightTexelWorld, const ScreenRect& rect) {
  // The draws shade only the texels whose pixel is stone (BounceGridDepth): the background's
  // keep the clear's -1, which their shaders write there.
  setGridDrawState();
  // The first bounce, from the light's map.
  glBindFramebuffer(GL_FRAMEBUFFER, firstFbo_.id());
  glViewport(0, 0, width_, height_);
  gl::clearFramebuffer(firstFbo_.id(), GL_COLOR, 0, kNone);
  scissorTo(scaledDown(rect, scale_));
  const gl::Program& gather = gatherProgram(lightM.directional);
  setFrameUniforms(gather, camera, lightM, light, lightTexelWorld);
  gather.set("u_scale", scale_);
  gl::drawFullscreenTriangle(gather.id(), emptyVao_.id());
  // Off before the next clear, which the scissor would cut too. Texels outside the cut keep an
  // earlier frame's values (or a new texture's undefined ones); the readers did not reach them
  // while every texel of a draw's rectangle was shaded, but the background skip (BounceGridDepth)
  // leaves texels there to the clear.
  scissorOff();
  // Its interleaved pattern evened out over the 2 x 2 blocks, on the same grid: what the merge
  // reads (the background's texels skipped: they keep the clear's -1, which the shader copies from
  // the first bounce there).
  glBindFramebuffer(GL_FRAMEBUFFER, evenedFbo_.id());
  gl::clearFramebuffer(evenedFbo_.id(), GL_COLOR, 0, kNone);
  scissorTo(scaledDown(rect, scale_));
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE, first_.id());
  setFrameUniforms(deinterleaveProgram_, camera, lightM, light, lightTexelWorld);
  deinterleaveProgram_.set("u_scale", scale_);
  gl::drawFullscreenTriangle(deinterleaveProgram_.id(), emptyVao_.id());
  scissorOff();
}

}  // namespace marble

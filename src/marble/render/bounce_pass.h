#pragma once
// The bounce pass (`marble` only): the one diffuse bounce (shaders/bounce.glsl) gathered from the
// reflective shadow map at a quarter of the lighting pass's resolution each way (a sixteenth of its
// texels; an eighth of the frame's each way at the blur's default half), into an RGBA16F texture
// the lighting pass upsamples (shaders/bounce_upsample.glsl). Gathered at every lighting texel it
// was ~26 ms of the dragon's 800² lighting pass on llvmpipe; here ~2 (docs/performance.md, "The
// bounce gathered coarsely"); at half the lighting's resolution each way the light frames stayed
// at 1.4x. The further bounces (the second to the fourth) come from a radiosity over the whole
// surface, solved on the CPU when the light moves (further_radiosity.h, since session 25; before it
// a second draw gathered them in screen space from the first, and found 0.41 of Cycles'), as a
// coarse 3D grid that setFurtherGrid() uploads; a second draw adds them to the first on its grid
// (shaders/bounce_merge.frag.glsl), applying the emitters' albedo and Fresnel factors there, once
// per texel of this grid: the pass reads the base colour and the ior, and where only they changed
// it runs that draw alone (`gather` false). A third draw gathers the first bounce at the
// light's side, on a level of the reflective shadow map (shaders/bounce_entry.frag.glsl), for
// the transmission to carry through thin parts; it depends on the light, the mesh, the base colour
// and the ior only, so it runs after markEntriesStale() (the renderer calls it whenever the
// light's map is redrawn) or when the material changed, not when only the camera moves.
// Since session 17 the first bounce is also gathered on a grid twice as fine, but only at the
// texels where the coarse grid's samples do not continue the surface (creases, silhouettes, thin
// parts): three compute steps (shaders/bounce_refine_{mark,gather,merge}.comp.glsl) mark them into
// a list, gather over the list by an indirect dispatch and merge them, so their cost follows the
// texels refined; the refined grid sits beside the coarse one in the output texture
// (shaders/bounce_refined_grid.glsl), and where nothing is refined the lighting pass reads the
// coarse grid exactly as before. Since session 21 the first bounce's interleaved pattern is evened
// out over its 2 x 2 blocks right after its gather, on the same grid
// (shaders/bounce_deinterleave.frag.glsl), and the merge reads that. The full-screen draws
// test depth against a buffer at their grid's resolution (BounceGridDepth) and shade only the
// texels whose pixel is stone, as the lighting pass does: about half of each grid's scissor
// rectangle is background on the dragon.
#include "marble/gl/program.h"
#include "marble/gl/program_variants.h"
#include "marble/render/further_radiosity.h"
#include "marble/render/bounce_grid_depth.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

// Where the pass's output holds its two grids (shaders/bounce_refined_grid.glsl), for the programs
// that read it: the coarse grid's full-resolution pixels per texel and texels, the refined grid's texels.
struct BounceGridLayout {
  int scale = 0;
  glm::ivec2 coarseSize{0}, fineSize{0};
};
void setBounceGridUniforms(const gl::Program& program, const BounceGridLayout& grid);

struct BounceInputs {
  GLuint normal, depth, bouncePosition, bounceNormal;  // the G-buffer's; the reflective shadow map
  int bounceMapSize;                                   // the reflective shadow map's finest width
  GLuint lightLayers;                                  // the light's entry and exit layers (LightDepthPass)
  int lightLayersSize;                                 // their width
};

class BouncePass {
public:
  explicit BouncePass(const ShaderLibrary& shaders);
  // Full-resolution pixels per texel of the lighting pass (the blur's scale, 1 or 2); this pass
  // has bounceScale() of them.
  void resize(int width, int height, int lightingScale);
  void run(const BounceInputs& in, const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
           const Material& material, float lightTexelWorld, const ScreenRect& rect, bool gather);
  // All bounces (bounce_merge.frag.glsl's output, and the refined grid beside it:
  // shaders/bounce_refined_grid.glsl), for the lighting pass.
  GLuint bounceTexture() const { return bounce_.id(); }
  // The refined texels' first bounce before the merge (refined grid, alpha -1 elsewhere), for tests.
  GLuint refinedFirstTexture() const { return refinedFirst_.id(); }
  // Texels of the refined grid gathered at the last gather (read back from the list: for tests).
  int refinedTexelCount() const;
  // The first bounce at the light's entries (bounce_entry.frag.glsl), for the lighting pass.
  GLuint entryTexture() const { return entry_.id(); }
  // The light's map was redrawn: the entry draw must run again at the next run().
  void markEntriesStale() { entriesStale_ = true; }
  // The further bounces for the light and the model matrix the frame draws with (FurtherRadiosity::
  // solve), read by the merges from the next run() on. Until the first call: none.
  void setFurtherGrid(const FurtherGrid& grid, const glm::mat4& model);
  void clearFurtherGrid();  // none (as until the first setFurtherGrid)
  int scale() const { return scale_; }  // full-resolution pixels per texel
  BounceGridLayout gridLayout() const { return {scale_, {width_, height_}, {fineWidth_, fineHeight_}}; }
  // RGBA16F: the first bounce on this grid (as gathered and evened out), all bounces on this grid
  // and the refined one beside it, the refined first bounce, the entries' grid; the refined list;
  // the further bounces' RGBA32F 3D grid.
  size_t bytes() const {
    const size_t fine = static_cast<size_t>(fineWidth_) * fineHeight_;
    return static_cast<size_t>(width_) * height_ * 16 + static_cast<size_t>(width_ + fineWidth_) * fineHeight_ * 8 +
           fine * 8 + static_cast<size_t>(entrySize_) * entrySize_ * 8 + 16 + fine * 4 + firstDepth_.bytes() +
           static_cast<size_t>(furtherCells_) * furtherCells_ * furtherCells_ * 16;
  }
  PassTimer& timer() { return timer_; }
  // For tests: off, the full-screen draws on the grids shade every texel of the rectangle (no depth test), the
  // reference the skip (BounceGridDepth, on by default) must equal bit for bit.
  void setSkipsBackground(bool on) { skipsBackground_ = on; }

private:
  // The grids' full-screen draws' state: the depth test against the grid's depth, or none.
  void setGridDrawState() const;
  // The first draw (and its evening out): the first bounce, before any material parameter.
  void gatherBounces(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
                     float lightTexelWorld, const ScreenRect& rect);
  // The depths the first three draws test (BounceGridDepth), for the view's G-buffer.
  void fillGridDepths(const ScreenRect& rect);
  // The fourth draw: the first bounce at the light's entries, the material applied.
  void gatherEntries(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
                     const Material& material, float lightTexelWorld, int mapSize);
  // The refinement's three steps: mark (every run: it also writes the refined grid's flags), gather
  // (with the coarse gather), merge (with the coarse merge).
  void markRefined(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light, float lightTexelWorld,
                   const ScreenRect& rect);
  void gatherRefined(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light, float lightTexelWorld);
  void mergeRefined(const CameraMatrices& camera, const LightMatrices& lightM, const Light& light, const Material& material,
                    float lightTexelWorld);
  // The further bounces' grid on its unit, and its matrix, for a merge program.
  void bindFurtherGrid(const gl::Program& program) const;
  // The first bounce's gather and the refinement's gather for the light's kind, a constant of their
  // programs (LIGHT_DIRECTIONAL, shaders/light_geometry.glsl): they ask for the light's vector and
  // distance at every sample.
  const gl::Program& gatherProgram(bool directional);
  const gl::Program& refineProgram(bool directional);
  gl::ProgramVariants gatherPrograms_;  // gatherProgram()
  gl::Program deinterleaveProgram_, mergeProgram_, entryProgram_, gridDepthProgram_;
  gl::Program markProgram_, refineMergeProgram_;
  gl::ProgramVariants refinePrograms_;  // refineProgram()
  gl::VertexArray emptyVao_;
  gl::Texture first_, evened_, bounce_, entry_, refinedFirst_;  // evened: the pattern evened out
  gl::Framebuffer firstFbo_, evenedFbo_, fbo_, entryFbo_;
  // The first bounce's grid (attached to firstFbo_, evenedFbo_ and fbo_; as large as bounce_, so
  // that fbo_ keeps its whole area).
  BounceGridDepth firstDepth_;
  gl::Texture furtherGrid_;  // 3D, RGBA32F (FurtherGrid's values)
  int furtherCells_ = 0;
  glm::mat4 furtherFromWorld_{1.0f};  // world space to the grid's texture coordinates
  gl::Buffer refineList_;  // shaders/bounce_refine_list.glsl: the indirect dispatch's arguments, the count, the texels
  int width_ = 0, height_ = 0, scale_ = 0, entrySize_ = 0;
  int fineWidth_ = 0, fineHeight_ = 0;  // the refined grid's texels (at scale_ / 2)
  bool entriesStale_ = true;
  bool gridDepthsStale_ = true;
  bool skipsBackground_ = true;  // made anew by resize(): filled at the next run() even without a gather
  PassTimer timer_;
};

// Full-resolution pixels per texel of the bounce pass, given the lighting pass's.
constexpr int bounceScale(int lightingScale) { return 4 * lightingScale; }

}  // namespace marble

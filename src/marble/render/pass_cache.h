#pragma once
// What each cached pass's output was made from, and whether it still holds for a frame: the
// renderer's one caching rule. A pass's output is current when every input it declares
// (pass_list.h) is what it was when the output was made: the frame's values, the renderer's
// state (by revision: each setter that changes it counts one), the material groups it reads
// in the frame's mode, and the outputs of the passes it reads (by generation: each run counts
// one). Nothing else is compared, so a wrong declaration shows as a stale picture, which the
// exact-equality tests (a cached frame equals a fresh one) catch.
#include <optional>

#include "marble/render/pass_list.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

// Everything of one frame that a pass can read (besides the renderer's state).
struct FrameInputs {
  Scene scene;
  glm::mat4 model{1.0f};
  CameraMatrices camera{};
  LightMatrices light{};
  int width = 0, height = 0;
  float seenAttenuation = 0.0f;  // `marble`: seenVeinAttenuation(scene); 0 otherwise
};

// Whether `a` and `b` agree on input `i` (the renderer's state inputs: always; they go by revision).
bool sameInput(PassInput i, const FrameInputs& a, const FrameInputs& b);

// Whether a and b agree on everything a `marble` frame's reflected light and upsampled blurred
// light are made from, of the frame's values: all of them but the pattern -- the material groups
// only the pattern's evaluation reads (groupsRead(kAlbedoPassBit)) and how it is seen (SeenPattern).
// (The passes' outputs and the renderer's state are compared by the caller.)
bool sameButPattern(const FrameInputs& a, const FrameInputs& b);

class PassCache {
public:
  // Whether p's stored output is what running it for `now` would make.
  bool current(Pass p, const FrameInputs& now) const;
  // The same, the material aside: p's output was made for `now` but for the material parameters it
  // reads (the bounce pass re-runs only its last, cheap draw for them).
  bool currentButMaterial(Pass p, const FrameInputs& now) const;
  // p's output was just made for `now`.
  void made(Pass p, const FrameInputs& now);
  // A renderer state input (LightMesh .. TurbulenceGrid) changed.
  void changed(PassInput state);
  // Every stored output is forgotten (new shaders: the passes and their textures are new).
  void forget();
  // Counts every change of the renderer's state (for Renderer::isCurrent).
  uint64_t stateRevision() const { return stateRevision_; }
  // Runs of each pass so far (outputs made), for what the post pass keeps (kStoredDiffuseReads).
  const PerPass<uint64_t>& generations() const { return generation_; }

private:
  struct Record {
    FrameInputs inputs;
    std::array<uint64_t, kRendererStateInputs> revisions{};
    PerPass<uint64_t> generations;
  };
  PerPass<std::optional<Record>> made_;
  PerPass<uint64_t> generation_;
  std::array<uint64_t, kRendererStateInputs> revision_{};
  uint64_t stateRevision_ = 0;
};

}  // namespace marble

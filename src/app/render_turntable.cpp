#include "render_turntable.h"

#include <cstdio>
#include <iostream>

#include <glm/gtc/matrix_transform.hpp>

#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/core/image_downsample.h"
#include "marble/render/offscreen_target.h"
#include "progress_bar.h"
#include "video_encode.h"

namespace marble {

std::string framePattern(const std::filesystem::path& folder, int frames) {
  int digits = 1;
  for (int n = frames - 1; n >= 10; n /= 10) ++digits;
  return (folder / ("frame_%0" + std::to_string(std::max(4, digits)) + "d.png")).string();
}

void renderTurntable(Renderer& renderer, const Scene& scene, const TurntableJob& job) {
  std::error_code ec;
  std::filesystem::create_directories(job.folder, ec);
  if (ec || !std::filesystem::is_directory(job.folder))
    throw InputError(job.folder.string(), "", "cannot create the frames' folder" + (ec ? ": " + ec.message() : ""));
  const std::string pattern = framePattern(job.folder, job.frames);
  const int n = job.supersample;
  OffscreenTarget target(scene.render.width * n, scene.render.height * n);
  // The pattern is the same in every frame: its turbulence grid is baked once and reused.
  renderer.setTurbulenceGridEnabled(true);
  std::vector<char> name(pattern.size() + 16);
  double seconds = 0.0;
  {
    ProgressBar progress(job.frames);
    for (int i = 0; i < job.frames; ++i) {
      const float angle = 360.0f * static_cast<float>(i) / static_cast<float>(job.frames);
      const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(angle), glm::vec3(0, 1, 0));
      Scene frame = scene;
      glm::mat4 model(1.0f);
      if (job.turnLight) frame.light.position = glm::vec3(turn * glm::vec4(scene.light.position, 1.0f));
      else model = turn;
      renderer.render(frame, model, target.fbo(), target.width(), target.height());
      std::snprintf(name.data(), name.size(), pattern.c_str(), i);
      writePng(name.data(), downsampleSrgb(target.read(), n));
      progress.step();
    }
    seconds = progress.elapsedSeconds();
  }  // the bar's line ends here
  std::printf("wrote %d frames to %s (%dx%d, the %s turning): %.2f s, %.0f ms per frame (%.2f frames/s)\n", job.frames,
                job.folder.string().c_str(), scene.render.width, scene.render.height,
              job.turnLight ? "light" : "object", seconds, 1000.0 * seconds / job.frames, job.frames / seconds);
  std::fflush(stdout);
  if (!job.video.empty()) {
    encodeVideo(pattern, job.frames, job.fps, job.video);
    std::printf("wrote %s (%d frames at %d frames/s, %.1f s)\n", job.video.c_str(), job.frames, job.fps,
                static_cast<double>(job.frames) / job.fps);
  }
}

}  // namespace marble

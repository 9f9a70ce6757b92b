#include "marble/bake/bake_job.h"

#include <unistd.h>

#include <system_error>

#include "marble/bake/gltf_export.h"
#include "marble/bake/texture_set_files.h"
#include "marble/core/error.h"

namespace marble {
namespace {

void checkGltfOutput(const std::filesystem::path& file) {
  if (file.empty()) throw InputError("-o", "", "an output file is required (e.g. -o model.glb)");
  gltfContainerFor(file);  // .glb or .gltf
  const auto folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) throw InputError(file.string(), "", "the folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK) != 0) throw InputError(file.string(), "", "the folder " + folder.string() + " is not writable");
}

}  // namespace

void checkBakeJob(const BakeJob& job) {
  if (job.size < kMinBakeSize || job.size > kMaxBakeSize)
    throw InputError("--size", "", "expected a whole number in [" + std::to_string(kMinBakeSize) + ", " +
                                       std::to_string(kMaxBakeSize) + "], got " + std::to_string(job.size));
  if (job.supersample < 1 || job.supersample > kMaxSupersample)
    throw InputError("--supersample", "", "expected 1 to " + std::to_string(kMaxSupersample) + ", got " + std::to_string(job.supersample));
  if (job.kind == BakeOutput::TextureSet) checkOutputFolder(job.output);
  else checkGltfOutput(job.output);
}

BakeJobResult runBakeJob(const Scene& scene, const Mesh& loaded, const BakeJob& job, const std::function<bool(double, const char*)>& progress,
                         const std::function<void(const std::string&)>& note) {
  checkBakeJob(job);
  BakeOptions options;
  options.size = job.size;
  options.supersample = job.supersample;
  options.progress = progress;
  const BakeMesh mesh = prepareBakeMesh(loaded, job.uvSource, job.size, options.dilationTexels, scene.mesh);
  if (!mesh.note.empty() && note) note(mesh.note);
  const TextureSet set = bakeTextureSet(mesh.mesh, scene.material, options);
  // The last chance to cancel: after this, the files are written.
  if (progress && !progress(1.0, "writing")) throw BakeCancelled();
  if (job.kind == BakeOutput::TextureSet)
    writeTextureSet(job.output, set, scene.mm_per_unit, describeTextureSet(set, scene.material, scene.mm_per_unit, mesh));
  else
    writeGltf(job.output, {mesh.mesh, set, scene.material, scene.mm_per_unit});
  BakeJobResult r;
  r.triangles = mesh.mesh.triangleCount();
  r.size = set.baseColor.width;
  r.thicknessSize = set.thickness.width;
  r.thicknessScaleMm = set.thicknessScale * scene.mm_per_unit;
  r.unwrapped = mesh.unwrapped;
  r.stats = mesh.stats;
  r.note = mesh.note;
  return r;
}

}  // namespace marble

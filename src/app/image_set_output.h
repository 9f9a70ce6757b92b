#pragma once
// Several PNGs that belong together (marble texture's stages) written so that the folder holds
// either the old set or the new one: every image goes to its own temporary first, and only when
// all are written and flushed are they renamed into place (AtomicFileSet, core/atomic_file.h).
// Ctrl-C or a failure before that leaves the old files untouched and no temporary behind.
#include <filesystem>
#include <string>
#include <vector>

#include "marble/core/image.h"

namespace marble {

struct NamedImage {
  std::string fileName;  // inside the folder
  const ImageRGBA8* image;
};

// Writes the images into `folder` as one set; prints each path written, one a line, on stdout.
void writeImageSet(const std::filesystem::path& folder, const std::vector<NamedImage>& images);

}  // namespace marble

#include "image_set_output.h"

#include <iostream>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"

namespace marble {

void writeImageSet(const std::filesystem::path& folder, const std::vector<NamedImage>& images) {
  AtomicFileSet set;
  for (const NamedImage& named : images) {
    const auto path = folder / named.fileName;
    std::string bytes;
    try {
      bytes = encodePng(*named.image);
    } catch (const std::runtime_error& e) {
      throw InputError(path.string(), "", e.what());
    }
    set.add(path, bytes);
  }
  set.commit();
  for (const NamedImage& named : images) std::cout << (folder / named.fileName).string() << "\n";
}

}  // namespace marble

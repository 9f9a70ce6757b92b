#include "marble/gl/program_variants.h"

namespace marble::gl {

ProgramVariants::ProgramVariants(const ShaderLibrary& library, std::vector<ShaderStageSource> stages)
    : library_(&library), stages_(std::move(stages)) {}

const Program& ProgramVariants::get(const std::vector<std::string>& defines) {
  auto it = programs_.find(defines);
  if (it == programs_.end()) it = programs_.emplace(defines, Program(*library_, stages_, defines)).first;
  return it->second;
}

}  // namespace marble::gl

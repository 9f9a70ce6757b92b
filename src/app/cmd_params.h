#pragma once
// `marble params`: every material parameter, from its description (scene/material_params.h):
// key, range, unit, default and the render modes that read it. `--update-doc FILE` rewrites the
// parameter tables of FILE (docs/materials.md) from the same descriptions.
#include <string>

namespace marble {
int runParamsCommand(const std::string& updateDoc);
}

#!/usr/bin/env bash
# Regenerates the golden images in tests/golden/ on purpose (after a deliberate change to
# shading, the pattern or the built-in mesh). Look at the new PNGs before committing them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/setup.sh"
MARBLE_UPDATE_GOLDENS=1 "$root/build/tests/marble_gl_tests" --gtest_filter='BuiltinMesh/Golden.*'
# The paper's texture stages (tests/vein_structure_cli.cpp: PaperTextureIsExactlyAsBefore).
"$root/build/marble" texture -o "$root/tests/golden/texture-paper" --preset paper --size 128 >/dev/null
git -C "$root" status --short tests/golden

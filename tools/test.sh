#!/usr/bin/env bash
# Sets everything up and runs the whole test suite (unit, headless GL on EGL, CLI, and the
# viewer under Xvfb), warnings as errors.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/setup.sh" -DMARBLE_WERROR=ON
cd "$root/build"
# setup.sh installed the web tools: the tests that need them must not skip.
export MARBLE_REQUIRE_WEB_TOOLS=1
ctest --output-on-failure -j2 "$@"

#!/bin/sh
# Regenerates docs/images/viewer.png (the README's and docs/viewer.md's picture of the viewer)
# from the project's own binary: the default scene, 5 frames under a virtual X server.
# Run from the repository root after building into build/.
set -eu
cd "$(dirname "$0")/.."
mkdir -p docs/images
xvfb-run -a -s '-screen 0 1400x900x24' build/marble view --frames 5 --width 1280 --height 800 --screenshot docs/images/viewer.png

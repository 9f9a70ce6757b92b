#!/usr/bin/env bash
# Installs the test suite's web tools into tools/web/node_modules with Debian's node and npm
# (tools/deps.txt): the Khronos glTF-Validator (tests/export_cli.cpp checks every exported file
# with it) and three.js (tools/web/compare.html, the web-viewer comparison). Versions are pinned
# in tools/web/package-lock.json. Safe to run again: `npm ci` only when something is missing.
set -euo pipefail
web=$(cd "$(dirname "$0")/web" && pwd)
if ! command -v npm > /dev/null; then
  echo "npm is missing (it is in tools/deps.txt; run tools/setup.sh as root)" >&2
  exit 1
fi
if [[ -f "$web/node_modules/gltf-validator/package.json" && -f "$web/node_modules/three/package.json" ]]; then
  exit 0
fi
echo "installing the web test tools (gltf-validator, three) into $web/node_modules"
(cd "$web" && npm ci --no-audit --no-fund --loglevel=error)

#!/bin/sh
# Rewrites docs/materials.md's parameter tables from the parameters' descriptions
# (src/marble/scene/material_params.cpp). tests/material_docs_test.cpp fails until this is run
# after a parameter changes. Usage: tools/update-material-docs.sh [path/to/marble]
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
marble=${1:-"$here/build/marble"}
"$marble" params --update-doc "$here/docs/materials.md"

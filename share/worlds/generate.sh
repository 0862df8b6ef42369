#!/usr/bin/env bash
# Regenerates the map-server pairs (PGM + YAML) of the bundled worlds from
# their wall descriptions (*.walls), with the project's own sancta-render.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
render="$here/../../bin/sancta-render"
for w in "$here"/*.walls; do
   base="${w%.walls}"
   "$render" "$w" --rasterize "$base"
done

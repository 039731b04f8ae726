#!/usr/bin/env bash
# The main job on a built-in default: read the real FZK-Haus building (IFC,
# from Debian's assimp-testmodels), describe it, keep it as glTF.
set -euo pipefail
build=${1:-build}
boxlod="$build/toolkit/cli/boxlod"
out=out/demo
mkdir -p "$out"
model=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc

echo "== boxlod info $model"
"$boxlod" info "$model"
echo
echo "== boxlod convert -> $out/fzk-haus.glb"
"$boxlod" convert "$model" -o "$out/fzk-haus.glb"
"$boxlod" info "$out/fzk-haus.glb" --json > "$out/fzk-haus.stats.json"
echo "statistics of the glTF: $out/fzk-haus.stats.json"

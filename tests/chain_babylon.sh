#!/usr/bin/env bash
# LoD chains (build --chain, MSFT_lod) in a real engine: Babylon.js (npm
# babylonjs + babylonjs-loaders, pinned) in Debian's headless Chromium, its
# MSFT_lod on as by default (tests/browser_clients.sh). For the FZK-Haus and
# each built-in sample, passes when the loader completes without an error,
# shows the coarsest level's triangles when ready and level 0's when
# complete (every level whole, none overlaid), and draws a picture.
# Usage: chain_babylon.sh BOXLOD [SAMPLE...]   (default samples: house office classical manual)
set -euo pipefail
boxlod=$1; shift
samples=${*:-house office classical manual}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/browser_clients.sh"
npm_client babylonjs-9.28.0-playwright-1.57.0 babylonjs@9.28.0 babylonjs-loaders@9.28.0 playwright-core@1.57.0
work=$(mktemp -d)
server=
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT

mkdir -p "$work/site"
ln -s "$client/node_modules/babylonjs" "$work/site/babylon"
ln -s "$client/node_modules/babylonjs-loaders" "$work/site/loaders"
cp "$here/chain_babylon.html" "$work/site/index.html"
models=fzk
cp /usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc "$work/fzk.ifc"
for sample in $samples; do
  "$boxlod" generate --sample "$sample" -o "$work/$sample.glb" > /dev/null
  models="$models $sample"
done
for model in $models; do
  input=$work/$model.glb; [ "$model" = fzk ] && input=$work/fzk.ifc
  "$boxlod" build "$input" --chain -o "$work/site/$model.glb" > "$work/$model.txt"
done
serve "$work/site"
failures=0
for model in $models; do
  open_page "http://127.0.0.1:$port/index.html?file=$model.glb" "$work/$model.json" "$work/$model.png"
  /usr/bin/python3 - "$work/$model.txt" "$work/$model.json" "$model" <<'PY' || failures=$((failures + 1))
import json, re, sys
triangles = [int(t) for t in re.findall(r"^triangles_lod = (\d+)$", open(sys.argv[1]).read(), re.M)]  # levels 0..N
result = json.load(open(sys.argv[2]))
print(f"chain_babylon {sys.argv[3]}: {len(triangles)} levels, triangles {triangles[0]}..{triangles[-1]}; Babylon.js: {result}")
assert "error" not in result, result["error"]
assert result["state"] == "complete" and not result["errors"], "the loader did not complete cleanly"
assert result["ready"] == triangles[-1], f"ready with {result['ready']} triangles, not the coarsest level's {triangles[-1]}"
assert result["complete"] == triangles[0], f"complete with {result['complete']} triangles, not level 0's {triangles[0]}"
assert result["drawn"] > 0.01 * result["pixels"], "the picture is blank"
PY
done
[ "$failures" = 0 ]

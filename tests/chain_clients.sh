#!/usr/bin/env bash
# LoD chains (build --chain, MSFT_lod) in real clients, in Debian's headless
# Chromium, npm packages pinned (tests/browser_clients.sh). For the FZK-Haus
# and each built-in sample, passes when
# - Babylon.js (babylonjs + babylonjs-loaders), its MSFT_lod on as by default,
#   completes without an error, showing the coarsest level's triangles when
#   ready and level 0's when complete (every level whole, none overlaid), and
#   draws a picture;
# - three.js in boxlod's viewer page (clients/chain_three.html: a THREE.LOD at
#   boxlod's switch distances) draws level 0 near, a middle level in the middle
#   of its distances and the coarsest far, each with boxlod's triangle count.
# Usage: chain_clients.sh BOXLOD [SAMPLE...]   (default samples: house office classical manual)
set -euo pipefail
boxlod=$1; shift
samples=${*:-house office classical manual}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/browser_clients.sh"
npm_client three-0.187.0-playwright-1.57.0 three@0.187.0 playwright-core@1.57.0
three=$client
npm_client babylonjs-9.28.0-playwright-1.57.0 babylonjs@9.28.0 babylonjs-loaders@9.28.0 playwright-core@1.57.0
work=$(mktemp -d)
server=
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT

mkdir -p "$work/site"
ln -s "$client/node_modules/babylonjs" "$work/site/babylon"
ln -s "$client/node_modules/babylonjs-loaders" "$work/site/loaders"
ln -s "$three/node_modules/three" "$work/site/three"
cp "$here/chain_babylon.html" "$work/site/babylon.html"
cp "$here/../clients/chain_three.html" "$work/site/three.html"
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
  open_page "http://127.0.0.1:$port/babylon.html?file=$model.glb" "$work/$model.babylon.json" "$work/$model.png"
  levels=$(grep -c "^triangles_lod = " "$work/$model.txt")
  for at in 0 $(((levels - 1) / 2)) $((levels - 1)); do
    open_page "http://127.0.0.1:$port/three.html?file=$model.glb&at=$at" "$work/$model.three$at.json" "$work/$model.three$at.png"
  done
  /usr/bin/python3 - "$work" "$model" <<'PY' || failures=$((failures + 1))
import glob, json, re, sys
work, model = sys.argv[1:]
triangles = [int(t) for t in re.findall(r"^triangles_lod = (\d+)$", open(f"{work}/{model}.txt").read(), re.M)]  # levels 0..N
result = json.load(open(f"{work}/{model}.babylon.json"))
print(f"chain_clients {model}: {len(triangles)} levels, triangles {triangles[0]}..{triangles[-1]}; Babylon.js: {result}")
assert "error" not in result, result["error"]
assert result["state"] == "complete" and not result["errors"], "the loader did not complete cleanly"
assert result["ready"] == triangles[-1], f"ready with {result['ready']} triangles, not the coarsest level's {triangles[-1]}"
assert result["complete"] == triangles[0], f"complete with {result['complete']} triangles, not level 0's {triangles[0]}"
assert result["drawn"] > 0.01 * result["pixels"], "the picture is blank"
for path in sorted(glob.glob(f"{work}/{model}.three*.json")):
    at = int(path.split(".three")[1].split(".")[0])
    result = json.load(open(path))
    print(f"chain_clients {model}: three.js at level {at}'s distances: {result}")
    assert "error" not in result, result["error"]
    assert result["levels"] == len(triangles), f"three.js found {result['levels']} levels, boxlod wrote {len(triangles)}"
    assert result["shown"] == at, f"three.js shows level {result['shown']} where boxlod switches to level {at}"
    assert result["triangles"] == triangles[at], f"level {at} has {result['triangles']} triangles, boxlod's {triangles[at]}"
    assert result["drawn"] > 0, "three.js drew nothing"
PY
done
[ "$failures" = 0 ]

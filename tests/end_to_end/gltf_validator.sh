#!/usr/bin/env bash
# A real client on every kind of file boxlod writes: the Khronos glTF-Validator
# (npm gltf-validator, pinned), installed into a cache folder on first use.
# Each file must have 0 errors, 0 warnings (but a chain's data URIs) and no
# unused object but the height textures (infos and hints are allowed otherwise).
# Usage: gltf_validator.sh BOXLOD
set -euo pipefail
boxlod=$1
here=$(cd "$(dirname "$0")" && pwd)
version=2.0.0-dev.3.10
cache=${BOXLOD_NPM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/boxlod/npm}/gltf-validator-$version
if [ ! -f "$cache/node_modules/gltf-validator/index.js" ]; then
  mkdir -p "$cache"
  if ! npm install --prefix "$cache" --no-audit --no-fund --loglevel=error "gltf-validator@$version" >&2; then
    echo "gltf_validator: cannot install gltf-validator@$version from the npm registry" >&2
    exit 1
  fi
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fzk=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
quiet() { "$@" > /dev/null 2>&1 || { echo "gltf_validator: failed: $*" >&2; exit 1; }; }

quiet "$boxlod" generate --sample house -o "$work/house.glb"                # generate
quiet "$boxlod" generate --sample manual -o "$work/manual.gltf"
quiet "$boxlod" generate --city 4 -o "$work/city.glb"
quiet "$boxlod" convert "$fzk" -o "$work/fzk.glb"                           # convert: IFC (its glass blended), glTF
quiet "$boxlod" convert "$fzk" -o "$work/fzk.gltf"
quiet "$boxlod" convert "$work/house.glb" -o "$work/house_converted.gltf"
specular_glossiness=/usr/share/assimp/models/glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf
quiet "$boxlod" convert "$specular_glossiness" -o "$work/specular_glossiness.glb"   # its extension kept
# Debian's metallic-roughness BoxTextured with KHR_materials_specular added (strength, and tint from its logo).
box=/usr/share/assimp/models/glTF2/BoxTextured-glTF
mkdir "$work/specular" && cp "$box"/* "$work/specular/"
node -e '
const fs = require("fs"), path = process.argv[1], gltf = JSON.parse(fs.readFileSync(path));
gltf.extensionsUsed = ["KHR_materials_specular"];
gltf.materials[0].extensions = {KHR_materials_specular: {specularFactor: 0.5, specularColorFactor: [1, 0.75, 0.5], specularColorTexture: {index: 0}}};
fs.writeFileSync(path, JSON.stringify(gltf));' "$work/specular/BoxTextured.gltf"
quiet "$boxlod" convert "$work/specular/BoxTextured.gltf" -o "$work/specular.glb"
quiet "$boxlod" build "$work/house.glb" -o "$work/level" --level 3 --resolution 256   # one level
quiet "$boxlod" build "$fzk" -o "$work/fzk_level" --level 2 --resolution 256
quiet "$boxlod" build "$work/house.glb" -o "$work/flat_level" --level 3 --resolution 128 --manual --min-texture-size 16 --flat-faces 8
grep -q '^flat_faces = [1-9]' "$work/flat_level/house_lod.stats.txt" || { echo "gltf_validator: no flat faces to validate" >&2; exit 1; }
quiet "$boxlod" build "$work/house.glb" -o "$work/baked_level" --level 1 --resolution 128 --level-mode hybrid --budgets 0.1
grep -q '^nodes_baked = [1-9]' "$work/baked_level/house_lod.stats.txt" || { echo "gltf_validator: no baked proxy to validate" >&2; exit 1; }
mkdir "$work/chain"
quiet "$boxlod" build "$work/house.glb" --chain -o "$work/chain/house.gltf" --resolution 256   # chains (MSFT_lod)
quiet "$boxlod" build "$fzk" --chain --level-mode hybrid -o "$work/fzk_chain.glb" --resolution 256
/usr/bin/python3 "$here/make_district.py" "$work/district.city.json" 4     # CityJSON: the origin as the root's translation
quiet "$boxlod" convert "$work/district.city.json" -o "$work/district.glb"
quiet "$boxlod" build "$work/district.city.json" --chain -o "$work/district_chain.glb" --resolution 256
quiet "$boxlod" convert "$here/../data/ifc/two_storeys.ifc" -o "$work/two_storeys.glb"   # IFC 4 through web-ifc
quiet "$boxlod" generate --city 2 -o "$work/city2.glb"                      # a city's 3D Tiles content
quiet "$boxlod" tiles "$work/city2.glb" -o "$work/tiles" --resolution 256

# Others' models: every file of Debian's assimp test models (595, of every
# format) is converted, exit 0 or 2 (one line, no file); what converts is read
# back and built into a chain, again 0 or 2. Both are validated below, the
# source's own tangent-less normal maps (ClearCoatTest.gltf) allowed the
# validator's warning on them.
mkdir "$work/others"
others=0
run_other() {  # OUTPUT ARGS...: status 0, or 2 with one line and no OUTPUT
  local output=$1 status=0
  shift
  timeout 120 "$boxlod" "$@" > /dev/null 2> "$work/other.err" || status=$?
  if [ "$status" = 2 ] && [ "$(wc -l < "$work/other.err")" = 1 ] && [ ! -e "$output" ]; then return 1; fi
  [ "$status" = 0 ] && return 0
  echo "gltf_validator: boxlod $* exited $status: $(head -c 300 "$work/other.err")" >&2
  exit 1
}
while IFS= read -r -d '' model; do
  others=$((others + 1))
  out="$work/others/$others"
  run_other "$out.glb" convert "$model" -o "$out.glb" || continue
  run_other "$out.chain.glb" build "$out.glb" --chain -o "$out.chain.glb" --resolution 64 || true
done < <(find /usr/share/assimp/models -type f -print0 | sort -z)
chains=$(find "$work/others" -name '*.chain.glb' | wc -l)
[ "$chains" -ge 170 ] || { echo "gltf_validator: only $chains of Debian's assimp test models built into chains (180 read)" >&2; exit 1; }
node "$here/gltf_validator.mjs" "$cache/node_modules/gltf-validator" --allow MESH_PRIMITIVE_GENERATED_TANGENT_SPACE \
  "$work"/others/*.glb > "$work/others.txt" || { grep -B1 '^  ' "$work/others.txt" | grep -v DATA_URI_GLB >&2; exit 1; }
echo "gltf_validator: $chains of Debian's assimp test models converted, read back and built into chains: valid"

cd "$work"
node "$here/gltf_validator.mjs" "$cache/node_modules/gltf-validator" house.glb manual.gltf city.glb fzk.glb fzk.gltf \
  house_converted.gltf specular_glossiness.glb specular.glb level/house_lod.gltf fzk_level/AC14-FZK-Haus_lod.gltf flat_level/house_lod.gltf chain/house.gltf fzk_chain.glb tiles/*.glb \
  district.glb district_chain.glb two_storeys.glb
# convert keeps the source's specular-glossiness material, factors as they were.
node -e '
const b = require("fs").readFileSync(process.argv[1]);
const sg = JSON.parse(b.subarray(20, 20 + b.readUInt32LE(12))).materials[0].extensions.KHR_materials_pbrSpecularGlossiness;
process.exit(sg && sg.glossinessFactor === 1 && sg.specularFactor[0] === 0.2 && sg.diffuseTexture.index === 0 ? 0 : 1);' \
  specular_glossiness.glb || { echo "gltf_validator: convert lost KHR_materials_pbrSpecularGlossiness" >&2; exit 1; }
node -e '
const b = require("fs").readFileSync(process.argv[1]);
const s = JSON.parse(b.subarray(20, 20 + b.readUInt32LE(12))).materials[0].extensions.KHR_materials_specular;
process.exit(s && s.specularFactor === 0.5 && s.specularColorFactor[1] === 0.75 && s.specularColorTexture.index >= 0 ? 0 : 1);' \
  specular.glb || { echo "gltf_validator: convert lost KHR_materials_specular" >&2; exit 1; }
# And the validator does fail: a node naming a mesh that does not exist.
echo '{"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 5}]}' > broken.gltf
if node "$here/gltf_validator.mjs" "$cache/node_modules/gltf-validator" broken.gltf > /dev/null; then
  echo "gltf_validator: the validator passed a broken file" >&2
  exit 1
fi

#!/usr/bin/env bash
# Assets that travel: the same commands run in two folders of different names
# and depths, on copies of the same inputs, with outputs into folders that do
# not exist yet, give byte-identical files, and no file names the folder it
# was built in (docs/design.md: Files), but the parameter files of a model
# given by its absolute path, which name it as given
# (docs/design.md: Parameter file).
set -euo pipefail
boxlod=$1
ifc=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
work=$(cd "$(mktemp -d)" && pwd)
trap 'rm -rf "$work"' EXIT
run_in() {  # run_in FOLDER: every command that writes an asset, from FOLDER
  mkdir -p "$1"
  cp "$ifc" "$1/house.ifc"
  (
    cd "$1"
    "$boxlod" generate --city 2 -o city.glb
    "$boxlod" build house.ifc --chain -o chain/house.glb
    "$boxlod" build house.ifc --all-levels --wanted-levels 3 -o levels
    "$boxlod" build "$PWD/house.ifc" --all-levels --wanted-levels 2 -o absolute
    "$boxlod" tiles city.glb -o tiles --resolution 128
    "$boxlod" convert house.ifc -o converted/house.gltf
    "$boxlod" simplify house.ifc --faces 1000 -o simplified/house.glb
  ) > /dev/null 2>&1
}
run_in "$work/one"
run_in "$work/two/deeper/still"
failures=0
files=$(cd "$work/one" && find . -type f ! -name house.ifc ! -path './absolute/*.params.txt' | sort)
[ "$(echo "$files" | wc -l)" -ge 20 ] || { echo "FAIL: too few outputs: $files"; exit 1; }
for f in $files; do
  cmp -s "$work/one/$f" "$work/two/deeper/still/$f" || { echo "FAIL: $f differs between the two folders"; failures=$((failures + 1)); }
done
for folder in "$work/one" "$work/two/deeper/still"; do
  grep -qxF "model = $folder/house.ifc" "$folder/absolute/house_lod_L0.params.txt" ||
    { echo "FAIL: $folder/absolute: the parameter file does not name the model as given"; failures=$((failures + 1)); }
done
if grep -rla --exclude='*.params.txt' -e "$work" "$work/one" "$work/two" ||
  grep -rla -e "$work" "$work/one/levels" "$work/two/deeper/still/levels"; then echo "FAIL: the files above name the folder they were built in"; failures=$((failures + 1)); fi
echo "portable_outputs: $(echo "$files" | wc -l) files, $failures failures"
[ "$failures" = 0 ]

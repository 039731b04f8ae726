#!/usr/bin/env bash
# Debug (-O0) and Release builds of boxlod write the same bytes: the demo's
# commands and every sample, box kind and render mode are run by both, each in
# a folder of its own, and every file and every stdout compared (docs/testing.md: Determinism).
# Usage: debug_release_agree.sh RELEASE_BOXLOD DEBUG_BOXLOD
set -u
release=$(realpath "$1")
debug=$(realpath -m "$2")
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ ! -x "$debug" ]; then
  echo "FAIL no Debug boxlod at $debug (make test builds it: make debug-build)"
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fzk=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
small=(--width 240 --height 180)

# The commands, run from the side's own folder; each command's stdout goes to
# a file named after the step, so printed statistics are compared too.
commands() {  # commands BOXLOD
  local boxlod=$1 sample kind mode
  step() { local name=$1; shift; "$boxlod" "$@" > "stdout_$name.txt" 2>/dev/null || echo "exit $? from: $*" >> failures.txt; }
  for sample in house office classical manual; do
    step "generate_$sample" generate --sample "$sample" -o "$sample.glb"
  done
  step generate_city generate --city 4 --seed 7 -o city.gltf
  step info_house info house.glb
  step info_fzk info "$fzk"
  step convert_fzk convert "$fzk" -o fzk.gltf
  for kind in scope expanded minimal; do
    step "build_house_$kind" build house.glb -o "house_$kind" --level 2 --box "$kind" --resolution 512 \
      --preview-width 240 --preview-height 180
  done
  # The IFC has no scopes, so every box kind is CGAL's minimal box there (docs/design.md: Boxes);
  # one build covers them.
  step build_fzk build "$fzk" -o fzk --level 3 --box minimal --resolution 512 --preview-width 240 --preview-height 180
  step build_house_levels build house.glb -o house_levels --all-levels --level-mode box-area --resolution 256 \
    --preview-width 240 --preview-height 180
  for mode in untextured normal parallax pom albedo; do
    step "render_lod_$mode" render house_expanded/house_lod.gltf -o "lod_$mode.png" --mode "$mode" "${small[@]}"
    step "render_fzk_$mode" render "$fzk" -o "fzk_$mode.png" --mode "$mode" --camera -X+Y "${small[@]}"
  done
  step render_extras render house.glb -o extras.png --exr extras.exr --coverage extras_mask.png --wireframe --axes \
    --split-view house_expanded/house_lod.gltf "${small[@]}"
  step compare compare lod_normal.png lod_pom.png --heatmap heatmap.png
  step simplify simplify house.glb --faces 500 -o house_simplified.glb
  # The demo's experiment at two levels (every level takes 150 s at -O0).
  sed 's/^levels = .*/levels = 2, 5/' "$root/experiments/configs/demo.txt" > demo_sweep.txt
  step sweep sweep demo_sweep.txt -o experiment
  rm -f experiment/timings.csv  # seconds, not results
  sed -i '/^boxlod_build = /d' experiment/settings.txt  # names the executable, which differs by design
  sed -i '/seconds/d' stdout_*.txt
}

for side in release debug; do
  mkdir -p "$work/$side"
  binary=$release; [ "$side" = debug ] && binary=$debug
  (cd "$work/$side" && commands "$binary")
done

failures=0
if [ -s "$work/release/failures.txt" ] || [ -s "$work/debug/failures.txt" ]; then
  cat "$work"/*/failures.txt
  failures=$((failures + 1))
fi
files=$(cd "$work/release" && find . -type f | sort)
count=0 passed=0
for file in $files; do
  count=$((count + 1))
  if cmp -s "$work/release/$file" "$work/debug/$file"; then
    passed=$((passed + 1))
  else
    echo "FAIL $file differs between Release and Debug"
    failures=$((failures + 1))
  fi
done
only_debug=$(cd "$work/debug" && find . -type f | sort | comm -13 <(echo "$files") -)
[ -n "$only_debug" ] && { echo "FAIL only Debug wrote: $only_debug"; failures=$((failures + 1)); }
[ "$count" -ge 100 ] || { echo "FAIL only $count files written"; failures=$((failures + 1)); }

echo "$passed passed, $failures failed"
[ "$failures" -eq 0 ]

#!/usr/bin/env bash
# The main job on built-in defaults: a generated building and a real one, each
# built into every level of its textured-box LoD, with a table and renders;
# then the first experiment, quality against triangles and bytes for five
# level modes (hybrid among them) and the simplification baseline.
set -euo pipefail
build=${1:-build}
boxlod="$build/boxlod"
out=out/demo
rm -rf "$out"
mkdir -p "$out"

# Prints one row per level from `boxlod build --all-levels` output; bytes =
# mesh + GPU-compressed textures (docs/design.md: Cost).
level_table() {
  awk -F' = ' '
    BEGIN { printf "%-6s %10s %10s %10s %8s %8s %6s %12s\n", "level", "faces", "triangles", "boxes", "pages", "size", "draws", "bytes" }
    $1 == "faces_lod" { faces = $2 } $1 == "triangles_lod" { tris = $2 } $1 == "nodes_with_box" { boxes = $2 }
    $1 == "lod_textures" { pages = $2 } $1 == "texture_size" { size = $2 }
    $1 == "draw_calls_lod" { draws = $2 } $1 == "bytes_lod" { bytes = $2 }
    $1 == "current_level" { printf "%-6s %10s %10s %10s %8s %8s %6s %12s\n", $2, faces, tris, boxes, pages, size, draws, bytes }'
}

demo_model() {  # demo_model NAME MODEL
  local name=$1 model=$2
  echo "== $name: $model"
  "$boxlod" info "$model" | grep -E '^(nodes|nodes_with_geometry|depth|faces_original|mesh_(width|height|depth)|draw_calls_original|bytes_original) '
  mkdir -p "$out/$name"
  # The manual's program: every level at one sizing distance, every sub-tree boxed.
  "$boxlod" build "$model" -o "$out/$name" --name "$name" --all-levels --manual --level-mode top-down --resolution 1080 \
    --timings > "$out/$name/build.txt" 2>/dev/null
  level_table < "$out/$name/build.txt"
  grep '^time_' "$out/$name/build.txt" | tr '\n' ' '; echo
  # The same levels as an engine would ship them, boxlod's defaults (docs/cost.md: Boxes that pay
  # their way): each level sized for where it is used, no box dearer than the geometry it replaces.
  echo "-- $name, the chain that pays its way (the defaults; the above: --manual)"
  "$boxlod" build "$model" -o "$out/$name/chain" --name "$name" --all-levels --level-mode top-down --resolution 1080 \
    > "$out/$name/chain.txt" 2>/dev/null
  level_table < "$out/$name/chain.txt"
  grep -E '^(bytes_chain|texture_bytes_gpu_chain) ' "$out/$name/chain.txt" | tr '\n' ' '; echo
  "$boxlod" render "$model" -o "$out/$name/original.png" > /dev/null
  local middle
  # The middle one of the levels written (a level that repeats the one before is not).
  middle=$(awk -F' = ' '$1 == "current_level" { c[n++] = $2 } END { print c[int(n / 2)] }' "$out/$name/build.txt")
  "$boxlod" render "$out/$name/${name}_L${middle}.gltf" --split-view "$model" -o "$out/$name/split_L${middle}.png" > /dev/null
  echo "renders: $out/$name/original.png, $out/$name/split_L${middle}.png (level $middle left, original right)"
  echo
}

"$boxlod" generate --sample house -o "$out/house.glb" > /dev/null
demo_model house "$out/house.glb"
demo_model fzk-haus /usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc

# The first experiment: every level of five level modes of the house,
# compared with the original from three views (experiments/configs/demo.txt).
echo "== experiment: quality against triangles and bytes, textured boxes (hybrid among them) and mesh simplification (PSNR, SSIM, FLIP over 3 views)"
"$boxlod" sweep experiments/configs/demo.txt -o "$out/experiment" > /dev/null 2>&1
/usr/bin/python3 experiments/plot_quality.py "$out/experiment/results.csv" "$out/experiment/quality.png"
echo
echo "all outputs: $out/"

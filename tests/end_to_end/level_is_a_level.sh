#!/usr/bin/env bash
# A level is a level (docs/design.md: Files): `build MODEL --level c` writes,
# byte for byte, the files of level c of `build MODEL --all-levels`, and so
# does building from that level's parameter file; for the FZK-Haus and every
# sample, every level --all-levels writes.
set -u
boxlod=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
options=(--resolution 128 --min-texture-size 16 --preview-width 32 --preview-height 24)
"$boxlod" convert /usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc -o "$work/fzk.glb" > /dev/null || exit 1
for sample in house manual classical office; do "$boxlod" generate --sample $sample -o "$work/$sample.glb" > /dev/null || exit 1; done

# Every file `folder` holds of level `name` equals the one in all/.
same_files() {  # same_files MODEL FOLDER NAME
  local made=0 f
  for f in "$work/$1/$2/$3".* "$work/$1/$2/$3"_*; do
    [ -e "$f" ] || continue
    made=$((made + 1))
    cmp -s "$f" "$work/$1/all/$(basename "$f")" || { echo "     $(basename "$f") differs"; return 1; }
  done
  test "$made" = "$(ls "$work/$1/all/$3".* "$work/$1/all/$3"_* 2> /dev/null | wc -l)"
}

for model in fzk house manual classical office; do
  if ! "$boxlod" build "$work/$model.glb" -o "$work/$model/all" --all-levels "${options[@]}" > /dev/null 2>&1; then
    echo "FAIL $model: build --all-levels"; failures=$((failures + 1)); continue
  fi
  for params in "$work/$model/all/"*_L*.params.txt; do
    name=$(basename "$params" .params.txt)
    level=${name##*_L}
    "$boxlod" build "$work/$model.glb" --level "$level" -o "$work/$model/single" --name "$name" "${options[@]}" > /dev/null 2>&1
    if same_files "$model" single "$name"; then echo "ok   $model: --level $level"; else echo "FAIL $model: --level $level"; failures=$((failures + 1)); fi
    "$boxlod" build "$params" -o "$work/$model/again" --name "$name" --preview-width 32 --preview-height 24 > /dev/null 2>&1
    if same_files "$model" again "$name"; then echo "ok   $model: $name.params.txt"; else echo "FAIL $model: $name.params.txt"; failures=$((failures + 1)); fi
  done
done
echo "$failures failed"
[ "$failures" = 0 ]

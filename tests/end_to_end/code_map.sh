#!/usr/bin/env bash
# docs/code.md names every header of every layer, and every header it names
# exists (docs/code.md: Checks of this page and of the docs).
# Usage: code_map.sh SOURCE_DIR
set -u
root=$1 doc=$1/docs/code.md
# Every layer folder and its sub-folders (toolkit's concept folders, commands/).
layers=$(cd "$root" && find base renderer toolkit data_gen experiments -type d -not -path '*/grammars*' -not -path '*/workflow*' \
         -not -path '*/configs*' -not -path '*/benchmarks*' | sort)
bad=0 checked=0
for layer in $layers; do
  for header in "$root/$layer"/*.h; do
    [ -e "$header" ] || continue
    checked=$((checked + 1))
    name=$(basename "$header")
    grep -qE "(^|[^a-z_0-9])${name//./\\.}([^a-z_0-9]|$)" "$doc" && continue
    # A commands/ folder is named as a whole.
    [[ $layer == */commands ]] && grep -qF "\`commands/\`" "$doc" && continue
    echo "$doc: $layer/$name is not named"; bad=1
  done
done
for name in $(grep -oE "[a-z_0-9]+\.h\b" "$doc" | sort -u); do
  found=0
  for layer in $layers; do [ -e "$root/$layer/$name" ] && found=1; done
  [ $found -eq 1 ] || { echo "$doc: names $name, which no layer has"; bad=1; }
done
[ $bad -eq 0 ] && echo "code_map: $checked headers, each named in docs/code.md"
exit $bad

#!/usr/bin/env bash
# The layers point one way (docs/code.md): a file includes only headers of its
# own layer and the layers below it, base < renderer < toolkit < data_gen <
# experiments, and only a layer's commands/ folder includes commands/ headers
# (the program sits on the libraries, never inside them). Prints every include
# that breaks a rule and fails if there is one. Usage: layers_point_one_way.sh ROOT
set -u
cd "$1" || exit 2
rank() { case $1 in base) echo 0 ;; renderer) echo 1 ;; toolkit) echo 2 ;; data_gen) echo 3 ;; experiments) echo 4 ;; *) echo -1 ;; esac; }
broken=0
checked=0
while IFS= read -r file; do
  layer=${file%%/*}
  own=$(rank "$layer")
  checked=$((checked + 1))
  while IFS= read -r header; do
    [ -z "$header" ] && continue
    target=$(rank "${header%%/*}")
    [ "$target" -lt 0 ] && continue  # a system or third-party header
    if [ "$target" -gt "$own" ]; then
      echo "$file includes $header: $layer may not include ${header%%/*}, a layer above it"; broken=1
    fi
    if [[ $header == */commands/* && $file != */commands/* ]]; then
      echo "$file includes $header: only a commands/ folder includes commands"; broken=1
    fi
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$file")
done < <(find base renderer toolkit data_gen experiments -name '*.h' -o -name '*.cpp' | sort)
if [ "$checked" -lt 100 ]; then echo "only $checked files found under $1: wrong folder?"; exit 1; fi
[ $broken -eq 0 ] && echo "$checked files: every include points down or within its layer"
exit $broken

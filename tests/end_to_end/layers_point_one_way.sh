#!/usr/bin/env bash
# The layers point one way (docs/code.md): a file includes only headers of its
# own layer and the layers below it, base < renderer < toolkit < data_gen <
# experiments, and only a layer's commands/ folder includes commands/ headers
# (the program sits on the libraries, never inside them). Within toolkit the
# concept folders point one way too: model < cgal < drawing < metrics <
# formats < lod < selection < commands and the library's face (boxlod.h),
# and so do lod's: pages (boxes and their baked pages) < cut (which parts a
# level keeps) < hybrid (measured error per byte) < lod itself (a level: its
# parameters, session, builder, files) < chain. A level's session and the
# builder that fills it (lod_session.h, lod_builder.h, level_faces.h) are
# lod's own: elsewhere, tests included, a chain (lod/chain/chain.h) hands
# out levels (issue 72).
# Prints every include that breaks a rule and fails if there is one.
# Usage: layers_point_one_way.sh ROOT
set -u
cd "$1" || exit 2
rank() { case $1 in base) echo 0 ;; renderer) echo 1 ;; toolkit) echo 2 ;; data_gen) echo 3 ;; experiments) echo 4 ;; *) echo -1 ;; esac; }
toolkit_rank() {
  case $1 in
    toolkit/model/*) echo 0 ;; toolkit/cgal/*) echo 1 ;; toolkit/drawing/*) echo 2 ;; toolkit/metrics/*) echo 3 ;;
    toolkit/formats/*) echo 4 ;; toolkit/lod/pages/*) echo 5 ;; toolkit/lod/cut/*) echo 6 ;; toolkit/lod/hybrid/*) echo 7 ;;
    toolkit/lod/chain/*) echo 9 ;; toolkit/lod/*) echo 8 ;; toolkit/selection/*) echo 10 ;; *) echo 11 ;;
  esac
}
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
    if [[ $header =~ ^toolkit/lod/(lod_session|lod_builder|level_faces)\.h$ && $file != toolkit/lod/* && $file != tests/toolkit/lod/* ]]; then
      echo "$file includes $header: a level's session is lod/'s own; ask a Chain (toolkit/lod/chain/chain.h)"; broken=1
    fi
    [ "$layer" = tests ] && continue  # tests may include any layer
    if [ "$target" -gt "$own" ]; then
      echo "$file includes $header: $layer may not include ${header%%/*}, a layer above it"; broken=1
    fi
    if [ "$layer" = toolkit ] && [[ $header == toolkit/* ]] && [ "$(toolkit_rank "$header")" -gt "$(toolkit_rank "$file")" ]; then
      echo "$file includes $header: toolkit's ${file#toolkit/} may not include a concept folder above it"; broken=1
    fi
    if [[ $header == */commands/* && $file != */commands/* ]]; then
      echo "$file includes $header: only a commands/ folder includes commands"; broken=1
    fi
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$file")
done < <(find base renderer toolkit data_gen experiments tests -name '*.h' -o -name '*.cpp' | sort)
if [ "$checked" -lt 100 ]; then echo "only $checked files found under $1: wrong folder?"; exit 1; fi
# No two modules (a header with its .cpp) need each other, however
# indirectly: each idea sits on the ones it uses (issue 48).
cycles=$(/usr/bin/python3 - <<'PY'
import os, re, sys
needs = {}
for layer in ("base", "renderer", "toolkit", "data_gen", "experiments"):
    for folder, _, files in os.walk(layer):
        for name in files:
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(folder, name)
            module = os.path.splitext(path)[0]
            for header in re.findall(r'^\s*#\s*include\s*"([^"]+)\.h"', open(path, errors="replace").read(), re.M):
                if header != module and os.path.exists(header + ".h"):
                    needs.setdefault(module, set()).add(header)
# Strongly connected components (Tarjan): any with two or more modules is a cycle.
index, low, stack, on_stack, found = {}, {}, [], set(), []
def visit(v):
    index[v] = low[v] = len(index)
    stack.append(v); on_stack.add(v)
    for w in sorted(needs.get(v, ())):
        if w not in index:
            visit(w); low[v] = min(low[v], low[w])
        elif w in on_stack:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        component = []
        while True:
            w = stack.pop(); on_stack.discard(w); component.append(w)
            if w == v:
                break
        if len(component) > 1:
            found.append(" <-> ".join(sorted(component)))
sys.setrecursionlimit(10000)
for v in sorted(needs):
    if v not in index:
        visit(v)
print("\n".join(found))
PY
)
if [ -n "$cycles" ]; then echo "modules that need each other: $cycles"; broken=1; fi
[ $broken -eq 0 ] && echo "$checked files: every include points down or within its layer, and no two modules need each other"
exit $broken

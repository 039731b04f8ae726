#!/usr/bin/env bash
# Each concept once (issue 72; docs/code.md: Each concept once): outside tests/, the doubling rule,
# the bounding sphere's radius and an orthographic view are each written in one file only.
# Usage: concepts_once.sh SOURCE_DIR
set -euo pipefail
cd "$1"
git rev-parse --is-inside-work-tree > /dev/null || { echo "concepts_once: $1 is no git checkout"; exit 1; }
problems=0
# once PATTERN FILE WHAT: PATTERN (a fixed string) appears in FILE and in no other source outside tests/.
once() {
  local found
  found=$(git ls-files '*.cpp' '*.h' | grep -v '^tests/' | xargs grep -lF -- "$1" | sort || true)
  if [ "$found" != "$2" ]; then
    echo "concepts_once: $3 ('$1') is written in: ${found//$'\n'/, } (only in $2)"
    problems=$((problems + 1))
  fi
}
once 'ldexp(' toolkit/lod/chain/chain.cpp "the doubling rule d 2^(c-1)"
once '.size().norm()' toolkit/model/framing.cpp "the bounding sphere's radius"
once 'orthographic = true' renderer/camera.cpp "an orthographic view"
echo "concepts_once: $problems problems"
[ "$problems" -eq 0 ]

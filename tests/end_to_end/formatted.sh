#!/usr/bin/env bash
# Every C++ file of the project is laid out as clang-format-14 lays it out with
# .clang-format (issue 72; docs/code.md: Checks of this page and of the docs).
# Usage: formatted.sh SOURCE_DIR. `make format` formats the tree in place.
set -euo pipefail
cd "$1"
format=$(command -v clang-format-14 || true)
[ -n "$format" ] || { echo "formatted: clang-format-14 is missing (scripts/install-deps.sh installs it)"; exit 1; }
mapfile -t files < <(git ls-files '*.cpp' '*.h')
[ ${#files[@]} -gt 0 ] || { echo "formatted: no C++ file listed by git in $1 (a checkout is needed)"; exit 1; }
unformatted=()
for file in "${files[@]}"; do
  "$format" --style=file --dry-run --Werror "$file" > /dev/null 2>&1 || unformatted+=("$file")
done
for file in "${unformatted[@]}"; do echo "$file: not as clang-format-14 lays it out (make format)"; done
echo "formatted: ${#files[@]} files looked at, ${#unformatted[@]} not formatted"
[ ${#unformatted[@]} -eq 0 ]

#!/usr/bin/env bash
# docs/api_example.cpp, the library's example (toolkit/boxlod.h), run as a user
# would: on the FZK-Haus it prints the chain's levels, finest first from 0 m,
# and a level within 5 % of the bytes that looks like the house from twice the
# framing distance; boxlod reads the level it wrote. Usage: api_example.sh API_EXAMPLE BOXLOD
set -euo pipefail
example=$1 boxlod=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "api_example: $*" >&2; exit 1; }
"$example" /usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc "$work/level.glb" > "$work/out" || fail "exit $? on the FZK-Haus"
cat "$work/out"
head -1 "$work/out" | grep -qx 'chain level 0 from 0.0 m' || fail "the chain does not start with level 0"
test "$(grep -c '^chain level' "$work/out")" -ge 2 || fail "a chain of one level"
/usr/bin/python3 - "$work/out" <<'PY' || fail "the level is not within 5 % or does not look like the house"
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"^level 1: (\d+) bytes, FLIP over covered pixels ([0-9.]+), silhouette IoU ([0-9.]+)$", text, re.M)
distances = [float(d) for d in re.findall(r"^chain level \d+ from ([0-9.]+) m$", text, re.M)]
assert distances == sorted(distances) and len(set(distances)) == len(distances), distances
assert m and float(m.group(2)) < 0.25 and float(m.group(3)) > 0.8, text
PY
"$boxlod" info "$work/level.glb" > /dev/null || fail "boxlod cannot read the level it wrote"
status=0
"$example" "$work/none.ifc" "$work/other.glb" 2> "$work/err" || status=$?
test "$status" = 2 -a "$(wc -l < "$work/err")" = 1 -a ! -e "$work/other.glb" || fail "a missing model: exit $status, $(cat "$work/err")"
echo "api_example: ok"

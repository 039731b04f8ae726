#!/usr/bin/env bash
# A city as 3D Tiles, loaded by a real client: CesiumJS (npm cesium, pinned) in
# Debian's headless Chromium, driven by playwright-core (npm, pinned), both
# installed into a cache folder on first use; the page is served on localhost.
# Passes when CesiumJS has loaded every tile in view and the picture shows the
# city: more than 1 % of the pixels are not the black background.
# Usage: tiles_cesium.sh BOXLOD   (BOXLOD_TILES_SCREENSHOT=FILE keeps the picture)
set -euo pipefail
boxlod=$1
here=$(cd "$(dirname "$0")" && pwd)
cesium=1.145.0 playwright=1.57.0
cache=${BOXLOD_NPM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/boxlod/npm}/cesium-$cesium-playwright-$playwright
if [ ! -f "$cache/node_modules/cesium/Build/Cesium/Cesium.js" ] || [ ! -d "$cache/node_modules/playwright-core" ]; then
  mkdir -p "$cache"
  if ! npm install --prefix "$cache" --no-audit --no-fund --loglevel=error "cesium@$cesium" "playwright-core@$playwright" >&2; then
    echo "tiles_cesium: cannot install cesium@$cesium and playwright-core@$playwright from the npm registry" >&2
    exit 1
  fi
fi
work=$(mktemp -d)
server=
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT

"$boxlod" generate --city 4 -o "$work/city.glb" > /dev/null
"$boxlod" tiles "$work/city.glb" -o "$work/site/tiles" --resolution 256 > "$work/tiles.txt"
ln -s "$cache/node_modules/cesium/Build/Cesium" "$work/site/Cesium"
cp "$here/tiles_cesium.html" "$work/site/index.html"
port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
/usr/bin/python3 -m http.server "$port" --bind 127.0.0.1 --directory "$work/site" > /dev/null 2>&1 &
server=$!
for _ in $(seq 50); do
  /usr/bin/python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/tiles/tileset.json')" 2>/dev/null && break
  sleep 0.2
done
node "$here/tiles_cesium.mjs" "$cache/node_modules/playwright-core" "http://127.0.0.1:$port/index.html" \
  "$work/screenshot.png" > "$work/result.json"
[ -n "${BOXLOD_TILES_SCREENSHOT:-}" ] && cp "$work/screenshot.png" "$BOXLOD_TILES_SCREENSHOT"
/usr/bin/python3 - "$work/result.json" <<'PY'
import json, sys
result = json.load(open(sys.argv[1]))
print("tiles_cesium:", result)
assert "error" not in result, result["error"]
assert result["tilesLoaded"], "CesiumJS did not finish loading the tiles in view"
assert result["drawn"] > 0.01 * result["pixels"], "the picture is blank: the city is not drawn"
PY

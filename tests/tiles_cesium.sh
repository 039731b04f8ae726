#!/usr/bin/env bash
# A city as 3D Tiles, loaded by a real client: CesiumJS (npm cesium, pinned) in
# Debian's headless Chromium, driven by playwright-core (npm, pinned), both
# installed into a cache folder on first use (tests/browser_clients.sh).
# Passes when CesiumJS has loaded every tile in view and the picture shows the
# city: more than 1 % of the pixels are not the black background; and when a
# metre from the building with the most levels it draws its original (level
# 0), and far from it (the root refined, its coarsest level not) that coarsest
# level.
# Usage: tiles_cesium.sh BOXLOD   (BOXLOD_TILES_SCREENSHOT=FILE keeps the picture)
set -euo pipefail
boxlod=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/browser_clients.sh"
npm_client cesium-1.145.0-playwright-1.57.0 cesium@1.145.0 playwright-core@1.57.0
work=$(mktemp -d)
server=
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT

"$boxlod" generate --city 4 -o "$work/city.glb" > /dev/null
"$boxlod" tiles "$work/city.glb" -o "$work/site/tiles" --resolution 256 > "$work/tiles.txt"
ln -s "$client/node_modules/cesium/Build/Cesium" "$work/site/Cesium"
cp "$here/tiles_cesium.html" "$work/site/index.html"
serve "$work/site"
for view in city near far; do
  open_page "http://127.0.0.1:$port/index.html?view=$view" "$work/result_$view.json" "$work/screenshot_$view.png"
done
[ -n "${BOXLOD_TILES_SCREENSHOT:-}" ] && cp "$work/screenshot_city.png" "$BOXLOD_TILES_SCREENSHOT"
/usr/bin/python3 - "$work" <<'PY'
import json, sys
results = {view: json.load(open(f"{sys.argv[1]}/result_{view}.json")) for view in ("city", "near", "far")}
for view, result in results.items():
    print(f"tiles_cesium {view}:", result)
    assert "error" not in result, result["error"]
    assert result["tilesLoaded"], f"{view}: CesiumJS did not finish loading the tiles in view"
    assert result["drawn"] > 0.01 * result["pixels"] or view == "far", f"{view}: the picture is blank"
near, far, coarsest = results["near"]["tiles"], results["far"]["tiles"], results["near"]["coarsest"]
prefix = coarsest[:coarsest.rindex("_L") + 1]  # object_K_
assert prefix + "L0.glb" in near, f"near {prefix[:-1]} CesiumJS draws {near}, not its original"
assert [t for t in far if t.startswith(prefix)] == [coarsest], f"far from {prefix[:-1]} CesiumJS draws {far}, not {coarsest}"
PY

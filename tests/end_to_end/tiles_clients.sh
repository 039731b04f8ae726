#!/usr/bin/env bash
# A city as 3D Tiles, loaded by real clients in Debian's headless Chromium,
# npm packages pinned and installed into a cache folder on first use
# (tests/end_to_end/browser_clients.sh): CesiumJS and 3d-tiles-renderer (three.js).
# Passes when CesiumJS has loaded every tile in view and the picture shows the
# city: more than 1 % of the pixels are not the black background; and when
# both clients, a metre from the building with the most levels, draw its
# original (level 0), and far from it (the root refined, its coarsest level
# not) that coarsest level.
# Usage: tiles_clients.sh BOXLOD   (BOXLOD_TILES_SCREENSHOT=FILE keeps CesiumJS's picture)
set -euo pipefail
boxlod=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/browser_clients.sh"
npm_client 3d-tiles-renderer-0.5.3-three-0.187.0-playwright-1.57.0 3d-tiles-renderer@0.5.3 three@0.187.0 playwright-core@1.57.0
tiles_three=$client
npm_client cesium-1.145.0-playwright-1.57.0 cesium@1.145.0 playwright-core@1.57.0
work=$(mktemp -d)
server=
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT

"$boxlod" generate --city 4 -o "$work/city.glb" > /dev/null
"$boxlod" tiles "$work/city.glb" -o "$work/site/tiles" --resolution 256 > "$work/tiles.txt"
ln -s "$client/node_modules/cesium/Build/Cesium" "$work/site/Cesium"
cp "$here/tiles_cesium.html" "$work/site/index.html"
ln -s "$tiles_three/node_modules/three" "$work/site/three"
ln -s "$tiles_three/node_modules/3d-tiles-renderer" "$work/site/3d-tiles-renderer"
cp "$here/tiles_three.html" "$work/site/three.html"
serve "$work/site"
for view in city near far; do
  open_page "http://127.0.0.1:$port/index.html?view=$view" "$work/cesium_$view.json" "$work/screenshot_$view.png"
done
for view in near far; do
  open_page "http://127.0.0.1:$port/three.html?view=$view" "$work/three_$view.json" "$work/three_$view.png"
done
# A CityJSON district of 50 buildings 450 km from its CRS's origin, placed by that CRS, each
# Building an object: under a minute on 2 cores, then shown by both clients.
/usr/bin/python3 "$here/make_district.py" "$work/district.city.json" 50
start=$(date +%s.%N)
"$boxlod" tiles "$work/district.city.json" -o "$work/site/tiles" > "$work/district.txt"
district_seconds=$(/usr/bin/python3 -c "import sys; print(round($(date +%s.%N) - $start, 1))")
open_page "http://127.0.0.1:$port/index.html?view=city" "$work/cesium_district.json" "$work/district.png"
open_page "http://127.0.0.1:$port/three.html?view=near" "$work/three_district.json" "$work/three_district.png"
[ -n "${BOXLOD_TILES_SCREENSHOT:-}" ] && cp "$work/screenshot_city.png" "$BOXLOD_TILES_SCREENSHOT" && cp "$work/district.png" "${BOXLOD_TILES_SCREENSHOT%.png}_district.png"
/usr/bin/python3 - "$work" "$district_seconds" <<'PY'
import json, sys
results = {view: json.load(open(f"{sys.argv[1]}/cesium_{view}.json")) for view in ("city", "near", "far")}
for view, result in results.items():
    print(f"tiles_clients CesiumJS {view}:", result)
    assert "error" not in result, result["error"]
    assert result["tilesLoaded"], f"{view}: CesiumJS did not finish loading the tiles in view"
    assert result["drawn"] > 0.01 * result["pixels"] or view == "far", f"{view}: the picture is blank"
for client in ("cesium", "three"):
    near, far = (json.load(open(f"{sys.argv[1]}/{client}_{view}.json")) for view in ("near", "far"))
    name = {"cesium": "CesiumJS", "three": "3d-tiles-renderer"}[client]
    if client == "three": print(f"tiles_clients {name} near: {near}\ntiles_clients {name} far: {far}")
    assert "error" not in near and "error" not in far, near.get("error") or far.get("error")
    assert near.get("settled", True) and far.get("settled", True), f"{name} did not settle"
    assert far.get("errorTarget", 16) == 16, f"{name}'s default limit is no longer 16 pixels"
    coarsest = near["coarsest"]
    prefix = coarsest[:coarsest.rindex("_L") + 1]  # object_K_
    assert prefix + "L0.glb" in near["tiles"], f"near {prefix[:-1]} {name} draws {near['tiles']}, not its original"
    drawn_far = [t for t in far["tiles"] if t.startswith(prefix)]
    assert drawn_far == [coarsest], f"far from {prefix[:-1]} {name} draws {far['tiles']}, not {coarsest}"
district = json.load(open(f"{sys.argv[1]}/cesium_district.json"))
print(f"tiles_clients CesiumJS district ({sys.argv[2]} s to tile):", district)
assert float(sys.argv[2]) < 60, f"tiling the 50-building district took {sys.argv[2]} s, not under a minute"
assert "error" not in district and district["tilesLoaded"], district
assert district["drawn"] > 0.01 * district["pixels"], "the district's picture is blank"
three = json.load(open(f"{sys.argv[1]}/three_district.json"))
assert "error" not in three and three.get("settled", True) and three["tiles"], three
assert open(f"{sys.argv[1]}/district.txt").read().count("objects = 50") == 1
# Placed by its reference system (RD New + NAP, x 85 km, y 447 km): in Delft, 52.01 N 4.37 E, not at KIT.
import math
x, y, z = json.load(open(f"{sys.argv[1]}/site/tiles/tileset.json"))["root"]["transform"][12:15]
latitude = math.degrees(math.atan2(z, math.hypot(x, y) * (1 - 6.69437999014e-3)))  # on the ellipsoid's surface
longitude = math.degrees(math.atan2(y, x))
print(f"tiles_clients district placed at {latitude:.4f} N {longitude:.4f} E")
assert abs(latitude - 52.01) < 0.02 and abs(longitude - 4.37) < 0.02, (latitude, longitude)
# The tiles are in the tileset's frame, at no system's origin: none names the file's system.
import glob
named = [g for g in glob.glob(f"{sys.argv[1]}/site/tiles/*.glb") if b"reference_system" in open(g, "rb").read()]
assert not named, f"tiles naming a reference system: {named[:3]}"
PY

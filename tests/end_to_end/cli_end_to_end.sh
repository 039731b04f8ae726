#!/usr/bin/env bash
# The boxlod CLI as a user meets it: real data, --help, --json, bad input.
set -u
boxlod=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check NAME CONDITION...
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
status_of() { "$@" >"$work/out" 2>"$work/err"; echo $?; }

ifc=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
check "info on the FZK-Haus IFC succeeds" test "$(status_of "$boxlod" info "$ifc")" = 0
check "info prints nodes = 114 (web-ifc: elements that draw, under their storeys)" grep -qx "nodes = 114" "$work/out"
check "info prints every required key" bash -c "for k in nodes nodes_with_geometry depth faces_original triangles_original vertices_original batches_original mesh_width mesh_height mesh_depth; do grep -q \"^\$k = \" '$work/out' || exit 1; done"

# Spatial relationships nested deep: web-ifc's own walk of them doubled with each level (2^depth).
python3 "$here/ifc_nested.py" "$ifc" "$work/nested150.ifc" 150 && python3 "$here/ifc_nested.py" "$ifc" "$work/nested250.ifc" 250
check "an IFC nested 150 deep reads in seconds" timeout 30 "$boxlod" info "$work/nested150.ifc" --json
check "an IFC nested 250 deep is refused, naming the depth" bash -c "'$boxlod' info '$work/nested250.ifc' 2>&1 >/dev/null | grep -q 'nested more than 200 levels deep'"
# One wall drawn 200,000 times (800 kB): web-ifc's node held 1.2 GB under a budget of 0.5 GB (not a
# bad_inputs case: under its ulimit -v node cannot reserve a WebAssembly memory at all).
python3 -c "import sys; t = open(sys.argv[1]).read(); open(sys.argv[2], 'w').write(t.replace(\"'SweptSolid',(#53));\", \"'SweptSolid',(\" + ','.join(['#53'] * 200000) + '));'))" "$here/../data/ifc/two_storeys.ifc" "$work/items.ifc"
check "web-ifc is stopped at the memory budget" bash -c "timeout 60 '$boxlod' info '$work/items.ifc' --max-memory 0.5 2>&1 >/dev/null | grep -q 'web-ifc grew past the memory budget of 500 MB'"
check "info --json succeeds" test "$(status_of "$boxlod" info "$ifc" --json)" = 0
check "info --json is a JSON object with nodes" python3 -c "import json,sys; d=json.load(open('$work/out')); sys.exit(0 if d['nodes']==114 else 1)"

check "convert to glb succeeds" test "$(status_of "$boxlod" convert "$ifc" -o "$work/fzk.glb")" = 0
check "converted glb has the same statistics but batches" bash -c "'$boxlod' info '$ifc' | grep -v -e ^batches -e ^draw_calls > '$work/a'; '$boxlod' info '$work/fzk.glb' | grep -v -e ^batches -e ^draw_calls > '$work/b'; diff '$work/a' '$work/b'"
# An importer's copies of materials (same name and values), made here: every other mesh draws a copy.
"$boxlod" convert "$ifc" -o "$work/fzk.gltf" > /dev/null
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); n=len(d['materials']); d['materials']+=[dict(m) for m in d['materials']]
for mesh in d['meshes'][1::2]:
    for p in mesh['primitives']: p['material']+=n
json.dump(d,open(sys.argv[2],'w'))" "$work/fzk.gltf" "$work/copies.gltf"
check "convert merges the copies into 13 materials" bash -c "'$boxlod' convert '$work/copies.gltf' -o '$work/merged.glb' > /dev/null && '$boxlod' info '$work/merged.glb' | grep -qx 'batches_original = 13'"
check "convert --keep-materials keeps them" bash -c "'$boxlod' convert '$work/copies.gltf' -o '$work/kept.glb' --keep-materials > /dev/null && test \$('$boxlod' info '$work/kept.glb' | sed -n 's/^batches_original = //p') -gt 13"
check "convert twice gives identical bytes" bash -c "'$boxlod' convert '$ifc' -o '$work/fzk2.glb' && cmp -s '$work/fzk.glb' '$work/fzk2.glb'"

check "render succeeds" test "$(status_of "$boxlod" render "$ifc" -o "$work/a.png" --width 320 --height 240 --threads 1 --exr "$work/a.exr" --coverage "$work/mask.png")" = 0
check "render wrote PNG, EXR and mask" test -s "$work/a.png" -a -s "$work/a.exr" -a -s "$work/mask.png"
check "render is identical with 1 and 2 threads" bash -c "'$boxlod' render '$ifc' -o '$work/b.png' --width 320 --height 240 --threads 2 >/dev/null && cmp -s '$work/a.png' '$work/b.png'"
check "render --wireframe --axes --split-view succeeds" test "$(status_of "$boxlod" render "$ifc" -o "$work/c.png" --width 320 --height 240 --wireframe --axes --split-view "$work/fzk.glb" --mode untextured --camera -X+Y)" = 0

check "levels succeeds" test "$(status_of "$boxlod" levels "$ifc" --level-mode bottom-up)" = 0
check "levels prints obtained_levels" grep -q "^obtained_levels = [1-9]" "$work/out"
check "levels prints one level per node" test "$(grep -c '^level\.[0-9]* = [0-9]*$' "$work/out")" = 114
check "levels with a box mode succeeds" test "$(status_of "$boxlod" levels "$ifc" --level-mode box-diagonal --box minimal --interpolation rank --wanted-levels 4 --threads 2)" = 0
check "levels with a box mode obtains the wanted levels" grep -qx "obtained_levels = 4" "$work/out"
check "levels is the same with 1 thread" bash -c "'$boxlod' levels '$ifc' --level-mode box-diagonal --box minimal --interpolation rank --wanted-levels 4 --threads 1 2>/dev/null | cmp -s - '$work/out'"

check "--help exits 0" test "$(status_of "$boxlod" --help)" = 0
check "--help lists info" grep -q "info" "$work/out"
for command in info convert render generate levels; do
  check "$command --help exits 0" test "$(status_of "$boxlod" $command --help)" = 0
  check "$command --help shows usage" grep -q "usage: boxlod $command" "$work/out"
done

bad() {  # bad NAME ARGS...: exit status 2 and exactly one line on stderr, nothing on stdout
  local name=$1; shift
  local status; status=$(status_of "$boxlod" "$@")
  check "$name: exit status 2" test "$status" = 2
  check "$name: one line on stderr" test "$(wc -l < "$work/err")" = 1
  check "$name: nothing on stdout" test ! -s "$work/out"
  check "$name: the line names boxlod once" bash -c "grep -q '^boxlod' '$work/err' && ! grep -q 'boxlod: boxlod' '$work/err'"
}
bad "missing file" info "$work/nope.gltf"
printf '{"asset": {"version": "2.0"}, "nodes": [' > "$work/broken.gltf"
bad "malformed glTF" info "$work/broken.gltf"
head -c 1000 "$work/fzk.glb" > "$work/truncated.glb"
bad "truncated glb" info "$work/truncated.glb"
echo hello > "$work/model.unknown"
bad "unknown format" info "$work/model.unknown"
bad "unknown command" frobnicate
bad "unknown option" info "$ifc" --frobnicate
bad "missing argument" info
bad "levels with an unknown mode" levels "$ifc" --level-mode sideways
bad "levels with zero wanted levels" levels "$ifc" --level-mode box-volume --wanted-levels 0
bad "levels without a mode" levels "$ifc"
# One triangle, marked as an exported LoD.
printf '{"asset": {"version": "2.0", "extras": {"boxlod": {"lod": true}}}, "scenes": [{"nodes": [0]}], "scene": 0, "nodes": [{"name": "n", "mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]}], "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}' > "$work/lod.gltf"
bad "levels on an exported LoD" levels "$work/lod.gltf" --level-mode top-down
check "levels on an exported LoD says why" grep -q "cannot be simplified again" "$work/err"
bad "render with an unknown camera position" render "$ifc" -o "$work/x.png" --camera +Q
bad "render with an unknown mode" render "$ifc" -o "$work/x.png" --mode shiny
bad "render with a bad light" render "$ifc" -o "$work/x.png" --light 1,2
check "no image after a failed render" test ! -e "$work/x.png"
bad "convert to an unsupported format" convert "$ifc" -o "$work/out.obj"
check "no half-written file after a failed convert" test ! -e "$work/out.obj"
# generate: grammars, samples, cities; same seed, same bytes; syntax errors are one line.
check "generate --sample house succeeds" test "$(status_of "$boxlod" generate --sample house -o "$work/house.glb")" = 0
check "generate prints the statistics" grep -qx "nodes = 251" "$work/out"
check "generate twice gives identical bytes" bash -c "'$boxlod' generate --sample house -o '$work/house2.glb' >/dev/null && cmp -s '$work/house.glb' '$work/house2.glb'"
check "generate --city 4 succeeds" test "$(status_of "$boxlod" generate --city 4 --seed 2 -o "$work/city.glb")" = 0
printf 'Lot --> extrude(3) Box\nBox --> i(box)\n' > "$work/box.grammar"
check "generate from a grammar file with --lot" test "$(status_of "$boxlod" generate "$work/box.grammar" --lot 4x2 -o "$work/box.gltf")" = 0
check "the generated box is 4 x 3 x 2" bash -c "grep -qx 'mesh_width = 4' '$work/out' && grep -qx 'mesh_height = 3' '$work/out' && grep -qx 'mesh_depth = 2' '$work/out'"
"$boxlod" generate --sample house -o "$work/a.gltf" > /dev/null && "$boxlod" generate --sample office -o "$work/b.gltf" > /dev/null
check "a generated .gltf's files are named after it, so another model beside it cannot overwrite them" bash -c "for m in a b; do grep -o '\"uri\":\"[^\"]*\"' \"$work/\$m.gltf\" | cut -d'\"' -f4 | while read -r f; do case \$f in \$m.bin|\$m\_*.png) test -s \"$work/\$f\" || exit 1;; *) exit 1;; esac; done || exit 1; done"
printf 'Lot --> split(y) { 1 : A\n' > "$work/broken.grammar"
bad "generate with a grammar syntax error" generate "$work/broken.grammar" -o "$work/broken.glb"
check "the syntax error names file:line:column" grep -q "broken.grammar:2:1: expected" "$work/err"
check "no output after a failed generate" test ! -e "$work/broken.glb"
bad "generate with an unknown sample" generate --sample castle -o "$work/castle.glb"
# compare: image metrics between two renders; sizes must match.
"$boxlod" render "$ifc" -o "$work/other.png" --width 320 --height 240 --mode untextured --camera -X+Y >/dev/null 2>&1
check "compare succeeds" test "$(status_of "$boxlod" compare "$work/a.png" "$work/other.png")" = 0
check "compare prints every metric" bash -c "for k in rmse psnr ssim flip iou; do grep -q \"^\$k = [0-9.e-]*\$\" '$work/out' || exit 1; done"
check "compare of an image with itself: rmse 0, psnr inf, ssim 1, flip 0" bash -c "'$boxlod' compare '$work/a.png' '$work/b.png' > '$work/same' && grep -qx 'rmse = 0' '$work/same' && grep -qx 'psnr = inf' '$work/same' && grep -qx 'ssim = 1' '$work/same' && grep -qx 'flip = 0' '$work/same'"
# Declared sizes first (73): two 16384x8192 PNGs of under 1 MB, whose decoding alone took tens of seconds before the refusal.
python3 -c "
import struct, sys, zlib
w, h = 16384, 8192
data = zlib.compress(b''.join(b'\\0' * (1 + 3 * w) for _ in range(h)), 9)
chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
open(sys.argv[1], 'wb').write(b'\\x89PNG\\r\\n\\x1a\\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) + chunk(b'IDAT', data) + chunk(b'IEND', b''))
" "$work/huge.png"
check "compare refuses images the memory budget cannot measure before decoding them" bash -c "timeout 10 '$boxlod' compare '$work/huge.png' '$work/huge.png' --max-memory 4 > /dev/null 2> '$work/err'; test \$? = 2 && grep -q 'measuring two 16384x8192 images would need' '$work/err'"
check "compare --json is a JSON object" bash -c "'$boxlod' compare '$work/a.png' '$work/other.png' --metric psnr,ssim --json | python3 -c \"import json,sys; d=json.load(sys.stdin); sys.exit(0 if set(d) == {'psnr', 'ssim'} and 0 < d['ssim'] < 1 else 1)\""
check "compare --heatmap writes a PNG" test "$(status_of "$boxlod" compare "$work/a.png" "$work/other.png" --metric rmse --heatmap "$work/heat.png" --heatmap-metric rmse)" = 0 -a -s "$work/heat.png"
check "compare with masks gives iou" test "$(status_of "$boxlod" compare "$work/a.png" "$work/b.png" --metric iou --mask-a "$work/mask.png" --mask-b "$work/mask.png")" = 0
check "iou of a mask with itself is 1" grep -qx "iou = 1" "$work/out"
"$boxlod" render "$ifc" -o "$work/small.png" --width 160 --height 120 >/dev/null 2>&1
bad "compare images of different sizes" compare "$work/a.png" "$work/small.png"
bad "compare with a missing image" compare "$work/a.png" "$work/nope.png"
bad "compare with an unknown metric" compare "$work/a.png" "$work/other.png" --metric sharpness
check "no heat map after a failed compare" bash -c "! '$boxlod' compare '$work/a.png' '$work/small.png' --heatmap '$work/heat2.png' 2>/dev/null; test ! -e '$work/heat2.png'"
# simplify: the quadric edge-collapse baseline.
check "simplify succeeds" test "$(status_of "$boxlod" simplify "$ifc" --faces 500 -o "$work/simple.glb" --threads 2)" = 0
check "simplify prints its counts" bash -c "for k in faces_original faces triangles vertices seconds; do grep -q \"^\$k = [0-9.e-]*\$\" '$work/out' || exit 1; done"
check "simplify keeps at most the faces asked for" bash -c "f=\$(sed -n 's/^faces = //p' '$work/out'); test \"\$f\" -le 500 -a \"\$f\" -ge 400"
check "the simplified model loads" test "$(status_of "$boxlod" info "$work/simple.glb")" = 0
bad "simplify with --faces 0" simplify "$ifc" --faces 0 -o "$work/none.glb"
bad "simplify to fewer faces than keep a triangle" simplify "$ifc" --faces 1 -o "$work/none.glb"
check "the refusal blames the request, not the model" grep -q "^boxlod: --faces 1: simplifying .* to 1 face(s) keeps no triangle; ask for more\$" "$work/err"
check "no output after a failed simplify" test ! -e "$work/none.glb"
# sweep: one mode, two levels (the first and the last), one view of the FZK-Haus; a bad config is one line, exit 2.
printf 'models = %s\nlevel_modes = top-down\nlevels = 0, 5\nviews = -Z\nwidth = 64\nheight = 48\nmetrics = psnr, ssim\n' "$ifc" > "$work/sweep.txt"
check "sweep succeeds" test "$(status_of "$boxlod" sweep "$work/sweep.txt" -o "$work/sweep" --threads 2)" = 0
check "sweep prints its counts" bash -c "grep -qx 'rows = 2' '$work/out' && grep -qx 'rows_computed = 2' '$work/out' && grep -qx 'lods_built = 2' '$work/out'"
check "sweep writes a header and two rows" test "$(wc -l < "$work/sweep/results.csv")" = 3
check "sweep level 0 is the original" grep -q "^$ifc,top-down,expanded,linear,0,-Z,1,normal,5,35792,.*,inf,1\$" "$work/sweep/results.csv"
check "sweep level 5 is one box" grep -q "^$ifc,top-down,expanded,linear,5,-Z,1,normal,5,6," "$work/sweep/results.csv"
check "sweep reports progress on stderr" grep -q "ETA" "$work/err"
check "sweep again skips every row" bash -c "'$boxlod' sweep '$work/sweep.txt' -o '$work/sweep' 2>/dev/null | grep -qx 'rows_skipped = 2'"
# Another build (here the same executable with one byte more) may draw other pixels: it does not take these rows.
cp "$boxlod" "$work/boxlod_rebuilt" && printf '\0' >> "$work/boxlod_rebuilt"
check "another build of boxlod refuses the sweep's folder" test "$(status_of "$work/boxlod_rebuilt" sweep "$work/sweep.txt" -o "$work/sweep")" = 2
check "in one line naming settings.txt and the build" bash -c "test \$(wc -l < '$work/err') = 1 && grep -q 'settings.txt: .*boxlod_build = ' '$work/err'"
check "and leaves the rows as they were" test "$(wc -l < "$work/sweep/results.csv")" = 3
printf 'models = %s\nlevel_modes = sideways\n' "$ifc" > "$work/bad_sweep.txt"
bad "sweep with a bad config" sweep "$work/bad_sweep.txt" -o "$work/bad_sweep"
check "the sweep error names file:line:key" grep -q "bad_sweep.txt: line 2: level_modes: unknown value 'sideways'" "$work/err"
# city: a fly-through with run-time LoD selection; bad strategies and keyframe files are one line, exit 2, no OUTDIR.
check "city succeeds" test "$(status_of "$boxlod" city --buildings 2 --strategy distance:40,80,160 --path orbit --frames 4 --width 64 --height 48 --error-every 2 --threads 2 -o "$work/city")" = 0
check "city prints its summary" bash -c "grep -qx 'frames = 4' '$work/out' && grep -qx 'buildings = 2' '$work/out' && grep -qx 'sampled_frames = 2' '$work/out' && grep -q '^faces_mean = [0-9]' '$work/out' && grep -q '^ssim_mean = ' '$work/out' && grep -q '^level_0_total = ' '$work/out'"
check "city writes frames, contact sheet and timings" test -s "$work/city/frames/frame_0000.png" -a -s "$work/city/frames/frame_0003.png" -a -s "$work/city/contact_sheet.png" -a -s "$work/city/timings.csv"
check "city frames.csv has the columns" bash -c "head -1 '$work/city/frames.csv' | grep -qx 'frame,strategy,detail,faces,triangles,draw_calls,mesh_bytes,texture_bytes,texture_bytes_gpu,bytes,buildings,level_0,\(level_[0-9]*,\)*levels_changed,psnr,ssim,flip'"
check "city frames.csv has one row per frame, errors on sampled frames" bash -c "test \$(wc -l < '$work/city/frames.csv') = 5 && sed -n 2p '$work/city/frames.csv' | grep -q '^0,\"distance:40,80,160\",1,[0-9]*,[0-9]*,[1-9][0-9]*,[1-9][0-9]*,[0-9]*,[0-9]*,[1-9][0-9]*,2,.*,[0-9.e-]*\$' && sed -n 3p '$work/city/frames.csv' | grep -q ',,,\$'"
check "city timings.csv has the columns" bash -c "head -1 '$work/city/timings.csv' | grep -qx 'frame,detail,select_seconds,unpack_seconds,render_seconds,levels_unpacked,resident_bytes'"
check "city is identical with 1 thread" bash -c "'$boxlod' city --buildings 2 --strategy distance:40,80,160 --path orbit --frames 4 --width 64 --height 48 --error-every 2 --threads 1 -o '$work/city1' >/dev/null 2>&1 && cmp -s '$work/city/frames.csv' '$work/city1/frames.csv' && cmp -s '$work/city/frames/frame_0002.png' '$work/city1/frames/frame_0002.png'"
printf '# a dolly\n0  100 20 100  0 0 0\n1  40 10 40  0 0 0\n' > "$work/keys.txt"
check "a second city run replaces the first's frames whole" bash -c "'$boxlod' city --buildings 1 --strategy distance:40,80,160 --frames 2 --width 32 --height 24 --error-every 0 -o '$work/city1' >/dev/null 2>&1 && test \$(ls '$work/city1/frames' | wc -l) = 2 && test \$(wc -l < '$work/city1/frames.csv') = 3"
check "city along a keyframe file succeeds" test "$(status_of "$boxlod" city --buildings 1 --strategy texel --path "$work/keys.txt" --frames 3 --width 64 --height 48 --budget 500 --json -o "$work/city_keys")" = 0
check "city refuses a keyframe file in OUTDIR named like its output, and keeps it" bash -c "mkdir -p '$work/city_in' && cp '$work/keys.txt' '$work/city_in/frames.csv' && { '$boxlod' city --buildings 1 --path '$work/city_in/frames.csv' --frames 2 --width 16 --height 16 -o '$work/city_in' 2>'$work/city_in.err' >/dev/null; test \$? = 2; } && grep -qx '.*frames.csv: -o .*city_in would write over it' '$work/city_in.err' && cmp '$work/keys.txt' '$work/city_in/frames.csv'"
check "city --json is a JSON object" python3 -c "import json,sys; d=json.load(open('$work/out')); sys.exit(0 if d['frames']==3 and d['faces_max']<=500 else 1)"
# A city from a CityJSON file: its Buildings are the fly-through's buildings.
/usr/bin/python3 "$(dirname "$0")/make_district.py" "$work/district.city.json" 6
check "city from a CityJSON district succeeds" test "$(status_of "$boxlod" city "$work/district.city.json" --frames 3 --width 64 --height 48 --error-every 0 -o "$work/city_district")" = 0
check "city from a CityJSON district flies over its 6 buildings" bash -c "grep -qx 'buildings = 6' '$work/out' && test \$(wc -l < '$work/city_district/frames.csv') = 4"
# The same district with an unused vertex 300 m out: read relative to another local origin, and drawn
# in the first one's frame by render --split-view.
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); d['vertices'].append([600000, 0, 0]); json.dump(d, open(sys.argv[2], 'w'))" "$work/district.city.json" "$work/district_moved.city.json"
"$boxlod" render "$work/district.city.json" --split-view "$work/district.city.json" -o "$work/split_same.png" --width 64 --height 48 > /dev/null
"$boxlod" render "$work/district.city.json" --split-view "$work/district_moved.city.json" -o "$work/split_moved.png" --width 64 --height 48 > /dev/null
check "render --split-view draws a model kept relative to another origin in place" cmp -s "$work/split_same.png" "$work/split_moved.png"
bad "city with a bad strategy" city --buildings 1 --strategy distance:80,40 -o "$work/city_bad"
check "the strategy error names the option" grep -q "^boxlod: --strategy: distance bands: thresholds must increase strictly\$" "$work/err"
bad "city with an unknown strategy" city --buildings 1 --strategy sideways -o "$work/city_bad"
printf '0 0 2 50 0 2 0\n1 0 2 oops 0 2 0\n' > "$work/bad_keys.txt"
bad "city with a bad keyframe file" city --buildings 1 --path "$work/bad_keys.txt" -o "$work/city_bad"
check "the keyframe error names file:line" grep -q "bad_keys.txt: line 2: expected a number, got 'oops'" "$work/err"
bad "city with a missing keyframe file" city --buildings 1 --path "$work/nope.txt" -o "$work/city_bad"
bad "city with zero frames" city --buildings 1 --frames 0 -o "$work/city_bad"
bad "city with a bad detail" city --buildings 1 --detail 1,-2 -o "$work/city_bad"
# A chain sized per level: level c for the sizing distance x 2^(c-1); its pages shrink with c
# (the manual's cut, every sub-tree boxed, so that every level has pages).
"$boxlod" generate --sample house -o "$work/house.glb" > /dev/null
check "build --level-distances auto succeeds" test "$(status_of "$boxlod" build "$work/house.glb" -o "$work/chain" --all-levels --manual --level-distances auto --resolution 256 --min-texture-size 16 --preview-width 32 --preview-height 24)" = 0
check "each level is sized for twice the previous level's distance" bash -c "awk -F' = ' '\$1 == \"sizing_distance\" { d[++n] = \$2 } END { for (c = 3; c <= n; ++c) if ((d[c] - 2 * d[c - 1]) ^ 2 > (1e-6 * d[c]) ^ 2) exit 1; exit n < 5 }' '$work/out'"
check "coarser levels of the chain pay fewer texture bytes" bash -c "awk -F' = ' '\$1 == \"page_texels\" { t[++n] = \$2 } END { exit !(t[2] > t[4] && t[4] > t[6]) }' '$work/out'"
check "the chain's cost follows its levels" bash -c "grep -qx 'name = house_lod_chain' '$work/out' && grep -q '^texture_bytes_gpu_chain = [1-9]' '$work/out' && grep -q '^chain_texture_ratio = ' '$work/out'"
check "a level's parameter file records the chain's distances" bash -c "grep -qx 'level_distances = auto' '$work/chain/house_lod_L9.params.txt' && grep -qx \"distance = \$(awk -F' = ' '\$1 == \"sizing_distance\" { d[++n] = \$2 } END { print d[1] }' '$work/out')\" '$work/chain/house_lod_L9.params.txt'"
# Without the rule the house's level 1 boxes single quads and costs more than the original; with it no level does.
over_original="awk -F' = ' '\$1 == \"bytes_lod\" { b = \$2 } \$1 == \"bytes_original\" && b > \$2 { over = 1 } END { exit !over }'"
check "a box-everything chain has a level dearer than the original" bash -c "$over_original '$work/out'"
check "build --all-levels succeeds with the defaults" test "$(status_of "$boxlod" build "$work/house.glb" -o "$work/cheap" --all-levels --resolution 256 --preview-width 32 --preview-height 24)" = 0
check "by default boxes pay their way: no level costs more than the original" bash -c "! $over_original '$work/out' && grep -qx 'keep_cheaper_subtrees = true' '$work/cheap/house_lod_L0.params.txt'"
# A folder in the way of one level (73): its cause named, and no level left (L0-L4 stayed behind).
mkdir -p "$work/in_the_way/house_lod_L5.glb/x"
check "a level that cannot be written names why and leaves no level" bash -c "'$boxlod' build '$work/house.glb' --all-levels --glb -o '$work/in_the_way' --resolution 256 --preview-width 32 --preview-height 24 > /dev/null 2> '$work/err'; test \$? = 2 && grep -qx 'boxlod: $work/in_the_way/house_lod_L5.glb: cannot write: Is a directory' '$work/err' && test \"\$(ls -A '$work/in_the_way')\" = house_lod_L5.glb"
check "by default levels are sized per level" bash -c "awk -F' = ' '\$1 == \"sizing_distance\" { d[++n] = \$2 } END { exit !(n > 4 && d[4] > 1.99 * d[3]) }' '$work/out'"
check "--manual sizes every level for one distance and boxes every sub-tree" bash -c "'$boxlod' build '$work/house.glb' -o '$work/manual' --all-levels --manual --resolution 256 --preview-width 32 --preview-height 24 > '$work/manual.txt' && test \$(awk -F' = ' '\$1 == \"sizing_distance\"' '$work/manual.txt' | sort -u | wc -l) = 1 && grep -qx 'keep_cheaper_subtrees = false' '$work/manual/house_lod_L3.params.txt' && grep -qx 'min_texture_size = 256' '$work/manual/house_lod_L3.params.txt'"
# Levels by byte budget (docs/design.md: Levels by byte budget): each level's bytes within its budget, stated beside them.
check "build --budgets keeps every level within its budget" bash -c "'$boxlod' build '$work/house.glb' -o '$work/budgets' --all-levels --level-mode hybrid --budgets 0.5,0.25 --resolution 256 --min-texture-size 16 --preview-width 32 --preview-height 24 > '$work/budgets.txt' && awk -F' = ' '\$1 == \"bytes_lod\" { b = \$2 } \$1 == \"budget_bytes\" { n++; if (b > \$2) exit 1 } END { exit n != 2 }' '$work/budgets.txt'"
bad "budgets that do not descend" build "$work/house.glb" -o "$work/chain_bad" --all-levels --level-mode hybrid --budgets 0.1,0.5
check "the budgets error names the option" grep -q "^boxlod: --budgets: '0.5' comes after '0.1': budgets must descend" "$work/err"
bad "a budget below the coarsest cut" build "$work/house.glb" -o "$work/chain_bad" --all-levels --level-mode hybrid --budgets 0.5,0.001 --resolution 256 --min-texture-size 16
check "the refusal names the level and the coarsest cut's bytes" grep -q "level 2's budget of [0-9]* bytes is below the coarsest cut's [0-9]* bytes\$" "$work/err"
# Flat faces (docs/design.md: Atlas): some faces drawn from swatches, the same bytes on one thread as on two.
flat_chain="build '$work/house.glb' --all-levels --level-distances auto --resolution 256 --min-texture-size 16 --preview-width 32 --preview-height 24 --flat-faces 8"
check "a chain with flat faces draws some faces flat" bash -c "'$boxlod' $flat_chain -o '$work/flat1' --threads 1 > '$work/flat1.txt' && grep -q '^flat_faces = [1-9]' '$work/flat1.txt'"
check "a chain with flat faces is identical on two threads" bash -c "'$boxlod' $flat_chain -o '$work/flat2' --threads 2 >/dev/null && diff -r '$work/flat1' '$work/flat2'"
bad "level distances that do not ascend" build "$work/house.glb" -o "$work/chain_bad" --all-levels --level-distances 20,10,30,40,50,60,70,80,90
bad "a negative level distance" build "$work/house.glb" -o "$work/chain_bad" --all-levels --level-distances -5,10,20,30,40,50,60,70,80
bad "a NaN level distance" build "$work/house.glb" -o "$work/chain_bad" --all-levels --level-distances nan,10,20,30,40,50,60,70,80
bad "too few level distances" build "$work/house.glb" -o "$work/chain_bad" --all-levels --level-distances 10,20
bad "equal level distances" build "$work/house.glb" -o "$work/chain_bad" --all-levels --level-distances 10,10,30,40,50,60,70,80,90
check "equal distances are refused by name" grep -q "^boxlod: --level-distances: 10 comes after 10: the distances must ascend" "$work/err"
check "no output folder for a refused chain" test ! -e "$work/chain_bad"
# The same chain in one .glb (MSFT_lod): level 0 in the scene, the others listed by its root,
# switch hints falling with distance, each texture stored once.
check "build --chain --switch-error 0 succeeds" test "$(status_of "$boxlod" build "$work/house.glb" --chain --switch-error 0 -o "$work/house_chain_texels.glb" --resolution 256 --min-texture-size 16)" = 0
check "without a threshold a level switches in at its sizing distance" bash -c "awk -F' = ' '\$1 == \"sizing_distance\" { d = \$2 } \$1 == \"switch_distance\" { s[++n] = \$2; if ((\$2 - d) ^ 2 > (1e-6 * d) ^ 2) exit 1 } \$1 == \"screen_coverage\" { c[n] = \$2 } END { for (k = 2; k <= n; ++k) if (!(s[k] > s[k - 1] && c[k] < c[k - 1])) exit 1; exit n < 3 }' '$work/out'"
check "build --chain succeeds" test "$(status_of "$boxlod" build "$work/house.glb" --chain -o "$work/house_chain.glb" --resolution 256 --min-texture-size 16 --switch-error 0.1)" = 0
check "a chain level switches in where its measured error stays within the threshold, farther and cheaper than the one before" /usr/bin/python3 - "$work/out" <<'PY'
import sys
blocks, measured = [], None
for line in open(sys.argv[1]):
    key, _, value = line.strip().partition(' = ')
    if key == 'measured_distances': measured = [float(v) for v in value.split(',')]
    elif key == 'name' and value.startswith('house_chain_L'): blocks.append({})
    elif blocks and key: blocks[-1][key] = value
assert measured and len(blocks) >= 2, (measured, len(blocks))
for finer, level in zip(blocks, blocks[1:]):
    assert float(level['switch_distance']) > float(finer.get('switch_distance', 0)), (finer, level)
    assert int(level['bytes_lod']) < int(finer['bytes_lod']), (finer['bytes_lod'], level['bytes_lod'])
    errors = [float(v) for v in level['errors_by_distance'].split(',')]
    assert all(e <= 0.1 for d, e in zip(measured, errors) if d >= float(level['switch_distance'])), errors
PY
check "the chain .glb lists every level through MSFT_lod" /usr/bin/python3 - "$work/house_chain.glb" "$work/out" <<'PY'
import json, struct, sys
data = open(sys.argv[1], 'rb').read()
length = struct.unpack_from('<I', data, 12)[0]
gltf = json.loads(data[20:20 + length])
levels = sum(1 for line in open(sys.argv[2]) if line.startswith('name = house_chain_L'))
root = gltf['nodes'][gltf['scenes'][0]['nodes'][0]]
ids, coverage = root['extensions']['MSFT_lod']['ids'], root['extras']['MSFT_screencoverage']
assert gltf['scenes'][0]['nodes'] == [0] and len(ids) == levels - 1 and len(coverage) == levels, (ids, coverage)
assert coverage == sorted(coverage, reverse=True) and coverage[-1] == 0, coverage
assert 'MSFT_lod' in gltf['extensionsUsed']
# Levels 1.. keep some of the original's parts: their textures are the level 0 images, not copies.
names = [image['name'] for image in gltf['images']]
assert names.count('brick_color.png') == 1 and len(names) == len(set(names)), names
PY
bad "a chain written to a .txt" build "$work/house.glb" --chain -o "$work/house_chain.txt"
# Each level once: Testwuson.X's boxes cost more than its geometry, so its
# finer levels keep the original, which the chain has once (it had it 10
# times) and the tileset once (it had two equal tiles).
testwuson=/usr/share/assimp/models/X/Testwuson.X
check "build --chain writes each level once" bash -c "'$boxlod' build '$testwuson' --chain -o '$work/once.glb' 2>'$work/once.err' >/dev/null && grep -q '^boxlod build: level 10 draws what level 0 does' '$work/once.err' && /usr/bin/python3 '$here/chain_levels_once.py' '$work/once.glb'"
check "the house chain draws each level once" /usr/bin/python3 "$here/chain_levels_once.py" "$work/house_chain.glb"
check "tiles writes each level once" bash -c "'$boxlod' tiles '$testwuson' -o '$work/tiles_once' | grep -qx 'tiles = 1' && test -s '$work/tiles_once/object_0_L0.glb' -a ! -e '$work/tiles_once/object_0_L1.glb'"
# A city as 3D Tiles: a tileset naming one glb per level of every object, the same bytes for any thread count.
"$boxlod" generate --city 2 -o "$work/city2.glb" > /dev/null
check "tiles succeeds" test "$(status_of "$boxlod" tiles "$work/city2.glb" -o "$work/tiles1" --resolution 128 --threads 1)" = 0
check "tiles reports its objects" grep -qx "objects = 3" "$work/out"
check "every tile's content is there" /usr/bin/python3 - "$work/tiles1" <<'PY'
import json, os, sys
tileset = json.load(open(os.path.join(sys.argv[1], 'tileset.json')))
def contents(tile):
    yield from ([tile['content']['uri']] if 'content' in tile else [])
    for child in tile.get('children', []):
        yield from contents(child)
uris = list(contents(tileset['root']))
assert len(uris) == len(set(uris)) > 3 and all(os.path.getsize(os.path.join(sys.argv[1], u)) > 0 for u in uris), uris
assert sorted(uris) == sorted(f for f in os.listdir(sys.argv[1]) if f.endswith('.glb'))
PY
check "tiles refuses a model in OUTDIR named like a tile, and keeps it" bash -c "mkdir -p '$work/tiles_in' && cp '$work/city2.glb' '$work/tiles_in/object_0_L0.glb' && { '$boxlod' tiles '$work/tiles_in/object_0_L0.glb' -o '$work/tiles_in' --resolution 64 2>'$work/tiles_in.err' >/dev/null; test \$? = 2; } && grep -qx '.*object_0_L0.glb: -o .*tiles_in would write over it' '$work/tiles_in.err' && cmp '$work/city2.glb' '$work/tiles_in/object_0_L0.glb'"
check "tiles gives the same bytes on two threads" bash -c "'$boxlod' tiles '$work/city2.glb' -o '$work/tiles2' --resolution 128 --threads 2 >/dev/null && diff -r '$work/tiles1' '$work/tiles2'"
# A model from a file keeps its geometry where it is: all on the root, one
# object; on the root and below it, the root's own geometry one object more.
/usr/bin/python3 - "$work" <<'PY'
import json, shutil, sys
work = sys.argv[1]
tree = json.load(open('/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf'))
shutil.copy('/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured0.bin', work)
shutil.copy('/usr/share/assimp/models/glTF2/BoxTextured-glTF/CesiumLogoFlat.png', work)
root = tree['scenes'][tree.get('scene', 0)]['nodes'][0]
tree['nodes'][root]['mesh'] = 0  # the box on the root too, beside its child's (the matrix turns it)
json.dump(tree, open(f'{work}/root_and_child.gltf', 'w'))
PY
# Placed by default at KIT; by a reference system the user names, where PROJ puts its origin
# (RD New's (0, 0), south-west of the Netherlands: 47.97 N, 3.31 E).
check "tiles places a model without a system at KIT" bash -c "'$boxlod' tiles '$work/city2.glb' -o '$work/tiles_kit' --resolution 64 | grep -qx 'placed_by = default'"
check "tiles places a model by the reference system given" bash -c "'$boxlod' tiles '$work/city2.glb' -o '$work/tiles_rd' --resolution 64 --reference-system EPSG:28992 > '$work/tiles_rd.txt' && grep -q '^placed_by = EPSG:28992 (PROJ: ' '$work/tiles_rd.txt' && grep -q '^latitude = 47\.97' '$work/tiles_rd.txt' && grep -q '^longitude = 3\.3' '$work/tiles_rd.txt'"
check "tiles of a model all on its root: one object" bash -c "'$boxlod' tiles /usr/share/assimp/models/OBJ/box.obj -o '$work/tiles_box' --resolution 64 | grep -qx 'objects = 1' && test -s '$work/tiles_box/object_0_L0.glb'"
check "tiles of geometry on the root and below: the root's own one object more" bash -c "'$boxlod' tiles '$work/root_and_child.gltf' -o '$work/tiles_root' --resolution 64 | grep -qx 'objects = 2' && test -s '$work/tiles_root/object_1_L0.glb'"
check "city with several details runs each over one build" test "$(status_of "$boxlod" city --buildings 2 --strategy texel --frames 2 --width 64 --height 48 --detail 0.5,2 -o "$work/city_details")" = 0
check "city with several details reports and images each" bash -c "grep -q '^detail_0.5.faces_mean = ' '$work/out' && grep -q '^detail_2.flip_mean = ' '$work/out' && test -s '$work/city_details/detail_2/contact_sheet.png' -a -s '$work/city_details/detail_0.5/frames/frame_0001.png' && test \$(wc -l < '$work/city_details/frames.csv') = 5"
check "no OUTDIR after a failed city" test ! -e "$work/city_bad"
check "no temporary files left behind" bash -c "! ls -a '$work' | grep -q 'boxlod-tmp\|boxlod-commit'"

# Kill safety: a build interrupted at any moment leaves whole levels and no
# temporaries; one killed outright (SIGKILL) leaves whole levels and no
# temporaries (files wait unnamed), or one that goes at the next run, or,
# killed while placing a level, its journal, and the next run completes it.
cat > "$work/whole_levels.py" <<'PY'
import json, os, re, sys
folder = sys.argv[1]
files = os.listdir(folder) if os.path.isdir(folder) else []  # interrupted before its first level
levels = {m.group(1) for f in files if '.boxlod-tmp' not in f for m in [re.match(r'(manual_lod_L\d+)[._]', f)] if m}
for level in levels:
    gltf = os.path.join(folder, level + '.gltf')
    if not os.path.exists(gltf):
        sys.exit(level + ': files without their .gltf')
    document = json.load(open(gltf))
    for item in document.get('images', []) + document.get('buffers', []):
        if not os.path.exists(os.path.join(folder, item['uri'])):
            sys.exit(level + ': ' + item['uri'] + ' missing')
    for suffix in ('.params.txt', '.preview.png', '.stats.txt'):
        if not os.path.exists(os.path.join(folder, level + suffix)):
            sys.exit(level + ': ' + suffix + ' missing')
PY
"$boxlod" generate --sample manual -o "$work/manual.glb" > /dev/null
check "a chain keeping 32,000 nodes warns that engines import them slowly" bash -c "'$boxlod' build '$work/manual.glb' --chain --keep-hierarchy --switch-error 0 -o '$work/manual_nodes.glb' 2>&1 >/dev/null | grep -q '^boxlod build: warning: the chain holds [0-9]* nodes (--keep-hierarchy)' && ! '$boxlod' build '$work/house.glb' --chain --keep-hierarchy --switch-error 0 -o '$work/house_nodes.glb' 2>&1 >/dev/null | grep -q warning"
# --manual at 2160 pixels: some 20 s, its first levels written in the first 2 s.
"$boxlod" build "$work/manual.glb" --all-levels --manual --resolution 2160 -o "$work/interrupted" --preview-width 64 --preview-height 48 > /dev/null 2> "$work/err" &
build_pid=$!
sleep 3
kill -TERM $build_pid
wait $build_pid
status=$?
check "an interrupted build exits 143 (or had finished)" bash -c "test $status = 143 -o $status = 0"
check "an interrupted build says so" bash -c "test $status = 0 || grep -q 'interrupted (signal 15); partial outputs removed' '$work/err'"
check "an interrupted build leaves no temporary" bash -c "! ls -a '$work/interrupted' | grep -q 'boxlod-tmp\|boxlod-commit'"
check "every level left is whole: its .gltf and every file it names" python3 "$work/whole_levels.py" "$work/interrupted"
# Killed outright at several moments (so at least once while a level is written).
for moment in 1 2 3 4; do
  "$boxlod" build "$work/manual.glb" --all-levels --manual --resolution 2160 -o "$work/killed" --preview-width 64 --preview-height 48 > /dev/null 2>&1 &
  build_pid=$!
  sleep $moment
  kill -KILL $build_pid
  wait $build_pid
  check "a build killed outright after ${moment} s leaves only whole levels" python3 "$work/whole_levels.py" "$work/killed"
  # Files wait unnamed (O_TMPFILE): at most the one being renamed into place has a name, unless a level was being placed.
  check "and no temporary (at most the one file being placed, or a level's with its journal)" \
    bash -c "test \$(ls '$work/killed' 2>/dev/null | grep -c 'boxlod-tmp') -le 1 || ls -a '$work/killed' | grep -q '^\.boxlod-commit'"
done
check "the next run succeeds in the same folder" test "$(status_of "$boxlod" build "$work/manual.glb" -o "$work/killed" --level 2 --resolution 64 --preview-width 32 --preview-height 24)" = 0
check "and removes the temporaries of the runs killed outright" bash -c "! ls -a '$work/killed' | grep -q 'boxlod-tmp\|boxlod-commit'"
check "and every level there is whole" python3 "$work/whole_levels.py" "$work/killed"

# A tileset replaces the one in its folder in one step (OutputFolder): a
# run killed outright at any moment leaves the old tileset or the new one,
# each whole, never tiles of both; the staging folder a kill leaves beside
# it goes at the next run.
cat > "$work/whole_tileset.py" <<'PY'
import json, os, re, sys
folder, wanted = sys.argv[1], {int(n) for n in sys.argv[2:]}
def uris(tile):
    yield from ([tile['content']['uri']] if 'content' in tile else [])
    for child in tile.get('children', []):
        yield from uris(child)
named = set(uris(json.load(open(os.path.join(folder, 'tileset.json')))['root']))
files = set(os.listdir(folder)) - {'tileset.json'}
if files != named:
    sys.exit('tiles and tileset disagree: %s' % sorted(files ^ named))
if len(named) not in wanted:
    sys.exit('%d tiles, expected one of %s' % (len(named), sorted(wanted)))
PY
"$boxlod" generate --city 4 -o "$work/city4.glb" > /dev/null
"$boxlod" tiles "$work/city4.glb" -o "$work/tileset" --level-mode box-area --wanted-levels 3 > /dev/null
old_tiles=$(ls "$work/tileset" | grep -c glb)
"$boxlod" tiles "$work/city4.glb" -o "$work/tileset_new" > /dev/null
new_tiles=$(ls "$work/tileset_new" | grep -c glb)
check "the two tilesets differ in their tiles" test "$old_tiles" != "$new_tiles"
for moment in 0.05 0.15 0.25 0.35 0.45 0.55 0.7; do
  "$boxlod" tiles "$work/city4.glb" -o "$work/tileset" > /dev/null 2>&1 &
  tiles_pid=$!
  sleep $moment
  kill -KILL $tiles_pid 2> /dev/null
  wait $tiles_pid
  check "tiles killed outright after ${moment} s leaves one whole tileset" python3 "$work/whole_tileset.py" "$work/tileset" "$old_tiles" "$new_tiles"
done
"$boxlod" tiles "$work/city4.glb" -o "$work/tileset" --level-mode box-area --wanted-levels 3 > /dev/null
check "the next run puts its tileset in place" python3 "$work/whole_tileset.py" "$work/tileset" "$old_tiles"
check "and removes the staging folders of the runs killed outright" bash -c "! ls '$work' | grep -q 'tileset\.boxlod-staging'"
# A fly-through of many frames stops within 2 s of SIGTERM, whatever it has
# staged (it removed 27,600 staged frames first, 52 s); what is left of its
# staging folder goes with the next run, which does not wait for it.
"$boxlod" city --buildings 1 --frames 100000 --width 16 --height 16 --error-every 0 -o "$work/flight" > /dev/null 2> "$work/flight_err" &
city_pid=$!
sleep 4
stopped_at=$(date +%s%N)
kill -TERM $city_pid
wait $city_pid
status=$?
stop_ms=$(( ($(date +%s%N) - stopped_at) / 1000000 ))
check "a city stopped by SIGTERM exits 143 within 2 s (${stop_ms} ms)" bash -c "test $status = 143 -a $stop_ms -lt 2000"
check "and says so" grep -q 'interrupted (signal 15); partial outputs removed' "$work/flight_err"
started_at=$(date +%s%N)
check "the next city in that folder succeeds" test "$(status_of "$boxlod" city --buildings 1 --frames 2 --width 16 --height 16 -o "$work/flight")" = 0
next_ms=$(( ($(date +%s%N) - started_at) / 1000000 ))
check "without waiting for the staged frames to go (${next_ms} ms)" test $next_ms -lt 10000
check "whose staging folder is out of the way at once" bash -c "! ls '$work' | grep -q '^flight\.boxlod-staging'"
check "and gone soon after" bash -c "for i in \$(seq 60); do ls '$work' | grep -q '^flight\.' || exit 0; sleep 0.5; done; exit 1"
mkdir -p "$work/shared" && echo notes > "$work/shared/notes.txt"
"$boxlod" tiles "$work/city4.glb" -o "$work/shared" --level-mode box-area --wanted-levels 3 > /dev/null
check "a folder holding other files keeps them beside the tileset" test -s "$work/shared/notes.txt" -a -s "$work/shared/tileset.json"

# No output replaces an input: each refusal is exit 2 and leaves the input as it was.
mkdir -p "$work/own" && "$boxlod" generate --sample house -o "$work/own/house.glb" > /dev/null
cp "$work/own/house.glb" "$work/house_kept.glb"
cp "$work/own/house.glb" "$work/own/tree_L1.glb"
printf 'key m\n' > "$work/own/replay.txt"
"$boxlod" render "$work/own/house.glb" -o "$work/own/a.png" --width 16 --height 16 > /dev/null
"$boxlod" render "$work/own/house.glb" -o "$work/own/b.png" --width 16 --height 16 --camera -X+Y > /dev/null
cp "$work/own/a.png" "$work/own/m.png"
for args in "build HOUSE --save-params HOUSE" "build HOUSE --chain -o HOUSE" "build HOUSE -o OWN --name house --glb" \
            "build OWN/tree_L1.glb -o OWN --name tree --glb --all-levels --level-mode box-area --wanted-levels 1" \
            "simplify HOUSE --faces 10 -o HOUSE" "convert HOUSE -o HOUSE" "convert HOUSE#House -o HOUSE" \
            "view HOUSE --replay OWN/replay.txt --params-out HOUSE --width 16 --height 16" \
            "compare OWN/a.png OWN/b.png --metric iou --mask-a OWN/m.png --mask-b OWN/b.png --heatmap OWN/m.png"; do
  words=${args//HOUSE/$work/own/house.glb}
  read -r -a words <<< "${words//OWN/$work/own}"
  check "$args: refused, exit 2" test "$(SDL_VIDEODRIVER=dummy status_of "$boxlod" "${words[@]}")" = 2
done
# Without a display SDL falls back to an off-screen driver, where a person's viewer would wait for ever:
# refused at once; an empty replay stops at once; a display SDL cannot open is exit 2 too.
status=$(unset DISPLAY WAYLAND_DISPLAY; SDL_VIDEODRIVER=offscreen timeout 30 "$boxlod" view "$work/own/house.glb" --width 16 --height 16 2> "$work/view_err"; echo $?)
check "view without a display: exit 2" test "$status" = 2
check "and says what to do" grep -q "no display to open a window on (SDL's video driver is offscreen): set DISPLAY" "$work/view_err"
: > "$work/own/empty_replay.txt"
check "view --replay of an empty file stops at once, exit 0" test "$(SDL_VIDEODRIVER=offscreen timeout 30 "$boxlod" view "$work/own/house.glb" --replay "$work/own/empty_replay.txt" --width 16 --height 16 > /dev/null 2>&1; echo $?)" = 0
check "a display SDL cannot open: exit 2" test "$(SDL_VIDEODRIVER=no_such_driver status_of "$boxlod" view "$work/own/house.glb" --width 16 --height 16)" = 2
check "the models are as they were" bash -c "cmp -s '$work/own/house.glb' '$work/house_kept.glb' && cmp -s '$work/own/tree_L1.glb' '$work/house_kept.glb'"
check "a build's files beside a model of another name are written" test "$(status_of "$boxlod" build "$work/own/house.glb" -o "$work/own" --name house_lod --resolution 16 --preview-width 16 --preview-height 16)" = 0

echo "$((failures == 0 ? 1 : 0)) passed, $failures failed" >/dev/null
if [ "$failures" -ne 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all checks passed"

#!/usr/bin/env python3
"""Writes the big and deeply nested hostile inputs of the bad-input corpus test
into OUTDIR (run by bad_inputs.sh; not stored in the repository)."""
import base64
import json
import math
import os
import struct
import sys
import zlib

out = sys.argv[1]
os.makedirs(out, exist_ok=True)


def put(name, data):
    with open(os.path.join(out, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


# ---------------------------------------------------------------- glTF nested deeply
triangle = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)


def gltf_text(node_extras=None, asset_extras=None, unknown=None, buffer_uri=True):
    g = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "n", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36}],
    }
    if buffer_uri:
        g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(triangle).decode()
    text = json.dumps(g)
    # Splice raw nested text in (json.dumps itself would recurse).
    if node_extras:
        text = text.replace('"name": "n",', '"name": "n", "extras": %s,' % node_extras, 1)
    if asset_extras:
        text = text.replace('"version": "2.0"', '"version": "2.0", "extras": %s' % asset_extras, 1)
    if unknown:
        text = text[:-1] + ', "unknownDeepKey": %s}' % unknown
    return text


def arrays(depth):
    return "[" * depth + "]" * depth


def objects(depth):
    return '{"a":' * depth + "1" + "}" * depth


put("deep_node_extras_20000.gltf", gltf_text(node_extras=arrays(20000)))
put("deep_node_extras_200000.gltf", gltf_text(node_extras=arrays(200000)))
put("deep_asset_extras_objects_20000.gltf", gltf_text(asset_extras=objects(20000)))
put("deep_unknown_key_20000.gltf", gltf_text(unknown=arrays(20000)))
put("deep_boxlod_extras_20000.gltf", gltf_text(node_extras='{"boxlod": {"scope": %s}}' % arrays(20000)))
# Shallow but wide: a tree of some 30 times the text (toolkit/formats/json_input.h), 3 MB each.
put("wide_extras.gltf", gltf_text(node_extras="[" + ",".join(["[]"] * 1000000) + "]"))
put("wide_attributes.city.json", json.dumps({
    "type": "CityJSON", "version": "2.0", "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
    "CityObjects": {"b": {"type": "Building", "attributes": {"x": "WIDE"}}}, "vertices": []})
    .replace('"WIDE"', "[" + ",".join(["[]"] * 1000000) + "]"))

json_chunk = gltf_text(node_extras=arrays(20000), buffer_uri=False).encode()
while len(json_chunk) % 4:
    json_chunk += b" "
body = struct.pack("<I", len(json_chunk)) + b"JSON" + json_chunk + struct.pack("<I", 36) + b"BIN\0" + triangle
put("deep_node_extras_20000.glb", b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body)

# One mesh of 20,000 primitives used by 20,000 nodes: each node's copy asks 400 million primitives.
shared = json.loads(gltf_text())
shared["meshes"][0]["primitives"] *= 20000
shared["nodes"] *= 20000
del shared["scene"], shared["scenes"]
put("mesh_shared_by_many_nodes.gltf", json.dumps(shared))
# The same as points, and as strips of two vertices: read, and left out, for every node all the same.
shared["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 0}, "mode": 0}] * 20000
put("points_shared_by_many_nodes.gltf", json.dumps(shared))
shared["accessors"].append({"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3"})
shared["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 1}, "mode": 5}] * 20000
put("short_strips_shared_by_many_nodes.gltf", json.dumps(shared))

# A CityJSON template of 20,000 triangles placed 10 times: the copies would ask 96 MB (docs/design.md: Errors).
identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
put("instances_many.city.json", json.dumps({
    "type": "CityJSON", "version": "2.0", "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
    "geometry-templates": {"templates": [{"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 2]]] * 20000}],
                           "vertices-templates": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
    "CityObjects": {"t": {"type": "SolitaryVegetationObject", "geometry": [
        {"type": "GeometryInstance", "template": 0, "boundaries": [0], "transformationMatrix": identity}] * 10}},
    "vertices": [[0, 0, 0]]}))

# A small template and a MultiPoint of all 400,000 template points (which draws nothing), each placed
# 20,000 times, then an instance naming no template: placing the whole pool per instance took
# 1.6 * 10^10 point transforms (minutes) before refusing.
instance = {"type": "GeometryInstance", "template": 0, "boundaries": [0], "transformationMatrix": identity}
put("instances_over_a_large_pool.city.json", json.dumps({
    "type": "CityJSON", "version": "2.0", "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
    "geometry-templates": {"templates": [{"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 2]]]},
                                         {"type": "MultiPoint", "lod": "2", "boundaries": list(range(400003))}],
                           "vertices-templates": [[0, 0, 0], [1, 0, 0], [0, 1, 0]] + [[0, 0, 0]] * 400000},
    "CityObjects": {"t": {"type": "SolitaryVegetationObject", "geometry":
        [instance] * 20000 + [dict(instance, template=1)] * 20000 + [dict(instance, template=2)]}},
    "vertices": [[0, 0, 0]]}))

# A replay longer than SDL's event queue (65,535): its end was dropped without a word.
put("replay_70000.txt", "key z\n" * 70000 + "key f5\n")

# ---------------------------------------------------------------- grammars nested deeply or very long
n = 3000
put("grammar_parens_3000.grammar", "Lot --> extrude(%s3%s) i(box)\n" % ("(" * n, ")" * n))
put("grammar_calls_3000.grammar", "Lot --> extrude(%s3%s) i(box)\n" % ("abs(" * n, ")" * n))
put("grammar_brackets_3000.grammar", "Lot --> extrude(3) %si(box)%s\n" % ("[ " * n, " ]" * n))
put("grammar_splits_3000.grammar",
    "Lot --> extrude(3) %si(box)%s\n" % ("split(x) { ~1 : " * n, " }" * n))
put("grammar_minus_3000.grammar", "Lot --> extrude(%s3) i(box)\n" % ("- " * n))
put("grammar_not_3000.grammar", "Lot --> extrude(3 * (%s1)) i(box)\n" % ("! " * n))
put("grammar_plus_chain_200000.grammar", "Lot --> extrude(%s) i(box)\n" % " + ".join(["0.00001"] * 200000))
put("grammar_rule_chain_3000.grammar",
    "".join("R%d --> R%d\n" % (i, i + 1) for i in range(n)) + "R%d --> extrude(3) i(box)\n" % n)

# ---------------------------------------------------------------- COLLADA nested deeply
depth = 100000
put("dae_nodes_100000.dae",
    '<?xml version="1.0"?>\n<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">'
    '<library_visual_scenes><visual_scene id="vs">' + '<node>' * depth + '</node>' * depth +
    '</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#vs"/></scene></COLLADA>\n')
put("dae_xml_100000.dae", '<?xml version="1.0"?>\n<COLLADA version="1.4.1">' + "<a>" * depth + "</a>" * depth + "</COLLADA>\n")

# ---------------------------------------------------------------- a PLY whose header is one huge line
put("ply_header_16mb.ply", "ply\nformat ascii 1.0\ncomment " + "x" * (16 << 20) + "\nend_header\n")

# ---------------------------------------------------------------- a 270 KB PNG that declares 16384 x 16384 grey pixels
side = 16384
packer = zlib.compressobj(9)
idat = b"".join(packer.compress(b"\0" * (side + 1)) for _ in range(side)) + packer.flush()


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


put("declared_16384.png", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", side, side, 8, 0, 0, 0, 0)) +
    chunk(b"IDAT", idat) + chunk(b"IEND", b""))
# and a real 128 x 128 one, whose metrics (84 bytes a pixel) need more than 1 MB
put("grey_128.png", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 128, 128, 8, 0, 0, 0, 0)) +
    chunk(b"IDAT", zlib.compress(b"\0" * (129 * 128))) + chunk(b"IEND", b""))

# A sweep whose cross product would not fit in memory: 65 levels x 26 views x
# 99,900 distances x 2 groups, 338 million rows (refused before a model is read).
put("sweep_enormous.txt", ("models = sample:house\nlevel_modes = top-down\nlevels = all\nwanted_levels = 64\nviews = all\n"
                           "baselines = simplification\ndistances = " +
                           ", ".join("%.2f" % (1 + i * 0.01) for i in range(99900)) + "\n").encode())


# One 1024 x 1024 grey PNG (1 KB) named by 64 images of a glTF: each alone fits 100 MB, all of them do not.
grey_1024 = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1024, 1024, 8, 0, 0, 0, 0)) + \
    chunk(b"IDAT", zlib.compress(b"\0" * (1025 * 1024))) + chunk(b"IEND", b"")
put("grey_1024.png", grey_1024)
many_images = json.loads(gltf_text())
many_images["images"] = [{"uri": "grey_1024.png"}] * 64
put("images_one_file_64_times.gltf", json.dumps(many_images))

# A CityJSON polygon whose ring is wound as a star {201/100}: about 20,000 crossings.
star = [[round(1000 * math.cos(2 * math.pi * (j * 100 % 201) / 201)), round(1000 * math.sin(2 * math.pi * (j * 100 % 201) / 201)), 0]
        for j in range(201)]
put("ring_star.city.json", json.dumps({
    "type": "CityJSON", "version": "2.0", "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0, 0, 0]},
    "CityObjects": {"b": {"type": "Building", "geometry": [
        {"type": "MultiSurface", "lod": "2", "boundaries": [[list(range(201))]]}]}},
    "vertices": star}))

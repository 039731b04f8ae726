# A chain (build --chain, MSFT_lod) draws each level once: no two levels in a
# row draw the same primitives (their data and materials, whatever indices
# they were written under).
#   chain_levels_once.py CHAIN.glb
import hashlib, json, struct, sys
data = open(sys.argv[1], 'rb').read()
length = struct.unpack_from('<I', data, 12)[0]
gltf = json.loads(data[20:20 + length])
binary = data[20 + length + 8:]
root = gltf['scenes'][0]['nodes'][0]
levels = [root] + gltf['nodes'][root]['extensions']['MSFT_lod']['ids']
def accessor(k):
    """An accessor's data and layout (not its index)."""
    a = dict(gltf['accessors'][k])
    view = gltf['bufferViews'][a.pop('bufferView')]
    start = view.get('byteOffset', 0) + a.pop('byteOffset', 0)
    return hashlib.sha1(json.dumps(a, sort_keys=True).encode() + binary[start:view.get('byteOffset', 0) + view['byteLength']]).hexdigest()
def drawn(node):
    """What the level's node tree draws: each primitive's data and material."""
    n = gltf['nodes'][node]
    own = []
    for p in gltf['meshes'][n['mesh']]['primitives'] if 'mesh' in n else []:
        own.append((sorted((name, accessor(k)) for name, k in p['attributes'].items()), accessor(p['indices']),
                    json.dumps(gltf['materials'][p['material']], sort_keys=True)))
    return sorted(own + [p for child in n.get('children', []) for p in drawn(child)])
assert all(drawn(a) != drawn(b) for a, b in zip(levels, levels[1:])), "two levels in a row draw the same"

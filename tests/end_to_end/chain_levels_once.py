# A chain (build --chain, MSFT_lod) draws each level once: no two levels in a
# row draw the same primitives (their data and materials, whatever indices
# they were written under).
#   chain_levels_once.py CHAIN.glb
import base64, hashlib, json, struct, sys

data = open(sys.argv[1], 'rb').read()
length = struct.unpack_from('<I', data, 12)[0]
gltf = json.loads(data[20:20 + length])
glb_binary = data[20 + length + 8:]
root = gltf['scenes'][0]['nodes'][0]
levels = [root] + gltf['nodes'][root].get('extensions', {}).get('MSFT_lod', {}).get('ids', [])
COMPONENTS = {'SCALAR': 1, 'VEC2': 2, 'VEC3': 3, 'VEC4': 4, 'MAT4': 16}
SIZES = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}


def buffer(k):
    """Buffer k's bytes: the GLB's binary chunk, or a data URI (levels' own small index buffers)."""
    uri = gltf['buffers'][k].get('uri')
    return glb_binary if uri is None else base64.b64decode(uri.split(',', 1)[1])


def accessor(k):
    """An accessor's elements and layout, not its index."""
    a = gltf['accessors'][k]
    view = gltf['bufferViews'][a['bufferView']]
    element = COMPONENTS[a['type']] * SIZES[a['componentType']]
    stride = view.get('byteStride', element)
    start = view.get('byteOffset', 0) + a.get('byteOffset', 0)
    source = buffer(view['buffer'])
    elements = b''.join(source[start + i * stride:start + i * stride + element] for i in range(a['count']))
    layout = json.dumps({key: a[key] for key in ('type', 'componentType', 'count', 'normalized') if key in a})
    return hashlib.sha1(layout.encode() + elements).hexdigest()


def drawn(node):
    """What a level's node tree draws: each primitive's data and material."""
    n = gltf['nodes'][node]
    own = []
    for p in gltf['meshes'][n['mesh']]['primitives'] if 'mesh' in n else []:
        own.append((sorted((name, accessor(k)) for name, k in p['attributes'].items()), accessor(p['indices']),
                    json.dumps(gltf['materials'][p['material']], sort_keys=True)))
    return sorted(own + [p for child in n.get('children', []) for p in drawn(child)])


assert all(drawn(a) != drawn(b) for a, b in zip(levels, levels[1:])), "two levels in a row draw the same"

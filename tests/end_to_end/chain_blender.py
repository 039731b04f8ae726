# Run by tests/end_to_end/chain_blender.sh inside Blender: imports one glTF with Blender's
# own importer (which has no MSFT_lod: every level of a chain becomes objects,
# each level under its root) and prints, as JSON, the import's seconds, the
# object count and each root's triangles.
import json, sys, time

import bpy
import numpy

if not hasattr(numpy, "bool"):  # Debian 12's Blender 3.4 importer still uses the alias numpy 1.24 removed
    numpy.bool = bool

path = sys.argv[sys.argv.index("--") + 1]
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)
start = time.monotonic()
bpy.ops.import_scene.gltf(filepath=path)
seconds = time.monotonic() - start


def triangles(obj):
    count = 0
    if obj.type == "MESH":
        obj.data.calc_loop_triangles()
        count = len(obj.data.loop_triangles)
    return count + sum(triangles(child) for child in obj.children)


roots = {obj.name: triangles(obj) for obj in bpy.data.objects if obj.parent is None}
print("chain_blender " + json.dumps({"seconds": seconds, "objects": len(bpy.data.objects), "roots": roots}))

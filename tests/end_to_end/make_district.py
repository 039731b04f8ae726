#!/usr/bin/env python3
"""Writes a CityJSON 2.0 district of N buildings (default 50) for the tests:
a grid of gabled houses 25 m apart, 85 km and 447 km from the CRS origin
(coordinates as in the Dutch RD system), each a Solid at LoD 2.2 with ground,
wall and roof surfaces and a window cut into its front wall, and a
lower-detail LoD 1.2 block. Sizes vary per house from its own seeded stream.
Usage: make_district.py OUT.city.json [N]"""
import json
import random
import sys

out, count = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 50
vertices, objects = [], {}


def vertex(x, y, z):
    """A vertex index; coordinates in millimetres (transform scale 0.001)."""
    vertices.append([round(x * 1000), round(y * 1000), round(z * 1000)])
    return len(vertices) - 1


for i in range(count):
    rng = random.Random(i)
    x0, y0 = (i % 10) * 25.0, (i // 10) * 25.0
    w, d, h, ridge = rng.uniform(8, 14), rng.uniform(7, 11), rng.uniform(5, 8), rng.uniform(2, 4)
    g = [vertex(x0, y0, 0), vertex(x0 + w, y0, 0), vertex(x0 + w, y0 + d, 0), vertex(x0, y0 + d, 0)]
    t = [vertex(x0, y0, h), vertex(x0 + w, y0, h), vertex(x0 + w, y0 + d, h), vertex(x0, y0 + d, h)]
    r = [vertex(x0, y0 + d / 2, h + ridge), vertex(x0 + w, y0 + d / 2, h + ridge)]
    win = [vertex(x0 + w * 0.3, y0, h * 0.3), vertex(x0 + w * 0.6, y0, h * 0.3),
           vertex(x0 + w * 0.6, y0, h * 0.7), vertex(x0 + w * 0.3, y0, h * 0.7)]
    shell = [
        [[g[0], g[3], g[2], g[1]]],                              # ground, facing down
        [[g[0], g[1], t[1], t[0]], [win[0], win[3], win[2], win[1]]],  # front wall with the window's hole
        [[win[0], win[1], win[2], win[3]]],                      # the window
        [[g[1], g[2], t[2], t[1]]], [[g[2], g[3], t[3], t[2]]],
        [[g[3], g[0], t[0], t[3]]],
        [[t[0], t[1], r[1], r[0]]], [[t[2], t[3], r[0], r[1]]],   # roof planes
        [[t[1], t[2], r[1]]], [[t[3], t[0], r[0]]],                # gables
    ]
    block = [[[g[0], g[3], g[2], g[1]]], [[t[0], t[1], t[2], t[3]]]] + \
        [[[g[k], g[(k + 1) % 4], t[(k + 1) % 4], t[k]]] for k in range(4)]
    objects[f"house_{i}"] = {
        "type": "Building",
        "geometry": [
            {"type": "Solid", "lod": "1.2", "boundaries": [block]},
            {"type": "Solid", "lod": "2.2", "boundaries": [shell],
             "semantics": {"surfaces": [{"type": "GroundSurface"}, {"type": "WallSurface"},
                                        {"type": "Window", "parent": 1}, {"type": "RoofSurface"}],
                           "values": [[0, 1, 2, 1, 1, 1, 3, 3, 1, 1]]}},
        ],
    }

district = {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [0.001, 0.001, 0.001], "translate": [85000.0, 447000.0, 0.0]},
            "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
            "CityObjects": objects, "vertices": vertices}
with open(out, "w") as f:
    json.dump(district, f)

#!/usr/bin/env python3
"""Writes hemiroll's scenery meshes into assets/meshes/ (our own geometry, no
third-party art): flag.obj (a pole with a pennant, OBJ) and cone.gltf (a
traffic cone, glTF 2.0 with its buffer embedded as base64, vertex colours).
Levels place them with scene.props (docs/LEVELS.md); the renderer scales
each to the sphere of the prop's size, so the units here are arbitrary.

Run from the project root: python3 tools/assets/make_meshes.py
"""
import base64
import json
import math
import os
import struct

OUT = os.path.join(os.path.dirname(__file__), "..", "..", "assets", "meshes")


def flag_obj():
    lines = ["# hemiroll: a flag (pole and pennant), written by tools/assets/make_meshes.py.",
             "# Up is +z. Loaded through assimp; a level places it with scene.props."]
    verts, faces = [], []
    sides, radius, height = 8, 0.04, 2.0
    for k in range(sides):  # the pole: a thin prism
        a = 2 * math.pi * k / sides
        verts.append((radius * math.cos(a), radius * math.sin(a), 0.0))
        verts.append((radius * math.cos(a), radius * math.sin(a), height))
    for k in range(sides):
        a, b = 2 * k, 2 * ((k + 1) % sides)
        faces.append((a + 1, b + 1, b + 2))
        faces.append((a + 1, b + 2, a + 2))
    top = len(verts)  # the pennant: a triangle off the top of the pole
    verts += [(0.0, 0.0, height), (0.0, 0.0, height - 0.6), (0.9, 0.0, height - 0.3)]
    faces.append((top + 1, top + 2, top + 3))
    lines += ["v %.6f %.6f %.6f" % v for v in verts]
    lines += ["f %d %d %d" % f for f in faces]
    return "\n".join(lines) + "\n"


def cone_gltf():
    sides, radius, height = 24, 0.5, 1.2
    positions, colours, indices = [], [], []
    orange, white = (0.95, 0.45, 0.1, 1.0), (0.95, 0.95, 0.95, 1.0)
    apex = 0
    positions.append((0.0, 0.0, height))
    colours.append(orange)
    for ring, (r, z, c) in enumerate([(radius, 0.0, orange), (radius * 0.55, height * 0.45, white)]):
        for k in range(sides):
            a = 2 * math.pi * k / sides
            positions.append((r * math.cos(a), r * math.sin(a), z))
            colours.append(c)
    base, band = 1, 1 + sides
    for k in range(sides):
        n = (k + 1) % sides
        indices += [base + k, base + n, band + n, base + k, band + n, band + k]  # lower part
        indices += [band + k, band + n, apex]                                  # upper part
    centre = len(positions)
    positions.append((0.0, 0.0, 0.0))
    colours.append(orange)
    for k in range(sides):
        indices += [centre, base + (k + 1) % sides, base + k]  # the bottom disc
    # glTF is y up (its specification); the engine turns it to z up on loading.
    positions = [(x, z, -y) for (x, y, z) in positions]
    pos = b"".join(struct.pack("<3f", *p) for p in positions)
    col = b"".join(struct.pack("<4f", *c) for c in colours)
    idx = b"".join(struct.pack("<H", i) for i in indices)
    while len(idx) % 4:
        idx += b"\0"
    buffer = pos + col + idx
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]

    doc = {
        "asset": {"version": "2.0", "generator": "hemiroll tools/assets/make_meshes.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "cone"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "indices": 2}]}],
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "target": 34962},
            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(col), "target": 34962},
            {"buffer": 0, "byteOffset": len(pos) + len(col), "byteLength": 2 * len(indices), "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": len(colours), "type": "VEC4"},
            {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
    }
    return json.dumps(doc, indent=1) + "\n"


if __name__ == "__main__":
    with open(os.path.join(OUT, "flag.obj"), "w") as f:
        f.write(flag_obj())
    with open(os.path.join(OUT, "cone.gltf"), "w") as f:
        f.write(cone_gltf())

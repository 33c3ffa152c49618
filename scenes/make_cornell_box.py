#!/usr/bin/env python3
"""Writes the Cornell box (geometry as published by the Cornell Program of
Computer Graphics, millimetres) as cornell_box.gltf (with its camera and a
point light, KHR_lights_punctual) and as cornell_box.obj + .mtl (geometry and
materials only).

The published light is a quad lying in the ceiling plane; this scene lights the
box with a point light below that quad's centre, 100 mm under the ceiling (so
that the ceiling has no near-singular hot spot to dominate error metrics),
and leaves the quad out (it would be coplanar with the ceiling)."""
import base64
import json
import math
import struct

WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)

QUADS = {
    "white": [
        # floor
        [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)],
        # ceiling
        [(556.0, 548.8, 0), (556.0, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0)],
        # back wall
        [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556.0, 548.8, 559.2)],
        # short block
        [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)],
        [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)],
        [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)],
        [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)],
        [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)],
        # tall block
        [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)],
        [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)],
        [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)],
        [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)],
        [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)],
    ],
    "red": [[(552.8, 0, 0), (549.6, 0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0)]],
    "green": [[(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]],
}
COLORS = {"white": WHITE, "red": RED, "green": GREEN}
LIGHT_POS = (278.0, 448.8, 279.5)
LIGHT_INTENSITY = 6.0e5  # W/sr, white
CAMERA_POS = (278.0, 273.0, -800.0)
FOV_Y = 2 * math.atan(0.0125 / 0.035)  # 25 mm film, 35 mm lens


def triangles(quads):
    for q in quads:
        yield q[0], q[1], q[2]
        yield q[0], q[2], q[3]


def write_obj():
    with open("cornell_box.mtl", "w") as m:
        for name, c in COLORS.items():
            m.write(f"newmtl {name}\nKd {c[0]} {c[1]} {c[2]}\nKs 0 0 0\nNs 1\n\n")
    with open("cornell_box.obj", "w") as f:
        f.write("# Cornell box, published geometry (mm); see make_cornell_box.py\n")
        f.write("mtllib cornell_box.mtl\n")
        base = 1
        for name, quads in QUADS.items():
            f.write(f"o {name}\nusemtl {name}\n")
            for q in quads:
                for v in q:
                    f.write(f"v {v[0]} {v[1]} {v[2]}\n")
                f.write(f"f {base} {base + 1} {base + 2} {base + 3}\n")
                base += 4


def write_gltf():
    blob = bytearray()
    accessors, views, primitives, materials = [], [], [], []
    for mi, (name, quads) in enumerate(QUADS.items()):
        verts = [v for t in triangles(quads) for v in t]
        offset = len(blob)
        for v in verts:
            blob += struct.pack("<3f", *v)
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(verts) * 12})
        lo = [min(v[i] for v in verts) for i in range(3)]
        hi = [max(v[i] for v in verts) for i in range(3)]
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126,
                          "count": len(verts), "type": "VEC3", "min": lo, "max": hi})
        primitives.append({"attributes": {"POSITION": len(accessors) - 1}, "material": mi})
        c = COLORS[name]
        materials.append({"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": [c[0], c[1], c[2], 1.0], "metallicFactor": 0.0,
            "roughnessFactor": 1.0}})
    doc = {
        "asset": {"version": "2.0", "generator": "make_cornell_box.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "ceiling_light", "type": "point", "color": [1.0, 1.0, 1.0],
             "intensity": LIGHT_INTENSITY}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "box", "mesh": 0},
            # glTF cameras look down -z; turn 180 degrees about y to look at +z.
            {"name": "camera", "camera": 0, "translation": list(CAMERA_POS),
             "rotation": [0.0, 1.0, 0.0, 0.0]},
            {"name": "ceiling_light", "translation": list(LIGHT_POS),
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"type": "perspective", "perspective": {
            "aspectRatio": 1.0, "yfov": FOV_Y, "znear": 1.0, "zfar": 10000.0}}],
        "meshes": [{"name": "box", "primitives": primitives}],
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(blob)).decode()}],
    }
    with open("cornell_box.gltf", "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    write_obj()
    write_gltf()

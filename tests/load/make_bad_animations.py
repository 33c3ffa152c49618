#!/usr/bin/env python3
"""Writes glTF files whose one animation is bad, into the folder given:
nan_key.gltf (a translation that is not a number), unordered.gltf (key
times that go back), zero_scale.gltf (a scale of 0), no_node.gltf (a
channel aimed at a node the file does not have). One triangle each; the
standard library only."""
import base64
import json
import math
import os
import struct
import sys


def write(path, times, values, path_kind="translation", node=0):
    blob = bytearray()
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0)]:
        blob += struct.pack("<3f", *p)
    for i in (0, 1, 2):
        blob += struct.pack("<I", i)
    t_off = len(blob)
    for t in times:
        blob += struct.pack("<f", t)
    v_off = len(blob)
    for v in values:
        blob += struct.pack("<3f", *v)
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "tri"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(blob)).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 12},
                        {"buffer": 0, "byteOffset": t_off, "byteLength": v_off - t_off},
                        {"buffer": 0, "byteOffset": v_off, "byteLength": len(blob) - v_off}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"},
                      {"bufferView": 2, "componentType": 5126, "count": len(times),
                       "type": "SCALAR", "min": [min(times)], "max": [max(times)]},
                      {"bufferView": 3, "componentType": 5126, "count": len(values),
                       "type": "VEC3"}],
        "animations": [{"name": "bad", "samplers": [{"input": 2, "output": 3,
                                                     "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0,
                                      "target": {"node": node, "path": path_kind}}]}],
    }
    with open(path, "w") as f:
        json.dump(gltf, f)


def main():
    out = sys.argv[1]
    write(os.path.join(out, "nan_key.gltf"), [0, 1, 2], [(0, 0, 0), (math.nan, 0, 0), (0, 0, 0)])
    write(os.path.join(out, "unordered.gltf"), [0, 2, 1], [(0, 0, 0), (1, 0, 0), (0, 0, 0)])
    write(os.path.join(out, "zero_scale.gltf"), [0, 1], [(1, 1, 1), (1, 0, 1)], "scale")
    write(os.path.join(out, "no_node.gltf"), [0, 1], [(0, 0, 0), (1, 0, 0)], node=5)


if __name__ == "__main__":
    main()

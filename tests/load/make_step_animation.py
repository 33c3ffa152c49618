#!/usr/bin/env python3
"""Writes tests/load/inputs/load_step_keys.gltf: one triangle whose unnamed node
moves by a STEP sampler, keys (0 0 0) at 0 s, (1 0 0) at 1 s, (0 2 0) at
2 s, and a named node turned by a LINEAR one. The standard library only."""
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    blob = bytearray()
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0)]:
        blob += struct.pack("<3f", *p)
    for i in (0, 1, 2):
        blob += struct.pack("<I", i)
    t_off = len(blob)
    for t in (0.0, 1.0, 2.0):
        blob += struct.pack("<f", t)
    v_off = len(blob)
    for v in [(0, 0, 0), (1, 0, 0), (0, 2, 0)]:
        blob += struct.pack("<3f", *v)
    q_off = len(blob)
    for q in [(0, 0, 0, 1), (0, 0.7071068, 0, 0.7071068), (0, 0, 0, 1)]:
        blob += struct.pack("<4f", *q)
    gltf = {
        "asset": {"version": "2.0", "generator": "tests/load/make_step_animation.py"},
        "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"mesh": 0, "name": "turned", "translation": [3, 0, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(blob)).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 12},
                        {"buffer": 0, "byteOffset": t_off, "byteLength": 12},
                        {"buffer": 0, "byteOffset": v_off, "byteLength": 36},
                        {"buffer": 0, "byteOffset": q_off, "byteLength": 48}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"},
                      {"bufferView": 2, "componentType": 5126, "count": 3, "type": "SCALAR",
                       "min": [0], "max": [2]},
                      {"bufferView": 3, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 4, "componentType": 5126, "count": 3, "type": "VEC4"}],
        "animations": [{"name": "steps",
                        "samplers": [{"input": 2, "output": 3, "interpolation": "STEP"},
                                     {"input": 2, "output": 4, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                     {"sampler": 1, "target": {"node": 1, "path": "rotation"}}]}],
    }
    with open(os.path.join(HERE, "inputs", "load_step_keys.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)


if __name__ == "__main__":
    main()

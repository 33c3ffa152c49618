#!/usr/bin/env python3
"""One object that moves in a scene that holds still: copies a glTF file (its
buffers embedded) and replaces its animations by one, "move", that slides
node NODE by (DX, DY, DZ) from its place over SECONDS and back over as many.

usage: make_moving.py IN.gltf OUT.gltf NODE DX DY DZ SECONDS"""
import base64
import json
import struct
import sys


def main():
    src, dst, node = sys.argv[1], sys.argv[2], int(sys.argv[3])
    d = [float(v) for v in sys.argv[4:7]]
    seconds = float(sys.argv[7])
    g = json.load(open(src))
    rest = g["nodes"][node].get("translation", [0.0, 0.0, 0.0])
    moved = [rest[k] + d[k] for k in range(3)]
    keys = struct.pack("<3f", 0.0, seconds, 2 * seconds) + struct.pack("<9f", *rest, *moved, *rest)
    g["buffers"].append({"byteLength": len(keys), "uri": "data:application/octet-stream;base64,"
                         + base64.b64encode(keys).decode()})
    buf = len(g["buffers"]) - 1
    g["bufferViews"] += [{"buffer": buf, "byteOffset": 0, "byteLength": 12},
                         {"buffer": buf, "byteOffset": 12, "byteLength": 36}]
    view = len(g["bufferViews"]) - 2
    g["accessors"] += [{"bufferView": view, "componentType": 5126, "count": 3, "type": "SCALAR",
                        "min": [0.0], "max": [2 * seconds]},
                       {"bufferView": view + 1, "componentType": 5126, "count": 3,
                        "type": "VEC3"}]
    acc = len(g["accessors"]) - 2
    g["animations"] = [{"name": "move",
                        "samplers": [{"input": acc, "output": acc + 1, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0,
                                      "target": {"node": node, "path": "translation"}}]}]
    json.dump(g, open(dst, "w"))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes glTF files whose samplers are cubic splines (CUBICSPLINE), into the
folder given (default tests/load/inputs): one triangle on an unnamed node
translated along x, keys 1 at 0 s and 4 at 2 s, the first key's out-tangent
3 and the second's in-tangent 5 (units a second); and a node "turned" about y,
keys 0 and 90 degrees at 0 and 1 s, tangents 0. The same data three ways:
cubic_keys.gltf (an embedded base64 buffer), cubic_keys_bin.gltf (beside it,
cubic_keys.bin), cubic_keys.glb (the binary chunk). Then bad ones:
cubic_nan_tangent.gltf (a tangent that is not a number) and
cubic_short.gltf (one value a key instead of three). The standard library
only."""
import base64
import json
import math
import os
import struct
import sys

H = math.sqrt(0.5)


def blob_and_gltf(tangent=3.0, triples=True):
    blob = bytearray()
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0)]:
        blob += struct.pack("<3f", *p)
    for i in (0, 1, 2):
        blob += struct.pack("<I", i)
    views = [(0, 36), (36, 12)]

    def add(fmt, rows):
        start = len(blob)
        for r in rows:
            blob.extend(struct.pack(fmt, *r))
        views.append((start, len(blob) - start))
        return len(views) - 1

    t_move = add("<f", [(0.0,), (2.0,)])
    # (in-tangent, value, out-tangent) for each key
    moves = [(0, 0, 0), (1, 0, 0), (tangent, 0, 0), (5, 0, 0), (4, 0, 0), (0, 0, 0)]
    if not triples:
        moves = [(1, 0, 0), (4, 0, 0)]
    v_move = add("<3f", moves)
    t_turn = add("<f", [(0.0,), (1.0,)])
    zero = (0, 0, 0, 0)
    v_turn = add("<4f", [zero, (0, 0, 0, 1), zero, zero, (0, H, 0, H), zero])
    accessors = [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                  "min": [0, 0, 0], "max": [1, 1, 0]},
                 {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"},
                 {"bufferView": t_move, "componentType": 5126, "count": 2, "type": "SCALAR",
                  "min": [0], "max": [2]},
                 {"bufferView": v_move, "componentType": 5126, "count": len(moves),
                  "type": "VEC3"},
                 {"bufferView": t_turn, "componentType": 5126, "count": 2, "type": "SCALAR",
                  "min": [0], "max": [1]},
                 {"bufferView": v_turn, "componentType": 5126, "count": 6, "type": "VEC4"}]
    gltf = {
        "asset": {"version": "2.0", "generator": "tests/load/make_cubic_animation.py"},
        "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"mesh": 0, "name": "turned", "translation": [3, 0, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(blob)}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
        "accessors": accessors,
        "animations": [{"name": "splines",
                        "samplers": [{"input": 2, "output": 3, "interpolation": "CUBICSPLINE"},
                                     {"input": 4, "output": 5, "interpolation": "CUBICSPLINE"}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                     {"sampler": 1, "target": {"node": 1, "path": "rotation"}}]}],
    }
    return bytes(blob), gltf


def embedded(path, blob, gltf):
    gltf["buffers"][0]["uri"] = ("data:application/octet-stream;base64,"
                                 + base64.b64encode(blob).decode())
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "inputs")
    blob, gltf = blob_and_gltf()
    if len(sys.argv) > 1:  # the bad ones, for the command line's refusals
        embedded(os.path.join(out, "cubic_nan_tangent.gltf"), *blob_and_gltf(tangent=math.nan))
        embedded(os.path.join(out, "cubic_short.gltf"), *blob_and_gltf(triples=False))
        return
    with open(os.path.join(out, "cubic_keys.bin"), "wb") as f:
        f.write(blob)
    gltf["buffers"][0]["uri"] = "cubic_keys.bin"
    with open(os.path.join(out, "cubic_keys_bin.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
    del gltf["buffers"][0]["uri"]
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    body = blob + b"\0" * (-len(blob) % 4)
    glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(body))
    glb += struct.pack("<I4s", len(text), b"JSON") + text
    glb += struct.pack("<I4s", len(body), b"BIN\0") + body
    with open(os.path.join(out, "cubic_keys.glb"), "wb") as f:
        f.write(glb)
    embedded(os.path.join(out, "cubic_keys.gltf"), blob, gltf)


if __name__ == "__main__":
    main()

"""Animations added to a glTF file's JSON for the benches (make_pan.py,
make_moving.py): keys stored in a new embedded buffer."""
import base64
import struct


def add_animation(g, name, node, path, times, values):
    """Replaces g's animations by one, `name`, whose LINEAR sampler moves
    `path` ("translation": 3 floats a key, "rotation": 4) of node `node`
    through `values` at `times` (seconds)."""
    width = len(values[0])
    keys = struct.pack(f"<{len(times)}f", *times)
    keys += struct.pack(f"<{len(values) * width}f", *[x for v in values for x in v])
    g["buffers"].append({"byteLength": len(keys), "uri": "data:application/octet-stream;base64,"
                         + base64.b64encode(keys).decode()})
    buf = len(g["buffers"]) - 1
    g["bufferViews"] += [{"buffer": buf, "byteOffset": 0, "byteLength": 4 * len(times)},
                         {"buffer": buf, "byteOffset": 4 * len(times),
                          "byteLength": len(keys) - 4 * len(times)}]
    view = len(g["bufferViews"]) - 2
    g["accessors"] += [{"bufferView": view, "componentType": 5126, "count": len(times),
                        "type": "SCALAR", "min": [min(times)], "max": [max(times)]},
                       {"bufferView": view + 1, "componentType": 5126, "count": len(values),
                        "type": f"VEC{width}"}]
    acc = len(g["accessors"]) - 2
    g["animations"] = [{"name": name,
                        "samplers": [{"input": acc, "output": acc + 1, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": node, "path": path}}]}]

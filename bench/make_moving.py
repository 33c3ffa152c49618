#!/usr/bin/env python3
"""One object that moves in a scene that holds still: copies a glTF file (its
buffers embedded) and replaces its animations by one, "move", that slides
node NODE by (DX, DY, DZ) from its place over SECONDS and back over as many.

usage: make_moving.py IN.gltf OUT.gltf NODE DX DY DZ SECONDS"""
import json
import sys

from gltf_anim import add_animation


def main():
    src, dst, node = sys.argv[1], sys.argv[2], int(sys.argv[3])
    d = [float(v) for v in sys.argv[4:7]]
    seconds = float(sys.argv[7])
    g = json.load(open(src))
    rest = g["nodes"][node].get("translation", [0.0, 0.0, 0.0])
    moved = [rest[k] + d[k] for k in range(3)]
    add_animation(g, "move", node, "translation", [0.0, seconds, 2 * seconds],
                  [rest, moved, rest])
    json.dump(g, open(dst, "w"))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A camera pan through a scene: copies a glTF file (its buffers embedded) and
replaces its animations by one, "pan", that turns its camera node about the
world's up axis from -DEG to +DEG degrees over SECONDS, its eye still. With
DEG 0 the camera stays: the same sequence with nothing moving.

usage: make_pan.py IN.gltf OUT.gltf DEG SECONDS"""
import json
import os
import sys

from gltf_anim import add_animation

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes",
                                "suite"))
from gltf_scene import quaternion_product, yaw_quaternion  # noqa: E402


def main():
    src, dst, deg, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    g = json.load(open(src))
    cam = next(i for i, n in enumerate(g["nodes"]) if "camera" in n)
    q0 = g["nodes"][cam].get("rotation", [0, 0, 0, 1])
    ends = [quaternion_product(yaw_quaternion(d), q0) for d in (-deg, deg)]
    add_animation(g, "pan", cam, "rotation", [0.0, seconds], ends)
    json.dump(g, open(dst, "w"))


if __name__ == "__main__":
    main()

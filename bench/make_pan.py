#!/usr/bin/env python3
"""A camera pan through a scene: copies a glTF file (its buffers embedded) and
replaces its animations by one, "pan", that turns its camera node about the
world's up axis from -DEG to +DEG degrees over SECONDS, its eye still. With
DEG 0 the camera stays: the same sequence with nothing moving.

usage: make_pan.py IN.gltf OUT.gltf DEG SECONDS"""
import json
import math
import sys

from gltf_anim import add_animation


def yaw(deg, q):
    """The world-space turn about +y by deg, then q (x y z w)."""
    h = math.radians(deg) / 2
    a = (0.0, math.sin(h), 0.0, math.cos(h))
    ax, ay, az, aw = a
    bx, by, bz, bw = q
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def main():
    src, dst, deg, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    g = json.load(open(src))
    cam = next(i for i, n in enumerate(g["nodes"]) if "camera" in n)
    q0 = g["nodes"][cam].get("rotation", [0, 0, 0, 1])
    add_animation(g, "pan", cam, "rotation", [0.0, seconds], [yaw(-deg, q0), yaw(deg, q0)])
    json.dump(g, open(dst, "w"))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes instanced_spheres.gltf: one 5,120-triangle sphere placed by 64
nodes (turned, scaled, some squashed) on a floor before a wall, under a
point light; an animation ("roll", 2 s) moves the first sphere. Loaded, the file holds the sphere once; flattened, 327,680
triangles: what a two-level acceleration structure saves."""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "suite"))
from gltf_scene import Scene  # noqa: E402


def main():
    s = Scene()
    floor = s.material("floor", (0.7, 0.7, 0.68))
    wall = s.material("wall", (0.6, 0.62, 0.7))
    ball = s.material("ball", (0.75, 0.35, 0.2), roughness=0.6)
    s.quads(floor, [[(-6, 0, -6), (-6, 0, 6), (6, 0, 6), (6, 0, -6)]])
    s.quads(wall, [[(-6, 0, -6), (6, 0, -6), (6, 6, -6), (-6, 6, -6)]])
    sphere = s.sphere(ball, (0, 0, 0), 1.0, rings=41, segments=64)  # 5,120 triangles
    for i in range(8):
        for j in range(8):
            k = 8 * i + j
            r = 0.28 + 0.06 * ((3 * k) % 5)
            angle = 0.37 * k
            squash = 0.6 if k % 7 == 0 else 1.0
            rotation = (0.0, math.sin(angle / 2), 0.0, math.cos(angle / 2))
            s.place(sphere, (-4.9 + 1.4 * j, r * squash, -4.9 + 1.4 * i), rotation,
                    (r, r * squash, r))
    # the first sphere rolls to the right and back over two seconds
    y0 = 0.28 * 0.6  # its radius, squashed
    s.animate("roll", sphere, 0, [0.0, 1.0, 2.0],
              [(-4.9, y0, -4.9), (-3.5, y0, -4.9), (-4.9, y0, -4.9)])
    s.point_light((0.5, 5.0, 3.0), 120.0)
    s.look((0.0, 5.5, 9.5), (0.0, 0.3, -0.5), 50.0)
    s.write(os.path.join(HERE, "instanced_spheres.gltf"))


if __name__ == "__main__":
    main()

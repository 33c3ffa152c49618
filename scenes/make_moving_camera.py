#!/usr/bin/env python3
"""Writes moving_camera.gltf: a floor, a wall and three boxes under a point
light; an animation ("fly", 2 s) moves the camera's node (sideways, turning
towards the boxes) and the light's node (across the room). Nothing with
triangles moves: the camera and the light are what a frame changes."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "suite"))
from gltf_scene import Scene, quaternion_product, yaw_quaternion  # noqa: E402


def main():
    s = Scene()
    floor = s.material("floor", (0.7, 0.7, 0.68))
    wall = s.material("wall", (0.6, 0.62, 0.7))
    red = s.material("red", (0.7, 0.2, 0.15))
    s.quads(floor, [[(-5, 0, -5), (-5, 0, 5), (5, 0, 5), (5, 0, -5)]])
    s.quads(wall, [[(-5, 0, -5), (5, 0, -5), (5, 4, -5), (-5, 4, -5)]])
    for k, x in enumerate((-2.5, 0.0, 2.5)):
        h = 0.6 + 0.4 * k
        s.box(red, (x - 0.5, 0.0, -2.0), (x + 0.5, h, -1.0))
    s.point_light((-3.0, 3.5, 1.0), 60.0)
    s.look((0.0, 1.6, 6.0), (0.0, 0.8, -1.5), 50.0)
    # The camera's node: rest pose as look() placed it; the animation moves it
    # 2 units to the right and back, turning it 10 degrees left at 1 s.
    rest = s.camera_rotation()
    turned = quaternion_product(yaw_quaternion(10.0), rest)
    s.animate("fly", "camera", 0, [0.0, 1.0, 2.0],
              [(0.0, 1.6, 6.0), (2.0, 1.6, 5.5), (0.0, 1.6, 6.0)],
              rotations=[rest, turned, rest])
    s.animate("fly", "light", 0, [0.0, 1.0, 2.0],
              [(-3.0, 3.5, 1.0), (3.0, 3.0, 0.0), (-3.0, 3.5, 1.0)])
    s.write(os.path.join(HERE, "moving_camera.gltf"))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Flicker under a camera that turns about its eye: each frame of a sequence
against the frame before, brought into its view. A turn moves no surface
across another, so each pixel's ray, turned into the previous frame's
camera, says exactly where that frame saw the same point; it is read there
(bilinear). Pixels left out: those the previous frame does not show (off
screen), and those on an edge (a tap's surface point, from the position
AOV, more than 3 % of its distance from the pixel's own). Prints the mean
absolute change of the rest over the mean of the image, averaged over the
frame pairs, then its largest pair, then the share of pixels kept.

usage: temporal_pan.py PAN.gltf DEG SECONDS FPS PATTERN POSITIONS N
  PAN.gltf, DEG, SECONDS: as make_pan.py made it (the eye and the camera's
  rest turn and field of view are read from it)
  PATTERN, POSITIONS: printf patterns of the frames and of their position AOVs"""
import json
import math
import os
import sys

import numpy as np

from pfm import read_pfm

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes",
                                "suite"))
from gltf_scene import quaternion_product, yaw_quaternion  # noqa: E402


def yaw(deg, q):
    """The world-space turn about +y by deg, then q (x y z w)."""
    return quaternion_product(yaw_quaternion(deg), q)


def basis(q):
    """The camera's right, up and back axes (glTF: it looks down -z)."""
    x, y, z, w = q
    r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return r[:, 0], r[:, 1], r[:, 2]


def pixel_rays(q, fov_y, w, h):
    """Each pixel centre's ray direction in the world (vct's camera: y down)."""
    right, up, back = basis(q)
    t = math.tan(math.radians(fov_y) / 2)
    x, y = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
    sx = (2 * x / w - 1) * t * w / h
    sy = (1 - 2 * y / h) * t
    return sx[..., None] * right + sy[..., None] * up - back


def project(dirs, q, fov_y, w, h):
    """Where directions from the eye fall in the camera turned by q (pixel coordinates)."""
    right, up, back = basis(q)
    z = -(dirs @ back)
    t = math.tan(math.radians(fov_y) / 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        sx, sy = (dirs @ right) / z, (dirs @ up) / z
    px = (sx / (t * w / h) + 1) * w / 2 - 0.5
    py = (1 - sy / t) * h / 2 - 0.5
    return px, py, z


def bilinear(img, px, py):
    h, w = img.shape[:2]
    x0, y0 = np.floor(px).astype(int), np.floor(py).astype(int)
    fx, fy = (px - x0)[..., None], (py - y0)[..., None]
    x0c, y0c = np.clip(x0, 0, w - 2), np.clip(y0, 0, h - 2)
    taps = [img[y0c, x0c], img[y0c, x0c + 1], img[y0c + 1, x0c], img[y0c + 1, x0c + 1]]
    value = (taps[0] * (1 - fx) * (1 - fy) + taps[1] * fx * (1 - fy)
             + taps[2] * (1 - fx) * fy + taps[3] * fx * fy)
    inside = (x0 >= 0) & (y0 >= 0) & (x0 <= w - 2) & (y0 <= h - 2)
    return value, taps, inside


def main():
    g = json.load(open(sys.argv[1]))
    deg, seconds, fps = (float(v) for v in sys.argv[2:5])
    pattern, positions, n = sys.argv[5], sys.argv[6], int(sys.argv[7])
    node = next(c for c in g["nodes"] if "camera" in c)
    eye = np.array(node.get("translation", [0, 0, 0]), dtype=float)
    q0 = node.get("rotation", [0, 0, 0, 1])
    fov_y = math.degrees(g["cameras"][node["camera"]]["perspective"]["yfov"])
    changes, kept = [], []
    for k in range(1, n):
        now, before = read_pfm(pattern % k), read_pfm(pattern % (k - 1))
        p_now, p_before = read_pfm(positions % k), read_pfm(positions % (k - 1))
        h, w = now.shape[:2]
        angle = lambda f: -deg + 2 * deg * (f / fps) / seconds
        dirs = pixel_rays(yaw(angle(k), q0), fov_y, w, h)
        px, py, z = project(dirs, yaw(angle(k - 1), q0), fov_y, w, h)
        value, _, inside = bilinear(before, px, py)
        _, taps, _ = bilinear(p_before, px, py)
        dist = np.linalg.norm(p_now - eye, axis=-1)
        same = np.ones_like(inside)
        for t in taps:
            same &= np.linalg.norm(t - p_now, axis=-1) <= 0.03 * dist
        valid = inside & same & (z > 0) & np.all(np.isfinite(p_now), axis=-1)
        changes.append(np.mean(np.abs(now[valid] - value[valid])) / np.mean(now))
        kept.append(valid.mean())
    print(f"{np.mean(changes):.5f} {np.max(changes):.5f} {np.mean(kept):.3f}")


if __name__ == "__main__":
    main()

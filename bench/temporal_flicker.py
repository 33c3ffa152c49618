#!/usr/bin/env python3
"""Flicker where nothing moved: two consecutive frames of a method, and
the ray-cast frames that say which pixels the moving object touches
(directly or by its shadow: any pixel that differs, grown by `grow`
pixels). Prints the RMS change of the other pixels between the frames
over the first frame's mean, and their count.

usage: temporal_flicker.py A.pfm B.pfm RAYCAST_A.pfm RAYCAST_B.pfm GROW"""
import sys

import numpy as np

from pfm import read_pfm


def main():
    a, b, ra, rb = (read_pfm(p) for p in sys.argv[1:5])
    grow = int(sys.argv[5])
    touched = np.any(ra != rb, axis=-1)
    for _ in range(grow):  # grown by one pixel a step, 4-connected
        t = touched.copy()
        t[1:, :] |= touched[:-1, :]
        t[:-1, :] |= touched[1:, :]
        t[:, 1:] |= touched[:, :-1]
        t[:, :-1] |= touched[:, 1:]
        touched = t
    rest = ~touched
    change = np.sqrt(np.mean((b[rest] - a[rest]) ** 2)) / np.mean(a)
    print(f"{change:.5f} {int(rest.sum())}")


if __name__ == "__main__":
    main()

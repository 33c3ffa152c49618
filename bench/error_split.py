#!/usr/bin/env python3
"""Where cone tracing's error lies in one image: its direct term (the `direct`
AOV) against the path tracer's direct light (its `direct` AOV at
`--max-depth 1`), the rest (its
indirect light) against the reference less that, each as its own NRMSE over
the reference's mean, and the surfaces (by the `normal` AOV's dominant axis)
whose indirect light holds the largest share of that term's squared error.
Where the camera sees glass or a mirror (the `specular` AOV not zero), cone
tracing's direct term is the light of the surface seen through them, which
the path tracer finds on longer paths: the image is not split. Prints one
Markdown row for bench/error_split.sh.

usage: error_split.py NAME CT.pfm DIRECT_REFERENCE.pfm REFERENCE.pfm
(CT_direct.pfm, CT_specular.pfm and CT_normal.pfm beside CT.pfm, as
`vct render --aov` writes them)"""
import sys

import numpy as np

from pfm import read_pfm

AXES = ("+x", "-x", "+y", "-y", "+z", "-z", "other")


def orientation(normal):
    """Per pixel, the index into AXES of the normal's dominant axis (within
    26 degrees of it), 6 elsewhere (curved, oblique or no surface)."""
    axis = np.argmax(np.abs(normal), axis=2)
    value = np.take_along_axis(normal, axis[..., None], axis=2)[..., 0]
    return np.where(np.abs(value) >= 0.9, 2 * axis + (value < 0), 6)


def nrmse(image, reference, mean):
    return np.sqrt(((image - reference) ** 2).mean()) / mean


def main():
    name, ct_path, direct_path, ref_path = sys.argv[1:5]
    stem = ct_path[:-len(".pfm")]
    ct, ref = read_pfm(ct_path), read_pfm(ref_path)
    mean = ref.mean()
    row = f"| {name} | {nrmse(ct, ref, mean):.3f} |"
    if np.any(read_pfm(stem + "_specular.pfm") != 0.0):
        print(row + " glass or mirrors in view: not split | | | | | | |")
        return
    direct, ref_direct = read_pfm(stem + "_direct.pfm"), read_pfm(direct_path)
    rest, ref_rest = ct - direct, ref - ref_direct
    row += (f" {direct.mean() / ref_direct.mean():.3f} | {nrmse(direct, ref_direct, mean):.3f} |"
            f" {rest.mean() / ref_rest.mean():.3f} | {nrmse(rest, ref_rest, mean):.3f} |")
    error = ((rest - ref_rest) ** 2).sum(axis=2)
    classes = orientation(read_pfm(stem + "_normal.pfm"))
    worst = max(range(len(AXES)), key=lambda k: error[classes == k].sum())
    pixels = classes == worst
    row += (f" {AXES[worst]} ({100 * pixels.mean():.0f} % of pixels) |"
            f" {rest[pixels].mean() / ref_rest[pixels].mean():.3f} |"
            f" {error[pixels].sum() / error.sum():.2f} |")
    print(row)


if __name__ == "__main__":
    main()

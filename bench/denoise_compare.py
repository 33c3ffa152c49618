#!/usr/bin/env python3
"""One row of bench/denoise.sh: a path-traced EXR written by `vct render
--method pt --denoise --aov` (the denoised image, its `noisy` layer and the
guides), the same noisy image through Intel Open Image Denoise (PyPI's
pyoidn: the RT filter, HDR, with the albedo and normal guides as clean
auxiliaries), and each against a reference PFM. Prints: noisy NRMSE, ours,
OIDN's and OIDN's filter time in ms (the second of two calls: the first
builds the filter), or "-" for OIDN where pyoidn cannot be had.

usage: denoise_compare.py RENDER.exr REFERENCE.pfm"""
import sys
import time

import numpy as np
import OpenEXR

from pfm import read_pfm


def layer(channels, name, letters):
    prefix = f"{name}." if name else ""
    return np.stack([channels[prefix + c].pixels.astype(np.float32) for c in letters], axis=-1)


def nrmse(image, ref):
    return float(np.sqrt(np.mean((image - ref) ** 2)) / np.mean(ref))


def oidn_filter(exr):
    """The noisy layer of a `vct render --method pt --denoise --aov` EXR
    through OIDN's RT filter (HDR, its albedo and normal layers as clean
    auxiliaries): (image, the second call's time in ms), or None where
    pyoidn cannot be had."""
    try:
        import pyoidn
    except ImportError:
        return None
    ch = OpenEXR.File(exr, separate_channels=True).channels()
    noisy, albedo = layer(ch, "noisy", "RGB"), layer(ch, "albedo", "RGB")
    normal = layer(ch, "normal", "XYZ")
    lengths = np.linalg.norm(normal, axis=-1, keepdims=True)
    normal = np.where(lengths > 0, normal / np.maximum(lengths, 1e-12), 0.0).astype(np.float32)
    args = dict(hdr=True, clean_aux=True)
    pyoidn.denoise(noisy, albedo, normal, **args)  # the first call builds the filter
    start = time.perf_counter()
    out = pyoidn.denoise(noisy, albedo, normal, **args)
    return np.asarray(out, dtype=np.float64), (time.perf_counter() - start) * 1e3


def main():
    exr, reference = sys.argv[1:3]
    ch = OpenEXR.File(exr, separate_channels=True).channels()
    ref = read_pfm(reference)
    ours, noisy = layer(ch, "", "RGB"), layer(ch, "noisy", "RGB")
    oidn, oidn_ms = "-", "-"
    filtered = oidn_filter(exr)
    if filtered is not None:
        oidn, oidn_ms = f"{nrmse(filtered[0], ref):.4f}", f"{filtered[1]:.1f}"
    print(f"{nrmse(noisy, ref):.4f} {nrmse(ours, ref):.4f} {oidn} {oidn_ms}")

if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""EXR files written by vct, read back by OpenEXR's own Python bindings (not
our reader): the image and every AOV layer hold the same pixels as the PFM
files of the same render, bit for bit with --exr float and as the PFM values
rounded to half floats by numpy with --exr half; the channels are named as
compositors expect (R, G, B; direct.R, ...; normal.X, ...; ao.Y, ...). A
failed write leaves no file. `vct compare` reads EXR as it reads PFM.

usage: test_exr.py VCT_CLI SCENE OUT_DIR"""
import os
import subprocess
import sys

import numpy as np
import OpenEXR

LAYERS = {"direct": "RGB", "indirect": "RGB", "specular": "RGB", "ao": "Y",
          "position": "XYZ", "normal": "XYZ", "albedo": "RGB",
          "indirect_variance": "Y"}
failures = 0


def check(ok, what):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += 0 if ok else 1


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        assert scale < 0, "little-endian PFM"
        n = 3 if kind == b"PF" else 1
        data = np.frombuffer(f.read(), dtype="<f4").reshape(h, w, n)
    return data[::-1]  # PFM rows run bottom to top, EXR's top to bottom


def render(cli, scene, out, *extra):
    cmd = [cli, "render", scene, "--size", "40", "30", "--voxel-res", "32", "--aov", "-o", out]
    return subprocess.run(cmd + list(extra), capture_output=True, text=True)


def main():
    cli, scene, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    pfm, exr_half, exr_float = (os.path.join(out, n) for n in ("a.pfm", "half.exr", "float.exr"))
    for path, extra in ((pfm, ()), (exr_half, ()), (exr_float, ("--exr", "float"))):
        r = render(cli, scene, path, *extra)
        if r.returncode:
            print(r.stdout, r.stderr)
            return 1
    ref = {"": read_pfm(pfm)}
    for name in LAYERS:
        ref[name] = read_pfm(os.path.join(out, f"a_{name}.pfm"))
    for path, dtype in ((exr_half, np.float16), (exr_float, np.float32)):
        channels = OpenEXR.File(path, separate_channels=True).channels()
        expected = {"R", "G", "B"} | {f"{n}.{c}" for n, cs in LAYERS.items() for c in cs}
        check(set(channels) == expected, f"{os.path.basename(path)}: channels {sorted(channels)}")
        for layer, letters in [("", "RGB")] + list(LAYERS.items()):
            for k, c in enumerate(letters):
                name = f"{layer}.{c}" if layer else c
                if name not in channels:
                    continue
                got = channels[name].pixels
                want = ref[layer][:, :, k].astype(dtype)
                same = got.dtype == dtype and got.shape == want.shape and np.array_equal(
                    got.view(np.uint16 if dtype == np.float16 else np.uint32),
                    want.view(np.uint16 if dtype == np.float16 else np.uint32))
                if not same:
                    check(False, f"{os.path.basename(path)} {name}: differs from the PFM")
        check(failures == 0, f"{os.path.basename(path)}: every channel equals the PFM's "
              f"({'rounded to half' if dtype == np.float16 else 'bit for bit'})")
    # vct compare reads the EXR: a float EXR against its PFM is no error at all.
    r = subprocess.run([cli, "compare", exr_float, pfm], capture_output=True, text=True)
    check(r.returncode == 0 and "nrmse 0\n" in r.stdout, "vct compare float.exr a.pfm: nrmse 0")
    # A write that fails leaves nothing behind.
    bad = "/proc/vct_test.exr"
    r = render(cli, scene, bad)
    check(r.returncode != 0 and not os.path.exists(bad), "unwritable EXR: an error, no file")
    print(f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

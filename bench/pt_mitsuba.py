#!/usr/bin/env python3
"""Mitsuba 3's path tracer (its LLVM backend, PyPI's `mitsuba`) on a glTF scene
as tools/mitsuba_check.py converts it, timed on THREADS threads: the scene
loaded once, rendered once to compile its kernels, then N times; prints the
fastest render's seconds. The integrator matches vct's path tracer in depth
and in where Russian roulette starts.

usage: bench/pt_mitsuba.py SCENE.gltf SPP WIDTH HEIGHT MAX_DEPTH RR_DEPTH
           [--ambient R G B] [--repeat N] [--out IMAGE.pfm]"""
import argparse
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tools"))
import mitsuba_check  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("spp", type=int)
    ap.add_argument("width", type=int)
    ap.add_argument("height", type=int)
    ap.add_argument("max_depth", type=int)
    ap.add_argument("rr_depth", type=int)
    ap.add_argument("--ambient", type=float, nargs=3, default=None)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    import drjit as dr
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")
    dr.set_thread_count(int(os.environ.get("THREADS", "2")))
    with tempfile.TemporaryDirectory() as tmp:
        desc = mitsuba_check.convert(mi, a.scene, tmp, a.width, a.height, a.spp, a.ambient,
                                     a.max_depth)
        # vct counts surfaces, Mitsuba the camera's vertex too (as convert does for max_depth)
        desc["integrator"]["rr_depth"] = a.rr_depth + 1
        scene = mi.load_dict(desc)
        image = mi.render(scene, seed=0)  # compiles the kernels
        dr.eval(image)
        best = float("inf")
        for k in range(a.repeat):
            start = time.perf_counter()
            image = mi.render(scene, seed=k + 1)
            dr.eval(image)
            dr.sync_thread()
            best = min(best, time.perf_counter() - start)
        if a.out:
            import numpy as np
            mitsuba_check.write_pfm(a.out, np.array(image)[:, :, :3])
    print("%.4f" % best)


if __name__ == "__main__":
    main()

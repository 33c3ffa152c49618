#!/usr/bin/env python3
"""The path tracer against an independent one (Mitsuba 3, through
tools/mitsuba_check.py) on scenes of the suite that together hold every light
and material kind the converter maps: a point light, a sky through a window
with a sun (through a window, and through a roof slit onto thin slabs and
banners), double-sided emissive lamp shades, an emissive panel and two small
ones lighting a room alone, mirrors, glass, a glossy metal, base-colour
textures and an alpha-masked plant. Both render the same glTF file at 64x64 and 1024
spp; the NRMSE of 4x4-pixel block means and the ratio of the means must stay
within a bound above the noise left at that count (measured: block NRMSE at
most 0.039, in the lamp room, means within 0.7 %) and below what a wrong light
unit, a one-sided emitter or a texture upside down gives (a 5 % brighter point
light: means 1.03-1.05 off; one-sided emitters: 0.81-0.85; textures flipped
in v: 0.070 in the textured room).

usage: test_independent.py VCT_CLI SOURCE_DIR OUT_DIR"""
import os
import subprocess
import sys
import time

SIZE, SPP = 64, 1024
BLOCK, BLOCK_NRMSE, MEAN_OFF = 4, 0.055, 0.015
SCENES = [("cornell_box", "scenes/cornell_box.gltf", None),
          ("window_room", "scenes/suite/window_room.gltf", (0.35, 0.45, 0.6)),
          ("lamp_room", "scenes/suite/lamp_room.gltf", None),
          ("small_objects", "scenes/suite/small_objects.gltf", None),
          ("glass_mirror_box", "scenes/suite/glass_mirror_box.gltf", None),
          ("textured_room", "scenes/suite/textured_room.gltf", None),
          ("blinds_fins", "scenes/suite/blinds_fins.gltf", (0.35, 0.45, 0.6)),
          ("long_hall", "scenes/suite/long_hall.gltf", (0.35, 0.45, 0.6)),
          ("panel_room", "scenes/suite/panel_room.gltf", None)]


def main():
    cli, source, out = sys.argv[1:4]
    sys.path.insert(0, os.path.join(source, "tools"))
    try:
        import mitsuba  # noqa: F401
    except ImportError:
        print(f"test_independent: Mitsuba 3 is not installed for {sys.executable}: "
              "run tools/deps.sh")
        return 1
    import mitsuba_check as mc
    os.makedirs(out, exist_ok=True)
    if not all(os.path.exists(os.path.join(source, rel)) for _, rel, _ in SCENES):
        # the suite's files are generated, not kept (as bench/suite.sh does)
        subprocess.run([sys.executable, os.path.join(source, "scenes/suite/make_suite.py")],
                       check=True, stdout=subprocess.DEVNULL)
    failed = 0
    for name, rel, ambient in SCENES:
        scene = os.path.join(source, rel)
        ours = os.path.join(out, name + "_vct.pfm")
        cmd = [cli, "render", scene, "--method", "pt", "--spp", str(SPP), "--seed", "3",
               "--size", str(SIZE), str(SIZE), "-o", ours]
        if ambient:
            cmd += ["--ambient"] + [str(c) for c in ambient]
        t0 = time.time()
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if run.returncode != 0:
            sys.exit("test_independent: %s failed:\n%s" % (" ".join(cmd), run.stdout))
        t1 = time.time()
        theirs = mc.render_mitsuba(scene, os.path.join(out, name), SIZE, SIZE, SPP, ambient)
        t2 = time.time()
        mc.write_pfm(os.path.join(out, name + "_mitsuba.pfm"), theirs)
        blocks, ratio = mc.block_metrics(mc.read_pfm(ours), theirs, BLOCK)
        ok = blocks < BLOCK_NRMSE and abs(ratio - 1.0) < MEAN_OFF
        failed += not ok
        print("%s %s: %dx%d block NRMSE %.4f (bound %.3f), mean ratio %.4f (bound 1 +- %.3f); "
              "vct %.1f s, Mitsuba %.1f s" % ("ok  " if ok else "FAIL", name, BLOCK, BLOCK, blocks,
                                              BLOCK_NRMSE, ratio, MEAN_OFF, t1 - t0, t2 - t1))
    print("test_independent: %d of %d scenes failed" % (failed, len(SCENES)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Gathers bench/suite.sh's per-scene accuracy.csv files into one Markdown
table: scene x method x setting -> NRMSE, mean ratio, device time (and its
stages: the acceleration structure, the voxels and their light, the image), the
path tracer's time to reach each cone-traced or photon-mapped image's
error. With --summary, one row per method over the whole suite.

usage: suite_table.py OUT_DIR MANIFEST [--summary]"""
import csv
import math
import os
import sys


def pt_time_for(rows, error):
    """The path tracer's time to `error`, log-log between the sample counts
    around it; None when no run was that accurate."""
    prev = None
    for r in rows:
        if not r["setting"].startswith("path trace"):
            continue
        if float(r["nrmse"]) <= error:
            if prev is None:
                return float(r["total_ms"])
            e0, e1 = float(prev["nrmse"]), float(r["nrmse"])
            t0, t1 = float(prev["total_ms"]), float(r["total_ms"])
            f = math.log(e0 / error) / math.log(e0 / e1)
            return math.exp(math.log(t0) + f * math.log(t1 / t0))
        prev = r
    return None


VCT_DEFAULT = "vct 128^3, 9 cones, step 1, offset 4, iso, 4 bounces"
SUMMARY = [("ray cast (direct light only)", lambda s: s == "ray cast (direct only)"),
           ("cone tracing, default", lambda s: s == VCT_DEFAULT),
           ("path tracing, 16 spp", lambda s: s == "path trace 16 spp"),
           ("path tracing, 256 spp", lambda s: s == "path trace 256 spp"),
           ("photon mapping, 64 passes",
            lambda s: s == "photon mapping, progressive, 64 passes")]


def summary(root, names):
    """One row per method at its default over the whole suite: the mean and
    worst NRMSE and the median device time."""
    print("| method | mean NRMSE | worst NRMSE (scene) | median device ms |")
    print("|---|---:|---:|---:|")
    for label, match in SUMMARY:
        found = []
        for name in names:
            path = os.path.join(root, name, "accuracy.csv")
            if os.path.exists(path):
                found += [(float(r["nrmse"]), float(r["total_ms"]), name)
                          for r in csv.DictReader(open(path)) if match(r["setting"])]
        if not found:
            continue
        errors = [f[0] for f in found]
        times = sorted(f[1] for f in found)
        worst = max(found)
        print(f"| {label} | {sum(errors) / len(errors):.3f} | {worst[0]:.3f} ({worst[2]}) | "
              f"{times[len(times) // 2]:.0f} |")


def main():
    root, manifest = sys.argv[1], sys.argv[2]
    names = [line.split()[0] for line in open(manifest)
             if line.strip() and not line.startswith("#")]
    if len(sys.argv) > 3 and sys.argv[3] == "--summary":
        summary(root, names)
        return
    print("| scene | method and setting | NRMSE | mean / reference | device ms | "
          "accel / build / render ms | path tracer to this error |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for name in names:
        path = os.path.join(root, name, "accuracy.csv")
        if not os.path.exists(path):
            continue
        rows = list(csv.DictReader(open(path)))
        keep = [r for r in rows if r["setting"].startswith(("ray cast", "vct"))
                or r["setting"] in ("path trace 16 spp", "path trace 256 spp",
                                    "photon mapping, progressive, 16 passes",
                                    "photon mapping, progressive, 64 passes",
                                    "photon mapping, fixed radius, 16 passes",
                                    "photon mapping, final gathering, 16 passes")]
        for r in keep:
            to = ""
            if r["setting"].startswith(("vct", "photon")):
                t = pt_time_for(rows, float(r["nrmse"]))
                to = f"{t:.0f} ms" if t else "not reached by 1024 spp"
            stages = (f"{float(r['accel_ms']):.0f} / {float(r['build_ms']):.0f} / "
                      f"{float(r['render_ms']):.0f}")
            print(f"| {name} | {r['setting']} | {float(r['nrmse']):.3f} | "
                  f"{float(r['mean_ratio']):.3f} | {float(r['total_ms']):.0f} | {stages} | "
                  f"{to} |")


if __name__ == "__main__":
    main()

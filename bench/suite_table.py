#!/usr/bin/env python3
"""Gathers bench/suite.sh's per-scene accuracy.csv files into one Markdown
table: scene x method x setting -> NRMSE, mean ratio, device time (and its
stages: the acceleration structure, the voxels and their light, the image), the
path tracer's time to reach each cone-traced or photon-mapped image's
error."""
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


def main():
    root, manifest = sys.argv[1], sys.argv[2]
    names = [line.split()[0] for line in open(manifest)
             if line.strip() and not line.startswith("#")]
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

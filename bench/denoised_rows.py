#!/usr/bin/env python3
"""The denoised path tracer in a scene's accuracy table (bench/suite.sh):
renders the path tracer at 1, 4, 16, 64, 256 and 1024 spp with the engine's filter
(`vct render --method pt --denoise --aov`), passes the same noisy image
through Intel Open Image Denoise (denoise_compare.oidn_filter), and appends
both to OUT/accuracy.csv as "path trace N spp + denoiser" and "path trace N
spp + OIDN", each measured by `vct compare` against the reference. Their
time: the acceleration structure, the path tracer, the guides (both filters
use them) and the filter, device time for the engine's stages, the filter
call's time on the same CPU for OIDN. The Pareto column is recomputed over
every row and the plot (OUT/accuracy.gp) drawn again. Without pyoidn, the
OIDN rows are left out with a message.

With --repeat N, every row is rendered and filtered N times, the rows in
turn, and each stage keeps its fastest time (bench/accuracy's --repeat).

usage: denoised_rows.py [--repeat N] VCT SCENE REFERENCE.pfm OUT SIZE [RENDER OPTIONS...]"""
import csv
import os
import subprocess
import sys

from denoise_compare import oidn_filter
from pfm import write_pfm

SPPS = (1, 4, 16, 64, 256, 1024)


def stage_ms(stats, stage):
    """A stage's device ms from `vct render --stats`' table (0 if absent)."""
    for line in stats.splitlines():
        if line.startswith(stage + "  "):
            return float(line[len(stage):].split()[0])
    return 0.0


def compare(vct, image, reference):
    out = subprocess.run([vct, "compare", image, reference], check=True, capture_output=True,
                         text=True).stdout
    return dict(line.split() for line in out.splitlines() if len(line.split()) == 2)


def row(setting, accel, render, metrics):
    return {"setting": setting, "accel_ms": f"{accel:.3f}", "build_ms": "0.000",
            "render_ms": f"{render:.3f}", "total_ms": f"{accel + render:.3f}",
            "wall_ms": f"{accel + render:.3f}", "nrmse": metrics["nrmse"],
            "rmse": metrics["rmse"], "relative_rmse": metrics["relative_rmse"],
            "relative_mse": metrics["relative_mse"], "mae": metrics["mae"],
            "psnr_db": metrics["psnr_db"], "pareto": "0", "mean_ratio": metrics["mean_ratio"]}


def mark_pareto(rows):
    """A row is on the front when no other is at least as fast and as
    accurate, and better in one (bench/accuracy.c's rule)."""
    for r in rows:
        t, e = float(r["total_ms"]), float(r["nrmse"])
        r["pareto"] = "0" if any(
            float(o["total_ms"]) <= t and float(o["nrmse"]) <= e and
            (float(o["total_ms"]) < t or float(o["nrmse"]) < e) for o in rows if o is not r) else "1"


def main():
    args = sys.argv[1:]
    repeat = 1
    if args[:1] == ["--repeat"]:
        repeat, args = max(int(args[1]), 1), args[2:]
    vct, scene, reference, out, size = args[:5]
    extra = args[5:]
    have_oidn = True
    times = {spp: {} for spp in SPPS}  # each stage's fastest ms, OIDN's filter call's too
    filtered = {}
    # the sample counts in turn, `repeat` times over, so that a slow spell of
    # a shared CPU falls on one of each row's runs; the same images each time
    for _ in range(repeat):
        for spp in SPPS:
            exr = os.path.join(out, f"pt_denoised_{spp}.exr")
            stats = subprocess.run(
                [vct, "render", scene, "--method", "pt", "--spp", str(spp), "--seed", "1",
                 "--size", size, size, "--denoise", "--aov", "--exr", "float", "--stats", "-o",
                 exr] + extra, check=True, capture_output=True, text=True)
            text = stats.stdout + stats.stderr
            for stage in ("bvh build", "path trace", "guides", "denoise"):
                times[spp][stage] = min(times[spp].get(stage, float("inf")),
                                        stage_ms(text, stage))
            result = oidn_filter(exr) if have_oidn else None
            if result is None:
                have_oidn = False
                continue
            filtered[spp] = result[0]
            times[spp]["oidn"] = min(times[spp].get("oidn", float("inf")), result[1])
    added = []
    for spp in SPPS:
        t = times[spp]
        accel, traced = t["bvh build"], t["path trace"] + t["guides"]
        exr = os.path.join(out, f"pt_denoised_{spp}.exr")
        added.append(row(f"path trace {spp} spp + denoiser", accel, traced + t["denoise"],
                         compare(vct, exr, reference)))
        if have_oidn:
            pfm = os.path.join(out, f"pt_oidn_{spp}.pfm")
            write_pfm(pfm, filtered[spp])
            added.append(row(f"path trace {spp} spp + OIDN", accel, traced + t["oidn"],
                             compare(vct, pfm, reference)))
    if not have_oidn:
        print("denoised_rows: pyoidn cannot be had: no OIDN rows", file=sys.stderr)
    path = os.path.join(out, "accuracy.csv")
    with open(path) as f:
        reader = csv.DictReader(f)
        fields = reader.fieldnames
        rows = [r for r in reader if "+ denoiser" not in r["setting"]
                and "+ OIDN" not in r["setting"]]
    rows += added
    mark_pareto(rows)
    with open(path, "w") as f:  # as bench/accuracy writes it: the setting quoted
        f.write(",".join(fields) + "\n")
        for r in rows:
            f.write(",".join(f'"{r[k]}"' if k == "setting" else r[k] for k in fields) + "\n")
    plot = os.path.join(out, "accuracy.gp")
    if os.path.exists(plot):
        subprocess.run(["gnuplot", plot], check=False, capture_output=True)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The error-time front of every suite scene in one figure (gnuplot): per
scene, NRMSE against device time on log-log axes for the path tracer (1 to
1024 spp), the path tracer denoised by the engine's filter and by OIDN (1 to
64 spp, bench/denoised_rows.py), cone tracing at its default and photon
mapping (progressive, 16 and 64 passes). bench/suite.sh writes it beside
doc/results/suite.md.

usage: suite_plot.py OUT_DIR MANIFEST PNG TITLE"""
import csv
import os
import subprocess
import sys

from suite_table import VCT_DEFAULT, path_trace_kind

SERIES = [  # title, which rows, gnuplot style
    ("path tracer", lambda s: path_trace_kind(s) == "",
     "with linespoints lw 2 pt 7 ps 0.6 lc rgb '#555555'"),
    ("+ engine's denoiser", lambda s: path_trace_kind(s) == "denoiser",
     "with linespoints lw 2 pt 5 ps 0.6 lc rgb '#1f77b4'"),
    ("+ OIDN", lambda s: path_trace_kind(s) == "OIDN",
     "with linespoints lw 2 pt 9 ps 0.7 lc rgb '#ff7f0e'"),
    ("cone tracing", lambda s: s == VCT_DEFAULT, "with points pt 13 ps 1.6 lc rgb '#d62728'"),
    ("photon mapping", lambda s: s in ("photon mapping, progressive, 16 passes",
                                       "photon mapping, progressive, 64 passes"),
     "with linespoints lw 1 pt 11 ps 1.0 lc rgb '#2ca02c'"),
]


def main():
    root, manifest, png, title = sys.argv[1:5]
    names = [line.split()[0] for line in open(manifest)
             if line.strip() and not line.startswith("#")]
    names = [n for n in names if os.path.exists(os.path.join(root, n, "accuracy.csv"))]
    data = os.path.join(root, "front.dat")
    with open(data, "w") as f:  # one gnuplot index per scene and series
        for name in names:
            rows = list(csv.DictReader(open(os.path.join(root, name, "accuracy.csv"))))
            for _, match, _ in SERIES:
                picked = [r for r in rows if match(r["setting"])]
                for r in picked:
                    f.write(f"{float(r['total_ms']):.3f} {float(r['nrmse']):.5f}\n")
                if not picked:
                    f.write("nan nan\n")
                f.write("\n\n")
    cols = 4
    lines = [f"set terminal pngcairo size 1500,{330 * ((len(names) + cols - 1) // cols) + 60} "
             "font ',10'",
             f"set output '{png}'", "set logscale xy", "set grid",
             "set format y '%g'", "set xlabel 'device ms'", "set ylabel 'NRMSE'",
             f"set multiplot layout {(len(names) + cols - 1) // cols},{cols} "
             f"title \"{title}\" font ',11' noenhanced"]
    for i, name in enumerate(names):
        lines.append(f"set title '{name}' noenhanced")
        lines.append("set key " + ("top right font ',8'" if i == 0 else "off"))
        plots = [f"'{data}' index {i * len(SERIES) + k} using 1:2 {style} "
                 f"title \"{label}\" noenhanced"""
                 for k, (label, _, style) in enumerate(SERIES)]
        lines.append("plot " + ", ".join(plots))
    lines.append("unset multiplot")
    script = os.path.join(root, "front.gp")
    with open(script, "w") as f:
        f.write("\n".join(lines) + "\n")
    done = subprocess.run(["gnuplot", script], capture_output=True, text=True)
    if done.returncode:
        sys.exit(f"suite_plot: gnuplot failed: {done.stderr.strip() or 'is it installed?'}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Gathers bench/suite.sh's per-scene accuracy.csv files into one Markdown
table: scene x method x setting -> NRMSE, mean ratio, device time (and its
stages: the acceleration structure, the voxels and their light, the image), the
path tracer's time to reach each cone-traced or photon-mapped image's
error, as it is and denoised (by the engine's filter and by OIDN). With
--summary, one row per method over the whole suite, how many scenes
cone tracing reaches its error on in less time than the denoised path
tracer, and on how many its frame alone takes a tenth of that time.

usage: suite_table.py OUT_DIR MANIFEST [--summary]"""
import csv
import math
import os
import sys


def path_trace_kind(setting):
    """"": the path tracer as it is; "denoiser" or "OIDN": denoised by it;
    None: another method."""
    if not setting.startswith("path trace"):
        return None
    return setting.split("+ ")[1] if "+ " in setting else ""


def pt_time_for(rows, error, kind=""):
    """The path tracer's time to `error` (denoised by `kind`, as
    path_trace_kind names it), log-log between the sample counts around it;
    None when no run was that accurate."""
    prev = None
    for r in rows:
        if path_trace_kind(r["setting"]) != kind:
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
           ("path tracing, 4 spp + the engine's denoiser",
            lambda s: s == "path trace 4 spp + denoiser"),
           ("path tracing, 4 spp + OIDN", lambda s: s == "path trace 4 spp + OIDN"),
           ("path tracing, 16 spp + the engine's denoiser",
            lambda s: s == "path trace 16 spp + denoiser"),
           ("path tracing, 16 spp + OIDN", lambda s: s == "path trace 16 spp + OIDN"),
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
    front(root, names)


def front(root, names):
    """Where cone tracing at its default stands against the denoised path
    tracer: the scenes where it reaches its error in less time than the
    path tracer denoised by OIDN (and by the engine's filter) needs."""
    counts = {"OIDN": [0, 0, 0], "denoiser": [0, 0, 0]}
    # the frame alone (render ms, the voxels kept) against a tenth of that
    # time: scenes within it, scenes counted, the closest (ratio, scene), and
    # the scenes left undecided
    frames = {"OIDN": [0, 0, None, []], "denoiser": [0, 0, None, []]}
    for name in names:
        path = os.path.join(root, name, "accuracy.csv")
        if not os.path.exists(path):
            continue
        rows = list(csv.DictReader(open(path)))
        for r in rows:
            if r["setting"] != VCT_DEFAULT:
                continue
            for kind, count in counts.items():
                t = pt_time_for(rows, float(r["nrmse"]), kind)
                if t is None and not any(path_trace_kind(o["setting"]) == kind for o in rows):
                    continue  # no such rows (no pyoidn)
                count[1] += 1
                frame = frames[kind]
                if t is None:
                    # not reached: cone tracing is faster only if it beat the
                    # longest denoised run, which still fell short of its error
                    longest = max(float(o["total_ms"]) for o in rows
                                  if path_trace_kind(o["setting"]) == kind)
                    won = float(r["total_ms"]) < longest
                    count[0] += won
                    count[2] += not won
                    if longest < 10.0 * float(r["render_ms"]):
                        # the time it needs is longer than its longest run
                        # by an unknown amount: undecided
                        frame[3].append(name)
                        continue
                    t = longest
                else:
                    count[0] += float(r["total_ms"]) < t
                ratio = t / float(r["render_ms"])
                frame[0] += ratio >= 10.0
                frame[1] += 1
                if frame[2] is None or ratio < frame[2][0]:
                    frame[2] = (ratio, name)
    for kind, label in (("OIDN", "OIDN"), ("denoiser", "the engine's denoiser")):
        won, of, open_ = counts[kind]
        if of:
            print(f"\nCone tracing at its default reaches its error in less time than the path "
                  f"tracer denoised by {label} on {won} of {of} scenes" +
                  (f"; on {open_} more the denoised path tracer's most samples fell short of "
                   f"its error in less time than cone tracing took, which leaves it undecided."
                   if open_ else "."))
        won, of, closest, undecided = frames[kind]
        if of:
            print(f"\nIts frame alone (the render column: the voxels kept, as a camera move "
                  f"costs) takes at most a tenth of the time the path tracer denoised by {label} "
                  f"needs for the same error on {won} of {of} scenes (the least margin: "
                  f"{closest[1]}, 1/{closest[0]:.1f}; where the denoised path tracer does not "
                  f"reach the error, against its longest run)" +
                  (f"; undecided on {', '.join(undecided)}, where the longest run, short of the "
                   f"error, took less than ten frames." if undecided else "."))


def main():
    root, manifest = sys.argv[1], sys.argv[2]
    names = [line.split()[0] for line in open(manifest)
             if line.strip() and not line.startswith("#")]
    if len(sys.argv) > 3 and sys.argv[3] == "--summary":
        summary(root, names)
        return
    print("| scene | method and setting | NRMSE | mean / reference | device ms | "
          "accel / build / render ms | path tracer to this error | denoised | with OIDN |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for name in names:
        path = os.path.join(root, name, "accuracy.csv")
        if not os.path.exists(path):
            continue
        rows = list(csv.DictReader(open(path)))
        keep = [r for r in rows if r["setting"].startswith(("ray cast", "vct"))
                or r["setting"] in ("path trace 16 spp", "path trace 256 spp",
                                    "path trace 4 spp + denoiser", "path trace 4 spp + OIDN",
                                    "path trace 16 spp + denoiser", "path trace 16 spp + OIDN",
                                    "photon mapping, progressive, 16 passes",
                                    "photon mapping, progressive, 64 passes",
                                    "photon mapping, fixed radius, 16 passes",
                                    "photon mapping, final gathering, 16 passes")]
        for r in keep:
            to = ["", "", ""]
            if r["setting"].startswith(("vct", "photon")):
                for i, kind in enumerate(("", "denoiser", "OIDN")):
                    runs = [o for o in rows if path_trace_kind(o["setting"]) == kind]
                    if not runs:
                        continue
                    most = max(int(o["setting"].split()[2]) for o in runs)
                    t = pt_time_for(rows, float(r["nrmse"]), kind)
                    to[i] = f"{t:.0f} ms" if t else f"not reached by {most} spp"
            stages = (f"{float(r['accel_ms']):.0f} / {float(r['build_ms']):.0f} / "
                      f"{float(r['render_ms']):.0f}")
            print(f"| {name} | {r['setting']} | {float(r['nrmse']):.3f} | "
                  f"{float(r['mean_ratio']):.3f} | {float(r['total_ms']):.0f} | {stages} | "
                  f"{' | '.join(to)} |")


if __name__ == "__main__":
    main()

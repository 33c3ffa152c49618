#!/usr/bin/env python3
"""Checks that calls and includes flow one way through the pipeline's stages.

Usage: check_layers.py SOURCE_DIR BUILD_DIR

- host/src/<stage>/*.o may call only into its own stage or the stages
  below it in STAGES (read from the object files' symbols with nm);
- no two files call each other, directly or through others (no cycles in
  the call graph between files);
- no two headers include each other, in host/ or kernels/;
- kernels/<stage>/ includes only its own stage, the stages below, and the
  shared vct_types.h.
Exits non-zero and names each violation."""
import os
import re
import subprocess
import sys

STAGES = ["runtime", "program", "parallel", "scene", "load", "accel", "light", "voxel", "frame", "photon", "raytrace",
          "pathtrace", "conetrace", "render", "image", "denoise", "device_scene", "multi"]
# program/ builds, caches and launches kernel programs over runtime/'s
# context, buffers and statistics; load/ reads scene files into the host scene (scene/ is the scene itself
# and its device-side data); frame/ is what every method shares (the frame, the plan, the shaded first
# hit, progress); photon/ holds photon mapping and the photons cone tracing
# gathers for caustics; raytrace/, pathtrace/ and conetrace/ are the other
# methods; render/ is the one entry to all of them.
# image/ (files and metrics of host images) is used by the renderers but
# uses only the runtime, and denoise/ (a filter over images and their
# guides) only the runtime and images: they sit beside the pipeline, not
# above render.
BELOW = {s: set(STAGES[: i + 1]) for i, s in enumerate(STAGES)}
BELOW["image"] = {"runtime", "program", "image"}
BELOW["denoise"] = {"runtime", "program", "image", "denoise"}
for stage in ["frame", "photon", "raytrace", "pathtrace", "conetrace", "render"]:
    BELOW[stage] |= {"image", "denoise"}


def objects(src, build):
    """The library's object files whose sources still exist (a stale build
    keeps objects of removed files)."""
    root = os.path.join(build, "CMakeFiles", "vct-objects.dir", "host", "src")
    for stage in STAGES:
        d = os.path.join(root, stage)
        if os.path.isdir(d):
            for f in sorted(os.listdir(d)):
                if f.endswith(".c.o") and os.path.exists(
                        os.path.join(src, "host", "src", stage, f[:-2])):
                    yield stage, f[:-4], os.path.join(d, f)


def nm(path, flags):
    out = subprocess.run(["nm"] + flags + [path], capture_output=True, text=True, check=True)
    return out.stdout.splitlines()


def call_graph(src, build):
    defined, used = {}, {}
    for stage, name, path in objects(src, build):
        key = f"{stage}/{name}"
        for line in nm(path, ["--defined-only", "-g"]):
            parts = line.split()
            if len(parts) == 3 and parts[1] in "TDBRC":
                defined[parts[2]] = key
        used[key] = {l.split()[-1] for l in nm(path, ["-u"])}
    edges = {k: {defined[s] for s in syms if s in defined and defined[s] != k}
             for k, syms in used.items()}
    return edges


def find_cycles(edges):
    cycles, state, stack = [], {}, []

    def visit(n):
        state[n] = 1
        stack.append(n)
        for m in sorted(edges.get(n, ())):
            if state.get(m) == 1:
                cycles.append(stack[stack.index(m):] + [m])
            elif m not in state:
                visit(m)
        stack.pop()
        state[n] = 2

    for n in sorted(edges):
        if n not in state:
            visit(n)
    return cycles


def includes(path):
    with open(path, encoding="utf-8") as f:
        return re.findall(r'^\s*#\s*include\s+"([^"]+)"', f.read(), re.M)


def main():
    src, build = sys.argv[1], sys.argv[2]
    problems = []
    edges = call_graph(src, build)
    if not edges:
        problems.append(f"no object files under {build}: build the library first")
    for a, targets in sorted(edges.items()):
        for b in sorted(targets):
            sa, sb = a.split("/")[0], b.split("/")[0]
            if sb not in BELOW[sa]:
                problems.append(f"{a} calls up into {b} ({sa} may use {sorted(BELOW[sa])})")
    for c in find_cycles(edges):
        problems.append("call cycle: " + " -> ".join(c))

    files = {}
    for tree in ("host", "kernels"):
        for d, _, names in os.walk(os.path.join(src, tree)):
            for f in names:
                if f.endswith((".h", ".c", ".cl")):
                    p = os.path.join(d, f)
                    files[os.path.relpath(p, src)] = includes(p)
    roots = ["host/src", "host/include", "host/app", "kernels"]
    graph = {}
    for p, incs in files.items():
        graph[p] = set()
        for i in incs:
            for base in [os.path.dirname(p)] + roots:
                q = os.path.normpath(os.path.join(base, i))
                if q in files:
                    graph[p].add(q)
                    break
    for c in find_cycles(graph):
        problems.append("include cycle: " + " -> ".join(c))
    for p, incs in files.items():
        parts = p.split(os.sep)
        if parts[0] != "kernels" or len(parts) < 3:
            continue
        stage = parts[1]
        allowed = BELOW.get(stage, {stage}) | {stage}
        for i in incs:
            top = i.split("/")[0]
            if i != "vct_types.h" and ("/" not in i or top not in allowed):
                problems.append(f"{p} includes {i}: a {stage} kernel may include "
                                f"vct_types.h and {sorted(allowed)}")
    for p in problems:
        print("layers:", p)
    print(f"layers: {len(edges)} host files, {'ok' if not problems else f'{len(problems)} problems'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

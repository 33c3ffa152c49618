#!/usr/bin/python3
"""Times OpenVDB's mesh-to-volume on a mesh written by bench_voxelize.

Input: a raw file of uint32 vertex count, uint32 triangle count, float32
positions, uint32 triangle indices. Builds a narrow-band level set of half
width 1 voxel (the closest OpenVDB comes to a surface voxelization) at the
given voxel size and prints the best wall time of `runs` and the active
voxel count.
"""
import sys
import time

import numpy as np
import pyopenvdb as vdb


def main():
    path, voxel_size, runs = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
    with open(path, "rb") as f:
        nv, nt = np.frombuffer(f.read(8), dtype=np.uint32)
        points = np.frombuffer(f.read(12 * int(nv)), dtype=np.float32).reshape(-1, 3)
        tris = np.frombuffer(f.read(12 * int(nt)), dtype=np.uint32).reshape(-1, 3)
    points = points.astype(np.float64)
    tris = tris.astype(np.int32)
    transform = vdb.createLinearTransform(voxelSize=voxel_size)
    best = float("inf")
    active = 0
    for _ in range(runs):
        start = time.perf_counter()
        grid = vdb.FloatGrid.createLevelSetFromPolygons(
            points, triangles=tris, transform=transform, halfWidth=1.0)
        best = min(best, time.perf_counter() - start)
        active = grid.activeVoxelCount()
    print(f"seconds {best:.6f} active_voxels {active}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A host that is not ours: PyOpenCL builds the kernel sources straight from
kernels/ with nothing but -I <kernels> (and documented -D options), runs the
scan, the voxelization and a cone trace on its own buffers, and compares the
results with the C library's on the same input (written by foreign_ref).

Usage: foreign_host.py KERNEL_DIR FOREIGN_REF SCENE
Fails, naming the interpreter, when PyOpenCL is missing (tools/deps.sh installs it)."""
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
    import pyopencl as cl
except ImportError as e:  # pragma: no cover - depends on the machine
    print(f"foreign_host: {e} for {sys.executable}: run tools/deps.sh")
    sys.exit(1)

KERNELS, REF, SCENE = sys.argv[1], sys.argv[2], sys.argv[3]
failures = 0
checks = 0


def check(ok, what):
    global failures, checks
    checks += 1
    if not ok:
        failures += 1
        print(f"FAIL {what}")
    else:
        print(f"ok   {what}")


def pick_device():
    want = os.environ.get("VCT_DEVICE", "")
    for p in cl.get_platforms():
        for d in p.get_devices():
            if not want or want.lower() in (d.name + " " + p.name).lower():
                return d
    raise SystemExit("foreign_host: no OpenCL device matches VCT_DEVICE=" + want)


device = pick_device()
ctx = cl.Context([device])
queue = cl.CommandQueue(ctx)
mf = cl.mem_flags
print(f"foreign_host: PyOpenCL {cl.VERSION_TEXT} on {device.name}")


def build(name, options=()):
    with open(os.path.join(KERNELS, name), encoding="utf-8") as f:
        source = f.read()
    return cl.Program(ctx, source).build(options=["-I", KERNELS, *options])


def buf(array, write=False):
    flags = (mf.READ_WRITE if write else mf.READ_ONLY) | mf.COPY_HOST_PTR
    return cl.Buffer(ctx, flags, hostbuf=np.ascontiguousarray(array))


def empty(nbytes):
    return cl.Buffer(ctx, mf.READ_WRITE, max(int(nbytes), 4))


def read(b, dtype, count):
    out = np.empty(count, dtype=dtype)
    if count:
        cl.enqueue_copy(queue, out, b)
    return out


# Every kernel file builds as it stands, with its documented -D options.
VARIANTS = {
    "render/vct_render.cl": [(), ("-DVCT_DIRECT", "-DVCT_SHADOWS", "-DVCT_INDIRECT",
                                  "-DVCT_SPECULAR", "-DVCT_AO", "-DVCT_EMISSION",
                                  "-DVCT_SOFT_SHADOWS", "-DVCT_REFRACTION", "-DVCT_ANISOTROPIC",
                                  "-DVCT_CONE_NEAREST_LEVEL", "-DVCT_CAUSTICS"),
                             ("-DVCT_AO", "-DVCT_SPARSE_DIFFUSE", "-DVCT_CONE_PROBE")],
    "voxel/bricks.cl": [(), ("-DVCT_ANISOTROPIC",)],
    "render/raycast.cl": [(), ("-DVCT_ACCEL_BVH",), ("-DVCT_ACCEL_BVH2",)],
    "render/pathtrace.cl": [(), ("-DVCT_ACCEL_BVH2",)],
    "parallel/radix_sort.cl": [(), ("-D", "KEY_T=ulong", "-D", "RADIX_BITS=4", "-D", "WG=64")],
    "parallel/scan.cl": [(), ("-D", "WG=1", "-D", "ITEM_SPAN=1024")],
}
for root, _, files in os.walk(KERNELS):
    for f in sorted(files):
        if f.endswith(".cl"):
            rel = os.path.relpath(os.path.join(root, f), KERNELS)
            for opts in VARIANTS.get(rel, [()]):
                try:
                    build(rel, opts)
                    ok = True
                except cl.RuntimeError as e:
                    print(e)
                    ok = False
                check(ok, f"{rel} builds with -I <kernels> {' '.join(opts)}".rstrip())

work = tempfile.mkdtemp(prefix="vct-foreign-")
subprocess.run([REF, SCENE, work], check=True)


def load(name, dtype):
    return np.fromfile(os.path.join(work, name), dtype=dtype)


# ---- scan: reduce, group offsets, downsweep, as kernels/README.md says.
WG, SPAN_ITEMS = 1, 1024
scan = build("parallel/scan.cl", ["-D", f"WG={WG}", "-D", f"ITEM_SPAN={SPAN_ITEMS}"])


def exclusive_scan(values_buf, n, out_buf, groups_wanted=8):
    tile = WG * SPAN_ITEMS
    span = max(tile, -(-(-(-n // groups_wanted)) // tile) * tile)
    groups = max(1, -(-n // span))
    sums = empty(8 * (groups + 1))
    scan.scan_reduce(queue, (groups * WG,), (WG,), values_buf, np.uint32(n), np.uint32(span),
                     np.uint32(0), sums)
    scan.scan_group_offsets(queue, (1,), (1,), sums, np.uint32(groups))
    scan.scan_downsweep(queue, (groups * WG,), (WG,), values_buf, out_buf, np.uint32(n),
                        np.uint32(span), np.uint32(0), np.uint32(0), sums)
    return int(read(sums, np.uint64, groups + 1)[groups])


scan_in = load("scan_in.u32", np.uint32)
out = empty(4 * scan_in.size)
total = exclusive_scan(buf(scan_in), scan_in.size, out, groups_wanted=13)
mine = read(out, np.uint32, scan_in.size)
check(np.array_equal(mine, load("scan_out.u32", np.uint32)),
      f"scan of {scan_in.size} values equals the library's, bit for bit")
check(total == int(scan_in.astype(np.uint64).sum()), "scan total")

# ---- voxelization: quantise, chunks, count, write, sort, reduce.
positions = load("positions.f32", np.float32).reshape(-1, 3)
triangles = load("triangles.u32", np.uint32).reshape(-1, 3)
tri_material = load("triangle_material.u32", np.uint32)
materials = load("materials.desc", np.float32)
vol = load("volume.desc", np.uint8)
origin = np.frombuffer(vol[:16].tobytes(), np.float32)
res = np.frombuffer(vol[16:32].tobytes(), np.uint32)
# The volume's origin and side in double, as the library keeps them, are the
# float values widened: vct_voxel_info holds the doubles; the float desc is
# what kernels read. Quantisation needs the doubles: foreign_ref's scene is
# framed by the library, so recompute its frame the documented way.
lo = positions.min(axis=0).astype(np.float64)
hi = positions.max(axis=0).astype(np.float64)
R = int(res[0])
ext = float((hi - lo).max())
side = ext * (R + 2.0) / R
cube_origin = 0.5 * (lo + hi) - 0.5 * side
check(np.allclose(cube_origin.astype(np.float32), origin[:3]) and
      np.float32(side) == origin[3], "the volume frame follows the documented rule")
UNITS = 1 << 18
q = np.rint((positions[triangles].astype(np.float64) - cube_origin) * (UNITS / side))
tris = np.zeros((triangles.shape[0], 3, 4), np.int32)
tris[:, :, :3] = q.astype(np.int32)
tris[:, 0, 3] = tri_material.astype(np.int32)
n_tris = triangles.shape[0]
vox = build("voxel/voxelize.cl")
tris_buf = buf(tris)
vol_desc = np.frombuffer(vol.tobytes(), np.uint8)
chunk_start = empty(4 * n_tris)
tri_normals = empty(16 * n_tris)
vox.vox_chunks(queue, (n_tris,), None, tris_buf, vol_desc, np.uint32(0), chunk_start, tri_normals)
chunks = exclusive_scan(chunk_start, n_tris, chunk_start)
counts = empty(4 * chunks)
thin = np.int32(0)
vox.vox_count(queue, (chunks,), None, tris_buf, vol_desc, np.uint32(0), thin, chunk_start, np.uint32(chunks),
              counts)
fragments = exclusive_scan(counts, chunks, counts)
keys = empty(4 * fragments)
ids = empty(4 * fragments)
vox.vox_write(queue, (chunks,), None, tris_buf, vol_desc, np.uint32(0), thin, chunk_start, np.uint32(chunks),
              counts, keys, ids)
frag_keys = read(keys, np.uint32, fragments)
frag_ids = read(ids, np.uint32, fragments)
order = np.argsort(frag_keys, kind="stable")  # the library's radix sort is stable too
frag_keys, frag_ids = frag_keys[order], frag_ids[order]
voxel_keys, voxel_start = np.unique(frag_keys, return_index=True)
lib_fragments, lib_voxels = load("voxel_counts.u32", np.uint32)
check(fragments == lib_fragments, f"{fragments} fragments, the library made {lib_fragments}")
check(np.array_equal(voxel_keys, load("voxel_keys.u32", np.uint32)),
      f"{voxel_keys.size} voxel keys equal the library's")
nv = voxel_keys.size
albedo, normal, emission = empty(16 * nv), empty(16 * nv), empty(16 * nv)
# no textures: one-element texel, table and coordinate buffers (kernels/README.md)
no_texels, no_table, no_uvs = empty(16), empty(16), empty(32)
vox.vox_reduce(queue, (nv,), None, buf(frag_ids), buf(voxel_start.astype(np.uint32)),
               np.uint32(nv), np.uint32(fragments), tri_normals, buf(materials),
               buf(voxel_keys.astype(np.uint32)), tris_buf, vol_desc, no_texels, no_table,
               no_uvs, albedo, normal, emission)
check(np.array_equal(read(albedo, np.float32, 4 * nv), load("voxel_albedo.f32", np.float32)),
      "voxel albedo and opacity equal the library's, bit for bit")
check(np.array_equal(read(normal, np.float32, 4 * nv), load("voxel_normal.f32", np.float32)),
      "voxel normals equal the library's, bit for bit")

# ---- a cone trace through the library's bricks and octree, on our buffers.
render = build("render/vct_render.cl", ("-DVCT_CONE_PROBE",))
cones = load("cones.f32", np.float32)
n_cones = cones.size // 8
result = empty(32 * n_cones)
# CONE_POOLS without VCT_ANISOTROPIC: radiance, its shade and its plane
render.cone_probe(queue, (n_cones,), None, buf(load("bricks_radiance.f16", np.uint16)),
                  buf(load("bricks_shade.f16", np.uint16)),
                  buf(load("bricks_plane.f16", np.uint16)),
                  buf(load("octree_child.u32", np.uint32)), load("cone.desc", np.uint8),
                  buf(cones), np.uint32(n_cones), result)
mine = read(result, np.float32, 8 * n_cones)
theirs = load("cone_results.f32", np.float32)
check(np.array_equal(mine, theirs), f"{n_cones} cones equal the library's, bit for bit")
check(np.isfinite(mine).all() and (mine.reshape(-1, 8)[:, 3] > 0).any(),
      "cones are finite and meet geometry")

print(f"foreign_host: {checks} checks, {failures} failed")
sys.exit(1 if failures else 0)

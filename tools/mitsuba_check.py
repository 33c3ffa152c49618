#!/usr/bin/env python3
"""The path tracer against an independent one: each glTF scene of the suite,
converted here to a Mitsuba 3 scene (PyPI's `mitsuba`, its scalar RGB
variant), rendered with Mitsuba's own path tracer and compared with a vct
image of the same scene: NRMSE, the ratio of the means, and the NRMSE of
8x8-pixel block means, which noise hardly touches. tests/render/
test_independent.py holds vct's path tracer to it.

usage: tools/mitsuba_check.py SCENE.gltf VCT.pfm [--spp N] [--size W H]
           [--ambient R G B] [--max-depth D] [--out DIR]

What the conversion keeps, read as vct's loader reads the file: triangles with
node transforms; base colour as Lambert (both sides, as vct shades both);
metallic > 0.5 as a conductor of the base colour without Fresnel (a mirror
below roughness 0.14, else Beckmann with alpha = roughness^2, the width of
vct's Phong lobe);
transmission as a smooth dielectric of the material's ior; emission
(times KHR_materials_emissive_strength) on both sides, as vct emits whatever
doubleSided says; KHR_lights_punctual point, spot and directional
lights; the perspective camera; the sky as a constant environment; a box
pixel filter; base-colour textures (sRGB, bilinear, repeating) and alpha
masks (MASK mode, the cutoff taken per texel). A spot light's penumbra is
approximate: Mitsuba ramps linearly in angle from the inner to the outer cone,
glTF (and vct) square a ramp in the cosine."""
import argparse
import base64
import json
import math
import os
import sys

import numpy as np


def quat_matrix(q):
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0],
                     [0, 0, 0, 1]])


def node_matrix(node):
    if "matrix" in node:
        return np.array(node["matrix"], dtype=float).reshape(4, 4).T
    m = np.eye(4)
    if "scale" in node:
        m = np.diag(list(node["scale"]) + [1.0]) @ m
    if "rotation" in node:
        m = quat_matrix(node["rotation"]) @ m
    if "translation" in node:
        t = np.eye(4)
        t[:3, 3] = node["translation"]
        m = t @ m
    return m


class Gltf:
    def __init__(self, path):
        self.path = path
        with open(path) as f:
            self.j = json.load(f)
        self.buffers = []
        for b in self.j.get("buffers", []):
            uri = b["uri"]
            if uri.startswith("data:"):
                self.buffers.append(base64.b64decode(uri.split(",", 1)[1]))
            else:
                with open(os.path.join(os.path.dirname(path), uri), "rb") as f:
                    self.buffers.append(f.read())

    def accessor(self, index):
        a = self.j["accessors"][index]
        view = self.j["bufferViews"][a["bufferView"]]
        kinds = {5126: np.float32, 5125: np.uint32, 5123: np.uint16, 5121: np.uint8}
        comps = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[a["type"]]
        dtype = np.dtype(kinds[a["componentType"]])
        start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        stride = view.get("byteStride", dtype.itemsize * comps)
        rows = np.ndarray((a["count"], comps), dtype=dtype, buffer=self.buffers[view["buffer"]],
                          offset=start, strides=(stride, dtype.itemsize))
        return rows.copy()

    def walk(self):
        """(node, world matrix) for every node of the default scene."""
        scene = self.j["scenes"][self.j.get("scene", 0)]
        stack = [(n, np.eye(4)) for n in scene["nodes"]]
        while stack:
            i, parent = stack.pop()
            node = self.j["nodes"][i]
            world = parent @ node_matrix(node)
            yield node, world
            stack.extend((c, world) for c in node.get("children", []))

    def triangles(self):
        """(world positions, faces, uvs or None, material) of every triangle
        primitive of the default scene."""
        for node, world in self.walk():
            for p in self.j["meshes"][node["mesh"]]["primitives"] if "mesh" in node else []:
                if p.get("mode", 4) != 4:
                    continue
                pos = self.accessor(p["attributes"]["POSITION"]).astype(np.float64)
                pos = (np.c_[pos, np.ones(len(pos))] @ world.T)[:, :3]
                idx = (self.accessor(p["indices"]).reshape(-1, 3) if "indices" in p else
                       np.arange(len(pos)).reshape(-1, 3)).astype(np.int32)
                uvs = (self.accessor(p["attributes"]["TEXCOORD_0"]).astype(np.float64)
                       if "TEXCOORD_0" in p["attributes"] else None)
                yield pos, idx, uvs, self.j["materials"][p["material"]] if "material" in p else {}


def texture_file(g, out, index):
    """Texture index's image, written beside the meshes; its path."""
    image = g.j["images"][g.j["textures"][index]["source"]]
    if "bufferView" in image:
        view = g.j["bufferViews"][image["bufferView"]]
        start = view.get("byteOffset", 0)
        data = g.buffers[view["buffer"]][start:start + view["byteLength"]]
    elif image["uri"].startswith("data:"):
        data = base64.b64decode(image["uri"].split(",", 1)[1])
    else:
        with open(os.path.join(os.path.dirname(g.path), image["uri"]), "rb") as f:
            data = f.read()
    path = os.path.join(out, "texture%d.png" % index)
    with open(path, "wb") as f:
        f.write(data)
    return path


def alpha_file(path, cutoff):
    """The mask of a base-colour image: opaque where its alpha reaches the cutoff."""
    from PIL import Image
    alpha = np.array(Image.open(path).convert("RGBA"))[:, :, 3]
    mask = np.where(alpha / 255.0 >= cutoff, 255, 0).astype(np.uint8)
    out = path[:-4] + "_mask.png"
    Image.fromarray(mask, "L").save(out)
    return out


def bsdf_of(g, out, mat):
    pbr = mat.get("pbrMetallicRoughness", {})
    factor = list(pbr.get("baseColorFactor", [1, 1, 1, 1]))
    color = {"type": "rgb", "value": factor[:3]}
    tex = pbr.get("baseColorTexture")
    if tex is not None:
        png = texture_file(g, out, tex["index"])
        # sRGB decoded, bilinear, repeating: as vct's loader and kernels read it
        color = {"type": "bitmap", "filename": png, "filter_type": "bilinear",
                 "wrap_mode": "repeat", "raw": False}
        if factor[:3] != [1, 1, 1]:
            sys.exit("mitsuba_check: a base-colour factor times a texture is not converted")
    metallic, rough = pbr.get("metallicFactor", 1.0), pbr.get("roughnessFactor", 1.0)
    ext = mat.get("extensions", {})
    transmission = ext.get("KHR_materials_transmission", {}).get("transmissionFactor", 0.0)
    if transmission > 0.0:
        ior = ext.get("KHR_materials_ior", {}).get("ior", 1.5)
        return {"type": "dielectric", "int_ior": ior, "ext_ior": 1.0}
    if metallic > 0.5:
        if rough < 0.14:  # VCT_MIRROR_ROUGHNESS
            inner = {"type": "conductor", "material": "none", "specular_reflectance": color}
        else:
            inner = {"type": "roughconductor", "material": "none", "distribution": "beckmann",
                     "alpha": rough * rough, "specular_reflectance": color}
    else:
        inner = {"type": "diffuse", "reflectance": color}
    bsdf = {"type": "twosided", "bsdf": inner}
    if mat.get("alphaMode", "OPAQUE") == "MASK" and tex is not None:
        # a hard cutoff of each texel's alpha, then bilinear: the edges differ
        # from vct's cutoff of the interpolated alpha by under a texel
        cutoff = mat.get("alphaCutoff", 0.5) / factor[3]
        bsdf = {"type": "mask", "bsdf": bsdf,
                "opacity": {"type": "bitmap", "filename": alpha_file(png, cutoff),
                            "filter_type": "bilinear", "wrap_mode": "repeat", "raw": True}}
    elif mat.get("alphaMode", "OPAQUE") != "OPAQUE":
        sys.exit("mitsuba_check: alpha mode %s of %s is not converted" %
                 (mat["alphaMode"], mat.get("name", "?")))
    return bsdf


def emission_of(mat):
    e = mat.get("emissiveFactor", [0, 0, 0])
    s = mat.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get(
        "emissiveStrength", 1.0)
    return [c * s for c in e]


def write_ply(path, pos, faces, uvs=None):
    """A binary PLY file; uvs as glTF has them (Mitsuba also puts v = 0 at an
    image's top row, and its PLY reader does not flip v as its OBJ reader
    does: checked on a quad of four coloured quarters)."""
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
                 "property float x\nproperty float y\nproperty float z\n%s"
                 "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                 % (len(pos), "property float u\nproperty float v\n" if uvs is not None else "",
                    len(faces))).encode())
        f.write(np.c_[pos, uvs].astype("<f4").tobytes() if uvs is not None else
                pos.astype("<f4").tobytes())
        rows = np.zeros(len(faces), dtype=[("n", "u1"), ("v", "<i4", 3)])
        rows["n"] = 3
        rows["v"] = faces
        f.write(rows.tobytes())


def behind(pos, faces, offset):
    """Each face on its own vertices, moved by offset along its own normal:
    the flipped copy of a double-sided emitter lies just behind the original,
    not in its plane, where the two would take each other's hits (Mitsuba's
    area lights emit on the front only)."""
    tri = pos[faces]  # faces x 3 x 3
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
    moved = tri + offset * n[:, None, :]
    return moved.reshape(-1, 3), np.arange(3 * len(faces), dtype=np.int32).reshape(-1, 3)


def look_at(mi, world):
    origin, forward, up = world[:3, 3], -world[:3, 2], world[:3, 1]
    return mi.ScalarTransform4f().look_at(origin=origin.tolist(),
                                          target=(origin + forward).tolist(), up=up.tolist())


def convert(mi, path, out, width, height, spp, ambient, max_depth):
    g = Gltf(path)
    j = g.j
    # Mitsuba counts the camera's vertex in its depth, vct counts surfaces.
    scene = {"type": "scene", "integrator": {"type": "path", "max_depth": max_depth + 1}}
    lights = j.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    prims = list(g.triangles())
    extent = float(np.max(np.max([p.max(axis=0) for p, _, _, _ in prims], axis=0) -
                          np.min([p.min(axis=0) for p, _, _, _ in prims], axis=0)))
    for count, (pos, idx, uvs, mat) in enumerate(prims):
        emit = emission_of(mat)
        emissive = any(c > 0 for c in emit)
        # vct's emitters send light from both sides, whatever doubleSided says:
        # the back is a flipped copy just behind the front, of the same
        # (two-sided) BSDF; a null BSDF there made Mitsuba's floor under an
        # upward-facing lamp 12 % darker
        for k in range(2 if emissive else 1):
            ply = os.path.join(out, "mesh%d_%d.ply" % (count, k))
            if k == 0:
                write_ply(ply, pos, idx, uvs)
            else:
                write_ply(ply, *behind(pos, idx[:, ::-1], 1e-5 * extent))
            entry = {"type": "ply", "filename": ply, "face_normals": True,
                     "bsdf": bsdf_of(g, out, mat)}
            if emissive:
                entry["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": emit}}
            scene["mesh%d_%d" % (count, k)] = entry
    for node, world in g.walk():
        light = node.get("extensions", {}).get("KHR_lights_punctual", {}).get("light")
        if light is not None:
            l = lights[light]
            rgb = {"type": "rgb",
                   "value": [c * l.get("intensity", 1.0) for c in l.get("color", [1, 1, 1])]}
            if l["type"] == "point":
                scene["light%d" % light] = {"type": "point", "position": world[:3, 3].tolist(),
                                            "intensity": rgb}
            elif l["type"] == "spot":
                spot = l.get("spot", {})
                scene["light%d" % light] = {
                    "type": "spot", "intensity": rgb, "to_world": look_at(mi, world),
                    "cutoff_angle": math.degrees(spot.get("outerConeAngle", math.pi / 4)),
                    "beam_width": math.degrees(spot.get("innerConeAngle", 0.0))}
            else:
                scene["light%d" % light] = {"type": "directional", "irradiance": rgb,
                                            "direction": (-world[:3, 2]).tolist()}
        if "camera" in node:
            cam = j["cameras"][node["camera"]]["perspective"]
            scene["camera"] = {
                "type": "perspective", "fov_axis": "y", "fov": math.degrees(cam["yfov"]),
                "to_world": look_at(mi, world),
                "film": {"type": "hdrfilm", "width": width, "height": height,
                         "rfilter": {"type": "box"}, "pixel_format": "rgb"},
                "sampler": {"type": "independent", "sample_count": spp}}
    if any(e.get("bsdf", {}).get("type") == "mask" for e in scene.values() if isinstance(e, dict)):
        # the path integrator's shadow rays stop at a mask's transparent
        # texels; volpath's see through them
        scene["integrator"]["type"] = "volpath"
    if ambient and any(c > 0 for c in ambient):
        scene["sky"] = {"type": "constant", "radiance": {"type": "rgb", "value": list(ambient)}}
    return scene


def write_pfm(path, rgb):
    h, w, _ = rgb.shape
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(np.ascontiguousarray(rgb[::-1], dtype="<f4").tobytes())  # bottom row first


def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(h, w, 3)[::-1]


def block_metrics(test, ref, block=8):
    """NRMSE of block x block means (bias that noise hardly hides) and the
    ratio of the images' means."""
    h, w = (ref.shape[0] // block) * block, (ref.shape[1] // block) * block
    bt = test[:h, :w].reshape(h // block, block, w // block, block, 3).mean(axis=(1, 3))
    br = ref[:h, :w].reshape(h // block, block, w // block, block, 3).mean(axis=(1, 3))
    return math.sqrt(np.mean((bt - br) ** 2)) / br.mean(), test.mean() / ref.mean()


def render_mitsuba(path, out, width, height, spp, ambient=None, max_depth=16, seed=7):
    """The scene rendered by Mitsuba's path tracer: linear RGB, row 0 at the top."""
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    os.makedirs(out, exist_ok=True)
    scene = mi.load_dict(convert(mi, path, out, width, height, spp, ambient, max_depth))
    return np.array(mi.render(scene, seed=seed))[:, :, :3]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("vct_image")
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--size", type=int, nargs=2, default=[128, 128])
    ap.add_argument("--ambient", type=float, nargs=3, default=None)
    ap.add_argument("--max-depth", type=int, default=16)
    ap.add_argument("--out", default="out/mitsuba")
    a = ap.parse_args()
    image = render_mitsuba(a.scene, a.out, a.size[0], a.size[1], a.spp, a.ambient, a.max_depth)
    name = os.path.splitext(os.path.basename(a.scene))[0]
    pfm = os.path.join(a.out, name + "_mitsuba.pfm")
    write_pfm(pfm, image)
    nrmse = math.sqrt(np.mean((read_pfm(a.vct_image) - image) ** 2)) / image.mean()
    blocks, ratio = block_metrics(read_pfm(a.vct_image), image)
    print("%s: NRMSE %.4f, 8x8 block means NRMSE %.4f, mean ratio %.4f (vct / Mitsuba), "
          "Mitsuba's image %s" % (name, nrmse, blocks, ratio, pfm))


if __name__ == "__main__":
    main()

"""A small glTF 2.0 writer for the scene suite: meshes made of quads and
triangles, one material each (metallic-roughness, emission with
KHR_materials_emissive_strength, KHR_materials_transmission and
KHR_materials_ior, a base-colour texture with an alpha mask), a perspective
camera and KHR_lights_punctual lights, all in one .gltf file with its buffer
and images embedded (base64)."""
import base64
import json
import math
import struct
import zlib


def png_rgba(width, height, pixel):
    """A PNG of width x height RGBA8 pixels, pixel(x, y) -> 4 ints, row 0 at the top."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # no filter
        for x in range(width):
            rows.extend(pixel(x, y))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    return (b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(bytes(rows))) + chunk(b"IEND", b""))


class Scene:
    def __init__(self):
        self.materials = []
        self.images = []  # PNG bytes
        self.meshes = []  # (material index, positions, indices, texture coordinates or None)
        self.lights = []
        self.camera = None
        self.placements = {}  # mesh index -> [(translation, rotation, scale)]
        self.animations = []  # (name, mesh, placement, times, translations)

    def material(self, name, color, roughness=1.0, metallic=0.0, emission=None,
                 strength=1.0, transmission=0.0, ior=1.5, texture=None, alpha_cutoff=None):
        """texture: PNG bytes for the base colour; alpha_cutoff: alphaMode MASK."""
        m = {"name": name,
             "pbrMetallicRoughness": {"baseColorFactor": [*color, 1.0],
                                      "metallicFactor": metallic,
                                      "roughnessFactor": roughness},
             "doubleSided": True}
        if texture is not None:
            self.images.append(texture)
            m["pbrMetallicRoughness"]["baseColorTexture"] = {"index": len(self.images) - 1}
        if alpha_cutoff is not None:
            m["alphaMode"] = "MASK"
            m["alphaCutoff"] = alpha_cutoff
        ext = {}
        if emission:
            m["emissiveFactor"] = list(emission)
            if strength != 1.0:
                ext["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
        if transmission > 0.0:
            ext["KHR_materials_transmission"] = {"transmissionFactor": transmission}
            ext["KHR_materials_ior"] = {"ior": ior}
        if ext:
            m["extensions"] = ext
        self.materials.append(m)
        return len(self.materials) - 1

    def mesh(self, material, positions, indices, uvs=None):
        """Returns the mesh's index (None for a mesh without triangles)."""
        if indices:
            self.meshes.append((material, list(positions), list(indices),
                                list(uvs) if uvs else None))
            return len(self.meshes) - 1
        return None

    def place(self, mesh, translation=(0, 0, 0), rotation=(0, 0, 0, 1), scale=(1, 1, 1)):
        """One more node showing `mesh` (glTF TRS; rotation a quaternion x, y,
        z, w). A placed mesh has only the nodes placed, not its own."""
        self.placements.setdefault(mesh, []).append((translation, rotation, scale))

    def quads(self, material, quads, textured=False, repeat=(1, 1)):
        """Each quad: four corners in order around it; textured: the texture
        over it repeat[0] x repeat[1] times, (0, 0) at its first corner,
        (repeat[0], 0) at its second. Returns the mesh's index."""
        pos, idx, uvs = [], [], []
        ru, rv = repeat
        for q in quads:
            base = len(pos)
            pos.extend(q)
            uvs.extend([(0, 0), (ru, 0), (ru, rv), (0, rv)])
            idx.extend([base, base + 1, base + 2, base, base + 2, base + 3])
        return self.mesh(material, pos, idx, uvs if textured else None)

    def box(self, material, lo, hi, skip=()):
        """An axis-aligned box as six quads (faces named -x +x -y +y -z +z
        can be left out)."""
        (x0, y0, z0), (x1, y1, z1) = lo, hi
        faces = {
            "-x": [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
            "+x": [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
            "-y": [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
            "+y": [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
            "-z": [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
            "+z": [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
        }
        return self.quads(material, [f for k, f in faces.items() if k not in skip])

    def sphere(self, material, centre, radius, rings=24, segments=48):
        pos, idx = [], []
        for r in range(rings + 1):
            theta = math.pi * r / rings
            for s in range(segments + 1):
                phi = 2 * math.pi * s / segments
                pos.append((centre[0] + radius * math.sin(theta) * math.cos(phi),
                            centre[1] + radius * math.cos(theta),
                            centre[2] + radius * math.sin(theta) * math.sin(phi)))
        for r in range(rings):
            for s in range(segments):
                a = r * (segments + 1) + s
                b = a + segments + 1
                if r > 0:
                    idx.extend([a, b, a + 1])
                if r < rings - 1:
                    idx.extend([a + 1, b, b + 1])
        return self.mesh(material, pos, idx)

    def animate(self, name, mesh, placement, times, translations, rotations=None):
        """An animation moving the node of placement `placement` of `mesh`:
        its translation at each time (seconds), linearly between; mesh
        "camera" moves the camera's node, "light" the node of light number
        `placement`. Rotations (x y z w, one per time) turn the node too."""
        self.animations.append((name, mesh, placement, list(times), list(translations),
                                list(rotations) if rotations else None))

    def point_light(self, position, intensity, color=(1, 1, 1)):
        self.lights.append(({"type": "point", "color": list(color), "intensity": intensity},
                            position, None))

    def spot_light(self, position, target, intensity, inner_deg, outer_deg, color=(1, 1, 1)):
        """A spot at position aimed at target; its cone's half-angles in degrees."""
        spot = {"innerConeAngle": math.radians(inner_deg),
                "outerConeAngle": math.radians(outer_deg)}
        direction = _normalise([target[k] - position[k] for k in range(3)])
        self.lights.append(({"type": "spot", "color": list(color), "intensity": intensity,
                             "spot": spot}, position, direction))

    def sun(self, direction, irradiance, color=(1, 1, 1)):
        self.lights.append(({"type": "directional", "color": list(color),
                             "intensity": irradiance}, None, direction))

    def look(self, position, target, fov_y_deg, aspect=1.0):
        self.camera = (position, target, fov_y_deg, aspect)

    def camera_rotation(self):
        """The rotation (x y z w) of the camera's node as look() set it."""
        position, target = self.camera[0], self.camera[1]
        return tuple(_rotation_from_minus_z(
            _normalise([target[k] - position[k] for k in range(3)])))

    def write(self, path):
        blob = bytearray()
        accessors, views, meshes, nodes = [], [], [], []

        def accessor(fmt, items, kind, **extra):
            """items packed into the blob as a view and an accessor: its index"""
            offset = len(blob)
            for item in items:
                blob.extend(struct.pack(fmt, *(item if isinstance(item, tuple | list)
                                               else (item,))))
            views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset})
            accessors.append({"bufferView": len(views) - 1,
                              "componentType": 5125 if fmt == "<I" else 5126,
                              "count": len(items), "type": kind, **extra})
            return len(accessors) - 1

        placed_nodes = {}  # mesh -> its nodes' indices, in placement order
        for material, pos, idx, uvs in self.meshes:
            lo = [min(p[k] for p in pos) for k in range(3)]
            hi = [max(p[k] for p in pos) for k in range(3)]
            attributes = {"POSITION": accessor("<3f", pos, "VEC3", min=lo, max=hi)}
            indices = accessor("<I", idx, "SCALAR")
            if uvs:
                attributes["TEXCOORD_0"] = accessor("<2f", uvs, "VEC2")
            meshes.append({"primitives": [{"attributes": attributes, "indices": indices,
                                           "material": material}]})
            mesh = len(meshes) - 1
            placed_nodes[mesh] = []
            for t, r, sc in self.placements.get(mesh, [((0, 0, 0), (0, 0, 0, 1), (1, 1, 1))]):
                placed_nodes[mesh].append(len(nodes))
                node = {"mesh": mesh}
                if tuple(t) != (0, 0, 0):
                    node["translation"] = list(t)
                if tuple(r) != (0, 0, 0, 1):
                    node["rotation"] = list(r)
                if tuple(sc) != (1, 1, 1):
                    node["scale"] = list(sc)
                nodes.append(node)
        gltf = {"asset": {"version": "2.0", "generator": "vct scenes/suite"},
                "scene": 0, "materials": self.materials, "meshes": meshes,
                "accessors": accessors, "bufferViews": views}
        if self.images:
            gltf["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png).decode()}
                              for png in self.images]
            gltf["textures"] = [{"source": i} for i in range(len(self.images))]
        light_nodes, camera_node = [], None
        used = {"KHR_lights_punctual"} if self.lights else set()
        for m in self.materials:
            used |= set(m.get("extensions", {}).keys())
        if used:
            gltf["extensionsUsed"] = sorted(used)
        if self.lights:
            gltf["extensions"] = {"KHR_lights_punctual": {"lights": [l for l, _, _ in self.lights]}}
            for i, (_, position, direction) in enumerate(self.lights):
                light_nodes.append(len(nodes))
                node = {"extensions": {"KHR_lights_punctual": {"light": i}}}
                if position:
                    node["translation"] = list(position)
                if direction:
                    node["rotation"] = _rotation_from_minus_z(direction)
                nodes.append(node)
        if self.camera:
            position, target, fov, aspect = self.camera
            gltf["cameras"] = [{"type": "perspective",
                                "perspective": {"yfov": math.radians(fov), "aspectRatio": aspect,
                                                "znear": 0.01}}]
            fwd = _normalise([target[k] - position[k] for k in range(3)])
            camera_node = len(nodes)
            nodes.append({"camera": 0, "translation": list(position),
                          "rotation": _rotation_from_minus_z(fwd)})
        animations = []
        for name, mesh, placement, times, translations, rotations in self.animations:
            times_accessor = accessor("<f", times, "SCALAR", min=[min(times)], max=[max(times)])
            moves = accessor("<3f", translations, "VEC3")
            if mesh == "camera":
                node = camera_node
            elif mesh == "light":
                node = light_nodes[placement]
            else:
                node = placed_nodes[mesh][placement]
            # animations of one name are one animation: its channels added up
            anim = next((a for a in animations if a["name"] == name), None)
            if anim is None:
                anim = {"name": name, "samplers": [], "channels": []}
                animations.append(anim)
            samplers, channels = anim["samplers"], anim["channels"]
            parts = [("translation", moves)]
            if rotations:
                parts.append(("rotation", accessor("<4f", rotations, "VEC4")))
            for part, values in parts:
                samplers.append({"input": times_accessor, "output": values,
                                 "interpolation": "LINEAR"})
                channels.append({"sampler": len(samplers) - 1,
                                 "target": {"node": node, "path": part}})
        if animations:
            gltf["animations"] = animations
        # once everything, the animations' keys included, is in the blob
        gltf["buffers"] = [{"byteLength": len(blob),
                            "uri": "data:application/octet-stream;base64,"
                                   + base64.b64encode(bytes(blob)).decode()}]
        gltf["nodes"] = nodes
        gltf["scenes"] = [{"nodes": list(range(len(nodes)))}]
        with open(path, "w") as f:
            json.dump(gltf, f, indent=1)


def yaw_quaternion(degrees):
    """A turn about +y, as a quaternion (x y z w)."""
    h = math.radians(degrees) / 2
    return (0.0, math.sin(h), 0.0, math.cos(h))


def quaternion_product(a, b):
    """The quaternion a b (x y z w): b's turn, then a's."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def _normalise(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def _rotation_from_minus_z(d):
    """The quaternion (x, y, z, w) turning -z to unit d, keeping +y up."""
    f = _normalise(d)
    up = [0.0, 1.0, 0.0]
    if abs(f[1]) > 0.999:
        up = [0.0, 0.0, -1.0 if f[1] > 0 else 1.0]
    r = _normalise([f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2],
                    f[0] * up[1] - f[1] * up[0]])
    u = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]]
    b = [-f[0], -f[1], -f[2]]  # the camera's +z
    m = [[r[0], u[0], b[0]], [r[1], u[1], b[1]], [r[2], u[2], b[2]]]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = math.sqrt(trace + 1.0) * 2
        return [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s,
                0.25 * s]
    if m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        return [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s,
                (m[2][1] - m[1][2]) / s]
    if m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        return [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s,
                (m[0][2] - m[2][0]) / s]
    s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
    return [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s,
            (m[1][0] - m[0][1]) / s]

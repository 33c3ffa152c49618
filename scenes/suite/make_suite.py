#!/usr/bin/env python3
"""Writes the scene suite: scenes unlike each other, each with its camera and
its lights, made here from code (nothing is downloaded). suite.txt lists
them with the options they render with (the sky of the open scenes, which a
glTF file cannot hold, is given as --ambient).

  atrium            columns and arches around a court open to the sky, sun
  window_room       a closed room lit through one window by the sun and sky
  glass_mirror_box  a box lit by its emissive ceiling panel alone, with a glass
                    sphere, a mirror sphere and a glossy block
  blinds_fins       a room behind half-open blinds, thin fins and a plant of
                    cut-out leaves (an alpha-masked texture), sun-lit
  dense_hall        a 10^5-triangle bumpy sphere in a large hall, one lamp
  lamp_room         a living room lit by two emissive lamp shades and a
                    small point light, single-quad furniture wound either way
  small_objects     200 beads of 1.5 cm (diffuse, mirror and glass) before a
                    wall under a point light: a few pixels each on screen
  textured_room     a room with a parquet floor and striped wallpaper
                    (base-colour textures), a table and a lamp
  spot_gallery      a closed gallery lit by three spot lights alone (soft and
                    hard cone edges) on pictures, a statue and the floor
  long_hall         a long stone hall, columns 3 voxels wide, gallery slabs one
                    voxel thick, banners of zero thickness, lit by the sun
                    and sky through a slit in its roof
  panel_room        a furnished room lit only by two small emissive ceiling
                    panels: a table on thin legs, stools, a shelf of thin books
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_scene import Scene, png_rgba  # noqa: E402

OUT = os.path.dirname(os.path.abspath(__file__))
STONE = (0.62, 0.58, 0.5)
PLASTER = (0.75, 0.74, 0.7)


def atrium():
    s = Scene()
    stone = s.material("stone", STONE)
    floor = s.material("floor", (0.45, 0.42, 0.38))
    red = s.material("banner", (0.6, 0.1, 0.08))
    s.quads(floor, [[(-12, 0, -8), (-12, 0, 8), (12, 0, 8), (12, 0, -8)]])
    # the outer walls, two storeys, open roof
    for x0, x1, z0, z1 in [(-12, 12, -8, -7.6), (-12, 12, 7.6, 8), (-12, -11.6, -7.6, 7.6),
                           (11.6, 12, -7.6, 7.6)]:
        s.box(stone, (x0, 0, z0), (x1, 9, z1))
    # a gallery floor on the first storey around the court
    for x0, x1, z0, z1 in [(-11.6, 11.6, -7.6, -4.5), (-11.6, 11.6, 4.5, 7.6)]:
        s.box(stone, (x0, 4.2, z0), (x1, 4.5, z1))
    # columns and arches along both sides of the court
    for side in (-4.5, 4.5):
        for i in range(7):
            x = -9 + 3 * i
            s.box(stone, (x - 0.3, 0, side - 0.3), (x + 0.3, 4.2, side + 0.3))
            if i < 6:  # a round arch to the next column, in 12 segments
                for k in range(12):
                    a0, a1 = math.pi * k / 12, math.pi * (k + 1) / 12
                    xa, xb = x + 1.5 - 1.2 * math.cos(a0), x + 1.5 - 1.2 * math.cos(a1)
                    ya, yb = 3.0 + 1.2 * math.sin(a0), 3.0 + 1.2 * math.sin(a1)
                    for z in (side - 0.3, side + 0.3):
                        s.quads(stone, [[(xa, ya, z), (xb, yb, z), (xb, 4.2, z), (xa, 4.2, z)]])
                    s.quads(stone, [[(xa, ya, side - 0.3), (xa, ya, side + 0.3),
                                     (xb, yb, side + 0.3), (xb, yb, side - 0.3)]])
    # hanging banners: single quads
    for x in (-6, 0, 6):
        s.quads(red, [[(x - 0.8, 5.5, -7.5), (x + 0.8, 5.5, -7.5), (x + 0.8, 8.5, -7.5),
                       (x - 0.8, 8.5, -7.5)]])
    s.sun((-0.35, -0.8, 0.45), 4.0, (1.0, 0.93, 0.82))
    s.look((-10.5, 1.7, 6.2), (4, 3.2, -3), 60)
    s.write(os.path.join(OUT, "atrium.gltf"))


def window_room():
    s = Scene()
    wall = s.material("plaster", PLASTER)
    wood = s.material("wood floor", (0.5, 0.32, 0.18))
    blue = s.material("sofa", (0.15, 0.22, 0.5))
    s.quads(wood, [[(0, 0, 0), (0, 0, 6), (7, 0, 6), (7, 0, 0)]])
    s.quads(wall, [[(0, 3, 0), (7, 3, 0), (7, 3, 6), (0, 3, 6)],
                   [(0, 0, 0), (7, 0, 0), (7, 3, 0), (0, 3, 0)],
                   [(0, 0, 6), (0, 3, 6), (7, 3, 6), (7, 0, 6)],
                   [(0, 0, 0), (0, 3, 0), (0, 3, 6), (0, 0, 6)]])
    # the +x wall with a window over z 2..4.5, y 0.9..2.4
    x = 7.0
    s.quads(wall, [[(x, 0, 0), (x, 0.9, 0), (x, 0.9, 6), (x, 0, 6)],
                   [(x, 2.4, 0), (x, 3, 0), (x, 3, 6), (x, 2.4, 6)],
                   [(x, 0.9, 0), (x, 2.4, 0), (x, 2.4, 2), (x, 0.9, 2)],
                   [(x, 0.9, 4.5), (x, 2.4, 4.5), (x, 2.4, 6), (x, 0.9, 6)]])
    s.box(blue, (1.0, 0, 1.0), (1.9, 0.8, 4.2))
    s.box(wall, (3.2, 0, 2.5), (4.4, 0.45, 3.7))
    s.sun((-0.75, -0.45, 0.3), 6.0, (1.0, 0.95, 0.85))
    s.look((0.4, 1.6, 5.6), (6, 1.0, 1.5), 65)
    s.write(os.path.join(OUT, "window_room.gltf"))


def glass_mirror_box():
    s = Scene()
    white = s.material("white", (0.73, 0.71, 0.68))
    red = s.material("red", (0.63, 0.065, 0.05))
    green = s.material("green", (0.14, 0.45, 0.091))
    lamp = s.material("ceiling panel", (0, 0, 0), emission=(1.0, 0.85, 0.6), strength=12.0)
    glass = s.material("glass", (1, 1, 1), roughness=0.0, transmission=1.0, ior=1.5)
    mirror = s.material("mirror", (0.9, 0.9, 0.9), roughness=0.0, metallic=1.0)
    glossy = s.material("glossy block", (0.2, 0.3, 0.6), roughness=0.3, metallic=1.0)
    w = 4.0
    s.quads(white, [[(0, 0, 0), (0, 0, w), (w, 0, w), (w, 0, 0)],
                    [(0, w, 0), (w, w, 0), (w, w, w), (0, w, w)],
                    [(0, 0, w), (0, w, w), (w, w, w), (w, 0, w)]])
    s.quads(red, [[(0, 0, 0), (0, w, 0), (0, w, w), (0, 0, w)]])
    s.quads(green, [[(w, 0, 0), (w, 0, w), (w, w, w), (w, w, 0)]])
    s.quads(lamp, [[(1.4, w - 0.01, 1.6), (2.6, w - 0.01, 1.6), (2.6, w - 0.01, 2.8),
                    (1.4, w - 0.01, 2.8)]])
    s.sphere(glass, (1.2, 0.75, 1.6), 0.75)
    s.sphere(mirror, (2.9, 0.7, 2.7), 0.7)
    s.box(glossy, (2.5, 0, 0.6), (3.3, 1.2, 1.4))
    s.look((2.0, 2.0, -5.0), (2.0, 1.8, 2.0), 42)
    s.write(os.path.join(OUT, "glass_mirror_box.gltf"))


def blinds_fins():
    s = Scene()
    wall = s.material("plaster", PLASTER)
    floor = s.material("floor", (0.4, 0.4, 0.42))
    slat = s.material("slats", (0.85, 0.83, 0.78))
    fin = s.material("fins", (0.7, 0.45, 0.2))
    s.quads(floor, [[(0, 0, 0), (0, 0, 6), (6, 0, 6), (6, 0, 0)]])
    s.quads(wall, [[(0, 3, 0), (6, 3, 0), (6, 3, 6), (0, 3, 6)],
                   [(0, 0, 6), (0, 3, 6), (6, 3, 6), (6, 0, 6)],
                   [(0, 0, 0), (0, 3, 0), (0, 3, 6), (0, 0, 6)],
                   [(6, 0, 0), (6, 0, 6), (6, 3, 6), (6, 3, 0)]])
    # the -z wall is a window from y 0.5 to 2.7, behind blinds: slats 3 cm
    # deep and 2 mm thick every 8 cm, tilted 40 degrees (closed boxes)
    s.quads(wall, [[(0, 0, 0), (6, 0, 0), (6, 0.5, 0), (0, 0.5, 0)],
                   [(0, 2.7, 0), (6, 2.7, 0), (6, 3, 0), (0, 3, 0)]])
    tilt = math.radians(40)
    y = 0.55
    while y < 2.68:
        dy, dz = 0.015 * math.sin(tilt), 0.015 * math.cos(tilt)
        ty, tz = 0.001 * math.cos(tilt), -0.001 * math.sin(tilt)
        c = (y, 0.1)
        corners = [(c[0] - dy - ty, c[1] - dz - tz), (c[0] + dy - ty, c[1] + dz - tz),
                   (c[0] + dy + ty, c[1] + dz + tz), (c[0] - dy + ty, c[1] - dz + tz)]
        quads = []
        for i in range(4):
            (ya, za), (yb, zb) = corners[i], corners[(i + 1) % 4]
            quads.append([(0.05, ya, za), (5.95, ya, za), (5.95, yb, zb), (0.05, yb, zb)])
        s.quads(slat, quads)
        y += 0.08
    # thin fins standing on the floor: single quads, every other one wound the other way
    for i in range(9):
        x = 1.0 + 0.5 * i
        q = [(x, 0, 3.0), (x, 1.4, 3.0), (x, 1.4, 4.6), (x, 0, 4.6)]
        s.quads(fin, [q if i % 2 else q[::-1]])
    # a plant of cut-out leaves: quads whose texture's alpha masks all but
    # three leaf shapes (alphaMode MASK), crossing at its stem
    leaves = s.material("leaves", (1.0, 1.0, 1.0), texture=leaf_texture(), alpha_cutoff=0.5)
    cx, cz = 4.9, 1.9
    sprites = []
    for k in range(6):
        a = math.pi * k / 6
        dx, dz = 0.45 * math.cos(a), 0.45 * math.sin(a)
        lo, hi = 0.25 + 0.1 * (k % 2), 1.25 + 0.1 * (k % 3)
        sprites.append([(cx - dx, lo, cz - dz), (cx + dx, lo, cz + dz),
                        (cx + dx, hi, cz + dz), (cx - dx, hi, cz - dz)])
    s.quads(leaves, sprites, textured=True)
    s.sun((0.2, -0.5, 0.84), 7.0, (1.0, 0.95, 0.85))
    s.look((5.5, 2.2, 5.7), (2.5, 0.8, 1.5), 62)
    s.write(os.path.join(OUT, "blinds_fins.gltf"))


def textured_room():
    s = Scene()
    parquet = s.material("parquet", (1.0, 1.0, 1.0), texture=parquet_texture())
    paper = s.material("wallpaper", (1.0, 1.0, 1.0), texture=stripes_texture())
    ceiling = s.material("ceiling", PLASTER)
    wood = s.material("table", (0.45, 0.3, 0.2))
    w, h, d = 5.0, 2.8, 4.0
    s.quads(parquet, [[(0, 0, 0), (0, 0, d), (w, 0, d), (w, 0, 0)]], textured=True,
            repeat=(4, 5))
    s.quads(paper, [[(0, 0, 0), (w, 0, 0), (w, h, 0), (0, h, 0)],
                    [(w, 0, d), (0, 0, d), (0, h, d), (w, h, d)],
                    [(0, 0, d), (0, 0, 0), (0, h, 0), (0, h, d)],
                    [(w, 0, 0), (w, 0, d), (w, h, d), (w, h, 0)]], textured=True,
            repeat=(6, 2))
    s.quads(ceiling, [[(0, h, 0), (w, h, 0), (w, h, d), (0, h, d)]])
    s.box(wood, (1.8, 0.7, 1.4), (3.2, 0.76, 2.4))
    for x, z in ((1.85, 1.45), (3.1, 1.45), (1.85, 2.3), (3.1, 2.3)):
        s.box(wood, (x, 0, z), (x + 0.05, 0.7, z + 0.05))
    s.point_light((2.5, 2.5, 2.0), 25.0, (1.0, 0.9, 0.75))
    s.look((4.6, 1.6, 3.7), (1.2, 0.6, 0.6), 65)
    s.write(os.path.join(OUT, "textured_room.gltf"))


def parquet_texture(size=64):
    """Planks: four rows of boards, each its own shade of brown."""
    def pixel(x, y):
        row = y * 4 // size
        board = (x + (row % 2) * size // 4) * 2 // size
        shade = 0.75 + 0.25 * (((row * 7 + board * 3) % 5) / 4.0)
        grain = 0.92 + 0.08 * math.sin(0.9 * x + 3.0 * row)
        edge = 0.6 if y % (size // 4) == 0 else 1.0
        f = shade * grain * edge
        return (int(180 * f), int(120 * f), int(70 * f), 255)
    return png_rgba(size, size, pixel)


def stripes_texture(size=64):
    """Wallpaper: pale stripes of two colours."""
    def pixel(x, y):
        return (210, 200, 170, 255) if (x * 4 // size) % 2 else (150, 170, 190, 255)
    return png_rgba(size, size, pixel)


def leaf_texture(size=64):
    """Three leaves (ellipses) on nothing: green where a leaf is, alpha 0
    elsewhere; row 0 at the top, v = 0 at the quad's foot."""
    shapes = [(0.3, 0.35, 0.14, 0.3, 0.5), (0.68, 0.45, 0.13, 0.3, -0.4),
              (0.5, 0.75, 0.12, 0.22, 0.1)]

    def pixel(x, y):
        u, v = (x + 0.5) / size, (y + 0.5) / size
        for cu, cv, a, b, turn in shapes:
            du, dv = u - cu, v - cv
            ru = du * math.cos(turn) + dv * math.sin(turn)
            rv = -du * math.sin(turn) + dv * math.cos(turn)
            if (ru / a) ** 2 + (rv / b) ** 2 <= 1.0:
                return (70, 140, 45, 255)
        return (70, 140, 45, 0)
    return png_rgba(size, size, pixel)


def dense_hall():
    s = Scene()
    wall = s.material("hall", (0.6, 0.6, 0.62))
    floor = s.material("floor", (0.35, 0.3, 0.25))
    statue = s.material("statue", (0.8, 0.55, 0.35), roughness=0.5)
    s.quads(floor, [[(-20, 0, -20), (-20, 0, 20), (20, 0, 20), (20, 0, -20)]])
    s.box(wall, (-20, 0, -20), (20, 14, 20), skip=("-y",))
    # a bumpy sphere of 105,600 triangles, 1.2 m across, on a plinth
    s.box(wall, (-0.8, 0, -0.8), (0.8, 0.8, 0.8))
    rings, segments = 220, 240
    pos, idx = [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for k in range(segments + 1):
            phi = 2 * math.pi * k / segments
            rad = 0.6 * (1 + 0.06 * math.sin(9 * theta) * math.sin(7 * phi))
            pos.append((rad * math.sin(theta) * math.cos(phi), 1.4 + rad * math.cos(theta),
                        rad * math.sin(theta) * math.sin(phi)))
    for r in range(rings):
        for k in range(segments):
            a = r * (segments + 1) + k
            b = a + segments + 1
            idx.extend([a, b, a + 1, a + 1, b, b + 1])
    s.mesh(statue, pos, idx)
    s.point_light((3, 6, 2), 400.0, (1.0, 0.9, 0.8))
    s.look((0, 1.6, 4.5), (0, 1.3, 0), 45)
    s.write(os.path.join(OUT, "dense_hall.gltf"))


def lamp_room():
    s = Scene()
    wall = s.material("walls", (0.7, 0.68, 0.62))
    floor = s.material("carpet", (0.35, 0.12, 0.1))
    table = s.material("table", (0.45, 0.3, 0.15))
    shade = s.material("lamp shade", (0, 0, 0), emission=(1.0, 0.8, 0.55), strength=6.0)
    s.quads(floor, [[(0, 0, 0), (0, 0, 5), (6, 0, 5), (6, 0, 0)]])
    s.box(wall, (0, 0, 0), (6, 2.8, 5), skip=("-y",))
    # a table: a single quad top on four thin legs
    table_meshes = [s.quads(table, [[(2, 0.75, 1.5), (4, 0.75, 1.5), (4, 0.75, 3), (2, 0.75, 3)]])]
    for x, z in [(2.05, 1.55), (3.9, 1.55), (2.05, 2.9), (3.9, 2.9)]:
        table_meshes.append(s.box(table, (x, 0, z), (x + 0.05, 0.75, z + 0.05)))
    # two lamp shades: open cylinders of emissive quads, wound inwards
    for cx, cz, h in [(0.8, 4.2, 1.6), (5.2, 0.8, 1.4)]:
        quads = []
        for k in range(16):
            a0, a1 = 2 * math.pi * k / 16, 2 * math.pi * (k + 1) / 16
            p0 = (cx + 0.22 * math.cos(a0), cz + 0.22 * math.sin(a0))
            p1 = (cx + 0.22 * math.cos(a1), cz + 0.22 * math.sin(a1))
            quads.append([(p0[0], h, p0[1]), (p1[0], h, p1[1]), (p1[0], h + 0.35, p1[1]),
                          (p0[0], h + 0.35, p0[1])])
        s.quads(shade, quads)
        s.box(table, (cx - 0.02, 0, cz - 0.02), (cx + 0.02, h, cz + 0.02))
    # "slide" (2 s): the table (its top and legs, 50 of the 150 triangles)
    # slides 0.8 m towards the window wall and back; at rest and at 0 s it
    # is where it was built
    for m in table_meshes:
        s.animate("slide", m, 0, [0.0, 1.0, 2.0], [(0, 0, 0), (-0.8, 0, 0.3), (0, 0, 0)])
    s.point_light((3, 2.6, 2.2), 3.0, (1.0, 0.95, 0.9))
    s.look((5.6, 1.7, 4.6), (2.5, 0.6, 1.6), 60)
    s.write(os.path.join(OUT, "lamp_room.gltf"))


def small_objects():
    s = Scene()
    wall = s.material("wall", (0.75, 0.74, 0.7))
    floor = s.material("floor", (0.3, 0.32, 0.35))
    beads = [s.material("red bead", (0.8, 0.1, 0.08)),
             s.material("steel bead", (0.9, 0.9, 0.9), roughness=0.0, metallic=1.0),
             s.material("glass bead", (1, 1, 1), roughness=0.0, transmission=1.0, ior=1.5),
             s.material("green bead", (0.1, 0.6, 0.15))]
    s.quads(floor, [[(-2, 0, -1), (-2, 0, 2), (2, 0, 2), (2, 0, -1)]])
    s.quads(wall, [[(-2, 0, 0), (2, 0, 0), (2, 2, 0), (-2, 2, 0)]])
    for i in range(20):
        for j in range(10):
            x, y = -1.14 + 0.12 * i, 0.3 + 0.12 * j
            s.sphere(beads[(i + j) % 4], (x, y, 0.25), 0.015, rings=6, segments=10)
    s.point_light((0.5, 1.8, 1.6), 4.0, (1.0, 0.95, 0.9))
    s.look((0, 0.9, 3.2), (0, 0.85, 0), 42, aspect=4 / 3)
    s.write(os.path.join(OUT, "small_objects.gltf"))


def spot_gallery():
    s = Scene()
    wall = s.material("walls", (0.72, 0.7, 0.66))
    floor = s.material("floor", (0.25, 0.22, 0.2))
    ceiling = s.material("ceiling", (0.8, 0.8, 0.8))
    pictures = [s.material("blue picture", (0.1, 0.2, 0.6)),
                s.material("ochre picture", (0.7, 0.5, 0.15))]
    stone = s.material("statue", (0.8, 0.78, 0.75))
    s.quads(floor, [[(0, 0, 0), (0, 0, 6), (8, 0, 6), (8, 0, 0)]])
    s.quads(ceiling, [[(0, 3.2, 0), (8, 3.2, 0), (8, 3.2, 6), (0, 3.2, 6)]])
    s.box(wall, (0, 0, 0), (8, 3.2, 6), skip=("-y", "+y"))
    # two pictures a centimetre off the back wall, each under its own spot
    for i, x in enumerate((1.5, 5.0)):
        s.quads(pictures[i], [[(x, 1.0, 0.01), (x + 1.5, 1.0, 0.01), (x + 1.5, 2.2, 0.01),
                               (x, 2.2, 0.01)]])
        s.spot_light((x + 0.75, 3.1, 1.6), (x + 0.75, 1.6, 0.0), 6.0, 14 if i else 0, 22,
                     (1.0, 0.92, 0.8))
    # a statue on a plinth in the middle, lit from above by a narrow hard spot
    s.box(stone, (3.6, 0, 2.6), (4.4, 0.9, 3.4))
    s.sphere(stone, (4.0, 1.3, 3.0), 0.4)
    s.spot_light((4.5, 3.1, 3.6), (4.0, 1.0, 3.0), 8.0, 18, 20, (0.95, 0.95, 1.0))
    s.look((7.3, 1.6, 5.6), (3.2, 1.2, 1.0), 60)
    s.write(os.path.join(OUT, "spot_gallery.gltf"))


def long_hall():
    s = Scene()
    stone = s.material("stone", STONE)
    floor = s.material("floor", (0.45, 0.42, 0.38))
    cloth = [s.material("red banner", (0.6, 0.1, 0.08)),
             s.material("blue banner", (0.1, 0.18, 0.55))]
    # a long closed hall, 36 x 10 m and 10 m high (a voxel at 128^3 is about 0.3 m)
    s.quads(floor, [[(-18, 0, -5), (-18, 0, 5), (18, 0, 5), (18, 0, -5)]])
    for x0, x1, z0, z1 in [(-18.3, 18.3, -5.3, -5), (-18.3, 18.3, 5, 5.3), (-18.3, -18, -5, 5),
                           (18, 18.3, -5, 5)]:
        s.box(stone, (x0, 0, z0), (x1, 10, z1))
    # the roof, open along a slit 0.8 m wide down the middle
    s.box(stone, (-18.3, 10, -5.3), (18.3, 10.3, -0.4))
    s.box(stone, (-18.3, 10, 0.4), (18.3, 10.3, 5.3))
    # galleries: slabs one voxel thick on both sides, on columns 3 voxels wide
    for z0, z1 in [(-5, -2.6), (2.6, 5)]:
        s.box(stone, (-18, 4.0, z0), (18, 4.3, z1))
    for side in (-2.6, 2.6):
        for i in range(9):
            x = -16 + 4 * i
            zc = side - 0.45 if side > 0 else side + 0.45
            s.box(stone, (x - 0.45, 0, zc - 0.45), (x + 0.45, 4.0, zc + 0.45))
    # banners of zero thickness hanging from the galleries' edges
    for k, x in enumerate((-14, -6, 2, 10)):
        for side in (-2.6, 2.6):
            s.quads(cloth[k % 2], [[(x, 1.6, side), (x + 1.4, 1.6, side), (x + 1.4, 3.9, side),
                                    (x, 3.9, side)]])
    # the sun through the slit, a strip of light along the floor
    s.sun((0.25, -0.95, 0.18), 6.0, (1.0, 0.93, 0.82))
    s.look((-16.5, 1.7, -1.2), (6, 3.5, 1.0), 60)
    s.write(os.path.join(OUT, "long_hall.gltf"))


def panel_room():
    s = Scene()
    wall = s.material("walls", (0.75, 0.73, 0.68))
    floor = s.material("floor", (0.42, 0.3, 0.2))
    wood = s.material("wood", (0.5, 0.34, 0.18))
    book_colours = [s.material("red books", (0.55, 0.08, 0.06)),
                    s.material("green books", (0.1, 0.35, 0.12)),
                    s.material("cream books", (0.8, 0.75, 0.6))]
    panel = s.material("ceiling panel", (0, 0, 0), emission=(1.0, 0.9, 0.75), strength=30.0)
    s.quads(floor, [[(0, 0, 0), (0, 0, 4), (5, 0, 4), (5, 0, 0)]])
    s.box(wall, (0, 0, 0), (5, 2.7, 4), skip=("-y",))
    # two small emissive panels, 0.4 m square, 1 cm below the ceiling
    for cx, cz in [(1.6, 1.6), (3.5, 2.6)]:
        s.quads(panel, [[(cx - 0.2, 2.69, cz - 0.2), (cx + 0.2, 2.69, cz - 0.2),
                         (cx + 0.2, 2.69, cz + 0.2), (cx - 0.2, 2.69, cz + 0.2)]])
    # a table: a top 3 cm thick on four legs 4 cm square
    s.box(wood, (1.8, 0.72, 1.4), (3.4, 0.75, 2.4))
    for x, z in [(1.85, 1.45), (3.31, 1.45), (1.85, 2.31), (3.31, 2.31)]:
        s.box(wood, (x, 0, z), (x + 0.04, 0.72, z + 0.04))
    # three stools: a seat on three thin legs
    for cx, cz in [(1.5, 2.9), (2.6, 0.9), (3.8, 2.9)]:
        s.box(wood, (cx - 0.17, 0.45, cz - 0.17), (cx + 0.17, 0.48, cz + 0.17))
        for k in range(3):
            a = 2 * math.pi * k / 3
            x, z = cx + 0.12 * math.cos(a), cz + 0.12 * math.sin(a)
            s.box(wood, (x - 0.015, 0, z - 0.015), (x + 0.015, 0.45, z + 0.015))
    # a shelf against the back wall, thin books standing on its boards
    for y in (0.9, 1.35, 1.8):
        s.box(wood, (0.6, y - 0.02, 3.7), (2.4, y, 3.98))
        x = 0.65
        k = 0
        while x < 2.3:
            t = 0.02 + 0.01 * (k % 3)
            h = 0.22 + 0.03 * ((k * 7) % 4)
            s.box(book_colours[k % 3], (x, y, 3.75), (x + t, y + h, 3.96))
            x += t + 0.005
            k += 1
    s.look((4.6, 1.6, 0.3), (1.8, 0.8, 3.2), 60)
    s.write(os.path.join(OUT, "panel_room.gltf"))


if __name__ == "__main__":
    for make in (atrium, window_room, glass_mirror_box, blinds_fins, dense_hall, lamp_room,
                 small_objects, textured_room, spot_gallery, long_hall, panel_room):
        make()
        print("wrote", make.__name__)

#!/usr/bin/env python3
"""Writes two glTF 2.0 scenes larger than the bench scenes, for the shadow techniques that split a
view or a light into several maps. Run from anywhere: `python3 tests/data/make_large_scenes.py`
rewrites them next to this script (deterministic output, standard library only; the Builder comes
from make_gltf.py, the geometry and camera helpers from make_bench_gltf.py).
`python3 tests/data/make_large_scenes.py --views DIR` writes six other views of the terrain into
DIR instead (TERRAIN_VIEWS: turned left and right, from 12 m up, a low, a high and a side sun;
docs/cascades.md), to check a choice tuned on terrain_km.gltf beyond its one frame.

  terrain_km.gltf  a sun 32 degrees up over rolling terrain a kilometre across (a 64x64-cell
                   heightfield, gentle hills within +-10 m) with 360 objects standing on it: houses
                   (boxes 4-15 m), poles (cylinders 0.3-1 m thick, 5-12 m tall), posts (thin boxes)
                   and boulders (spheres 1-4 m), five meshes instanced by many nodes. The camera
                   stands 1.9 m above the ground near the south edge and looks north along the
                   terrain, a few degrees down, out to the far edge 900 m away; a dozen objects
                   stand 6-40 m in front of it, none within 5 m. The sun shines from the front
                   right, so the shadows fall across the view and towards the camera. A test scene
                   for cascaded shadow maps: one map cannot resolve both the near shadows and the
                   kilometre.
  bulb_room.gltf   a closed room 8 x 3 x 6 m (floor, ceiling and four walls, all facing inwards) lit
                   by a bare bulb (a point light 1.8 m up near the middle) among boxes and spheres:
                   some on the floor, some on thin stands at the bulb's height, two hanging from the
                   ceiling on rods, placed so that the floor, the ceiling and each of the four walls
                   catch at least one shadow. The camera stands in a corner under the ceiling and
                   looks across the room with a wide (75 degree) field of view. A test scene for
                   omnidirectional (cube) shadow maps.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_bench_gltf as bench  # noqa: E402
from make_bench_gltf import box, cylinder, light_rotation, look_at_rotation  # noqa: E402
from make_gltf import USHORT, quat_axis_angle, uv_sphere, write_json  # noqa: E402


def rounded(values, digits=3):
    """Node fields rounded so the JSON stays short; millimetres are plenty for these scenes."""
    return [round(v, digits) + 0.0 for v in values]  # + 0.0 turns -0.0 into 0.0


class Lcg:
    """A 32-bit linear congruential generator (Numerical Recipes' constants): the same numbers on
    every Python version and platform, unlike `random`."""

    def __init__(self, seed):
        self.state = seed & 0xFFFFFFFF

    def uniform(self, lo, hi):
        self.state = (1664525 * self.state + 1013904223) & 0xFFFFFFFF
        return lo + (hi - lo) * (self.state / 4294967296.0)


class Scene(bench.Scene):
    """The bench scenes' builder (its materials), but meshes that many nodes instance (mesh() makes
    no node; place() does), and the camera given."""

    def mesh(self, name, geometry, material):
        pos, nrm, idx = geometry
        return self.b.mesh(name, [{"attributes": {"POSITION": self.b.vec3(pos), "NORMAL": self.b.vec3(nrm)},
                                   "indices": self.b.indices(idx, USHORT), "material": material}])

    def place(self, name, mesh, translation, rotation=None, scale=None):
        fields = {"name": name, "mesh": mesh, "translation": rounded(translation)}
        if rotation is not None:
            fields["rotation"] = rounded(rotation, 5)
        if scale is not None:
            fields["scale"] = rounded(scale)
        self.nodes.append(self.b.node(**fields))

    def write(self, name, camera, eye, target, light, light_node):
        self.nodes.append(self.b.node(name="camera", camera=0, translation=rounded(eye),
                                      rotation=rounded(look_at_rotation(eye, target), 5)))
        self.nodes.append(self.b.node(name="light", extensions={"KHR_lights_punctual": {"light": 0}}, **light_node))
        g = self.b.as_gltf()
        g["asset"]["generator"] = "penumbra tests/data/make_large_scenes.py"
        g["materials"] = self.materials
        g["cameras"] = [{"type": "perspective", "perspective": camera}]
        g["extensionsUsed"] = ["KHR_lights_punctual"]
        g["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
        g["scenes"] = [{"nodes": self.nodes}]
        g["scene"] = 0
        write_json(name, g)


# ---- terrain_km.gltf ---------------------------------------------------------------------------

TERRAIN_SIZE = 1000.0
TERRAIN_CELLS = 64
CELL = TERRAIN_SIZE / TERRAIN_CELLS

# Rolling hills: amplitude (m), wave numbers along x and z (1/m), phase.
HILLS = [
    (5.0, 1.0 / 95.0, 0.4 / 95.0, 0.3),
    (3.0, -0.3 / 70.0, 1.0 / 70.0, 1.7),
    (1.5, 0.8 / 38.0, 0.6 / 38.0, 4.1),
    (0.6, -0.7 / 21.0, 0.7 / 21.0, 2.6),
]


def hill_height(x, z):
    return sum(a * math.sin(kx * x + kz * z + ph) for a, kx, kz, ph in HILLS)


def hill_normal(x, z):
    dx = sum(a * kx * math.cos(kx * x + kz * z + ph) for a, kx, kz, ph in HILLS)
    dz = sum(a * kz * math.cos(kx * x + kz * z + ph) for a, kx, kz, ph in HILLS)
    n = (-dx, 1.0, -dz)
    length = math.sqrt(sum(c * c for c in n))
    return tuple(c / length for c in n)


def grid_coordinate(i):
    return -TERRAIN_SIZE / 2.0 + CELL * i


def terrain():
    """The heightfield: (cells + 1)^2 vertices, analytic normals, two triangles a cell (split along
    the cell's diagonal from (i, j) to (i + 1, j + 1)), counter-clockwise seen from above."""
    n = TERRAIN_CELLS + 1
    pos, nrm, idx = [], [], []
    for j in range(n):
        for i in range(n):
            x, z = grid_coordinate(i), grid_coordinate(j)
            pos.append((x, hill_height(x, z), z))
            nrm.append(hill_normal(x, z))
    for j in range(TERRAIN_CELLS):
        for i in range(TERRAIN_CELLS):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i, (j + 1) * n + i + 1
            idx += [a, c, d, a, d, b]
    return pos, nrm, idx


def surface_height(x, z):
    """The height of the triangulated terrain (not of the smooth hills) at x, z."""
    u, v = (x - grid_coordinate(0)) / CELL, (z - grid_coordinate(0)) / CELL
    i, j = min(int(u), TERRAIN_CELLS - 1), min(int(v), TERRAIN_CELLS - 1)
    fu, fv = u - i, v - j
    x0, x1, z0, z1 = grid_coordinate(i), grid_coordinate(i + 1), grid_coordinate(j), grid_coordinate(j + 1)
    h00, h11 = hill_height(x0, z0), hill_height(x1, z1)
    if fv >= fu:  # triangle (i, j), (i, j + 1), (i + 1, j + 1)
        return h00 + fv * (hill_height(x0, z1) - h00) + fu * (h11 - hill_height(x0, z1))
    return h00 + fu * (hill_height(x1, z0) - h00) + fv * (h11 - hill_height(x1, z0))


def lowest_under(x, z, radius):
    """The lowest terrain under a footprint: an object's base sinks to it so no edge floats."""
    return min(surface_height(x + dx * radius, z + dz * radius)
               for dx in (-1.0, 0.0, 1.0) for dz in (-1.0, 0.0, 1.0))


CAMERA_XZ = (-60.0, 440.0)
CAMERA_HEIGHT = 1.9


def terrain_objects(s, meshes, rng):
    """Hand-placed objects 6-40 m in front of the camera, then 348 scattered by the LCG over the
    kilometre (none within 45 m of the camera, no two overlapping)."""
    cx, cz = CAMERA_XZ
    # (kind, metres right of the camera, metres ahead, size): the view looks along -z.
    near = [
        ("pole", 2.0, -7.0, (0.3, 6.0)), ("boulder", -2.5, -9.0, 0.6), ("post", 5.0, -12.0, (0.4, 5.0)),
        ("boulder", 1.0, -15.0, 0.9), ("house", -14.0, -22.0, (6.0, 4.0, 5.0)), ("pole", -4.0, -19.0, (0.4, 8.0)),
        ("pole", 9.0, -24.0, (0.3, 5.5)), ("boulder", -1.5, -28.0, 1.2), ("house", 16.0, -36.0, (8.0, 5.0, 6.0)),
        ("post", -8.0, -32.0, (0.6, 9.0)), ("pole", 4.0, -38.0, (0.8, 11.0)), ("boulder", -4.0, -40.0, 1.8),
    ]
    placed = []
    for k, (kind, right, ahead, size) in enumerate(near):
        placed.append(put(s, meshes, "near %s %d" % (kind, k), kind, cx + right, cz + ahead, size,
                          rng.uniform(0.0, 90.0)))
    count = 0
    while count < 348:
        x, z = rng.uniform(-480.0, 480.0), rng.uniform(-480.0, 480.0)
        roll = rng.uniform(0.0, 1.0)
        if roll < 0.3:
            kind, size = "house", (rng.uniform(4.0, 15.0), rng.uniform(3.0, 9.0), rng.uniform(4.0, 15.0))
        elif roll < 0.6:
            kind, size = "pole", (rng.uniform(0.3, 1.0), rng.uniform(5.0, 12.0))
        elif roll < 0.75:
            kind, size = "post", (rng.uniform(0.3, 1.0), rng.uniform(5.0, 12.0))
        else:
            kind, size = "boulder", rng.uniform(0.5, 2.0)  # radius: 1-4 m across
        turn = rng.uniform(0.0, 90.0)
        r = footprint(kind, size)
        if math.hypot(x - cx, z - cz) < 45.0 + r:
            continue
        if any(math.hypot(x - px, z - pz) < r + pr + 2.0 for px, pz, pr in placed):
            continue
        placed.append(put(s, meshes, "%s %d" % (kind, count), kind, x, z, size, turn))
        count += 1
    return len(placed)


def footprint(kind, size):
    """The radius of the circle around an object's footprint."""
    if kind == "house":
        return 0.5 * math.hypot(size[0], size[2])
    if kind == "boulder":
        return size
    return 0.5 * size[0] * math.sqrt(2.0)


def put(s, meshes, name, kind, x, z, size, turn):
    """One node standing on the terrain at x, z; returns its footprint (x, z, radius)."""
    r = footprint(kind, size)
    base = lowest_under(x, z, r) - 0.1
    rotation = quat_axis_angle((0, 1, 0), turn)
    if kind == "house":
        s.place(name, meshes["box"], (x, base, z), rotation, size)
    elif kind == "boulder":
        # Sunk by a tenth of its radius, so it rests on the ground rather than touching a point.
        s.place(name, meshes["sphere"], (x, surface_height(x, z) + 0.9 * size, z), scale=(size, size, size))
    else:
        thick, tall = size
        mesh = meshes["cylinder"] if kind == "pole" else meshes["box"]
        s.place(name, mesh, (x, base, z), rotation if kind == "post" else None, (thick, tall, thick))
    return x, z, r


# Other views of the same terrain (`--views DIR`), for choices tuned on terrain_km.gltf (the
# cascades' split) to be checked beyond its one frame: (name, camera yaw right of north and pitch
# in degrees, camera height in metres, the sun's elevation and azimuth in degrees).
TERRAIN_VIEWS = [
    ("terrain_yaw_left", -25.0, -4.0, 1.9, 32.0, 197.0),
    ("terrain_yaw_right", 35.0, -6.0, 1.9, 32.0, 197.0),
    ("terrain_high", 8.0, -15.0, 12.0, 32.0, 197.0),
    ("terrain_low_sun", 8.0, -4.0, 1.9, 15.0, 197.0),
    ("terrain_high_sun", 8.0, -4.0, 1.9, 55.0, 160.0),
    ("terrain_side_sun", 8.0, -4.0, 1.9, 32.0, 270.0),
]


def terrain_km(path="terrain_km.gltf", yaw_deg=8.0, pitch_deg=-4.0, height=CAMERA_HEIGHT, sun_elevation=32.0,
               sun_azimuth=197.0):
    s = Scene()
    grass, stone, wood, plaster = (s.material("grass", (0.45, 0.6, 0.35)), s.material("stone", (0.6, 0.58, 0.55)),
                                   s.material("wood", (0.55, 0.4, 0.25)), s.material("plaster", (0.85, 0.8, 0.7)))
    ground = s.mesh("terrain", terrain(), grass)
    s.nodes.append(s.b.node(name="terrain", mesh=ground))
    meshes = {
        # Unit meshes standing on y = 0, sized by the nodes' scale.
        "box": s.mesh("unit box", box(0.0, 0.5, 0.0, 1.0, 1.0, 1.0), plaster),
        "cylinder": s.mesh("unit cylinder", cylinder(0.0, 0.0, 0.5, 1.0, segments=12), wood),
        "sphere": s.mesh("unit sphere", uv_sphere(1.0, 24, 12), stone),
    }
    objects = terrain_objects(s, meshes, Lcg(20240611))
    cx, cz = CAMERA_XZ
    eye = (cx, surface_height(cx, cz) + height, cz)
    # terrain_km.gltf: 4 degrees down, turned 8 degrees right of north (-z).
    yaw, pitch = math.radians(yaw_deg), math.radians(pitch_deg)
    target = (eye[0] + 100.0 * math.sin(yaw) * math.cos(pitch), eye[1] + 100.0 * math.sin(pitch),
              eye[2] - 100.0 * math.cos(yaw) * math.cos(pitch))
    # Travelling down-left and towards the camera: the sun stands to the front right.
    sun = light_rotation(sun_elevation, sun_azimuth)
    s.write(path, {"yfov": math.radians(58.0), "znear": 0.5, "zfar": 1500.0}, eye, target,
            {"name": "sun", "type": "directional", "color": [1.0, 0.97, 0.9], "intensity": 3.0},
            {"rotation": rounded(sun, 5), "translation": [0.0, 300.0, 0.0]})
    return objects


# ---- bulb_room.gltf ----------------------------------------------------------------------------

ROOM = (8.0, 3.0, 6.0)
BULB = (0.2, 1.8, -0.1)


def panel():
    """A unit square in the x-z plane facing +y; the room's nodes turn and size it."""
    pos = [(-0.5, 0.0, -0.5), (-0.5, 0.0, 0.5), (0.5, 0.0, 0.5), (0.5, 0.0, -0.5)]
    return pos, [(0.0, 1.0, 0.0)] * 4, [0, 1, 2, 0, 2, 3]


def room(s, floor_mat, wall_mat, ceiling_mat):
    """Six nodes of one panel mesh, each facing into the room (x -4..4, y 0..3, z -3..3)."""
    w, h, d = ROOM
    floor = s.mesh("floor panel", panel(), floor_mat)
    wall = s.mesh("wall panel", panel(), wall_mat)
    ceiling = s.mesh("ceiling panel", panel(), ceiling_mat)
    # The panel's local x and z are sized before it turns (T * R * S).
    s.place("floor", floor, (0.0, 0.0, 0.0), scale=(w, 1.0, d))
    s.place("ceiling", ceiling, (0.0, h, 0.0), quat_axis_angle((1, 0, 0), 180.0), (w, 1.0, d))
    s.place("wall -z", wall, (0.0, h / 2, -d / 2), quat_axis_angle((1, 0, 0), 90.0), (w, 1.0, h))
    s.place("wall +z", wall, (0.0, h / 2, d / 2), quat_axis_angle((1, 0, 0), -90.0), (w, 1.0, h))
    s.place("wall -x", wall, (-w / 2, h / 2, 0.0), quat_axis_angle((0, 0, 1), -90.0), (h, 1.0, d))
    s.place("wall +x", wall, (w / 2, h / 2, 0.0), quat_axis_angle((0, 0, 1), 90.0), (h, 1.0, d))


def bulb_room():
    s = Scene()
    floor_mat, wall_mat, ceiling_mat = (s.material("floor boards", (0.55, 0.42, 0.3)),
                                        s.material("wall paint", (0.8, 0.78, 0.72)),
                                        s.material("ceiling paint", (0.9, 0.9, 0.9)))
    red, blue, green, metal = (s.material("red", (0.8, 0.2, 0.15)), s.material("blue", (0.2, 0.35, 0.8)),
                               s.material("green", (0.25, 0.65, 0.3)), s.material("metal", (0.4, 0.4, 0.45)))
    room(s, floor_mat, wall_mat, ceiling_mat)
    unit_box = box(0.0, 0.0, 0.0, 1.0, 1.0, 1.0)
    cube = {m: s.mesh("box", unit_box, m) for m in (red, blue, metal)}
    ball = {m: s.mesh("sphere", uv_sphere(1.0, 32, 16), m) for m in (red, green)}
    ceiling = ROOM[1]

    def on_stand(name, x, z, top, mesh, size, sphere=False):
        """A thin metal stand from the floor to `top` with a box or a sphere resting on it."""
        s.place(name + " stand", cube[metal], (x, top / 2, z), scale=(0.05, top, 0.05))
        centre = top + (size if sphere else size[1] / 2)
        s.place(name, mesh, (x, centre, z), scale=(size, size, size) if sphere else size)

    def hanging(name, x, z, bottom, mesh, size, sphere=False):
        """A box or a sphere hanging from the ceiling by a thin rod down to `bottom`, its top."""
        s.place(name + " rod", cube[metal], (x, (ceiling + bottom) / 2, z), scale=(0.03, ceiling - bottom, 0.03))
        centre = bottom - (size if sphere else size[1] / 2)
        s.place(name, mesh, (x, centre, z), scale=(size, size, size) if sphere else size)

    # On the floor: their shadows fall on the floor (and the cabinet's on the -x and -z walls).
    s.place("crate", cube[red], (1.5, 0.4, 1.0), quat_axis_angle((0, 1, 0), 20.0), (0.8, 0.8, 0.8))
    s.place("ball", ball[green], (-1.2, 0.35, 1.2), scale=(0.35, 0.35, 0.35))
    s.place("footstool", cube[blue], (0.9, 0.25, -1.5), quat_axis_angle((0, 1, 0), -15.0), (0.6, 0.5, 0.6))
    s.place("cabinet", cube[blue], (-2.4, 1.1, -1.6), quat_axis_angle((0, 1, 0), 10.0), (0.6, 2.2, 0.5))
    # At the bulb's height: one shadow on each wall.
    on_stand("box on stand +x", 2.3, 0.0, 1.5, cube[red], (0.4, 0.4, 0.4))
    on_stand("sphere on stand -x", -2.0, 0.5, 1.3, ball[red], 0.25, sphere=True)
    on_stand("box on stand +z", 0.5, 1.8, 1.7, cube[blue], (0.5, 0.3, 0.3))
    on_stand("sphere on stand -z", -0.4, -1.9, 1.4, ball[green], 0.2, sphere=True)
    # Above the bulb: shadows on the ceiling.
    hanging("hanging sphere", 0.9, 0.6, 2.55, ball[red], 0.15, sphere=True)
    hanging("hanging box", -0.7, -0.7, 2.6, cube[metal], (0.5, 0.12, 0.35))
    eye, target = (3.7, 2.6, 2.7), (-1.5, 1.1, -1.3)
    s.write("bulb_room.gltf", {"yfov": math.radians(75.0), "znear": 0.05, "zfar": 20.0}, eye, target,
            {"name": "bulb", "type": "point", "color": [1.0, 0.9, 0.75], "intensity": 20.0, "range": 15.0},
            {"translation": list(BULB)})


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--views":
        for name, yaw, pitch, height, elevation, azimuth in TERRAIN_VIEWS:
            terrain_km(os.path.join(os.path.abspath(sys.argv[2]), name + ".gltf"), yaw, pitch, height, elevation, azimuth)
        return
    terrain_km()
    bulb_room()


if __name__ == "__main__":
    main()

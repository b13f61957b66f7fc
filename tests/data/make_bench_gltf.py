#!/usr/bin/env python3
"""Writes the glTF 2.0 scenes `penumbra bench` measures besides the course scene, from easy to hard
for a shadow map. Run from anywhere: `python3 tests/data/make_bench_gltf.py` rewrites them next to
this script (deterministic output, standard library only; the Builder comes from make_gltf.py).

  bench_easy.gltf    a sphere and a box on a ground under a directional light 55 degrees up: large
                     shadows, no grazing angles, one contact edge.
  bench_medium.gltf  a bench on four thin legs and a row of posts under a spot light about 30 degrees up:
                     long thin shadows, four contacts, a slab's shadow.
  bench_curved.gltf  two spheres and two tori (one standing, one lying) on a ground under a spot light
                     about 40 degrees up: smooth closed surfaces, where self-shadow acne rings the
                     terminator unless the map takes their back faces or the bias follows the slope.
  wide_cone.gltf     a cable 40 long on posts 1.2 above a long ground, lit across from close by a spot light
                     with an 80-degree outer cone (a 160-degree cone, issue 56): from 12 to 18 along it on
                     either side its shadow is 75-80 degrees off the spot's axis, beyond what one
                     perspective map holds (75 degrees a side) but inside the cone.
  bench_hard.gltf    a fine grille (bars 4 cm wide, 8 cm apart, along the light) 0.8 above the ground,
                     a staircase and a leaning plank, lit by a point light about 20 degrees up: slits a
                     few texels wide at small maps, grazing light on the ground (acne), many contacts
                     (peter-panning).
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_gltf import Builder, UINT, quat_axis_angle, uv_sphere, write_json  # noqa: E402


def box(cx, cy, cz, sx, sy, sz, rot_y=0.0):
    """A flat-shaded box (24 vertices, outward normals) centred at c with sizes s, turned about y."""
    c, s = math.cos(math.radians(rot_y)), math.sin(math.radians(rot_y))

    def place(x, y, z):
        return (cx + c * x + s * z, cy + y, cz - s * x + c * z)

    def turn(x, y, z):
        return (c * x + s * z, y, -s * x + c * z)

    hx, hy, hz = sx / 2.0, sy / 2.0, sz / 2.0
    faces = [  # normal, four corners counter-clockwise seen from outside
        ((1, 0, 0), [(hx, -hy, hz), (hx, -hy, -hz), (hx, hy, -hz), (hx, hy, hz)]),
        ((-1, 0, 0), [(-hx, -hy, -hz), (-hx, -hy, hz), (-hx, hy, hz), (-hx, hy, -hz)]),
        ((0, 1, 0), [(-hx, hy, hz), (hx, hy, hz), (hx, hy, -hz), (-hx, hy, -hz)]),
        ((0, -1, 0), [(-hx, -hy, -hz), (hx, -hy, -hz), (hx, -hy, hz), (-hx, -hy, hz)]),
        ((0, 0, 1), [(-hx, -hy, hz), (hx, -hy, hz), (hx, hy, hz), (-hx, hy, hz)]),
        ((0, 0, -1), [(hx, -hy, -hz), (-hx, -hy, -hz), (-hx, hy, -hz), (hx, hy, -hz)]),
    ]
    pos, nrm, idx = [], [], []
    for n, quad in faces:
        base = len(pos)
        pos += [place(*p) for p in quad]
        nrm += [turn(*n)] * 4
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, idx


def cylinder(cx, cz, radius, height, segments=24, y0=0.0):
    """An upright capped cylinder on y0, smooth sides, flat caps."""
    pos, nrm, idx = [], [], []
    for i in range(segments + 1):
        a = 2.0 * math.pi * i / segments
        n = (math.cos(a), 0.0, -math.sin(a))
        pos += [(cx + radius * n[0], y0, cz + radius * n[2]), (cx + radius * n[0], y0 + height, cz + radius * n[2])]
        nrm += [n, n]
    for i in range(segments):
        a, b = 2 * i, 2 * i + 2
        idx += [a, b, b + 1, a, b + 1, a + 1]
    for y, ny in ((y0 + height, 1.0), (y0, -1.0)):
        centre = len(pos)
        pos.append((cx, y, cz))
        nrm.append((0.0, ny, 0.0))
        for i in range(segments + 1):
            a = 2.0 * math.pi * i / segments
            pos.append((cx + radius * math.cos(a), y, cz - radius * math.sin(a)))
            nrm.append((0.0, ny, 0.0))
        for i in range(segments):
            p, q = centre + 1 + i, centre + 2 + i
            idx += [centre, p, q] if ny > 0 else [centre, q, p]
    return pos, nrm, idx


def merge(*parts):
    pos, nrm, idx = [], [], []
    for p, n, i in parts:
        base = len(pos)
        pos += p
        nrm += n
        idx += [base + k for k in i]
    return pos, nrm, idx


def look_at_rotation(eye, target):
    """The quaternion turning a glTF camera (looking down -z, +y up) at eye towards target."""
    f = [t - e for t, e in zip(target, eye)]
    fl = math.sqrt(sum(c * c for c in f))
    f = [c / fl for c in f]
    z = [-c for c in f]
    up = (0.0, 1.0, 0.0)
    x = [up[1] * z[2] - up[2] * z[1], up[2] * z[0] - up[0] * z[2], up[0] * z[1] - up[1] * z[0]]
    xl = math.sqrt(sum(c * c for c in x))
    x = [c / xl for c in x]
    y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]]
    m = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]  # rows of the rotation
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        return [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s]
    if m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        return [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    if m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        return [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
    return [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s]


def light_rotation(elevation_deg, azimuth_deg):
    """Rotation pointing a light's -z down at `elevation` below the horizon, towards azimuth (from +x to -z)."""
    el, az = math.radians(elevation_deg), math.radians(azimuth_deg)
    d = (math.cos(el) * math.cos(az), -math.sin(el), -math.cos(el) * math.sin(az))
    return look_at_rotation((0.0, 0.0, 0.0), d)


def ground(size):
    h = size / 2.0
    return ([(-h, 0.0, -h), (-h, 0.0, h), (h, 0.0, h), (h, 0.0, -h)], [(0.0, 1.0, 0.0)] * 4, [0, 1, 2, 0, 2, 3])


class Scene:
    def __init__(self):
        self.b = Builder()
        self.materials = []
        self.nodes = []

    def material(self, name, rgb):
        self.materials.append({"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": [rgb[0], rgb[1], rgb[2], 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.6}})
        return len(self.materials) - 1

    def mesh(self, name, geometry, material, **node):
        pos, nrm, idx = geometry
        m = self.b.mesh(name, [{"attributes": {"POSITION": self.b.vec3(pos), "NORMAL": self.b.vec3(nrm)},
                                "indices": self.b.indices(idx, UINT), "material": material}])
        self.nodes.append(self.b.node(name=name, mesh=m, **node))

    def write(self, name, camera_eye, camera_target, light, light_node):
        self.nodes.append(self.b.node(name="camera", camera=0, translation=list(camera_eye),
                                      rotation=look_at_rotation(camera_eye, camera_target)))
        self.nodes.append(self.b.node(name="light", extensions={"KHR_lights_punctual": {"light": 0}}, **light_node))
        g = self.b.as_gltf()
        g["asset"]["generator"] = "penumbra tests/data/make_bench_gltf.py"
        g["materials"] = self.materials
        g["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.75, "znear": 0.1, "zfar": 60.0}}]
        g["extensionsUsed"] = ["KHR_lights_punctual"]
        g["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
        g["scenes"] = [{"nodes": self.nodes}]
        g["scene"] = 0
        write_json(name, g)


def easy():
    s = Scene()
    grey, red, blue = s.material("grey", (0.7, 0.7, 0.7)), s.material("red", (0.8, 0.2, 0.15)), s.material("blue", (0.2, 0.35, 0.8))
    s.mesh("ground", ground(8.0), grey)
    pos, nrm, idx = uv_sphere(0.8, 48, 24)
    s.mesh("sphere", (pos, nrm, idx), red, translation=[-0.9, 1.1, 0.3])
    s.mesh("box", box(1.2, 0.6, -0.4, 1.0, 1.2, 0.8, rot_y=25.0), blue)
    s.write("bench_easy.gltf", (1.5, 4.5, 7.0), (0.0, 0.3, 0.0),
            {"name": "sun", "type": "directional", "color": [1.0, 0.97, 0.9], "intensity": 3.0},
            {"rotation": light_rotation(55.0, 120.0), "translation": [0.0, 6.0, 0.0]})


def medium():
    s = Scene()
    grey, wood, metal = s.material("grey", (0.7, 0.7, 0.7)), s.material("wood", (0.6, 0.4, 0.2)), s.material("metal", (0.5, 0.55, 0.6))
    s.mesh("ground", ground(10.0), grey)
    # A bench: a slab on four thin legs.
    legs = [cylinder(x, z, 0.05, 0.6) for x in (-1.0, 1.0) for z in (-0.3, 0.3)]
    s.mesh("bench", merge(box(0.0, 0.65, 0.0, 2.4, 0.1, 0.8), *legs), wood, translation=[-0.8, 0.0, 0.6])
    # A row of thin posts.
    posts = [cylinder(-2.5 + 0.7 * i, -1.2, 0.06, 1.6, segments=16) for i in range(8)]
    s.mesh("posts", merge(*posts), metal)
    s.write("bench_medium.gltf", (0.5, 4.0, 7.5), (0.0, 0.4, -0.3),
            {"name": "spot", "type": "spot", "color": [1.0, 0.95, 0.85], "intensity": 40.0,
             "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.85}},
            {"translation": [4.6, 3.3, 2.2], "rotation": look_at_rotation((4.6, 3.3, 2.2), (-0.5, 0.0, -0.3))})


def hard():
    s = Scene()
    grey, dark, stone = s.material("grey", (0.7, 0.7, 0.7)), s.material("dark", (0.25, 0.25, 0.3)), s.material("stone", (0.65, 0.6, 0.55))
    s.mesh("ground", ground(12.0), grey)
    # A grille of 16 bars 4 cm wide, 8 cm apart, on two rails, 0.8 above the ground.
    # The bars run along x, as the light does, so its grazing rays pass between them.
    bars = [box(0.0, 0.8, -0.9 + 0.12 * i, 1.6, 0.04, 0.04) for i in range(16)]
    rails = [box(x, 0.8, 0.0, 0.06, 0.04, 2.0) for x in (-0.8, 0.8)]
    s.mesh("grille", merge(*bars, *rails), dark, translation=[-2.6, 0.0, 1.0])
    # A staircase of five steps, and a plank leaning against its side.
    steps = [box(0.0, 0.1 + 0.2 * i, -0.25 * i, 1.2, 0.2, 1.6 - 0.5 * i) for i in range(4)]
    s.mesh("stairs", merge(*steps), stone, translation=[2.3, 0.0, -1.2])
    plank_tilt = quat_axis_angle((0, 0, 1), 35.0)
    s.mesh("plank", box(0.0, 0.0, 0.0, 0.08, 1.4, 0.3), stone, translation=[1.4, 0.57, 0.4], rotation=plank_tilt)
    s.write("bench_hard.gltf", (0.3, 3.2, 6.0), (0.4, 0.3, -0.2),
            {"name": "lamp", "type": "point", "color": [1.0, 0.9, 0.8], "intensity": 60.0},
            {"translation": [-6.5, 2.3, 1.1]})


def torus(major, minor, segments=64, sides=32):
    """A torus around the y axis, counter-clockwise from outside, the seam vertices duplicated."""
    pos, nrm, idx = [], [], []
    for i in range(segments + 1):
        u = 2.0 * math.pi * i / segments
        for j in range(sides + 1):
            v = 2.0 * math.pi * j / sides
            n = (math.cos(v) * math.cos(u), math.sin(v), math.cos(v) * math.sin(u))
            nrm.append(n)
            pos.append(((major + minor * math.cos(v)) * math.cos(u), minor * math.sin(v),
                        (major + minor * math.cos(v)) * math.sin(u)))
    row = sides + 1
    for i in range(segments):
        for j in range(sides):
            a, b = i * row + j, (i + 1) * row + j
            idx += [a, a + 1, b, a + 1, b + 1, b]
    return pos, nrm, idx


def curved():
    s = Scene()
    grey, red, gold, teal = (s.material("grey", (0.7, 0.7, 0.7)), s.material("red", (0.8, 0.25, 0.2)),
                             s.material("gold", (0.85, 0.65, 0.25)), s.material("teal", (0.2, 0.6, 0.6)))
    s.mesh("ground", ground(10.0), grey)
    s.mesh("big sphere", uv_sphere(0.9, 64, 32), red, translation=[-1.3, 0.9, 0.2])
    s.mesh("small sphere", uv_sphere(0.45, 48, 24), teal, translation=[0.4, 0.45, 1.3])
    s.mesh("lying torus", torus(0.7, 0.22), gold, translation=[1.2, 0.22, -0.6])
    s.mesh("standing torus", torus(0.6, 0.18), teal, translation=[-0.2, 0.78, -1.5],
           rotation=quat_axis_angle((1, 0, 0), 90.0))
    s.write("bench_curved.gltf", (0.8, 3.6, 6.5), (0.0, 0.4, -0.2),
            {"name": "spot", "type": "spot", "color": [1.0, 0.95, 0.85], "intensity": 50.0,
             "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.75}},
            {"translation": [4.0, 4.0, 2.5], "rotation": look_at_rotation((4.0, 4.0, 2.5), (-0.3, 0.3, -0.3))})


def wide_cone():
    s = Scene()
    grey, dark = s.material("grey", (0.7, 0.7, 0.7)), s.material("dark", (0.25, 0.25, 0.3))
    pos, nrm, idx = ground(48.0)
    s.mesh("ground", ([(x, y, z * 0.25 - 1.0) for x, y, z in pos], nrm, idx), grey)
    posts = [cylinder(x, 0.0, 0.08, 1.2, segments=12) for x in (-20.0, -10.0, 0.0, 10.0, 20.0)]
    s.mesh("cable", merge(box(0.0, 1.2, 0.0, 40.0, 0.16, 0.16), *posts), dark)
    # The spot 0.8 above the cable and 1 in front of it, looking down and across: the cable's
    # shadow falls 1.5 behind it, and from 12 to 18 along it on either side it is more than 75
    # degrees off the spot's axis but inside its cone.
    s.write("wide_cone.gltf", (0.0, 44.0, -30.0), (0.0, 0.0, -1.5),
            {"name": "spot", "type": "spot", "color": [1.0, 0.95, 0.85], "intensity": 30.0,
             "spot": {"innerConeAngle": 1.2, "outerConeAngle": math.radians(80.0)}},
            {"translation": [0.0, 2.0, 1.0], "rotation": look_at_rotation((0.0, 2.0, 1.0), (0.0, 0.0, -1.5))})


def main():
    wide_cone()
    curved()
    easy()
    medium()
    hard()


if __name__ == "__main__":
    main()

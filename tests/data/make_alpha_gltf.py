#!/usr/bin/env python3
"""Writes the alpha-tested test scene (glTF alphaMode MASK / BLEND) and its textures.

Run from anywhere: `python3 tests/data/make_alpha_gltf.py` rewrites the files next to this script.
Standard library only (it imports make_gltf.py's Builder and PNG writer); deterministic output.

Files:
  alpha_cutouts.gltf   a 12 x 12 "ground" (opaque grey, y = 0) under a point light at (1, 4, -2),
                       with
                         fence   a vertical 3 x 1.5 quad (x -2.5..0.5, z 0, facing the camera at +z),
                                 MASK, alphaCutoff 0.5, textured with alpha_fence.png: four slats
                                 (5 texels) with gaps (3 texels, alpha 0) and a rail across;
                         leaves  a horizontal 1.6 x 1.6 quad at y 1.3 (x 1.2..2.8, z -0.6..1) whose front
                                 face looks down: MASK, alphaCutoff 0.5, doubleSided, textured with
                                 alpha_leaves.png (three leaf shapes, alpha 0 around them); the
                                 camera above sees only its back face;
                         pane    a vertical 1.2 x 1 quad (x -2.2..-1, z 2), BLEND, base colour
                                 alpha 0.6, no texture: drawn translucent, casting only under
                                 --blend-shadows (then cut at the default cutoff 0.5: all of it);
                       and a perspective camera at (0.5, 4.5, 7) looking at (0.5, 0.4, 0.4).
  alpha_fence.png      32 x 32 RGBA.
  alpha_leaves.png     32 x 32 RGBA.
"""

import json
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_gltf import Builder, UINT, write_json, write_bytes, png  # noqa: E402

SIZE = 32


def png_rgba(width, height, pixel):
    """An 8-bit RGBA PNG; pixel(x, y) -> (r, g, b, a), y = 0 the top row."""
    return png(width, height, 8, 6, lambda y: b"".join(bytes(pixel(x, y)) for x in range(width)))


def fence_texel(x, y):
    # Columns: period 8, slat in 0..4, gap in 5..7 (alpha 0); rows 10..13: the rail.
    wood = (150, 105, 60)
    slat = x % 8 < 5 or 10 <= y <= 13
    return wood + ((255,) if slat else (0,))


def inside_leaf(u, v, cu, cv, angle, length, width):
    # A leaf: the lens between two circle arcs, pointed at both ends, along `angle`.
    c, s = math.cos(angle), math.sin(angle)
    a = (u - cu) * c + (v - cv) * s
    b = -(u - cu) * s + (v - cv) * c
    if abs(a) > length:
        return False
    return abs(b) <= width * (1.0 - (a / length) ** 2)


LEAVES = [(0.30, 0.35, 0.6, 0.26, 0.12), (0.68, 0.40, -0.9, 0.24, 0.11), (0.50, 0.74, 0.2, 0.27, 0.12)]


def leaf_texel(x, y):
    u, v = (x + 0.5) / SIZE, (y + 0.5) / SIZE
    on = any(inside_leaf(u, v, *leaf) for leaf in LEAVES)
    return (60, 140, 50) + ((255,) if on else (0,))


def quad(b, corners, normal, material):
    """corners: top-left, top-right, bottom-right, bottom-left as seen from the front (uv 0,0 at
    the top-left); two triangles wound counter-clockwise seen from the front."""
    uvs = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    return {"attributes": {"POSITION": b.vec3(corners), "NORMAL": b.vec3([normal] * 4),
                           "TEXCOORD_0": b.vec2(uvs)},
            "indices": b.indices([3, 2, 1, 3, 1, 0], UINT), "material": material}


def alpha_cutouts():
    b = Builder()
    g = 6.0
    # Seen from above (+y), the front: top-left is (-g, -g) in (x, z).
    ground = b.mesh("ground", [quad(b, [(-g, 0.0, -g), (g, 0.0, -g), (g, 0.0, g), (-g, 0.0, g)],
                                    (0.0, 1.0, 0.0), 0)])
    fence = b.mesh("fence", [quad(b, [(-2.5, 1.5, 0.0), (0.5, 1.5, 0.0), (0.5, 0.0, 0.0), (-2.5, 0.0, 0.0)],
                                   (0.0, 0.0, 1.0), 1)])
    # Seen from below (-y) the front: top-left is (1, 0.5), top-right (3, 0.5), as seen looking up.
    y = 1.3
    leaves = b.mesh("leaves", [quad(b, [(1.2, y, 1.0), (2.8, y, 1.0), (2.8, y, -0.6), (1.2, y, -0.6)],
                                     (0.0, -1.0, 0.0), 2)])
    pane = b.mesh("pane", [quad(b, [(-2.2, 1.0, 2.0), (-1.0, 1.0, 2.0), (-1.0, 0.0, 2.0), (-2.2, 0.0, 2.0)],
                                 (0.0, 0.0, 1.0), 3)])
    nodes = [b.node(name="ground", mesh=ground), b.node(name="fence", mesh=fence),
             b.node(name="leaves", mesh=leaves), b.node(name="pane", mesh=pane)]
    nodes.append(b.node(name="light", translation=[1.0, 4.0, -2.0], extensions={"KHR_lights_punctual": {"light": 0}}))
    # The camera at (0, 4.5, 7) looking at (0, 0.3, -0.2): a rotation about +x by the pitch.
    eye, at = (0.5, 4.5, 7.0), (0.5, 0.4, 0.4)
    pitch = math.degrees(math.atan2(at[1] - eye[1], eye[2] - at[2]))
    s, c = math.sin(math.radians(pitch) / 2.0), math.cos(math.radians(pitch) / 2.0)
    nodes.append(b.node(name="camera", camera=0, translation=list(eye), rotation=[s, 0.0, 0.0, c]))
    out = b.as_gltf()
    out["asset"]["generator"] = "penumbra tests/data/make_alpha_gltf.py"
    out["images"] = [{"name": "fence", "uri": "alpha_fence.png"}, {"name": "leaves", "uri": "alpha_leaves.png"}]
    out["textures"] = [{"source": 0}, {"source": 1}]
    out["materials"] = [
        {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.7, 0.68, 1.0]}},
        {"name": "fence", "alphaMode": "MASK", "alphaCutoff": 0.5,
         "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "baseColorTexture": {"index": 0}}},
        {"name": "leaves", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "baseColorTexture": {"index": 1}}},
        {"name": "glass", "alphaMode": "BLEND",
         "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.5, 0.9, 0.6]}},
    ]
    out["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.75, "znear": 0.1, "zfar": 50.0}}]
    out["extensionsUsed"] = ["KHR_lights_punctual"]
    out["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "lamp", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": 30.0}]}}
    out["scenes"] = [{"nodes": list(range(len(nodes)))}]
    out["scene"] = 0
    write_json("alpha_cutouts.gltf", out)
    write_bytes("alpha_fence.png", png_rgba(SIZE, SIZE, fence_texel))
    write_bytes("alpha_leaves.png", png_rgba(SIZE, SIZE, leaf_texel))


if __name__ == "__main__":
    alpha_cutouts()

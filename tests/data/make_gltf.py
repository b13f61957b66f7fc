#!/usr/bin/env python3
"""Writes the small glTF 2.0 files the glTF loader's unit tests read (tests/unit/test_gltf.cpp).

Run from anywhere: `python3 tests/data/make_gltf.py` rewrites the files next to this script.
Standard library only, so the data can be regenerated on any machine; the output is
deterministic (fixed float formatting, no timestamps) so a rerun leaves git clean.

Files:
  sphere_over_plane.gltf         UV sphere (r 1, centre y 2) over a 10x10 "ground" at y 0,
                                 a directional light pointing straight down, a perspective camera.
  boxes_no_camera_no_light.gltf  two boxes under a node hierarchy (matrix parent, TRS child),
                                 no camera, no light, `scenes` but no `scene` index.
  boxes_no_camera_no_light.glb   the same scene as a binary glTF (JSON + BIN chunk).
  textured_quad.gltf             a quad with normalized-ubyte TEXCOORD_0 (strided), a 4x4 RGB PNG
                                 baseColorTexture, a baseColorFactor, a spot then a point light;
                                 no `scenes` array at all (all root nodes are drawn).
  quad_point_light.gltf          the same quad lit by the point light alone.
  quad_grey16.gltf               the same quad with a 4x1 16-bit greyscale PNG texture.
  bad_json.gltf                  truncated JSON.
  bad_accessor_range.gltf        a POSITION accessor that reads past the end of its buffer.
  bad_no_position.gltf           a primitive with NORMAL but no POSITION.
  bad_mode_lines.gltf            a primitive drawn as LINES (mode 1).
  bad_index_range.gltf           an index that names a vertex the primitive does not have.
  bad_stride.gltf                a bufferView byteStride smaller than a VEC3 float.
"""

import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))

FLOAT = 5126
UBYTE = 5121
USHORT = 5123
UINT = 5125
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963


class Builder:
    """Accumulates one binary buffer plus the glTF JSON that describes views into it."""

    def __init__(self):
        self.bin = bytearray()
        self.gltf = {
            "asset": {"version": "2.0", "generator": "penumbra tests/data/make_gltf.py"},
            "buffers": [],
            "bufferViews": [],
            "accessors": [],
            "meshes": [],
            "nodes": [],
        }

    def _view(self, data, target, stride=None):
        # Every view starts 4-byte aligned, as glTF requires for float components.
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        if stride is not None:
            view["byteStride"] = stride
        self.bin.extend(data)
        self.gltf["bufferViews"].append(view)
        return len(self.gltf["bufferViews"]) - 1

    def _accessor(self, view, component_type, type_, count, **extra):
        acc = {"bufferView": view, "componentType": component_type, "count": count, "type": type_}
        acc.update(extra)
        self.gltf["accessors"].append(acc)
        return len(self.gltf["accessors"]) - 1

    def vec3(self, values):
        data = b"".join(struct.pack("<3f", *v) for v in values)
        view = self._view(data, ARRAY_BUFFER)
        # POSITION requires min/max in glTF; harmless on NORMAL.
        mn = [min(v[i] for v in values) for i in range(3)]
        mx = [max(v[i] for v in values) for i in range(3)]
        return self._accessor(view, FLOAT, "VEC3", len(values), min=mn, max=mx)

    def vec2(self, values):
        data = b"".join(struct.pack("<2f", *v) for v in values)
        return self._accessor(self._view(data, ARRAY_BUFFER), FLOAT, "VEC2", len(values))

    def vec2_ubyte_normalized(self, values):
        # Two bytes of data padded to a 4-byte stride, so the loader's byteStride path is used.
        data = b"".join(struct.pack("<2B2x", *(round(c * 255) for c in v)) for v in values)
        view = self._view(data, ARRAY_BUFFER, stride=4)
        return self._accessor(view, UBYTE, "VEC2", len(values), normalized=True)

    def indices(self, values, component_type):
        fmt = {UBYTE: "B", USHORT: "H", UINT: "I"}[component_type]
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        return self._accessor(self._view(data, ELEMENT_ARRAY_BUFFER), component_type, "SCALAR",
                              len(values))

    def mesh(self, name, primitives):
        self.gltf["meshes"].append({"name": name, "primitives": primitives})
        return len(self.gltf["meshes"]) - 1

    def node(self, **fields):
        self.gltf["nodes"].append(fields)
        return len(self.gltf["nodes"]) - 1

    def finish_buffer(self):
        while len(self.bin) % 4:
            self.bin.append(0)
        return bytes(self.bin)

    def as_gltf(self):
        data = self.finish_buffer()
        out = dict(self.gltf)
        out["buffers"] = [{
            "byteLength": len(data),
            "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode("ascii"),
        }]
        return out

    def as_glb(self):
        data = self.finish_buffer()
        doc = dict(self.gltf)
        doc["buffers"] = [{"byteLength": len(data)}]
        js = json.dumps(doc, separators=(",", ":")).encode("utf-8")
        js += b" " * ((4 - len(js) % 4) % 4)  # JSON chunk padded with spaces
        body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(data), b"BIN\0") + data
        return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def write_json(name, doc):
    with open(os.path.join(HERE, name), "w", encoding="utf-8", newline="\n") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def write_bytes(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


# ---- geometry --------------------------------------------------------------------------------

def uv_sphere(radius, slices, stacks):
    pos, nrm, idx = [], [], []
    for j in range(stacks + 1):
        theta = math.pi * j / stacks
        for i in range(slices + 1):
            phi = 2.0 * math.pi * i / slices
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            nrm.append(n)
            pos.append(tuple(radius * c for c in n))
    row = slices + 1
    for j in range(stacks):
        for i in range(slices):
            a, b = j * row + i, (j + 1) * row + i
            # Counter-clockwise seen from outside; the pole rows lose their degenerate triangle.
            if j != 0:
                idx += [a, a + 1, b]
            if j != stacks - 1:
                idx += [a + 1, b + 1, b]
    return pos, nrm, idx


def quad_xz(size):
    h = size / 2.0
    pos = [(-h, 0.0, -h), (-h, 0.0, h), (h, 0.0, h), (h, 0.0, -h)]
    nrm = [(0.0, 1.0, 0.0)] * 4
    uv = [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]
    return pos, nrm, uv, [0, 1, 2, 0, 2, 3]


def unit_cube_shared():
    """8 shared corners of the cube -0.5..0.5, 12 triangles wound outward; no normals."""
    pos = [(x, y, z) for z in (-0.5, 0.5) for y in (-0.5, 0.5) for x in (-0.5, 0.5)]
    # corner index = x + 2y + 4z (0 = low, 1 = high)
    faces = [
        (0, 2, 3, 1),  # -z
        (4, 5, 7, 6),  # +z
        (0, 4, 6, 2),  # -x
        (1, 3, 7, 5),  # +x
        (0, 1, 5, 4),  # -y
        (2, 6, 7, 3),  # +y
    ]
    idx = []
    for a, b, c, d in faces:
        idx += [a, b, c, a, c, d]
    return pos, idx


def unit_cube_soup():
    """The same cube as 36 unindexed vertices (one per triangle corner)."""
    pos, idx = unit_cube_shared()
    return [pos[i] for i in idx]


def quat_axis_angle(axis, degrees):
    s = math.sin(math.radians(degrees) / 2.0)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(math.radians(degrees) / 2.0)]


# ---- PNG ---------------------------------------------------------------------------------------

def png(width, height, bit_depth, color_type, row):
    """A PNG from row(y) -> the bytes of row y (big-endian samples), y = 0 is the top row."""
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    raw = b"".join(b"\0" + row(y) for y in range(height))  # filter type 0 on every row
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


def png_rgb(width, height, pixel):
    """An 8-bit RGB PNG; pixel(x, y) -> (r, g, b)."""
    return png(width, height, 8, 2, lambda y: b"".join(bytes(pixel(x, y)) for x in range(width)))


def png_grey16(values):
    """A one-row 16-bit greyscale PNG: the loader must scale it down to 8 bits and fill RGBA."""
    return png(len(values), 1, 16, 0, lambda y: struct.pack(">%dH" % len(values), *values))


def texel(x, y):
    # Distinct per pixel so a test can check both the position and the channel order.
    return (x * 64, y * 64, 200)


# ---- the scenes ----------------------------------------------------------------------------------

def sphere_over_plane():
    b = Builder()
    pos, nrm, idx = uv_sphere(1.0, 32, 16)
    sphere = b.mesh("sphere", [{
        "attributes": {"POSITION": b.vec3(pos), "NORMAL": b.vec3(nrm)},
        "indices": b.indices(idx, USHORT), "material": 0}])
    qpos, qnrm, quv, qidx = quad_xz(10.0)
    ground = b.mesh("ground", [{
        "attributes": {"POSITION": b.vec3(qpos), "NORMAL": b.vec3(qnrm), "TEXCOORD_0": b.vec2(quv)},
        "indices": b.indices(qidx, UINT), "material": 1}])
    n_sphere = b.node(name="sphere", mesh=sphere, translation=[0.0, 2.0, 0.0])
    n_ground = b.node(name="ground", mesh=ground)
    # -90 degrees about +x turns the node's -z (where glTF lights shine) into -y.
    n_sun = b.node(name="sun", rotation=quat_axis_angle((1, 0, 0), -90.0),
                   translation=[0.0, 10.0, 0.0], extensions={"KHR_lights_punctual": {"light": 0}})
    # A camera at (0, 4, 12) pitched down 10 degrees towards the sphere.
    n_cam = b.node(name="camera", camera=0, translation=[0.0, 4.0, 12.0],
                   rotation=quat_axis_angle((1, 0, 0), -10.0))
    g = b.as_gltf()
    g["materials"] = [
        {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1.0]}},
        {"name": "grey", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1.0]}},
    ]
    g["cameras"] = [{"type": "perspective",
                     "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100.0, "aspectRatio": 1.5}}]
    g["extensionsUsed"] = ["KHR_lights_punctual"]
    g["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "sun", "type": "directional", "color": [1.0, 0.9, 0.8], "intensity": 3.0}]}}
    g["scenes"] = [{"nodes": [n_sphere, n_ground, n_sun, n_cam]}]
    g["scene"] = 0
    write_json("sphere_over_plane.gltf", g)


def boxes():
    b = Builder()
    spos, sidx = unit_cube_shared()
    box_a = b.mesh("box_a", [{"attributes": {"POSITION": b.vec3(spos)},
                              "indices": b.indices(sidx, UBYTE), "material": 0}])
    # No indices and no material: the loader generates 0..35 and the default grey.
    box_b = b.mesh("box_b", [{"attributes": {"POSITION": b.vec3(unit_cube_soup())}}])
    # child: scale (2,1,1) then 90 degrees about +y; world = parent * T * R * S.
    child = b.node(name="box_a", mesh=box_a, rotation=quat_axis_angle((0, 1, 0), 90.0),
                   scale=[2.0, 1.0, 1.0])
    # parent: a column-major matrix holding the translation (1, 2, 3).
    parent = b.node(name="rig", children=[child],
                    matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1])
    other = b.node(name="box_b", mesh=box_b, translation=[-3.0, 0.5, 0.0], scale=[0.5, 0.5, 0.5])
    b.gltf["materials"] = [
        {"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.2, 0.9, 1.0]}}]
    # `scenes` without `scene`: the loader falls back to scene 0.
    b.gltf["scenes"] = [{"nodes": [parent, other]}]
    write_json("boxes_no_camera_no_light.gltf", b.as_gltf())
    write_bytes("boxes_no_camera_no_light.glb", b.as_glb())


def textured_quad(point_only=False, grey16=False):
    b = Builder()
    qpos, qnrm, quv, qidx = quad_xz(2.0)
    quad = b.mesh("quad", [{
        "attributes": {"POSITION": b.vec3(qpos), "NORMAL": b.vec3(qnrm),
                       "TEXCOORD_0": b.vec2_ubyte_normalized(quv)},
        "indices": b.indices(qidx, UINT), "material": 0}])
    # Spot first in node order, so it is the light the loader keeps.
    n_quad = b.node(name="quad", mesh=quad)
    n_spot = b.node(name="spot", translation=[0.0, 3.0, 0.0],
                    rotation=quat_axis_angle((1, 0, 0), -90.0),
                    extensions={"KHR_lights_punctual": {"light": 1}})
    n_point = b.node(name="point", translation=[2.0, 4.0, 1.0],
                     extensions={"KHR_lights_punctual": {"light": 0}})
    g = b.as_gltf()
    image = png_grey16([0x0000, 0x4000, 0x8000, 0xFFFF]) if grey16 else png_rgb(4, 4, texel)
    g["images"] = [{"name": "checker",
                    "uri": "data:image/png;base64," + base64.b64encode(image).decode("ascii")}]
    g["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
    g["textures"] = [{"sampler": 0, "source": 0}]
    g["materials"] = [{"name": "textured", "pbrMetallicRoughness": {
        "baseColorFactor": [1.0, 0.5, 0.25, 1.0], "baseColorTexture": {"index": 0}}}]
    g["extensionsUsed"] = ["KHR_lights_punctual"]
    g["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "point", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": 5.0},
        {"name": "spot", "type": "spot", "color": [0.5, 1.0, 0.25], "intensity": 20.0,
         "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
    ]}}
    # Root nodes only, no `scenes`: the loader walks every node that is nobody's child.
    assert [n_quad, n_spot, n_point] == [0, 1, 2]
    if grey16:
        write_json("quad_grey16.gltf", g)
    elif point_only:
        # Same quad lit by the point light alone; drop the spot node, keep both light definitions.
        del g["nodes"][n_spot]
        write_json("quad_point_light.gltf", g)
    else:
        write_json("textured_quad.gltf", g)


def one_triangle(**prim_overrides):
    """A valid one-triangle file that the callers then break in one specific way."""
    b = Builder()
    pos = b.vec3([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, -1.0)])
    nrm = b.vec3([(0.0, 1.0, 0.0)] * 3)
    prim = {"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": b.indices([0, 1, 2], USHORT)}
    prim.update(prim_overrides)
    b.mesh("triangle", [prim])
    b.node(name="triangle", mesh=0)
    b.gltf["scenes"] = [{"nodes": [0]}]
    b.gltf["scene"] = 0
    return b


def malformed():
    # Truncated halfway through an object: not JSON at all.
    with open(os.path.join(HERE, "bad_json.gltf"), "w", encoding="utf-8", newline="\n") as f:
        f.write('{"asset": {"version": "2.0"}, "meshes": [{"primitives": [\n')

    # POSITION claims 1000 vertices but its view holds 3.
    g = one_triangle().as_gltf()
    g["accessors"][0]["count"] = 1000
    write_json("bad_accessor_range.gltf", g)

    b = one_triangle()
    g = b.as_gltf()
    del g["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
    write_json("bad_no_position.gltf", g)

    write_json("bad_mode_lines.gltf", one_triangle(mode=1).as_gltf())

    # The second index becomes 7 while the triangle has 3 vertices.
    b = one_triangle()
    data = bytearray(b.finish_buffer())
    struct.pack_into("<H", data, b.gltf["bufferViews"][2]["byteOffset"] + 2, 7)
    b.bin = data
    write_json("bad_index_range.gltf", b.as_gltf())

    g = one_triangle().as_gltf()
    g["bufferViews"][0]["byteStride"] = 4  # a VEC3 float needs 12
    write_json("bad_stride.gltf", g)


def main():
    sphere_over_plane()
    boxes()
    textured_quad()
    textured_quad(point_only=True)
    textured_quad(grey16=True)
    malformed()


if __name__ == "__main__":
    main()

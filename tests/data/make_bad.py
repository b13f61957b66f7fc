#!/usr/bin/env python3
"""Writes tests/data/bad/: small hostile glTF files, one per class of the hostile-input audit, and
expected.tsv: for each file the exit status `penumbra render`, `export` and `truth` must end with
and a fragment of the one-line message they must print. Run it again after changing a case:
  python3 tests/data/make_bad.py            # rewrites tests/data/bad/
What cannot live in git (FIFOs, devices, folders named .gltf, symbolic links) is made at test time
by tests/bad_inputs.sh, which lists those cases itself."""
import base64
import copy
import json
import os
import struct
import sys
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bad")


def triangle(positions=None):
    """A one-triangle scene with a camera and a point light: the base every case spoils."""
    pos = positions or [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, -1.0)]
    data = b"".join(struct.pack("<3f", *p) for p in pos) + struct.pack("<3H", 0, 1, 2) + b"\0\0"
    return {
        "asset": {"version": "2.0", "generator": "penumbra tests/data/make_bad.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 10.0}]}},
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
        "meshes": [{"name": "triangle", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100.0}}],
        "nodes": [{"name": "triangle", "mesh": 0},
                  {"name": "camera", "camera": 0, "translation": [0.3, 1.0, 3.0]},
                  {"name": "light", "translation": [0.0, 3.0, 0.0],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "scenes": [{"nodes": [0, 1, 2]}],
        "scene": 0,
    }


def png(width, height):
    """An RGBA8 PNG of a pattern that does not compress away (so cutting it leaves IDAT short)."""
    raw = b"".join(b"\0" + bytes((x * 37 + y * 101 + c * 53) % 251 for x in range(width) for c in range(4))
                   for y in range(height))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def textured(image_uri):
    """The triangle with TEXCOORD_0 and a base colour texture from image_uri."""
    g = triangle()
    uv = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    data = base64.b64decode(g["buffers"][0]["uri"].split(",", 1)[1]) + uv
    g["buffers"][0] = {"byteLength": len(data),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}
    g["bufferViews"].append({"buffer": 0, "byteOffset": 44, "byteLength": 24})
    g["accessors"].append({"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"})
    g["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2
    g["meshes"][0]["primitives"][0]["material"] = 0
    g["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    g["textures"] = [{"source": 0}]
    g["images"] = [{"uri": image_uri}]
    return g


CASES = []  # (file name, exit status, message fragment, the document or bytes)


def case(name, status, message, doc):
    CASES.append((name, status, message, doc))


def spoil(edit):
    g = triangle()
    edit(g)
    return g


# Crashes: nesting that overflows a recursive parser, numbers that overflow what they become.
case("deep_nesting.gltf", 2, "nested deeper than 64 levels",
     b'{"asset":{"version":"2.0"},"extras":' + b"[" * 50000 + b"]" * 50000 + b"}")
case("translation_1e38.gltf", 2, "nodes[0].translation[0] is 1e+38: over the limit of 1e+12",
     spoil(lambda g: g["nodes"][0].update(translation=[1e38, 0.0, 0.0])))
case("number_overflows.gltf", 2, "number overflow parsing '1e400'",
     json.dumps(spoil(lambda g: g["nodes"][0].update(translation=[0.0, 12345.0, 0.0])))
     .replace("12345.0", "1e400").encode())
case("scale_1e30.gltf", 2, "nodes[0].scale[0] is 1e+30: over the limit of 1e+12",
     spoil(lambda g: g["nodes"][0].update(scale=[1e30, 1e30, 1e30])))
case("scale_far_out.gltf", 2, "nodes[0] puts 'triangle' at a coordinate of 1.05e+12: over the limit of 1e+12 world units",
     spoil(lambda g: g["nodes"][0].update(scale=[1e11, 1e11, 1e11], translation=[9.5e11, 0.0, 0.0])))
case("camera_scaled_to_zero.gltf", 2, "nodes[1] (camera 0): its transform is singular",
     spoil(lambda g: g["nodes"][1].update(scale=[0.0, 0.0, 0.0])))
case("zfar_1e300.gltf", 2, "cameras[0].perspective.zfar is 1e+300: outside 1e-09..1e+12",
     spoil(lambda g: g["cameras"][0]["perspective"].update(zfar=1e300)))
case("znear_1e-30.gltf", 2, "cameras[0].perspective.znear is 1e-30: outside 1e-09..1e+12",
     spoil(lambda g: g["cameras"][0]["perspective"].update(znear=1e-30)))
case("aspect_1e30.gltf", 2, "cameras[0].perspective.aspectRatio is 1e+30: outside 0.001..1000",
     spoil(lambda g: g["cameras"][0]["perspective"].update(aspectRatio=1e30)))
case("depth_range_1e12.gltf", 2, "zfar / znear is 1e+12, over the limit of 1e10",
     spoil(lambda g: g["cameras"][0]["perspective"].update(znear=1e-6, zfar=1e6)))
case("light_intensity_1e300.gltf", 2, "lights[0].intensity is 1e+300: outside 0..1e+12",
     spoil(lambda g: g["extensions"]["KHR_lights_punctual"]["lights"][0].update(intensity=1e300)))
case("light_colour_negative.gltf", 2, "lights[0].color[1] is -1: outside 0..1e+06",
     spoil(lambda g: g["extensions"]["KHR_lights_punctual"]["lights"][0].update(color=[1.0, -1.0, 1.0])))

# Accepted but wrong, before: versions, negative offsets and strides, non-finite vertices, an
# index of 1e20, absurd counts.
case("version_3.gltf", 2, "asset.version is '3.0': only glTF 2.x is read",
     spoil(lambda g: g["asset"].update(version="3.0")))
case("version_1.gltf", 2, "asset.version is '1.0': only glTF 2.x is read",
     spoil(lambda g: g["asset"].update(version="1.0")))
case("min_version_2.1.gltf", 2, "asset.minVersion is '2.1': this reader implements glTF 2.0",
     spoil(lambda g: g["asset"].update(minVersion="2.1")))
case("no_asset.gltf", 2, "asset: missing", spoil(lambda g: g.pop("asset")))
case("negative_byte_offset.gltf", 2, "bufferViews[1].byteOffset is -36: expected a whole number",
     spoil(lambda g: g["bufferViews"][1].update(byteOffset=-36)))
case("negative_byte_stride.gltf", 2, "bufferViews[0].byteStride is -12: expected a whole number",
     spoil(lambda g: g["bufferViews"][0].update(byteStride=-12)))
case("fractional_count.gltf", 2, "accessors[0].count is 2.5: expected a whole number",
     spoil(lambda g: g["accessors"][0].update(count=2.5)))
case("count_1e9.gltf", 2, "accessors[0].count is 1000000000: over the limit of 67108864",
     spoil(lambda g: g["accessors"][0].update(count=1000000000)))
case("light_index_1e20.gltf", 2,
     "nodes[2].extensions.KHR_lights_punctual.light is 1e+20: expected a whole number in 0..2147483647",
     spoil(lambda g: g["nodes"][2]["extensions"]["KHR_lights_punctual"].update(light=1e20)))
case("light_index_5.gltf", 2, "nodes[2].extensions.KHR_lights_punctual.light is 5: not a light's index (0..0)",
     spoil(lambda g: g["nodes"][2]["extensions"]["KHR_lights_punctual"].update(light=5)))
case("mesh_index_negative.gltf", 2, "nodes[0].mesh is -5: expected a whole number",
     spoil(lambda g: g["nodes"][0].update(mesh=-5)))
nan = float("nan")
case("nan_position.gltf", 2, "accessors[0] (POSITION of mesh 0 'triangle' primitive 0): element 1 is not finite",
     triangle([(0.0, 0.0, 0.0), (nan, 0.0, 0.0), (0.0, 0.0, -1.0)]))
case("inf_position.gltf", 2, "accessors[0] (POSITION of mesh 0 'triangle' primitive 0): element 2 is not finite",
     triangle([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, float("inf"), -1.0)]))

# Files a scene names: only inside its folder, only regular files, only relative names.
case("buffer_traversal.gltf", 2, "buffers[0].uri '../../../../../../../../etc/passwd' is outside the scene's folder",
     spoil(lambda g: g["buffers"][0].update(uri="../../../../../../../../etc/passwd")))
case("buffer_absolute.gltf", 2, "buffers[0].uri '/etc/passwd' is outside the scene's folder",
     spoil(lambda g: g["buffers"][0].update(uri="/etc/passwd")))
case("buffer_percent_traversal.gltf", 2, "is outside the scene's folder",
     spoil(lambda g: g["buffers"][0].update(uri="%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd")))
case("buffer_url.gltf", 2, "only relative file names and data: URIs are read",
     spoil(lambda g: g["buffers"][0].update(uri="file:///etc/passwd")))
case("buffer_is_folder.gltf", 2, "buffers[0].uri '.' is not a regular file",
     spoil(lambda g: g["buffers"][0].update(uri=".")))
case("image_traversal.gltf", 2, "images[0].uri '../../../../../../../../etc/passwd' is outside the scene's folder",
     textured("../../../../../../../../etc/passwd"))

def glb(doc):
    """doc (a document, or JSON text as bytes) as a binary glTF: the 12-byte header and one JSON
    chunk padded with spaces."""
    text = doc if isinstance(doc, bytes) else json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    return struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text)) + struct.pack("<I4s", len(text), b"JSON") + text


# The same checks reach the JSON chunk of a .glb.
case("version_3.glb", 2, "asset.version is '3.0': only glTF 2.x is read",
     glb(spoil(lambda g: g["asset"].update(version="3.0"))))
case("deep_nesting.glb", 2, "nested deeper than 64 levels",
     glb(b'{"asset":{"version":"2.0"},"extras":' + b"[" * 70 + b"]" * 70 + b"}"))
case("glb_traversal.glb", 2, "buffers[0].uri '../../../../../../../../etc/passwd' is outside the scene's folder",
     glb(spoil(lambda g: g["buffers"][0].update(uri="../../../../../../../../etc/passwd"))))

# The GLB header's own version: 1 (KHR_binary_glTF's layout, a glTF 1.0 document) was read as 2.
def glb_version(version, doc):
    data = glb(doc)
    return data[:4] + struct.pack("<I", version) + data[8:]


case("glb_header_version_1.glb", 2, "GLB header version is 1: only version 2 (glTF 2.0) is read",
     glb_version(1, triangle()))

# A damaged texture costs the texture, not the scene (exit 0, a note).
case("truncated_png.gltf", 0, "image 0 in",
     textured("data:image/png;base64," + base64.b64encode(png(32, 32)[:500]).decode()))


def main():
    os.makedirs(OUT, exist_ok=True)
    for old in os.listdir(OUT):
        if old.endswith(".gltf") or old.endswith(".glb"):
            os.remove(os.path.join(OUT, old))
    lines = ["# file\texit status\tmessage fragment (penumbra render, export and truth; written by make_bad.py)"]
    for name, status, message, doc in CASES:
        body = doc if isinstance(doc, bytes) else (json.dumps(doc, indent=1, allow_nan=True) + "\n").encode()
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(body)
        lines.append(f"{name}\t{status}\t{message}")
    with open(os.path.join(OUT, "expected.tsv"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {len(CASES)} files and expected.tsv to {OUT}")


if __name__ == "__main__":
    sys.exit(main())

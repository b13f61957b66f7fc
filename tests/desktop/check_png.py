#!/usr/bin/env python3
"""Checks that a PNG is a real picture: the expected size (optional) and not blank (many distinct
colours, a spread of brightness). Prints one line with what it found.

usage: check_png.py FILE.png [WIDTHxHEIGHT]
Decodes 8-bit greyscale, RGB and RGBA PNGs with the standard library (zlib), no imaging package.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or interlace or ctype not in (0, 2, 6):
                sys.exit(f"{path}: unsupported PNG (depth {depth}, colour type {ctype}, interlace {interlace})")
            channels = {0: 1, 2: 3, 6: 4}[ctype]
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def read_rgb(path):
    """width, height and the pixels' R, G, B in one flat list, rows top first."""
    w, h, c, rows = read_png(path)
    return w, h, [v for row in rows for x in range(w) for v in row[x * c:x * c + 3]]


def main():
    path = sys.argv[1]
    width, height, channels, rows = read_png(path)
    if len(sys.argv) > 2:
        want = tuple(int(v) for v in sys.argv[2].split("x"))
        if (width, height) != want:
            sys.exit(f"{path}: {width}x{height}, expected {sys.argv[2]}")
    colours, lum = set(), []
    for row in rows[::2]:
        for x in range(0, width, 2):
            px = tuple(row[x * channels:x * channels + min(channels, 3)])
            colours.add(px)
            lum.append(sum(px) / len(px))
    mean = sum(lum) / len(lum)
    sd = (sum((v - mean) ** 2 for v in lum) / len(lum)) ** 0.5
    print(f"{path}: {width}x{height}, {len(colours)} distinct colours, brightness mean {mean:.1f} sd {sd:.1f}")
    if len(colours) < 64 or sd < 10:
        sys.exit(f"{path}: looks blank")


if __name__ == "__main__":
    main()

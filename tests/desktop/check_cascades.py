#!/usr/bin/env python3
"""Checks frames of the cascades exercise (the terrain under a low sun, --aov cascades tints each
pixel by the cascade that shadows it: red, green, blue, yellow from near to far).

usage: check_cascades.py tints FILE.png N       the picture shows exactly the first N tints
       check_cascades.py faces FILE.png N       at least N of a point light's cube's six face tints
                                                (+x red, -x green, +y blue, -y yellow, +z magenta,
                                                -z cyan: the bulb exercise) are shown
       check_cascades.py differ A.png B.png S   more than a share S of the pixels differ (by over 16)
       check_cascades.py match A.png B.png      the same frame: mean absolute difference <= 1.5
                                                levels, under 0.5 % of pixels off by more than 16

A tint is counted on the saturated pixels (saturation over 0.3, value over 0.15: the dark sky is
neither) by hue: red within 25 degrees of 0, yellow 40..70, green 90..150, blue 200..260. A tint is
there when it holds at least 0.05 % of the picture's pixels and absent when it holds under 0.01 %
(the blend band mixes neighbours: between the two is neither). Prints one line with the shares.
Exit status 1 naming what failed.
"""
import colorsys
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_png import read_rgb  # noqa: E402

TINTS = [("red", lambda h: h <= 25 or h >= 335), ("green", lambda h: 90 <= h <= 150),
         ("blue", lambda h: 200 <= h <= 260), ("yellow", lambda h: 40 <= h <= 70)]
FACES = TINTS + [("magenta", lambda h: 285 <= h <= 320), ("cyan", lambda h: 170 <= h <= 195)]
PRESENT, ABSENT = 0.0005, 0.0001


def rgb(path):
    w, h, flat = read_rgb(path)
    return w, h, [tuple(flat[i:i + 3]) for i in range(0, len(flat), 3)]


def tint_shares(path, tints=TINTS):
    w, h, px = rgb(path)
    counts = {name: 0 for name, _ in tints}
    for r, g, b in px:
        hue, sat, val = colorsys.rgb_to_hsv(r / 255.0, g / 255.0, b / 255.0)
        if sat < 0.3 or val < 0.15:
            continue
        deg = hue * 360.0
        for name, inside in tints:
            if inside(deg):
                counts[name] += 1
                break
    return {k: v / float(w * h) for k, v in counts.items()}


def main():
    what = sys.argv[1]
    failed = []
    if what == "tints":
        path, n = sys.argv[2], int(sys.argv[3])
        shares = tint_shares(path)
        print("%s: %s" % (os.path.basename(path), ", ".join("%s %.3f %%" % (k, 100 * v) for k, v in shares.items())))
        for i, (name, _) in enumerate(TINTS):
            if i < n and shares[name] < PRESENT:
                failed.append("%s holds %.4f %% of the pixels: cascade %d is not shown" % (name, 100 * shares[name], i))
            if i >= n and shares[name] > ABSENT:
                failed.append("%s holds %.4f %% of the pixels with %d cascade(s)" % (name, 100 * shares[name], n))
    elif what == "faces":
        path, n = sys.argv[2], int(sys.argv[3])
        shares = tint_shares(path, FACES)
        print("%s: %s" % (os.path.basename(path), ", ".join("%s %.3f %%" % (k, 100 * v) for k, v in shares.items())))
        shown = [k for k, v in shares.items() if v >= PRESENT]
        if len(shown) < n:
            failed.append("%d face tints shown (%s), want at least %d" % (len(shown), ", ".join(shown), n))
    elif what in ("differ", "match"):
        wa, ha, a = rgb(sys.argv[2])
        wb, hb, b = rgb(sys.argv[3])
        if (wa, ha) != (wb, hb):
            failed.append("sizes differ: %dx%d and %dx%d" % (wa, ha, wb, hb))
        else:
            diff = [max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b)]
            mean = sum(sum(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b)) / (3.0 * len(a))
            off = sum(1 for d in diff if d > 16) / float(len(a))
            print("%s vs %s: mean abs diff %.3f, off by 16: %.3f %%" % (
                os.path.basename(sys.argv[2]), os.path.basename(sys.argv[3]), mean, 100 * off))
            if what == "differ" and not off > float(sys.argv[4]):
                failed.append("only %.3f %% of the pixels changed (want over %.3f %%)" % (100 * off, 100 * float(sys.argv[4])))
            if what == "match" and not (mean <= 1.5 and off <= 0.005):
                failed.append("the frames differ: mean %.3f (<= 1.5), off by 16 %.3f %% (<= 0.5 %%)" % (mean, 100 * off))
    else:
        sys.exit("check_cascades.py: unknown check '%s'" % what)
    for f in failed:
        print("FAILED: " + f)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""desktop.soft-penumbra: how wide the soft shadows exercise's penumbra is, measured on its
screenshots in the visibility view (white lit, black shadowed, grey between; written as RGB).

The width in pixels is the penumbra's area over its length: the pixels neither lit nor shadowed
(13..242) over the shadow's outline (the neighbour pairs, across and down, whose values lie on
either side of 128). A hard shadow's is 0; PCF's about its kernel; a light with a size widens it.

usage: check_soft.py shadow VIS.png MIN MAX        the share of shadowed pixels (< 64) lies in [MIN, MAX]
       check_soft.py wider A.png B.png FACTOR      A's penumbra is at least FACTOR times as wide as B's, and 1 px wider
"""
import sys

from check_png import read_png


def grey(path):
    width, height, channels, rows = read_png(path)
    return width, height, [[row[x * channels] for x in range(width)] for row in rows]


def penumbra_width(path):
    width, height, px = grey(path)
    area = sum(1 for row in px for v in row if 12 < v < 243)
    outline = 0
    for y in range(height):
        for x in range(width):
            v = px[y][x]
            if x + 1 < width and (v < 128) != (px[y][x + 1] < 128):
                outline += 1
            if y + 1 < height and (v < 128) != (px[y + 1][x] < 128):
                outline += 1
    return area / max(outline, 1), area, outline


def main():
    what = sys.argv[1]
    if what == "shadow":
        _, _, px = grey(sys.argv[2])
        share = sum(1 for row in px for v in row if v < 64) / sum(len(row) for row in px)
        lo, hi = float(sys.argv[3]), float(sys.argv[4])
        print(f"{sys.argv[2]}: {100 * share:.1f}% of the pixels shadowed (want {100 * lo:g}..{100 * hi:g}%)")
        if not lo <= share <= hi:
            sys.exit(f"{sys.argv[2]}: {100 * share:.1f}% shadowed, outside {100 * lo:g}..{100 * hi:g}%")
        return
    if what == "wider":
        (wa, aa, la), (wb, ab, lb) = penumbra_width(sys.argv[2]), penumbra_width(sys.argv[3])
        factor = float(sys.argv[4])
        print(f"penumbra width: {sys.argv[2]} {wa:.2f} px ({aa} px over an outline of {la}), "
              f"{sys.argv[3]} {wb:.2f} px ({ab} over {lb}); want at least x{factor:g} and +1 px")
        if la == 0:
            sys.exit(f"{sys.argv[2]}: no shadow outline")
        if not (wa >= factor * wb and wa >= wb + 1.0):
            sys.exit(f"the penumbra of {sys.argv[2]} ({wa:.2f} px) is not {factor:g} times as wide as {sys.argv[3]}'s ({wb:.2f} px)")
        return
    sys.exit(__doc__)


if __name__ == "__main__":
    main()

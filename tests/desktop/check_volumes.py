#!/usr/bin/env python3
"""desktop.volumes-*: what the shadow volumes exercise's screenshots must show, in its visibility
view (white lit, black shadowed; written as RGB).

usage: check_volumes.py shadow VIS.png MIN MAX      the share of shadowed pixels lies in [MIN, MAX]
       check_volumes.py same A.png B.png MAX        at most MAX of the pixels differ by more than 64
       check_volumes.py differ A.png B.png MIN      at least MIN of the pixels differ by more than 64
"""
import sys

from check_png import read_png


def grey(path):
    width, height, channels, rows = read_png(path)
    return width, height, [row[x * channels] for row in rows for x in range(width)]


def main():
    what = sys.argv[1]
    if what == "shadow":
        _, _, px = grey(sys.argv[2])
        share = sum(1 for v in px if v < 64) / len(px)
        lo, hi = float(sys.argv[3]), float(sys.argv[4])
        print(f"{sys.argv[2]}: {100 * share:.1f}% of the pixels shadowed (want {100 * lo:g}..{100 * hi:g}%)")
        if not lo <= share <= hi:
            sys.exit(f"{sys.argv[2]}: {100 * share:.1f}% shadowed, outside {100 * lo:g}..{100 * hi:g}%")
        return
    wa, ha, a = grey(sys.argv[2])
    wb, hb, b = grey(sys.argv[3])
    if (wa, ha) != (wb, hb):
        sys.exit(f"sizes differ: {wa}x{ha} and {wb}x{hb}")
    share = sum(1 for x, y in zip(a, b) if abs(x - y) > 64) / len(a)
    limit = float(sys.argv[4])
    print(f"{sys.argv[2]} against {sys.argv[3]}: {100 * share:.2f}% of the pixels differ")
    if what == "same" and share > limit:
        sys.exit(f"they differ in {100 * share:.2f}% of the pixels, more than {100 * limit:g}%")
    if what == "differ" and share < limit:
        sys.exit(f"they differ in only {100 * share:.2f}% of the pixels, less than {100 * limit:g}%")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Checks that a desktop screenshot is a real shadowed frame of the course scene, and that its
shadow lies where the geometry puts it.

usage: check_frame.py DESKTOP.png CLI.png UNSHADOWED.png [CLASSES.png]

  DESKTOP.png     penumbra-desktop's screenshot (the window's last frame)
  CLI.png         `penumbra render` of the same settings and time (headless EGL)
  UNSHADOWED.png  `penumbra render` of the same frame with --technique none: every pixel lit
  CLASSES.png     `penumbra truth`'s classes.png of the same frame: the Embree ray tracer's
                  visibility (valid pixels white where lit, black where shadowed), which shares
                  only the scene data with the renderer, never its shadow code

The table's pixels are those of UNSHADOWED that are neither the background (the clear colour of
its top left pixel) nor the orange teapot. A pixel is in shadow where the frame is markedly darker
than UNSHADOWED there (luma under SHADOW_RATIO of it). Checks, each printed with its figure:
  - the frame matches the CLI's: mean absolute difference, share of pixels off by more than 16;
  - the table is there: its share of the frame, and its lit pixels are bright;
  - there is a shadow on the table: its share of the table, and its contrast (mean luma in the
    shadow over mean luma on the lit table);
  - the shadow is where the CLI's frame has it and where the ray tracer has it: intersection over
    union of the shadow masks on the table, and the distance between their centroids.
Exit status 1 naming every check that failed.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_png import read_png  # noqa: E402

SHADOW_RATIO = 0.75  # a pixel is in shadow where its luma is under this share of the lit frame's

LIMITS = {
    "mean_abs_diff": ("<=", 1.5),     # levels of 255, per channel, against the CLI's frame
    "off_by_16": ("<=", 0.005),       # share of pixels with a channel off by more than 16
    "table_share": (">=", 0.25),      # share of the frame that is table
    "lit_table_luma": (">=", 150.0),  # mean luma of the table outside the shadow
    "shadow_share": ((">=", 0.03), ("<=", 0.5)),  # share of the table in shadow
    "contrast": ("<=", 0.6),          # mean luma in the shadow / on the lit table
    "iou_cli": (">=", 0.97),          # the shadow against the CLI frame's
    "iou_truth": (">=", 0.90),        # the shadow against the ray tracer's
    "centroid_truth_px": ("<=", 3.0),  # centroid distance against the ray tracer's, pixels
}


def pixels(path):
    w, h, c, rows = read_png(path)
    flat = []
    for row in rows:
        for x in range(w):
            flat.append(tuple(row[x * c:x * c + 3]) if c >= 3 else (row[x],) * 3)
    return w, h, flat


def luma(p):
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]


def iou(a, b):
    union = len(a | b)
    return len(a & b) / union if union else 0.0


def centroid(mask, w):
    if not mask:
        return (float("nan"), float("nan"))
    return (sum(i % w for i in mask) / len(mask), sum(i // w for i in mask) / len(mask))


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    w, h, shot = pixels(sys.argv[1])
    sizes = {(w, h)}
    _, _, cli = pixels(sys.argv[2])
    w2, h2, lit = pixels(sys.argv[3])
    sizes.add((w2, h2))
    if len(sizes) != 1 or len(cli) != len(shot):
        sys.exit("check_frame: the images differ in size")
    n = w * h

    background = lit[0]
    table = set()
    for i, p in enumerate(lit):
        is_background = max(abs(p[k] - background[k]) for k in range(3)) <= 12
        is_teapot = p[0] > 1.3 * p[2] + 8  # orange porcelain; the marble is white to bluish grey
        if not is_background and not is_teapot:
            table.add(i)

    def shadow_of(img):
        return {i for i in table if luma(img[i]) < SHADOW_RATIO * luma(lit[i])}

    shadow = shadow_of(shot)
    cli_shadow = shadow_of(cli)
    lit_table = table - shadow
    figures = {}
    figures["mean_abs_diff"] = sum(abs(a[k] - b[k]) for a, b in zip(shot, cli) for k in range(3)) / (3 * n)
    figures["off_by_16"] = sum(1 for a, b in zip(shot, cli) if max(abs(a[k] - b[k]) for k in range(3)) > 16) / n
    figures["table_share"] = len(table) / n
    figures["lit_table_luma"] = sum(luma(shot[i]) for i in lit_table) / max(1, len(lit_table))
    figures["shadow_share"] = len(shadow) / max(1, len(table))
    shadow_luma = sum(luma(shot[i]) for i in shadow) / len(shadow) if shadow else figures["lit_table_luma"]
    figures["contrast"] = shadow_luma / max(1e-6, figures["lit_table_luma"])
    figures["iou_cli"] = iou(shadow, cli_shadow)
    cx, cy = centroid(shadow, w)
    print(f"{sys.argv[1]}: {w}x{h}; against the CLI's frame: mean |diff| {figures['mean_abs_diff']:.3f} levels, "
          f"{100 * figures['off_by_16']:.3f}% of pixels off by > 16; table {100 * figures['table_share']:.1f}% of the "
          f"frame, lit table luma {figures['lit_table_luma']:.1f}; shadow {100 * figures['shadow_share']:.1f}% of the "
          f"table (centroid {cx:.1f}, {cy:.1f}), contrast {figures['contrast']:.3f}; shadow IoU against the CLI's "
          f"{figures['iou_cli']:.4f}")

    if len(sys.argv) == 5:
        wt, ht, classes = pixels(sys.argv[4])
        if (wt, ht) != (w, h):
            sys.exit("check_frame: the truth differs in size")
        truth = {i for i in table if classes[i] == (0, 0, 0)}  # valid and shadowed
        truth_valid = {i for i in table if classes[i] in ((0, 0, 0), (255, 255, 255))}
        # Pixels the ray tracer leaves out (silhouettes, surfaces facing away) are left out here too.
        figures["iou_truth"] = iou(shadow & truth_valid, truth)
        tx, ty = centroid(truth, w)
        figures["centroid_truth_px"] = ((cx - tx) ** 2 + (cy - ty) ** 2) ** 0.5 if shadow else float("inf")
        print(f"  against the ray tracer ({len(truth_valid)} valid table pixels, {len(truth)} shadowed, centroid "
              f"{tx:.1f}, {ty:.1f}): shadow IoU {figures['iou_truth']:.4f}, centroid {figures['centroid_truth_px']:.2f} px away")

    failed = []
    for key, value in figures.items():
        rules = LIMITS[key]
        for op, limit in (rules if isinstance(rules[0], tuple) else (rules,)):
            ok = value <= limit if op == "<=" else value >= limit
            if not ok or value != value:  # NaN fails
                failed.append(f"{key} {value:.4g} (must be {op} {limit})")
    if failed:
        sys.exit(f"{sys.argv[1]}: not the shadowed frame expected: " + "; ".join(failed))
    print(f"{sys.argv[1]}: a shadowed frame, its shadow where the CLI and the ray tracer put it")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Quality against triangles and bytes per level mode, from a sweep's results.csv.

    plot_quality.py results.csv quality.png

Prints one row per level mode and level (faces, triangles, bytes, and each
metric averaged over the views) and draws SSIM and FLIP against triangles
and against bytes (mesh + GPU-compressed textures: what a textured box pays
that a triangle count hides), one line per level mode and baseline:
triangles, because a simplified mesh's faces are triangles while a box's are
quads.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt


def main(results, figure):
    rows = list(csv.DictReader(open(results, newline="")))
    metrics = [m for m in ("psnr", "ssim", "flip") if rows and m in rows[0]]
    groups = defaultdict(list)
    for row in rows:
        groups[(row["model"], row["level_mode"], int(row["level"]))].append(row)
    print(f"{'level mode':<20} {'level':>5} {'faces':>7} {'tris':>7} {'bytes':>9} " + " ".join(f"{m:>7}" for m in metrics))
    curves = defaultdict(list)
    for (model, mode, level), members in sorted(groups.items()):
        faces, triangles = int(members[0]["faces"]), int(members[0]["triangles"])
        size = sum(int(r["bytes"]) for r in members) / len(members)  # the same for every view of a level
        means = {m: sum(float(r[m]) for r in members) / len(members) for m in metrics}
        print(f"{mode:<20} {level:>5} {faces:>7} {triangles:>7} {size:>9.0f} " + " ".join(f"{means[m]:>7.3f}" for m in metrics))
        curves[(model, mode)].append(({"triangles": triangles, "bytes": size}, means))
    figure_metrics = [m for m in ("ssim", "flip") if m in metrics]
    axes_of = {"triangles": "triangles drawn (log)", "bytes": "bytes: mesh + GPU-compressed textures (log)"}
    fig, axes = plt.subplots(len(figure_metrics), 2, figsize=(10, 4 * len(figure_metrics)), squeeze=False)
    for row, metric in enumerate(figure_metrics):
        for axis, cost in zip(axes[row], axes_of):
            for (model, mode), points in sorted(curves.items()):
                points.sort(key=lambda p: p[0][cost])
                style = {"marker": "o"}
                if mode == "simplification":
                    style = {"marker": "o", "linestyle": "--", "color": "black"}
                elif mode == "simplification-best":
                    style = {"marker": "+", "linestyle": ":", "color": "dimgrey"}
                elif mode == "single-box":
                    style = {"marker": "*", "markersize": 12, "linestyle": "none", "color": "black"}
                axis.plot([p[0][cost] for p in points], [p[1][metric] for p in points], label=mode, **style)
            axis.set_xscale("log")
            axis.set_xlabel(axes_of[cost])
            axis.set_ylabel(metric.upper() + (" (higher is better)" if metric == "ssim" else " (lower is better)"))
            axis.grid(True, alpha=0.3)
            axis.legend()
    fig.suptitle("textured-box LoD against mesh simplification: image quality per triangle and per byte")
    fig.tight_layout()
    fig.savefig(figure, dpi=100)
    print(f"plot: {figure}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_quality.py results.csv quality.png")
    main(sys.argv[1], sys.argv[2])

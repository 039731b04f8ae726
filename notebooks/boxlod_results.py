"""Shared helpers of the notebooks: where results are, reading sweep and city
CSVs, deterministic figure files, booktabs tables and LaTeX number macros.

The notebooks read BOXLOD_RESULTS (a workflow output folder, default
../out/workflow/full) and write into BOXLOD_GENERATED (default
RESULTS/paper/generated), the folder the paper's \\input and \\includegraphics
read from.
"""
import math
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import yaml  # noqa: E402

# Same bytes for the same data: fixed SVG ids, no dates or versions in files.
matplotlib.rcParams.update({
    "svg.hashsalt": "boxlod",
    "pdf.compression": 6,
    "figure.dpi": 100,
    "savefig.dpi": 150,
    "font.size": 9,
    "axes.titlesize": 9,
    "legend.fontsize": 7,
    "axes.grid": True,
    "grid.alpha": 0.3,
})

KEYS = ["model", "level_mode", "box_kind", "interpolation", "level", "view", "distance", "render_mode"]
# Level modes in the order of the manual, then the baselines (docs/sweeps.md).
MODES = ["top-down", "bottom-up", "bottom-up-siblings", "box-volume", "box-area", "box-diagonal",
         "box-max-extent", "error-greedy", "hybrid", "simplification", "simplification-best", "cgal", "single-box", "impostor",
         "proxy-baked", "file-lods"]
BASELINES = ("simplification", "simplification-best", "cgal", "single-box", "impostor", "proxy-baked", "file-lods")
# docs/design.md: Cost; bytes = mesh_bytes + texture_bytes_gpu, the uncompressed total is mesh_bytes + texture_bytes.
COST_COLUMNS = ("draw_calls", "mesh_bytes", "texture_bytes", "texture_bytes_gpu", "bytes")
_CYCLE = plt.get_cmap("tab10").colors
STYLE = {mode: dict(color=_CYCLE[i], marker="os^vD<>"[i], linestyle="-") for i, mode in enumerate(MODES[:7])}
STYLE["error-greedy"] = dict(color=_CYCLE[7], marker="P", linestyle="-")
STYLE["hybrid"] = dict(color=_CYCLE[8], marker="X", linestyle="-")
STYLE["simplification"] = dict(color="black", marker="x", linestyle="--")
STYLE["simplification-best"] = dict(color="dimgrey", marker="+", linestyle=":")
STYLE["cgal"] = dict(color="grey", marker="1", linestyle="-.")
STYLE["single-box"] = dict(color="black", marker="*", linestyle="none", markersize=10)
STYLE["impostor"] = dict(color="black", marker="D", linestyle="none", markersize=6)
STYLE["proxy-baked"] = dict(color="saddlebrown", marker="h", linestyle="--")
LOWER_IS_BETTER = {"flip": True, "rmse": True, "psnr": False, "ssim": False, "iou": False}
LABEL = {"psnr": "PSNR (dB)", "ssim": "SSIM", "flip": "FLIP", "rmse": "RMSE", "iou": "IoU"}


def results_dir():
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("BOXLOD_RESULTS", os.path.join(here, "..", "out", "workflow", "full"))


def generated_dir():
    path = os.environ.get("BOXLOD_GENERATED", os.path.join(results_dir(), "paper", "generated"))
    os.makedirs(path, exist_ok=True)
    return path


def profile():
    with open(os.path.join(results_dir(), "profile.yaml")) as f:
        return yaml.safe_load(f)


def sweep(name):
    """A sweep's results.csv (psnr may be inf) joined with its timings."""
    folder = os.path.join(results_dir(), "sweeps", name)
    results = pd.read_csv(os.path.join(folder, "results.csv"), dtype={"view": str, "box_kind": str,
                                                                      "interpolation": str})
    return results


def settings(name):
    """A sweep's settings.txt (the keys it ran with: budgets, sizing, ...)."""
    return host(os.path.join(results_dir(), "sweeps", name, "settings.txt"))


def budgets(setting):
    """A sweep's budgets from its settings: (value, in bytes?) each, a fraction of the original's bytes
    or a size (written NB: toolkit/lod/cut/level_budgets.h); empty for none."""
    text = setting.get("budgets", "none").strip()
    if text == "none":
        return []
    return [(float(b[:-1]), True) if b.endswith("B") else (float(b), False) for b in text.split(",")]


def geometric_mean(values):
    """The geometric mean of positive values (NaN for none)."""
    values = [v for v in values if v == v and v > 0]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def timings(name):
    return pd.read_csv(os.path.join(results_dir(), "sweeps", name, "timings.csv"), dtype={"view": str})


def host(path):
    """key = value lines of a host.txt (or a sweep's settings.txt)."""
    facts = {}
    with open(path) as f:
        for line in f:
            if " = " in line:
                key, value = line.rstrip("\n").split(" = ", 1)
                facts[key] = value
    return facts


def mode_order(modes):
    known = [m for m in MODES if m in set(modes)]
    return known + sorted(set(modes) - set(known))


def add_mse(frame):
    """Mean squared error from psnr (peak 1; inf -> 0), for averaging PSNR
    over views as the PSNR of the mean squared error."""
    frame = frame.copy()
    frame["mse"] = np.where(np.isinf(frame["psnr"]), 0.0, 10.0 ** (-frame["psnr"] / 10.0))
    return frame


def psnr_of(mse):
    return math.inf if mse <= 0 else -10.0 * math.log10(mse)


def per_level(frame, metrics=("psnr", "ssim", "flip")):
    """One row per model, level mode, box kind, interpolation, level, distance
    and render mode: faces, triangles and texels, and each metric over the
    views: mean (PSNR: of the mean squared error), min and max."""
    frame = add_mse(frame) if "psnr" in frame else frame
    group = [k for k in KEYS if k != "view"]
    rows = []
    for key, members in frame.groupby(group, sort=False):
        row = dict(zip(group, key))
        for column in ("obtained_levels", "faces", "triangles", "vertices", "texels", "face_texels", "pages",
                       "page_size", "nodes_with_box", "depth_error", *COST_COLUMNS):
            if column in members:
                row[column] = members[column].iloc[0]
        if "covered_pixels" in members:  # the view's, so a mean over the views
            row["covered_pixels"] = members["covered_pixels"].mean()
        row["views"] = len(members)
        for metric in metrics:
            if metric not in members:
                continue
            if metric == "psnr":
                row["psnr"] = psnr_of(members["mse"].mean())
            else:
                row[metric] = members[metric].mean()
            row[metric + "_min"] = members[metric].min()
            row[metric + "_max"] = members[metric].max()
            row[metric + "_median"] = members[metric].median()
        rows.append(row)
    return pd.DataFrame(rows)


def strongest_simplification(frame):
    """The strongest simplification baseline a sweep ran: simplification-best
    (the best of meshoptimizer's variants per level) when there, else plain."""
    return "simplification-best" if (frame["level_mode"] == "simplification-best").any() else "simplification"


def best_within(levels, mode, budget, metric="flip"):
    """The best mean metric among a level mode's levels with at most `budget`
    triangles (None if it has none that small)."""
    members = levels[(levels["level_mode"] == mode) & (levels["triangles"] <= budget)]
    if members.empty:
        return None
    values = members[metric]
    return values.min() if LOWER_IS_BETTER[metric] else values.max()


def level_means(results, model):
    """One row per family, level and distance measured in every view of the model: mean covered FLIP
    over the views, and the level's bytes (an impostor's or a best simplification's variant may differ
    by view: its largest)."""
    rows = results[results.model == model]
    means = rows.groupby(["level_mode", "level", "distance"], as_index=False).agg(
        error=("flip_covered", "mean"), measured=("flip_covered", "count"), bytes=("bytes", "max"))
    return means[means.measured == rows.view.nunique()]


def original_bytes(results, model):
    """The bytes of the model as read: a level mode's level 0. A baseline's level 0 is a level of its own
    (cgal's simplified mesh may be larger than the original, simplification's welded one smaller)."""
    rows = results[results.model == model]
    return rows[(rows.level == 0) & rows.baseline_variant.isna()].bytes.max()


def cheapest_level(means, original, family, distance, threshold):
    """(level, bytes) of the family's cheapest level within the threshold at the distance and every
    farther one (as a chain draws it from its switch on: toolkit/lod/chain/error_by_distance.h), (0, the
    original's bytes) if none is; (None, NaN) for a family the sweep did not run on the model."""
    if means[means.level_mode == family].empty:
        return None, float("nan")
    distances = sorted(means.distance.unique())
    rows = means[(means.level_mode == family) & (means.distance >= distance)]
    farther = sum(d >= distance for d in distances)
    levels = rows.groupby("level").agg(worst=("error", "max"), measured=("error", "count"), bytes=("bytes", "max"))
    within = levels[(levels.measured == farther) & (levels.worst <= threshold) & (levels.bytes < original)]
    if within.empty:
        return 0, original
    return int(within.bytes.idxmin()), within.bytes.min()


def cheapest_bytes(means, original, family, distance, threshold):
    """The bytes of cheapest_level."""
    return cheapest_level(means, original, family, distance, threshold)[1]


def save(fig, stem):
    """STEM.pdf (the paper) and STEM.png (a look), without dates or versions."""
    folder = generated_dir()
    fig.savefig(os.path.join(folder, stem + ".pdf"), bbox_inches="tight",
                metadata={"CreationDate": None, "ModDate": None, "Producer": None, "Creator": None})
    fig.savefig(os.path.join(folder, stem + ".png"), bbox_inches="tight", metadata={"Software": None})
    plt.close(fig)
    return [os.path.join(folder, stem + ext) for ext in (".pdf", ".png")]


def tex_escape(text):
    text = str(text)
    for a, b in (("\\", r"\textbackslash{}"), ("_", r"\_"), ("%", r"\%"), ("&", r"\&"), ("#", r"\#"),
                 ("$", r"\$"), ("{", r"\{"), ("}", r"\}")):
        text = text.replace(a, b)
    return text


def write_table(stem, header, rows, align=None, note=None):
    """A booktabs tabular (no float: the paper wraps it) in STEM.tex. Cells
    are written as given (strings) or escaped (anything else via str)."""
    align = align or "l" + "r" * (len(header) - 1)
    lines = [f"% generated by notebooks/ from the workflow's CSVs; do not edit",
             f"\\begin{{tabular}}{{{align}}}", "\\toprule",
             " & ".join(header) + r" \\", "\\midrule"]
    for row in rows:
        lines.append(" & ".join(str(cell) for cell in row) + r" \\")
    lines += ["\\bottomrule", "\\end{tabular}"]
    if note:
        lines.append(note)
    path = os.path.join(generated_dir(), stem + ".tex")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def macro_name(name):
    if not re.fullmatch(r"[A-Za-z]+", name):
        raise ValueError(f"LaTeX macro names are letters only: {name!r}")
    return name


def write_macros(stem, values):
    """\\newcommand lines for the paper's numbers (values already formatted)."""
    lines = ["% generated by notebooks/ from the workflow's CSVs; do not edit"]
    for name, value in values.items():
        lines.append(f"\\newcommand{{\\{macro_name(name)}}}{{{value}}}")
    path = os.path.join(generated_dir(), stem + ".tex")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def fmt(value, digits=3):
    """A number for the text or a table: -- for missing, \\infty for inf."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "--"
    if isinstance(value, float) and math.isinf(value):
        return r"$\infty$"
    if isinstance(value, (int, np.integer)):
        return f"{int(value):,}".replace(",", "\\,")
    return f"{value:.{digits}f}"


def count(value):
    return fmt(int(value))

#!/usr/bin/env python3
"""One table of boxlod against its peers from the benchmarks' JSON files
(`make bench` writes them to build/bench/): each row a figure of boxlod, the
peer measured in the same run, and the ratio (docs/performance.md).
Usage: ratio_table.py BENCH_DIR"""
import json
import os
import pathlib
import re
import sys

# (what, file stem, boxlod's benchmark, the peer's benchmark, the peer). Names are
# matched up to Google Benchmark's suffixes (min_time, real_time, iterations).
TIME_ROWS = [
    ("rasterizer, 1M triangles at 1920x1080, 2 threads", "rasterizer", "boxlod_frame/2", "llvmpipe_frame/2",
     "Mesa llvmpipe"),
    ("rasterizer, the same, 1 thread", "rasterizer_1_thread", "boxlod_frame/1", "llvmpipe_frame/1", "Mesa llvmpipe"),
    ("rasterizer, the FZK-Haus at 1920x1080, normal maps, 2 threads", "rasterizer", "boxlod_model/0/2",
     "llvmpipe_model/0/2", "Mesa llvmpipe"),
    ("rasterizer, `manual` at 1920x1080, normal maps, 2 threads", "rasterizer", "boxlod_model/1/2",
     "llvmpipe_model/1/2", "Mesa llvmpipe"),
    ("FLIP at 1920x1080 against a prepared reference, 2 threads", "metrics", "bm_flip_prepared/1920/1080/2",
     "bm_render/1920/1080/2", "rendering the frame"),
    ("a sweep's 26 rows at 256x256 (render + FLIP), 2 threads, each row on one thread", "metrics",
     "bm_sweep_rows/256/1", "bm_sweep_rows/256/0", "one row at a time"),
    ("PNG pages of one `manual` level (colour + normal)", "png", "boxlod_png/0", "stb_png/5/0", "stb_image_write"),
    ("writing level 0 of `manual` as .gltf (10,748 nodes)", "gltf", "BM_WriteManualLevel/writer:1",
     "BM_WriteManualLevel/writer:2", "tinygltf's writer (compact, its own .bin)"),
    ("simplifying `manual` to 10 % of its triangles", "simplification", "bm_meshoptimizer/100/1",
     "bm_cgal_garland_heckbert/100", "CGAL Garland-Heckbert"),
    ("unpacking every level of 25 city buildings", "city", "bm_unpack_levels/25", "bm_city_levels/25/0",
     "building them again"),
]


def load(folder, stem):
    path = folder / f"{stem}.json"
    if not path.exists():
        return None
    return json.loads(path.read_text())["benchmarks"]


def runs_of(benchmarks, name):
    pattern = re.compile(re.escape(name) + r"(/(min_time|iterations|real_time|repeats)[^/]*)*$")
    return [b for b in benchmarks or [] if pattern.match(b.get("run_name", b["name"]))]


def find(benchmarks, name):
    """The benchmark's median over its repetitions where it was repeated
    (`make bench` repeats every benchmark, interleaved at random with its
    peer, so both see the same states of a noisy machine), else its one run."""
    runs = runs_of(benchmarks, name)
    for b in runs:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median":
            return b
    for b in runs:
        if b.get("run_type", "iteration") == "iteration":
            return b
    return None


def spread(benchmarks, name):
    """The repetitions' coefficient of variation (standard deviation over
    mean of the time), or None for a benchmark run once."""
    for b in runs_of(benchmarks, name):
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "cv":
            return b["real_time"]
    return None


def repetitions(b):
    return int(b.get("repetitions", 1)) if b.get("run_type") == "aggregate" else 1


def milliseconds(b):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
    return b["real_time"] * scale


def show_ms(ms):
    return f"{ms * 1000:.0f} us" if ms < 1 else f"{ms:,.1f} ms" if ms < 100 else f"{ms:,.0f} ms"


def cpu_model():
    """The CPU the table was measured on, as /proc/cpuinfo names it."""
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "an unnamed CPU"


def main():
    folder = pathlib.Path(sys.argv[1])
    rows = []
    for what, stem, ours, peer, peer_name in TIME_ROWS:
        benchmarks = load(folder, stem)
        a, b = find(benchmarks, ours), find(benchmarks, peer)
        if not a or not b:
            rows.append((what, "not run", "not run", "", ""))
            continue
        ratio = milliseconds(b) / milliseconds(a)
        shown = [show_ms(milliseconds(x)) + (f" ±{cv * 100:.0f}%" if cv is not None else "")
                 for x, cv in ((a, spread(benchmarks, ours)), (b, spread(benchmarks, peer)))]
        if repetitions(a) > 1 and repetitions(b) > 1:
            what = f"{what} (medians of {min(repetitions(a), repetitions(b))}, interleaved; ± their spread)"
        if "faces" in a and "faces" in b:  # simplifiers: where each stopped
            shown = [f"{t}, {int(x['faces']):,} faces" for t, x in zip(shown, (a, b))]
        reads = f"faster than {peer_name}" if ratio >= 1 else f"{1 / ratio:.2f}x slower than {peer_name}"
        rows.append((what, *shown, f"{ratio:.2f}x", reads))
    city = load(folder, "city")
    levels, select = find(city, "bm_city_levels/25/0"), find(city, "bm_select_frame/10000")
    if levels:
        rows.append(("memory of every level of 25 city buildings", f"{levels['packed MB']:.1f} MB packed",
                     f"{levels['unpacked MB']:.1f} MB decoded", f"{levels['unpacked MB'] / levels['packed MB']:.1f}x",
                     "smaller than keeping them decoded"))
    # Time per building as the city grows (target: no higher than at 100) and as lots repeat designs.
    per_building = {n: find(city, f"bm_city_levels/{n}") for n in ("100/0", "1000/0", "10000/100")}
    for n, what, reads in (("1000/0", "building the levels of 1,000 unique buildings, per building",
                            "of the time per building at 100 (target: at most 1x)"),
                           ("10000/100", "building the levels of 10,000 lots of 100 designs, per building",
                            "faster than 100 unique buildings, each its own")):
        a, b = per_building[n], per_building["100/0"]
        if a and b:
            ratio = b["ms per building"] / a["ms per building"]
            rows.append((what, f"{a['ms per building']:.1f} ms", f"{b['ms per building']:.1f} ms at 100 unique",
                         f"{ratio:.2f}x" if n == "10000/100" else f"{1 / ratio:.2f}x", reads))
    if select:
        rows.append(("selecting the levels of 10,000 buildings, one frame", show_ms(milliseconds(select)), "1 ms target",
                     f"{1 / milliseconds(select):.1f}x", "under the target"))
    print(f"Measured on {cpu_model()} ({os.cpu_count()} cores); compare ratios, not times, across machines.\n")
    print("| what | boxlod | peer | ratio | |")
    print("|---|---:|---:|---:|---|")
    for row in rows:
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()

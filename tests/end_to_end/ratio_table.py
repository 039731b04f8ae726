#!/usr/bin/env python3
"""ratio_table.py on hand-made benchmark JSON: a repeated benchmark is shown
by its median (not its first run) and its spread beside its peer's, a single run as
it is, a missing file as "not run". Usage: ratio_table.py RATIO_TABLE_SCRIPT"""
import json
import pathlib
import subprocess
import sys
import tempfile


def runs(name, times, median=None, cv=None, counters=None):
    """Google Benchmark's JSON entries: one per repetition, and the median and
    coefficient-of-variation aggregates."""
    run_name = f"{name}/min_time:2.000/real_time"
    entries = [{"name": run_name, "run_name": run_name, "run_type": "iteration", "repetitions": len(times),
                "real_time": t, "time_unit": "ms", **(counters or {})} for t in times]
    if median is not None:
        entries.append({"name": run_name + "_median", "run_name": run_name, "run_type": "aggregate",
                        "aggregate_name": "median", "repetitions": len(times), "real_time": median,
                        "time_unit": "ms"})
    if cv is not None:
        entries.append({"name": run_name + "_cv", "run_name": run_name, "run_type": "aggregate",
                        "aggregate_name": "cv", "repetitions": len(times), "real_time": cv, "time_unit": "ms"})
    return entries


def main():
    script = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        bench = pathlib.Path(folder)
        # The first runs (100 ms, 200 ms) would read 2.00x; the medians read 1.67x.
        rasterizer = (runs("boxlod_frame/2", [100, 300, 120], 120, 0.05) +
                      runs("llvmpipe_frame/2", [200, 500, 180], 200, 0.104))
        (bench / "rasterizer.json").write_text(json.dumps({"benchmarks": rasterizer}))
        png = runs("boxlod_png/0", [50]) + runs("stb_png/5/0", [150])
        (bench / "png.json").write_text(json.dumps({"benchmarks": png}))
        city = (runs("bm_city_levels/25/0", [900], counters={"packed MB": 2.0, "unpacked MB": 13.0}) +
                runs("bm_city_levels/100/0", [4000], counters={"ms per building": 40.0}) +
                runs("bm_city_levels/1000/0", [42000], counters={"ms per building": 42.0}) +
                runs("bm_city_levels/10000/100", [5000], counters={"ms per building": 0.5}) +
                runs("bm_select_frame/10000", [0.5]))
        (bench / "city.json").write_text(json.dumps({"benchmarks": city}))
        table = subprocess.run([sys.executable, script, folder], check=True, capture_output=True, text=True).stdout
    rows = {line.split(" | ")[0].lstrip("| "): line for line in table.splitlines()}
    frame = rows.get("rasterizer, 1M triangles at 1920x1080, 2 threads (medians of 3, interleaved; ± their spread)")
    png_row = rows.get("PNG pages of one `manual` level (colour + normal)")
    failures = []
    if not frame or "| 120 ms ±5% | 200 ms ±10% | 1.67x |" not in frame:
        failures.append(f"repeated row not shown by its medians and their spread: {frame}")
    if not png_row or "| 50.0 ms | 150 ms | 3.00x |" not in png_row:
        failures.append(f"single-run row wrong: {png_row}")
    if "| rasterizer, the same, 1 thread | not run | not run |" not in table:
        failures.append("a missing file is not shown as not run")
    city_rows = {
        "memory of every level of 25 city buildings": "| 2.0 MB packed | 13.0 MB decoded | 6.5x |",
        "building the levels of 1,000 unique buildings, per building": "| 42.0 ms | 40.0 ms at 100 unique | 1.05x |",
        "building the levels of 10,000 lots of 100 designs, per building": "| 0.5 ms | 40.0 ms at 100 unique | 80.00x |",
        "selecting the levels of 10,000 buildings, one frame": "| 500 us | 1 ms target | 2.0x |",
    }
    for what, expected in city_rows.items():
        if expected not in rows.get(what, ""):
            failures.append(f"city row {what!r} is not {expected}: {rows.get(what)}")
    if failures:
        print(table)
        print("\n".join(failures))
        sys.exit(1)
    print("ratio table: medians, single runs and missing files as expected")


if __name__ == "__main__":
    main()

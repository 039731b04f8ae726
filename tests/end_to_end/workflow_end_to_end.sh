#!/usr/bin/env bash
# The experiment workflow end to end on its smoke profile, in a temporary
# folder: sweeps and city runs (boxlod), the notebooks executed headless, the
# paper compiled, the results document written. Checks the outputs: every file the paper \inputs or
# \includegraphics exists and is not empty; the level-mode table has one row
# per level mode of the sweep's CSV, the runs table one per job, the render
# modes table one per model and mode, whose parallax rows pay for height
# pages; no number
# macro is nan; the PDF has more than one page; the executed notebooks hold
# no error; a second run of snakemake has nothing to do; a notebook run again
# writes byte-identical figures and tables; a sweep's merged shards equal the
# same sweep run as one job.
# Usage: workflow_end_to_end.sh BOXLOD REPO [KEEP]
#   KEEP: a folder the run's outputs are moved to when every check passed, so
#   workflow_on_slurm.sh compares its SLURM run with them instead of running
#   the profile again. An earlier run's KEEP is replaced; any other folder is refused.
set -u
boxlod=$(realpath "$1")
repo=$(realpath "$2")
keep=${3:+$(realpath -m "$3")}
kept_mark=.workflow_end_to_end
if [ -n "$keep" ] && [ -e "$keep" ]; then
  [ -f "$keep/$kept_mark" ] || { echo "FAIL $keep exists and is not an earlier run's outputs: not replaced"; exit 1; }
  rm -rf "$keep"
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$work/out
generated=$out/paper/generated
python=/usr/bin/python3   # Debian's: pandas, matplotlib, nbconvert (a pyenv python3 on PATH has none)
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

for tool in /usr/bin/snakemake latexmk; do
  command -v "$tool" >/dev/null || { echo "FAIL $tool missing (scripts/install-deps.sh paper)"; exit 1; }
done

snake() {  # snake ARGS...: the workflow, smoke profile, run from the temporary folder
  (cd "$work" && /usr/bin/snakemake -s "$repo/experiments/Snakefile" -j2 \
     --config profile=smoke out="$out" boxlod="$boxlod" python="$python" "$@")
}

start=$(date +%s)
if ! snake > "$work/run1.txt" 2>&1; then
  tail -n 40 "$work/run1.txt"
  for log in "$out"/logs/*.log; do [ -s "$log" ] && { echo "--- $log"; tail -n 15 "$log"; }; done
  echo "FAIL the workflow did not finish"; exit 1
fi
ok "workflow finished in $(( $(date +%s) - start )) s"

# Every file the paper reads exists and is not empty (figures as PDF and PNG).
includes=$(sed -n 's/.*\\\(input\|includegraphics\)\(\[[^]]*\]\)\?{\([^}]*\)}.*/\1 \3/p' "$repo/paper/paper.tex")
[ -n "$includes" ] || fail "no \\input or \\includegraphics found in paper.tex"
while read -r kind name; do
  if [ "$kind" = input ]; then files="$generated/$name.tex"; else files="$generated/$name.pdf $generated/$name.png"; fi
  for file in $files; do
    if [ -s "$file" ]; then ok "generated $(basename "$file") ($(stat -c %s "$file") bytes)"; else fail "missing or empty: $file"; fi
  done
done <<< "$includes"

# Tables against the CSVs they come from; numbers are numbers.
"$python" - "$out" "$repo" <<'EOF' || failures=$((failures + 1))
import csv, glob, os, re, sys
import yaml
out, repo = sys.argv[1], sys.argv[2]
generated = os.path.join(out, "paper", "generated")
bad = 0
def body_rows(name):
    text = open(os.path.join(generated, name + ".tex")).read()
    body = text.split("\\midrule", 1)[1].split("\\bottomrule", 1)[0]
    return [line.split(" & ") for line in body.strip().splitlines()]
def check(condition, message):
    global bad
    print(("ok   " if condition else "FAIL ") + message)
    bad += not condition
modes = []
for row in csv.DictReader(open(os.path.join(out, "sweeps", "manual", "results.csv"))):
    if row["level_mode"] not in modes:
        modes.append(row["level_mode"])
rows = body_rows("table_level_modes")
names = [r[0].replace("\\_", "_") for r in rows]
check(sorted(names) == sorted(modes) and len(rows) == len(modes),
      f"table_level_modes: {len(rows)} rows for the {len(modes)} level modes of the CSV ({', '.join(modes)})")
check(all(b in modes for b in ("simplification", "simplification-best", "single-box")), "the manual sweep has every baseline")
profile = yaml.safe_load(open(os.path.join(out, "profile.yaml")))
jobs = len(profile["sweeps"]) + len(profile["city"]["strategies"])
check(len(body_rows("table_runs")) == jobs, f"table_runs: one row per sweep and city run ({jobs})")
models = {row["model"] for row in csv.DictReader(open(os.path.join(out, "sweeps", "buildings", "results.csv")))}
check(models == set(profile["buildings"]), f"the buildings sweep has the profile's {len(profile['buildings'])} buildings")
check(len(body_rows("table_models")) == 5 + len(profile["buildings"]), "table_models: the five models and each building")
# The hybrid's targets count the real buildings and the samples: a row per model and budget.
budget_models = [row["model"] for sweep in ("real_budgets", "sample_budgets")
                 for row in csv.DictReader(open(os.path.join(out, "sweeps", sweep, "results.csv")))]
check(len(body_rows("table_budgets")) == 4 * len(set(budget_models)) and "sample:house" in budget_models,
      f"table_budgets: four budgets for each of the {len(set(budget_models))} real buildings and samples")
check(len(body_rows("table_strategies")) == len(profile["city"]["strategies"]),
      "table_strategies: one row per strategy")
render = list(csv.DictReader(open(os.path.join(out, "sweeps", "render_modes", "results.csv"))))
pairs = {(row["model"], row["render_mode"]) for row in render if row["render_mode"] != "normal"}
check(len(body_rows("table_render_modes")) == len(pairs) > 0,
      f"table_render_modes: one row per model and render mode beside normal ({len(pairs)})")
# The same LoD costs more where its mode reads the height pages: the cost columns follow the render mode.
cost = {(row["model"], row["level"], row["view"], row["render_mode"]): int(row["texture_bytes_gpu"]) for row in render}
dearer = [key for key, value in cost.items() if key[3] == "parallax" and value > cost[key[:3] + ("normal",)]]
check(dearer and all(cost[key] >= cost[key[:3] + ("normal",)] for key in cost),
      f"render_modes: parallax rows pay for height pages ({len(dearer)} rows dearer than normal, none cheaper)")
for path in sorted(glob.glob(os.path.join(generated, "numbers_*.tex"))):
    values = re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", open(path).read())
    broken = [name for name, value in values if value.strip() == "" or "nan" in value.lower()]
    check(values and not broken, f"{os.path.basename(path)}: {len(values)} macros" + (f", broken: {broken}" if broken else ""))
macros = dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", open(os.path.join(generated, "numbers_bytes.tex")).read()))
for sweep, model in (("manual_bytes", "Manual"), ("fzk_bytes", "Fzk")):
    greedy = {row["level"] for row in csv.DictReader(open(os.path.join(out, "sweeps", sweep, "results.csv")))
              if row["level_mode"] == "error-greedy"}
    levels, beaten = macros.get(f"BytesGreedyLevels{model}", "-1"), macros.get(f"BytesGreedyBeaten{model}", "-1")
    check(greedy and levels.isdigit() and beaten.isdigit() and 0 < int(levels) <= len(greedy) and int(beaten) <= int(levels),
          f"{sweep}: error-greedy counted in the paper ({beaten} of {levels} levels beaten; {len(greedy)} in the CSV)")
# Flat faces shrink the chains' textures (the paying chain against the same chain with flat_faces).
for chain, flat in (("manual_bytes", "manual_flat"), ("fzk_bytes", "fzk_flat")):
    gpu = lambda sweep: {(row["level_mode"], row["level"]): int(row["texture_bytes_gpu"])
                         for row in csv.DictReader(open(os.path.join(out, "sweeps", sweep, "results.csv")))
                         if row["level_mode"] == "top-down"}
    without, with_flat = gpu(chain), gpu(flat)
    check(with_flat.keys() == without.keys() and all(with_flat[k] <= without[k] for k in with_flat)
          and sum(with_flat.values()) < sum(without.values()),
          f"{flat}: top-down textures {sum(with_flat.values())} bytes against {sum(without.values())} without flat faces")
check(len(body_rows("table_bytes")[0]) == 9, "table_bytes: a column for the chain with flat faces")
# The results document: a section per notebook, each generated table with its rows, each figure linked.
results = open(os.path.join(out, "results.md"), encoding="utf-8").read()
notebooks = sorted(glob.glob(os.path.join(repo, "notebooks", "*.ipynb")))
check(results.count("\n## ") == len(notebooks), f"results.md: a section per notebook ({len(notebooks)})")
for path in sorted(glob.glob(os.path.join(generated, "table_*.tex"))):
    stem = os.path.basename(path)[:-4]
    block = results.split(f"*{stem}*:", 1)[1].split("\n\n", 2)[1] if f"*{stem}*:" in results else ""
    check(len(block.splitlines()) == 2 + len(body_rows(stem)), f"results.md: {stem} with its {len(body_rows(stem))} rows")
links = re.findall(r"!\[[^]]*\]\(([^)]+)\)", results)
figures = glob.glob(os.path.join(generated, "*.png"))
check(len(links) == len(figures) and all(os.path.isfile(os.path.join(out, link)) for link in links),
      f"results.md: {len(links)} figures linked, of {len(figures)}")
check(not re.search(r"\\[A-Za-z]", results), "results.md: no LaTeX command left")
for path in sorted(glob.glob(os.path.join(out, "notebooks", "*.ipynb"))):
    import json
    cells = json.load(open(path))["cells"]
    errors = [o for c in cells for o in c.get("outputs", []) if o.get("output_type") == "error"]
    executed = all(c.get("execution_count") for c in cells if c["cell_type"] == "code")
    check(executed and not errors, f"{os.path.basename(path)} executed without errors")
sys.exit(1 if bad else 0)
EOF

# The PDF: count its pages from the page tree (object streams decompressed).
pages=$("$python" - "$out/paper/paper.pdf" <<'EOF'
import re, sys, zlib
data = open(sys.argv[1], "rb").read()
chunks = [data]
for match in re.finditer(rb"stream\r?\n(.*?)endstream", data, re.S):
    try:
        chunks.append(zlib.decompress(match.group(1)))
    except zlib.error:
        pass
counts = [int(m.group(1)) for chunk in chunks
          for m in re.finditer(rb"/Type\s*/Pages\b[^>]*?/Count\s+(\d+)", chunk)]
counts += [int(m.group(1)) for chunk in chunks
           for m in re.finditer(rb"/Count\s+(\d+)[^>]*?/Type\s*/Pages\b", chunk)]
print(max(counts) if counts and data.startswith(b"%PDF") else 0)
EOF
)
logged=$(sed -n 's/^Output written on paper.pdf (\([0-9]*\) pages.*/\1/p' "$out/paper/paper.log")
if [ "${pages:-0}" -gt 1 ] && [ "$pages" = "$logged" ]; then ok "paper.pdf: $pages pages"
else fail "paper.pdf: $pages pages in the file, LaTeX says '$logged'"; fi
if grep -q 'undefined' "$out/paper/paper.log"; then fail "undefined references or citations in paper.log"; fi

# Sharded and merged, a sweep writes what one job writes (docs/sweeps.md: Shards).
shards=$(ls -d "$out"/sweeps/manual/shards/*/ | wc -l)
"$boxlod" sweep "$out/configs/manual.txt" -o "$work/manual_whole" > /dev/null 2>&1 || fail "the manual sweep in one job failed"
if [ "$shards" -gt 1 ] && cmp -s "$work/manual_whole/results.csv" "$out/sweeps/manual/results.csv"; then
  ok "manual sweep: $shards shards merged = one job, byte for byte"
else fail "manual sweep: $shards shards, merged results.csv differs from one job's"; fi

# A second run has nothing to do.
snake > "$work/run2.txt" 2>&1 || fail "second snakemake run failed"
if grep -q 'Nothing to be done' "$work/run2.txt"; then ok "second run: nothing to be done"
else fail "second run did work:"; grep -E '^(rule|localrule) |reason' "$work/run2.txt" | head -n 10; fi

# A notebook run again writes the same bytes.
before=$(cd "$generated" && md5sum quality_manual.pdf quality_manual.png table_level_modes.tex numbers_quality.tex)
snake --forcerun notebook_01_quality > "$work/run3.txt" 2>&1 || fail "forced notebook run failed"
after=$(cd "$generated" && md5sum quality_manual.pdf quality_manual.png table_level_modes.tex numbers_quality.tex)
if [ "$before" = "$after" ]; then ok "01_quality run again: identical figures and tables"
else fail "01_quality run again changed its outputs"; diff <(echo "$before") <(echo "$after"); fi

echo "$(( $(date +%s) - start )) s in all"
[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
if [ -n "$keep" ]; then
  { mkdir -p "$(dirname "$keep")" && mv -T "$out" "$keep" && echo "outputs of workflow_end_to_end.sh" > "$keep/$kept_mark"; } ||
    { echo "FAIL cannot keep the outputs in $keep"; exit 1; }
fi
echo "all checks passed"

#!/usr/bin/env bash
# The experiment workflow on a real scheduler: a one-node SLURM cluster started
# here (tests/end_to_end/slurm_one_node.sh), the smoke profile run through
# `snakemake --profile experiments/workflow/slurm`, and the same profile run
# locally (or the local run workflow_end_to_end.sh kept). Checks: every job
# but Snakemake's local rules went through sbatch
# (each sweep shard, merge and city run records its SLURM job id, and
# Snakemake submitted as many jobs as it ran); the sweeps' results.csv, the
# city runs' frames.csv and every generated table, number and figure but the
# runs' own (times, hosts) equal the local run's byte for byte. Prints one
# SKIP line and exits 77 when this machine cannot start SLURM.
# Usage: workflow_on_slurm.sh BOXLOD REPO [CPUS [LOCAL]]
#   CPUS: the CPUs slurmd offers (default or `all`: every one), one per job.
#   LOCAL: the outputs of a local smoke run (workflow_end_to_end.sh's KEEP, the
#   ctest fixture), compared instead of running the profile locally here.
set -u
boxlod=$(realpath "$1")
repo=$(realpath "$2")
cpus=${3:-all}
[ "$cpus" = all ] && cpus=$(nproc)
kept=${4:-}
[ -z "$kept" ] || [ -d "$kept/sweeps" ] || { echo "FAIL no local run's outputs in $kept (workflow_end_to_end keeps them)"; exit 1; }
work=$(mktemp -d)
cluster=$work/cluster
source "$repo/tests/end_to_end/slurm_one_node.sh"
trap 'slurm_stop "$cluster"; [ -n "${KEEP_WORK:-}" ] || rm -rf "$work"' EXIT
python=/usr/bin/python3
export USER=${USER:-$(id -un)}  # Snakemake's SLURM executor reads it (a CI shell may not set it)
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

if ! slurm_start "$cluster" "$cpus"; then
  echo "SKIP workflow_on_slurm: cannot start a one-node SLURM cluster here: $SLURM_SKIP"
  exit 77
fi
ok "one-node SLURM cluster up: $(sinfo -h -o '%P %D %c %t')"

# One thread a job, so the node runs CPUS jobs at once: a smoke job's time is mostly
# Snakemake starting inside it, not its computing. The outputs do not depend on threads.
threads=(--set-threads sweep_shard=1 sweep=1 city=1)
snake() {  # snake FOLDER ARGS...: the smoke profile into FOLDER/out, run from FOLDER
  local folder=$1
  shift
  mkdir -p "$folder"
  (cd "$folder" && /usr/bin/snakemake -s "$repo/experiments/Snakefile" \
     --config profile=smoke out="$folder/out" boxlod="$boxlod" python="$python" "$@")
}

start=$(date +%s)
if ! snake "$work/slurm" --profile "$repo/experiments/workflow/slurm" "${threads[@]}" > "$work/slurm.txt" 2>&1; then
  tail -n 40 "$work/slurm.txt"
  for log in "$work"/slurm/out/logs/*.log "$work"/slurm/.snakemake/slurm_logs/*/*.log; do
    [ -s "$log" ] && { echo "--- $log"; tail -n 10 "$log"; }
  done
  echo "FAIL the workflow did not finish on SLURM"; exit 1
fi
slurm_seconds=$(( $(date +%s) - start ))
ok "workflow on SLURM ($cpus CPUs) finished in $slurm_seconds s"
local_out=$work/local/out
if [ -n "$kept" ]; then
  local_out=$kept
  ok "the same profile run locally by workflow_end_to_end: $kept"
else
  start=$(date +%s)
  snake "$work/local" -j "$cpus" > "$work/local.txt" 2>&1 || { tail -n 40 "$work/local.txt"; fail "the local run failed"; }
  ok "the same profile locally in $(( $(date +%s) - start )) s"
fi

# Every job went through the scheduler: Snakemake submitted each job it ran but
# the local rules, and every job that records its host ran inside a SLURM job.
ran=$(awk '/^Job stats:/ {on = 1; next} on && $1 == "total" {print $2; exit}' "$work/slurm.txt")
# The local rules as the Snakefile's `localrules:` line names them.
local_rules=$(sed -n 's/^localrules:[[:space:]]*//p' "$repo/experiments/Snakefile" | tr -d ' ')
local_jobs=$(awk -v rules="$local_rules" 'BEGIN {split(rules, r, ","); for (k in r) local[r[k]] = 1}
  /^Job stats:/ {on = 1; next} on && ($1 in local) {n += $2} on && $1 == "total" {print n + 0; exit}' "$work/slurm.txt")
submitted=$(grep -c 'has been submitted with SLURM jobid' "$work/slurm.txt")
if [ -n "$ran" ] && [ "$submitted" -gt 0 ] && [ "$submitted" -eq $((ran - local_jobs)) ]; then
  ok "$submitted of $ran jobs submitted with sbatch (the other $local_jobs: local rules)"
else fail "jobs run: ${ran:-?}, local rules: ${local_jobs:-?}, submitted to SLURM: $submitted"; fi
hosts=$(find "$work/slurm/out" -name host.txt | wc -l)
outside=$(find "$work/slurm/out" -name host.txt -exec grep -l '^slurm_job = none$' {} + | wc -l)
if [ "$hosts" -gt 0 ] && [ "$outside" -eq 0 ]; then ok "$hosts sweep shard, merge and city jobs ran inside SLURM jobs"
else fail "$outside of $hosts jobs ran outside SLURM"; fi

# The same files, with the same bytes, as the local run.
compared_files() {  # compared_files OUT: the results, frames, tables, numbers and figures of a run
  (cd "$1" && find sweeps city paper/generated -type f \
     \( -name results.csv -o -name frames.csv -o -name '*.tex' -o -name '*.png' \) \
     ! -path '*/shards/*' ! -name '*_runs.tex' | LC_ALL=C sort)
}
[ "$(compared_files "$local_out")" = "$(compared_files "$work/slurm/out")" ] ||
  fail "the runs wrote different files: $(diff <(compared_files "$local_out") <(compared_files "$work/slurm/out") | grep '^[<>]' | head -n 5 | tr '\n' ' ')"
compared=0
while read -r file; do
  compared=$((compared + 1))
  cmp -s "$work/slurm/out/$file" "$local_out/$file" || fail "differs from the local run: $file"
done < <(compared_files "$local_out")
[ "$compared" -gt 20 ] && ok "$compared files equal the local run's byte for byte" || fail "only $compared files compared"

echo "seconds_on_slurm = $slurm_seconds"
[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all checks passed"

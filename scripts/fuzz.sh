#!/usr/bin/env bash
# Runs every fuzz target of a BOXLOD_FUZZ build for SECONDS each and prints one
# table: executions, seconds and crashes per target. Usage: fuzz.sh BUILD SECONDS
set -u
build=$1
seconds=${2:-60}
source_corpus=$(cd "$(dirname "$0")/../tests/fuzz/corpus" && pwd)
mkdir -p "$build/corpus" "$build/crashes"
printf '%-22s %12s %8s %8s\n' target executions seconds crashes
failed=0
for fuzzer in "$build"/tests/fuzz/fuzz_*; do
  target=${fuzzer##*/fuzz_}
  mkdir -p "$build/corpus/$target"
  log="$build/fuzz_$target.log"
  # The found corpus first: libFuzzer adds new inputs to the first folder only.
  "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$build/crashes/$target-" "$build/corpus/$target" "$source_corpus/$target" >"$log" 2>&1
  status=$?
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  crashes=$(ls "$build/crashes" | grep -c "^$target-")
  printf '%-22s %12s %8s %8s\n' "$target" "${executions:-?}" "$seconds" "$crashes"
  if [ $status -ne 0 ] || [ "$crashes" -gt 0 ]; then failed=1; echo "  see $log and $build/crashes/$target-*"; fi
done
exit $failed

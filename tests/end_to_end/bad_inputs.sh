#!/usr/bin/env bash
# The bad-input corpus (docs/testing.md: Hardening): every case of bad_inputs.txt is
# hostile input a user could give, and boxlod must answer each with exit
# status 2 and one stderr line that names the file or option, never a crash,
# a hang, an internal error or a file left behind.
#
#   bad_inputs.sh BOXLOD CORPUS_DIR [CASE_REGEX]
#
# BAD_INPUTS_VERBOSE=1 adds each case's time and stderr line to its report.
#
# Manifest lines are `NAME | ARGS`, or `NAME | ARGS | WORDS` where the stderr
# line must also hold WORDS (that the check meant, not another, refused the
# input); ARGS is the boxlod command line (shell
# words, quotes allowed) with placeholders @C (CORPUS_DIR), @W (a fresh empty
# folder for the case, also its working directory) and @D (the big and deep
# inputs bad_inputs_generate.py writes at test time, plus folders, symlinks
# and truncated copies made below). Each case runs under `timeout 60` and
# `ulimit -v 4000000` (4 GB) and must
#   (a) exit with status 2,
#   (b) write exactly one non-empty line to stderr,
#   (c) not say "internal error", and name something (a heuristic): an
#       option or key given after the command name (--x-y, also spelt x_y),
#       the base name of a file or value given there, any --option, or a path,
#   (d) leave nothing in @W or beside it, and nothing new or changed in @C or
#       @D (outputs, temporaries such as *.boxlod-tmp*).
set -u
if [ $# -lt 2 ]; then
  echo "usage: $0 BOXLOD CORPUS_DIR [CASE_REGEX]" >&2
  exit 2
fi
boxlod=$(realpath "$1")
corpus=$(realpath "$2")
filter=${3:-}
here=$(dirname "$(realpath "$0")")
manifest=$here/bad_inputs.txt
time_limit=60
memory_kb=4000000
# AddressSanitizer reserves terabytes of address space for its shadow memory,
# so under it (make test-sanitize) neither ulimit -v nor boxlod's own ceiling
# while assimp reads can apply: the cases only that ceiling stops (assimp
# allocating what a header claims) are skipped, and leaks inside assimp on its
# error paths are not reported.
asan_skip=""
if ldd "$boxlod" 2>/dev/null | grep -q libasan; then
  memory_kb=unlimited
  asan_skip="^(assimp_dae_count_huge_dae|assimp_ply_list_count_huge_ply|assimp_tiny_x)$"
  export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
  echo "bad_inputs: $boxlod runs under AddressSanitizer: no memory limit, 3 cases that need one skipped"
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
generated=$tmp/generated
logs=$tmp/logs
mkdir -p "$logs" "$tmp/cases"

# ---------------------------------------------------------------- generated inputs (@D)
python3 "$here/bad_inputs_generate.py" "$generated" || { echo "FAIL setup: bad_inputs_generate.py"; exit 1; }
# An LoD chain boxlod wrote: viewable, never built from again (a city of two buildings, for tiles).
"$boxlod" generate --city 2 -o "$generated/city.glb" > /dev/null &&
  "$boxlod" build "$generated/city.glb" --chain -o "$generated/lod_chain.glb" --resolution 16 > /dev/null 2>&1 ||
  { echo "FAIL setup: the LoD chain"; exit 1; }
ifc=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc  # Debian assimp-testmodels
if [ -r "$ifc" ]; then
  size=$(stat -c %s "$ifc")
  for percent in 10 50 99; do head -c $((size * percent / 100)) "$ifc" > "$generated/fzk_${percent}_percent.ifc"; done
  # Reference cycles: the first local placement placed relative to a later one
  # that is (through #577) placed relative to it, and one relative to itself.
  sed 's/^#564= IFCLOCALPLACEMENT(\$,#44);/#564= IFCLOCALPLACEMENT(#593,#44);/' "$ifc" > "$generated/fzk_placement_cycle.ifc"
  sed 's/^#564= IFCLOCALPLACEMENT(\$,#44);/#564= IFCLOCALPLACEMENT(#564,#44);/' "$ifc" > "$generated/fzk_placement_self.ifc"
  # References to entities the file does not have: refused before web-ifc runs (they crash assimp's IFC
  # reader: tests/toolkit/formats/assimp_io.cpp).
  sed 's/^#564= IFCLOCALPLACEMENT(\$,#44);/#564= IFCLOCALPLACEMENT(#99999999,#44);/' "$ifc" > "$generated/fzk_placement_missing.ifc"
  sed 's/^#93= IFCPOLYLOOP((#61,#65,#69));/#93= IFCPOLYLOOP((#61,#65,#99999999));/' "$ifc" > "$generated/fzk_polyloop_missing.ifc"
  for f in cycle self missing; do
    if cmp -s "$ifc" "$generated/fzk_placement_$f.ifc"; then echo "FAIL setup: the IFC edit ($f) changed nothing"; exit 1; fi
  done
  if cmp -s "$ifc" "$generated/fzk_polyloop_missing.ifc"; then echo "FAIL setup: the IFC polyloop edit changed nothing"; exit 1; fi
else
  echo "note: $ifc missing (Debian assimp-testmodels); IFC cases will fail"
fi
cp /etc/passwd "$generated/passwd.obj"
cp /etc/passwd "$generated/passwd.gltf"
cp /etc/passwd "$generated/passwd.txt"
for d in dir.gltf dir.glb dir.obj dir.png dir.exr dir.txt dir.grammar clash/out.bin; do mkdir -p "$generated/$d"; done
printf 'a regular file, not a folder\n' > "$generated/a_file"
for f in zero.gltf zero.glb zero.obj zero.txt; do ln -s /dev/zero "$generated/$f"; done
mkdir -p "$generated/sweep_foreign_results"
printf 'some,other,columns\n1,2,3\n' > "$generated/sweep_foreign_results/results.csv"
# A sweep's folder read back (a resume, --merge): made by the good config, then
# damaged one way each, as a hand edit or a full disk would.
"$boxlod" sweep "$corpus/good/sweep.txt" -o "$generated/sweep_made" > /dev/null 2>&1 || { echo "FAIL setup: the good sweep"; exit 1; }
damaged_sweep() {  # NAME FILE SED-SCRIPT: a copy of the good folder with FILE edited
  cp -r "$generated/sweep_made" "$generated/sweep_$1"
  sed -i "$3" "$generated/sweep_$1/$2"
  if cmp -s "$generated/sweep_made/$2" "$generated/sweep_$1/$2"; then echo "FAIL setup: sweep_$1 is not damaged"; exit 1; fi
}
damaged_sweep non_number results.csv '2s/,1,\([0-9]*\),/,1,x\1,/'
damaged_sweep cut_row results.csv '2s/,[^,]*,[^,]*$//'
damaged_sweep nan_metric results.csv '2s/,[^,]*$/,nan/'
damaged_sweep metric_outside_its_range results.csv '2s/,[^,]*$/,-5/'
damaged_sweep duplicate_row results.csv '2p'
damaged_sweep timings_negative timings.csv '2s/,[^,]*$/,-1/'
damaged_sweep settings_binary settings.txt '1s/$/\x01\x02/'
damaged_sweep settings_cut settings.txt '3,$d'
damaged_sweep nul_text results.csv '2s/top-down/top\x00down/'
damaged_sweep binary_text results.csv '2s/^/\xff/'
damaged_sweep timings_nul_text timings.csv '2s/top-down/top\x00down/'
cp -r "$generated/sweep_made" "$generated/sweep_huge_field"
/usr/bin/python3 -c 'import sys; p = sys.argv[1]; t = open(p).read().split("\n"); t[1] = "x" * 1000000 + t[1][t[1].index(","):]; open(p, "w").write("\n".join(t))' \
  "$generated/sweep_huge_field/results.csv"
mkdir -p "$generated/sweep_shards_damaged" && cp -r "$generated/sweep_nan_metric" "$generated/sweep_shards_damaged/shard"
mkdir -p "$generated/sweep_shards_other" && cp -r "$generated/sweep_made" "$generated/sweep_shards_other/shard" &&
  sed -i 's/^width = .*/width = 999/' "$generated/sweep_shards_other/shard/settings.txt"
mkdir -p "$generated/sweep_shards_unsettled" && cp -r "$generated/sweep_made" "$generated/sweep_shards_unsettled/shard" &&
  rm "$generated/sweep_shards_unsettled/shard/settings.txt" && mkdir "$generated/sweep_shards_unsettled/shard/settings.txt"
# A whole shard beside one whose results.csv is a folder: merged, it would silently lose the second.
mkdir -p "$generated/sweep_shards_hollow" && cp -r "$generated/sweep_made" "$generated/sweep_shards_hollow/shard_a" &&
  mkdir -p "$generated/sweep_shards_hollow/shard_b/results.csv"

# Everything in @C and @D, to notice files a case leaves there (directories by name only:
# a temporary that was removed again changes a folder's time, not what it holds).
snapshot() {
  find "$corpus" "$generated" \( -type d -printf 'd %p\n' \) -o -printf '%y %p %s %T@\n' | LC_ALL=C sort
}
baseline=$(snapshot)

# ---------------------------------------------------------------- cases
passed=0
failed=0
total=0
declare -A seen
declare -A class_count
quote() { printf '%q' "$1"; }
option_pattern='(^|[^-])--[a-z]'
path_pattern='/[^/ :]{3,}'
C=$(quote "$corpus")
D=$(quote "$generated")

while IFS= read -r line || [ -n "$line" ]; do
  line=${line%$'\r'}
  [[ "$line" =~ ^[[:space:]]*(#|$) ]] && continue
  if [[ "$line" != *"|"* ]]; then echo "FAIL manifest: no '|' in: $line"; failed=$((failed + 1)); continue; fi
  name=${line%%|*}
  name=${name#"${name%%[![:space:]]*}"}
  name=${name%"${name##*[![:space:]]}"}
  args=${line#*|}
  expected=""  # `NAME | ARGS | WORDS`: the line must also hold WORDS (the check meant fired)
  if [[ "$args" == *"|"* ]]; then
    expected=${args##*|}
    expected=${expected#"${expected%%[![:space:]]*}"}
    args=${args%|*}
  fi
  if [ -n "${seen[$name]:-}" ]; then echo "FAIL manifest: case '$name' given twice"; failed=$((failed + 1)); continue; fi
  seen[$name]=1
  [ -n "$filter" ] && ! [[ "$name" =~ $filter ]] && continue
  [ -n "$asan_skip" ] && [[ "$name" =~ $asan_skip ]] && continue
  total=$((total + 1))

  case_dir=$tmp/cases/$name
  w=$case_dir/w
  mkdir -p "$w"
  W=$(quote "$w")
  expanded=${args//@C/$C}
  expanded=${expanded//@D/$D}
  expanded=${expanded//@W/$W}
  if ! eval "words=($expanded)" 2>/dev/null; then
    echo "FAIL $name: manifest: cannot split ARGS"; failed=$((failed + 1)); continue
  fi
  out=$logs/$name.out
  err=$logs/$name.err
  started=$EPOCHREALTIME
  # The outer subshell keeps bash's own "Segmentation fault" report off the output.
  ( (
    ulimit -v "$memory_kb"
    cd "$w" || exit 99
    unset DISPLAY WAYLAND_DISPLAY
    # `boxlod view` must fail before it opens a window; should it get that far, fail fast.
    export SDL_VIDEODRIVER=bad_inputs_no_window
    exec timeout -k 5 "$time_limit" "$boxlod" "${words[@]}"
  ) >"$out" 2>"$err" </dev/null; exit $? ) 2>/dev/null
  status=$?
  timing=""
  [ -n "${BAD_INPUTS_VERBOSE:-}" ] && timing=$(awk -v a="$started" -v b="$EPOCHREALTIME" 'BEGIN { printf " (%.1f s)", b - a }')

  reasons=()
  class=""
  add() {  # add CLASS REASON: the first class given is the case's class
    [ -z "$class" ] && class=$1
    reasons+=("$2")
  }
  lines=$(awk 'END { print NR }' "$err")
  last=$(awk 'NF { line = $0 } END { print line }' "$err")  # the error, after any progress lines
  if [ "$status" -eq 124 ] || [ "$status" -eq 137 ]; then
    add "hang" "hang: no answer within ${time_limit} s"
  elif [ "$status" -gt 128 ]; then
    add "crash" "crash: signal $((status - 128)) (SIG$(kill -l $((status - 128)) 2>/dev/null))"
  elif [ "$status" -eq 1 ]; then
    add "exit1" "exit 1"
  elif [ "$status" -eq 0 ]; then
    add "exit0" "exit 0"
  elif [ "$status" -ne 2 ]; then
    add "exit_other" "exit $status"
  fi
  if grep -qE "cannot open a window|no display to open a window" "$err"; then
    add "window" "view got as far as opening its window"
  fi
  if [ "$status" -ne 0 ] && [ "$lines" -ne 1 ] && ! { [ "$status" -gt 123 ] && [ "$lines" -eq 0 ]; }; then
    add "message" "$lines lines on stderr"
  fi
  if [ "$status" -eq 2 ] && [ "$lines" -eq 1 ]; then
    if [ -z "$last" ]; then
      add "message" "an empty line on stderr"
    elif [[ "$last" == *"internal error"* ]]; then
      add "message" "internal error"
    else
      # Names something: a word given after the command (an option, also spelt as a key with
      # '_', or the base name of a file or value, 3+ characters), any --option, or a path.
      named=""
      [[ "$last" =~ $option_pattern ]] && named=option
      [[ "$last" =~ $path_pattern ]] && named=path
      for ((i = 1; i < ${#words[@]} && ${#named} == 0; ++i)); do
        word=${words[i]}
        candidates=()
        case "$word" in
          '') candidates=("''") ;;  # an empty argument is named as ''
          --*) option=${word%%=*}; option=${option#--}; candidates=("$option" "${option//-/_}") ;;
          -o) candidates=("output") ;;
          *) base=${word%/}; base=${base##*/}; [ ${#base} -ge 3 ] && candidates=("$base") ;;
        esac
        for c in "${candidates[@]}"; do
          if [ ${#c} -ge 2 ] && [[ "$last" == *"$c"* ]]; then named=$c; break; fi
        done
      done
      [ -z "$named" ] && add "message" "the line names no file, option or key"
      [ -n "$expected" ] && [[ "$last" != *"$expected"* ]] && add "message" "the line does not say '$expected'"
    fi
  fi
  left=$(cd "$case_dir" && find . -mindepth 1 ! -path ./w | sed 's|^\./||' | LC_ALL=C sort)
  if [ -n "$left" ]; then
    if [ "$status" -eq 0 ]; then
      add "leftover" "wrote $(echo "$left" | wc -l) files/folders"
    else
      add "leftover" "left behind: $(echo "$left" | tr '\n' ' ' | sed 's/ $//')"
    fi
  fi
  now=$(snapshot)
  if [ "$now" != "$baseline" ]; then
    changed=$(diff <(echo "$baseline") <(echo "$now") | sed -n 's/^> [a-z] \([^ ]*\).*/\1/p' |
              sed "s|^$corpus|@C|; s|^$generated|@D|" | tr '\n' ' ')
    add "leftover" "left in @C/@D: ${changed% }"
    baseline=$now
  fi

  if [ ${#reasons[@]} -eq 0 ]; then
    if [ -n "${BAD_INPUTS_VERBOSE:-}" ]; then echo "ok   $name$timing: $(printf '%s' "$last" | cut -c1-150)"; else echo "ok   $name"; fi
    passed=$((passed + 1))
  else
    why=$(IFS=';'; echo "${reasons[*]}" | sed 's/;/; /g')
    shown=""
    [ -n "$last" ] && shown=": stderr: $(printf '%s' "$last" | cut -c1-150)"
    echo "FAIL $name$timing: $why$shown"
    failed=$((failed + 1))
    class_count[$class]=$(( ${class_count[$class]:-0} + 1 ))
  fi
  rm -rf "$case_dir"
done < "$manifest"

summary="bad_inputs: $total cases, $passed ok, $failed failed"
for c in crash hang exit1 exit0 exit_other window message leftover; do
  [ -n "${class_count[$c]:-}" ] && summary+=", $c ${class_count[$c]}"
done
echo "$summary"
[ "$failed" -eq 0 ]

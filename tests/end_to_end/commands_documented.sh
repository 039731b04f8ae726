#!/usr/bin/env bash
# docs/commands.md names every option of every command: each option that
# `boxlod COMMAND --help` lists appears in that command's rows of the table,
# or the row names a shared list: "[LoD options]" (build's), "[render
# options]" (render's); --max-memory, which every command takes, is named once
# above the table. Prints every option missing and fails if there is one.
# Usage: commands_documented.sh BOXLOD DOCS/commands.md
set -u
boxlod=$1 doc=$2
# "long short" per option ("output o"; "fovy" alone when it has no short form).
options_of() { "$boxlod" "$1" --help | sed -n 's/^ *\(-\(.\), \)\{0,1\}--\([a-z0-9-]*\).*/\3 \2/p' | grep -v '^help\|^max-memory'; }
commands=$("$boxlod" --help | sed -n 's/^  \([a-z]*\)  .*/\1/p')
[ -n "$commands" ] || { echo "no commands in '$boxlod --help'"; exit 1; }
missing=0 checked=0
grep -qF -- "--max-memory" "$doc" || { echo "$doc: --max-memory, which every command takes, is not named"; missing=1; }
for command in $commands; do
  rows=$(grep -F "| \`boxlod $command " "$doc")
  [ -n "$rows" ] || { echo "$doc: no row for '$command'"; missing=1; continue; }
  while read -r option short; do
    checked=$((checked + 1))
    grep -qF -- "--$option" <<<"$rows" && continue
    [ -n "$short" ] && grep -qF -- "-$short " <<<"$rows" && continue
    [ "$command" != build ] && grep -qF "[LoD options]" <<<"$rows" && options_of build | grep -q "^$option\b" && continue
    [ "$command" != render ] && grep -qF "[render options]" <<<"$rows" && options_of render | grep -q "^$option\b" && continue
    echo "$doc: boxlod $command --$option is not in its row"; missing=1
  done < <(options_of "$command")
done
[ $missing -eq 0 ] && echo "$checked options of $(wc -w <<<"$commands") commands, each in docs/commands.md"
exit $missing

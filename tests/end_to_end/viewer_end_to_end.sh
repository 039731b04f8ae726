#!/usr/bin/env bash
# boxlod view under a virtual X server, driven by event files: its screenshot
# must be byte-identical to `boxlod render` with the same parameters.
set -u
boxlod=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
model=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
failures=0
check() {
  local name=$1; shift
  if "$@"; then echo "ok   $name"; return; fi
  echo "FAIL $name"; failures=$((failures + 1))
  sed 's/^/     stderr: /' "$work/err" 2>/dev/null | head -5  # the last run's, to tell the viewer's failure from X's
}
# xvfb-run -a, again when the X server itself failed to start (another
# server taking the same display number at that moment): the viewer's own
# failures are never retried. stderr goes to $work/err. The authority file is
# ours (-f): xvfb-run's own temporary folder once failed its clean-up under
# ctest -j2, and its exit status 5 hid the viewer's.
xrun() {
  local attempt status
  for attempt in 1 2 3; do
    xvfb-run -a -f "$work/Xauthority" "$@" > /dev/null 2> "$work/err"
    status=$?
    grep -q "Xvfb failed to start" "$work/err" || return $status
  done
  return $status
}
view() {  # view EVENTS SCREENSHOT [options]
  local events=$1 shot=$2; shift 2
  xrun "$boxlod" view "$model" --replay "$events" --screenshot "$shot" --width 320 --height 240 --threads 2 "$@"
}
render() {  # render OUT [options]
  local out=$1; shift
  "$boxlod" render "$model" -o "$out" --width 320 --height 240 "$@" > /dev/null
}

printf '# nothing but the start view\n' > "$work/none.txt"
view "$work/none.txt" "$work/v0.png"; render "$work/r0.png"
check "start view equals render's defaults" cmp -s "$work/v0.png" "$work/r0.png"

printf 'key m\nkey m\n' > "$work/pom.txt"
view "$work/pom.txt" "$work/v1.png"; render "$work/r1.png" --mode pom
check "two M presses give parallax occlusion mapping" cmp -s "$work/v1.png" "$work/r1.png"

printf 'key c\nkey f\n' > "$work/camera.txt"
view "$work/camera.txt" "$work/v2.png"; render "$work/r2.png" --camera=-X-Y-Z --wireframe --threads 1
check "C moves to the next camera position, F draws the wireframe" cmp -s "$work/v2.png" "$work/r2.png"

printf 'key +\nkey +\nkey +\n' > "$work/level.txt"
view "$work/level.txt" "$work/v3.png" --resolution 256
check "+ shows an LoD level, not the original" bash -c "! cmp -s '$work/v3.png' '$work/v0.png'"

printf 'drag 40 -10\nwheel 2\n' > "$work/orbit.txt"
view "$work/orbit.txt" "$work/v4.png"
check "dragging and the wheel move the camera" bash -c "! cmp -s '$work/v4.png' '$work/v0.png'"

printf 'key m\nfrobnicate 3\n' > "$work/bad.txt"
xrun "$boxlod" view "$model" --replay "$work/bad.txt" --screenshot "$work/bad.png"
status=$?
check "a bad event file exits 2" test "$status" = 2
check "a bad event file names file and line" grep -q "bad.txt: line 2" "$work/err"
check "no screenshot after a bad event file" test ! -e "$work/bad.png"

# An action that fails (F5 saving into a folder under a file) is reported on stderr too, and ends a replay with 2.
printf 'key f5\n' > "$work/save.txt"
xrun "$boxlod" view "$model" --replay "$work/save.txt" --screenshot "$work/save.png" --params-out /etc/passwd/p.txt \
  --width 320 --height 240
status=$?
check "a replay whose F5 fails exits 2" test "$status" = 2
check "and says so in one stderr line naming the file" bash -c "test \$(wc -l < '$work/err') = 1 && grep -q '/etc/passwd/p.txt' '$work/err'"
check "and leaves no screenshot" test ! -e "$work/save.png"

if [ "$failures" -ne 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all checks passed"

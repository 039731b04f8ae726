#!/usr/bin/env bash
# `boxlod compare`'s SSIM against scikit-image's structural_similarity on real
# renders of the FZK-Haus (with and without the wireframe overlay, two
# distances, two render modes): equal within 1e-4.
# Usage: ssim_against_scikit_image.sh BOXLOD TESTS_DIR
set -u
boxlod=$1
tests=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ifc=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
tolerance=1e-4

# Debian's python3 has python3-skimage; a python3 earlier on PATH may not.
python=
for candidate in python3 /usr/bin/python3; do
  if "$candidate" -c "import skimage.metrics" 2>/dev/null; then python=$candidate; break; fi
done
if [ -z "$python" ]; then echo "FAIL no python3 with scikit-image (Debian: python3-skimage)"; exit 1; fi

render() {  # render NAME ARGS...
  local name=$1; shift
  "$boxlod" render "$ifc" -o "$work/$name.png" --width 160 --height 120 "$@" >/dev/null ||
    { echo "FAIL render $name"; exit 1; }
}
render untextured --mode untextured
render wireframe --mode untextured --wireframe
render near --mode normal --camera -X+Y-Z --distance 25
render far --mode normal --camera -X+Y-Z --distance 28

failures=0
for pair in "untextured wireframe" "near far" "untextured far"; do
  set -- $pair
  ours=$("$boxlod" compare "$work/$1.png" "$work/$2.png" --metric ssim | sed -n 's/^ssim = //p')
  theirs=$("$python" "$tests/end_to_end/ssim_reference.py" "$work/$1.png" "$work/$2.png")
  if [ -z "$ours" ] || [ -z "$theirs" ]; then echo "FAIL $1 vs $2: no value (boxlod '$ours', skimage '$theirs')"; failures=$((failures + 1)); continue; fi
  difference=$("$python" -c "print(f'{abs(float(\"$ours\") - float(\"$theirs\")):.3g}')")
  if "$python" -c "import sys; sys.exit(0 if float('$ours') < 0.999 and $difference <= $tolerance else 1)"; then
    echo "ok   $1 vs $2: boxlod $ours, scikit-image $theirs, difference $difference"
  else
    echo "FAIL $1 vs $2: boxlod $ours, scikit-image $theirs, difference $difference (tolerance $tolerance; the pair must differ)"
    failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ] || exit 1
echo "all checks passed"

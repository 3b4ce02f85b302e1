# A whole render replayed on Mesa llvmpipe (docs/explanation/mesa.md, whole
# renders): renders SCENE at WIDTH x HEIGHT with --trace and holds the trace
# to the conformance bounds with `mpr conform --quiet` (exit status 1 when a
# buffer is out of bounds, 2 when there is no Mesa).
# Usage: whole_render.sh MPR SCENE WIDTH HEIGHT [CONFORM OPTION...] (e.g. --exact)
set -uo pipefail
mpr="$1" scene="$2" width="$3" height="$4"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$mpr" render "$scene" --width "$width" --height "$height" -o "$work/render.png" \
  --trace "$work/trace.gls" > "$work/render.log" 2>&1 || { cat "$work/render.log"; echo "FAIL: render of $scene"; exit 1; }
[[ -s "$work/trace.gls" ]] || { echo "FAIL: empty trace of $scene"; exit 1; }
"$mpr" conform --quiet "${@:5}" "$work/trace.gls"

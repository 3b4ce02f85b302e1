# The layers (docs, "Layout"): each library includes only itself and the
# libraries below it. A quoted include of a module above fails this test.
# (Folders not listed here, e.g. cli/, may include anything.) The rooms, from
# the floor up: util, framebuffer, raster (set-up, coverage, span shading),
# pipeline/draw (lighting, clipping, primitive assembly), pipeline/gl (the GL
# state machine), script (the text language). The reference stands beside
# the pipeline: it sees the scene model, never the GL emulator; only the
# accuracy measure above both sees them both. Sub-rooms count as rooms of
# their own: pipeline/draw must not include pipeline/gl.
set -uo pipefail
SRC="$1"
below_gl="util framebuffer raster pipeline/draw pipeline/gl"
declare -A allowed=(
  [util]="util"
  [framebuffer]="util framebuffer"
  [raster]="util framebuffer raster"
  [pipeline/draw]="util framebuffer raster pipeline/draw"
  [pipeline/gl]="$below_gl"
  [script]="$below_gl script"
  [scene]="util framebuffer scene"
  [algorithms]="$below_gl script scene algorithms"
  [stepper]="$below_gl script stepper"
  [testing]="$below_gl script testing"
  [conformance]="$below_gl script conformance"
  [reference]="util framebuffer scene reference"
  [reference/accuracy]="$below_gl script scene algorithms reference"
)
failures=0
checked=0
for module in "${!allowed[@]}"; do
  for f in "$SRC/$module"/*.cpp "$SRC/$module"/*.hpp; do
    [[ -e "$f" ]] || continue
    checked=$((checked + 1))
    # The room an include names: its first folder, or pipeline/<sub-room>.
    while IFS= read -r dep; do
      [[ " ${allowed[$module]} " == *" $dep "* ]] && continue
      echo "FAIL: ${f#$SRC/} includes $dep/, above $module in the layers" >&2
      failures=$((failures + 1))
    done < <(grep -ho '^#include "[a-z_/]*/' "$f" | sed -E 's/#include "//; s#/$##; /^pipeline\//{s#^(pipeline/[a-z_]+).*#\1#;b;}; s#^([a-z_]+)/.*#\1#' | sort -u)
  done
done
# Every room must hold files: a moved room left in this table would check nothing.
for module in "${!allowed[@]}"; do
  compgen -G "$SRC/$module/*.?pp" >/dev/null || { echo "FAIL: $module/ has no sources" >&2; failures=$((failures + 1)); }
done
# Nothing may sit in pipeline/ itself, outside its two sub-rooms.
if compgen -G "$SRC/pipeline/*.?pp" >/dev/null; then
  echo "FAIL: pipeline/ holds files outside gl/ and draw/" >&2
  failures=$((failures + 1))
fi
((failures)) && exit 1
echo "ok: $checked files"

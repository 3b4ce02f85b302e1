# The layers (README, "Layout"): each library includes only itself and the
# libraries below it. A quoted include of a module above fails this test.
# (Folders not listed here, e.g. cli/, may include anything.) The reference
# stands beside the pipeline: it sees the scene model, never the GL emulator;
# only the accuracy measure above both sees them both.
set -uo pipefail
SRC="$1"
declare -A allowed=(
  [util]="util"
  [framebuffer]="util framebuffer"
  [raster]="util raster"
  [pipeline]="util framebuffer raster pipeline"
  [scene]="util framebuffer scene"
  [algorithms]="util framebuffer raster pipeline scene algorithms"
  [stepper]="util framebuffer raster pipeline stepper"
  [testing]="util framebuffer raster pipeline testing"
  [conformance]="util framebuffer raster pipeline conformance"
  [reference]="util framebuffer scene reference"
  [reference/accuracy]="util framebuffer raster pipeline scene algorithms reference"
)
failures=0
for module in "${!allowed[@]}"; do
  for f in "$SRC/$module"/*.cpp "$SRC/$module"/*.hpp; do
    [[ -e "$f" ]] || continue
    # A forwarding header (pipeline/vecmath.hpp -> util/) points downwards and is fine.
    while IFS= read -r dep; do
      [[ " ${allowed[$module]} " == *" $dep "* ]] && continue
      echo "FAIL: ${f#$SRC/} includes $dep/, above $module in the layers" >&2
      failures=$((failures + 1))
    done < <(grep -ho '^#include "[a-z_]*/' "$f" | sed 's/#include "//; s/\///' | sort -u)
  done
done
((failures)) && exit 1
echo ok

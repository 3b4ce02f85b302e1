# The scenes of new shapes (tests/accuracy/scenes, issue 43) render: each
# loads, renders with no GL error, and its multi-pass image differs from
# its single-pass one (its specular effects are drawn). Their errors against
# the reference are measured by scripts/accuracy-shapes (a long run).
source "$(dirname "$0")/lib.bash"
single=(--set render.shadows=false --set render.reflections=false --set render.refractions=false
        --set render.translucency=false --set render.frosted=false)
for scene in "$SRC"/tests/accuracy/scenes/*.yaml; do
  name="$(basename "$scene" .yaml)"
  out="$("$MPR" render "$scene" --width 80 --height 60 -o "$WORK/$name.png" --stats "$WORK/$name.json" 2>&1)" ||
    { fail "$name: render failed: $out"; continue; }
  "$MPR" render "$scene" --width 80 --height 60 -o "$WORK/$name-single.png" "${single[@]}" > /dev/null 2>&1 ||
    { fail "$name: single-pass render failed"; continue; }
  grep -q '"gl_errors": *0' "$WORK/$name.json" || fail "$name: GL errors: $(grep gl_errors "$WORK/$name.json")"
  cmp -s "$WORK/$name.png" "$WORK/$name-single.png" && fail "$name: the same image as its single pass"
done
finish

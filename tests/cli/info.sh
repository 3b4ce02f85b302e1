# mpr info: where the recursion runs out of depth (issue 43, defect 7). The
# views of the deepest level draw the specular faces they see as their own
# material, not looked through; the plan says how many views, how many faces
# each, and which objects, so a user knows to raise render.recursion_depth.
source "$(dirname "$0")/lib.bash"
box="$SRC/tests/accuracy/scenes/glass_box_on_mirror.yaml"
out="$("$MPR" info "$box" 2>&1)" || fail "info on the glass box failed: $out"
# 7 faces, depth 3: 7 * 6 * 6 = 252 views at level 3, each seeing up to 6.
want='  depth runs out at level 3 (render.recursion_depth 3): its 252 views (culling off) draw up to 6 specular faces each as their own material, not looked through: "floor" (1 mirror face), "glass box" (6 refracting faces); raise render.recursion_depth to look through them'
grep -qxF "$want" <<<"$out" || fail "glass box: no line '$want' in: $out"
out="$("$MPR" info "$box" --set render.recursion_depth=5 2>&1)"
# 7 * 6^4 = 9072 views at level 5.
[[ "$out" == *"depth runs out at level 5 (render.recursion_depth 5): its 9072 views (culling off) draw up to 6 specular faces each"* ]] ||
  fail "glass box at depth 5: $out"
# recursion_depth 0: the camera's own view draws every specular face.
out="$("$MPR" info "$box" --set render.recursion_depth=0 2>&1)"
[[ "$out" == *"depth runs out at level 0 (render.recursion_depth 0): its 1 view draws up to 7 specular faces as their own material"* ]] ||
  fail "glass box at depth 0: $out"
# One specular face: a view through it sees no other, depth never runs out.
out="$("$MPR" info "$SRC/scenes/refraction_plate.yaml" 2>&1)"
[[ "$out" == *"  depth never runs out: the one specular face is looked through at level 1, and the view through it sees no other"* ]] ||
  fail "refraction plate: $out"
# No specular face: no recursion, nothing runs out.
printf 'objects: [{primitive: box}]\n' > "$WORK/plain.yaml"
out="$("$MPR" info "$WORK/plain.yaml" 2>&1)"
[[ "$out" != *"runs out"* ]] || fail "plain scene: $out"
finish

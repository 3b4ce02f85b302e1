# mpr reference: the default scene and every sample scene trace; bad scenes
# and options exit 2 and write nothing; the bytes do not depend on --threads.
source "$(dirname "$0")/lib.bash"
"$MPR" reference --width 64 --height 48 --spp 2 -o "$WORK/default.png" 2>"$WORK/default.log" || fail "default scene failed"
[[ -s "$WORK/default.png" ]] || fail "default: no image"
grep -q "^traced <default scene> (64x48, 2 spp, pipeline) to $WORK/default.png in .* s (.* M rays/s)$" "$WORK/default.log" \
  || fail "closing line: $(cat "$WORK/default.log")"
for scene in "$SRC"/scenes/*.yaml; do
  name="$(basename "$scene" .yaml)"
  "$MPR" reference "$scene" --width 32 --height 24 --spp 1 -o "$WORK/$name.png" 2>/dev/null || { fail "$name: trace failed"; continue; }
  [[ -s "$WORK/$name.png" ]] || fail "$name: no image"
done
# The physical model, a bounce limit and the float format.
"$MPR" reference --width 16 --height 12 --spp 1 --model physical --bounces 1 -o "$WORK/x.exr" 2>/dev/null && [[ -s "$WORK/x.exr" ]] \
  || fail "no .exr output"
"$MPR" reference --width 16 --height 12 --spp 1 -o "$WORK/x.tif" 2>/dev/null && [[ -s "$WORK/x.tif" ]] || fail "no .tif output"
# Threads change nothing.
"$MPR" reference --width 48 --height 36 --spp 2 --threads 1 -o "$WORK/t1.png" 2>/dev/null || fail "--threads 1 failed"
"$MPR" reference --width 48 --height 36 --spp 2 --threads 2 -o "$WORK/t2.png" 2>/dev/null || fail "--threads 2 failed"
cmp -s "$WORK/t1.png" "$WORK/t2.png" || fail "--threads 1 and 2 give different bytes"
# A bad scene: status 2, the message located, no output, the old one untouched.
printf 'camera:\n  positon: [0, 1, 2]\n' > "$WORK/bad.yaml"
out="$("$MPR" reference "$WORK/bad.yaml" -o "$WORK/new.png" 2>&1)"; rc=$?
[[ $rc -eq 2 ]] || fail "bad scene exited $rc"
[[ "$out" == "$WORK/bad.yaml:2:3: unknown key 'positon' in camera; did you mean 'position'?" ]] || fail "message: $out"
[[ ! -e "$WORK/new.png" ]] || fail "a failed trace created its output"
echo old > "$WORK/keep.png"
"$MPR" reference "$WORK/bad.yaml" -o "$WORK/keep.png" >/dev/null 2>&1
[[ "$(cat "$WORK/keep.png")" == old ]] || fail "a failed trace overwrote its output"
"$MPR" reference "$WORK/missing.yaml" -o "$WORK/new.png" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "missing scene should exit 2"
# Bad options: status 2, nothing written.
"$MPR" reference --model radiosity -o "$WORK/new.png" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "bad --model should exit 2"
"$MPR" reference --spp 0 -o "$WORK/new.png" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "--spp 0 should exit 2"
"$MPR" reference --width 8 --height 6 -o "$WORK/new.bmp" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail ".bmp should be refused"
"$MPR" reference --set render.width=abc -o "$WORK/new.png" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "bad --set should exit 2"
[[ ! -e "$WORK/new.png" && ! -e "$WORK/new.bmp" ]] || fail "a refused trace wrote its output"
finish

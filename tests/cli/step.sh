# mpr step: pass list, a pixel's history derived by hand, the state of a pass.
source "$(dirname "$0")/lib.bash"
script="$SRC/tests/cli/data/step_history.gls"
out="$("$MPR" step "$script")" || fail "pass list failed"
expected="pass 0 (line 1): (before the first @pass)
pass 1 (line 3): setup
pass 2 (line 9): two overlapping faces in one draw: front INCR, back-of-cube style
pass 3 (line 21): test that fails"
[[ "$out" == "$expected" ]] || fail "pass list: $out"
# Pixel (3,2), centre (3.5,2.5): inside both triangles of the one draw (x + y < 8
# and y < x), so two fragments, each incrementing; then GL_EQUAL 5 fails on 194
# and sfail GL_ZERO clears it.
out="$("$MPR" step "$script" --pixel 3,2)" || fail "pixel history failed"
expected="pixel (3,2) of $script
pass 1 \"setup\"
  line 8 glClear: stencil 0 -> 192, depth 0 -> 0, colour (0,0,0,0) -> (0,0,0,0)
pass 2 \"two overlapping faces in one draw: front INCR, back-of-cube style\"
  line 20 glEnd, fragment 1: stencil GL_ALWAYS (0 & 0xff vs 192 & 0xff) passed; depth test off; dppass GL_INCR; colour (255,255,255,255); stencil 192 -> 193
  line 20 glEnd, fragment 2: stencil GL_ALWAYS (0 & 0xff vs 193 & 0xff) passed; depth test off; dppass GL_INCR; colour (255,255,255,255); stencil 193 -> 194
pass 3 \"test that fails\"
  line 24 glRectf, fragment 1: stencil GL_EQUAL (5 & 0xff vs 194 & 0xff) failed; sfail GL_ZERO; stencil 194 -> 0
final: stencil 0 = 0x0 = 0b00000000, depth 0, colour (255,255,255,255)"
[[ "$out" == "$expected" ]] || fail "pixel history: $out"
out="$("$MPR" step "$script" --state 3)" || fail "state failed"
[[ "$out" == *'"stencil": {"enabled": true, "func": "GL_EQUAL", "ref": 5, "value_mask": 255, "write_mask": 255, "sfail": "GL_ZERO"'* ]] || fail "state 3: $out"
"$MPR" step "$script" --state 9 >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "--state past the end should exit 2"
"$MPR" step "$script" --pixel 8,0 >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "--pixel outside should exit 2"
"$MPR" step "$script" --pixel 1 >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "malformed --pixel should exit 2"
# A scene steps through its render's GL calls.
out="$("$MPR" step "$SRC/scenes/default.yaml")" || fail "scene pass list failed"
[[ "$out" == *"pass 2 (line "*"): draw_window level 0 > ambient | draw_normal_objects(Camera, ZERO)"* ]] || fail "scene passes: $out"
finish

# Calls GL rejects are reported as FILE:LINE: GL_... in glX, and the run goes on.
source "$(dirname "$0")/lib.bash"
cat > "$WORK/e.gls" <<'GLS'
@framebuffer 4 4
glEnd
glStencilFunc GL_KEEP 1 0xFF
glPopMatrix
glEnable GL_STENCIL_TEST
glStencilFunc GL_ALWAYS 5 0xFF
glStencilOp GL_KEEP GL_KEEP GL_REPLACE
glBegin GL_QUADS
glClear GL_STENCIL_BUFFER_BIT
glVertex2f 0 0
glVertex2f 1 0
glVertex2f 1 1
glVertex2f 0 1
glEnd
GLS
out="$("$MPR" gl "$WORK/e.gls" --dump "$WORK/d" 2>"$WORK/err")"; rc=$?
[[ $rc -eq 0 ]] || fail "exit status $rc"
expected="$WORK/e.gls:2: GL_INVALID_OPERATION in glEnd
$WORK/e.gls:3: GL_INVALID_ENUM in glStencilFunc
$WORK/e.gls:4: GL_STACK_UNDERFLOW in glPopMatrix
$WORK/e.gls:9: GL_INVALID_OPERATION in glClear"
[[ "$(cat "$WORK/err")" == "$expected" ]] || fail "stderr was: $(cat "$WORK/err")"
[[ "$out" == *"4 GL errors"* ]] || fail "summary: $out"
finish

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

# With more than one thread the script is checked by its reading as it
# runs: what is printed and written is the same at any thread count. A
# script error anywhere wins over GL error reports and a failed probe
# before it: only it is printed, status 2, nothing written. (The error
# stands 100 000 lines on, so that the run has met the GL errors and the
# probe long before the reading meets it; after the probe the rest is
# checked whole.)
{ cat "$WORK/e.gls"; printf '@expect stencil 0 0 7\n'; yes glFinish | head -n 100000; printf 'glVertex2f 1\n'; } > "$WORK/late.gls"
for t in 1 2 3; do
  out="$("$MPR" gl --threads $t "$WORK/late.gls" --dump "$WORK/late-$t" 2>&1)"; rc=$?
  [[ $rc -eq 2 && "$out" == "$WORK/late.gls:100016:13: glVertex2f takes 2 arguments, got 1" ]] ||
    fail "late script error, $t threads: status $rc, $out"
  [[ ! -e "$WORK/late-$t" ]] || fail "late script error, $t threads: the dump was written"
done
# An error after a probe outside the window: the later error is the
# script's (checkScript places its probes at the end), at any thread count.
{ printf '@framebuffer 8 8\nglFinish\n@expect stencil 9 0 1\n'; yes glFinish | head -n 5000; printf 'glFoo\n'; } > "$WORK/outside.gls"
for t in 1 2; do
  out="$("$MPR" gl --threads $t "$WORK/outside.gls" 2>&1)"; rc=$?
  [[ $rc -eq 2 && "$out" == "$WORK/outside.gls:5004:1: 'glFoo' is not a call"* ]] ||
    fail "error after a probe outside, $t threads: status $rc, $out"
done
# Without it: the GL errors, then the probe that failed, status 1.
head -n 16 "$WORK/late.gls" > "$WORK/probe.gls"
for t in 1 2; do
  "$MPR" gl --threads $t "$WORK/probe.gls" --dump "$WORK/probe-$t" >/dev/null 2>"$WORK/probe-$t.err"; rc=$?
  [[ $rc -eq 1 && "$(head -n 4 "$WORK/probe-$t.err")" == "${expected//\/e.gls:/\/probe.gls:}" &&
     "$(sed -n 5p "$WORK/probe-$t.err")" == "$WORK/probe.gls:15: @expect stencil 0 0 7: "* &&
     $(wc -l < "$WORK/probe-$t.err") -eq 5 ]] || fail "failed probe, $t threads: status $rc, $(cat "$WORK/probe-$t.err")"
  [[ ! -e "$WORK/probe-$t" ]] || fail "failed probe, $t threads: the dump was written"
done
# A long script with GL errors all along: reports held back until the
# reading has ended, then printed in the same order as with one thread.
awk 'BEGIN { print "@framebuffer 8 8"; for (i = 0; i < 120000; ++i) { if (i % 20000 == 7) print "glPopMatrix";
             print "glRectf 0 0 0.5 0.5" } print "glEnd" }' > "$WORK/long.gls"
"$MPR" gl --threads 1 "$WORK/long.gls" 2>"$WORK/long-1.err" >"$WORK/long-1.out" || fail "long script, 1 thread"
"$MPR" gl --threads 2 "$WORK/long.gls" 2>"$WORK/long-2.err" >"$WORK/long-2.out" || fail "long script, 2 threads"
[[ $(wc -l < "$WORK/long-1.err") -eq 7 ]] || fail "long script: $(cat "$WORK/long-1.err")"
cmp -s "$WORK/long-1.err" "$WORK/long-2.err" || fail "long script: reports differ with 2 threads: $(cat "$WORK/long-2.err")"
cmp -s "$WORK/long-1.out" "$WORK/long-2.out" || fail "long script: summaries differ with 2 threads"
finish

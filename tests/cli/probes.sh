# Probes (@expect, @expect-picture) under `mpr gl` and `mpr test`: the
# scripts of tests/probes/pass hold, every script of tests/probes/fail fails
# with the exact message in its .expected file; located errors; JUnit XML
# against the schema's required part; difference images.
source "$(dirname "$0")/lib.bash"
cd "$SRC" || exit 1
for f in tests/probes/pass/*.gls; do
  out="$("$MPR" gl "$f" 2>&1)"; rc=$?
  [[ $rc -eq 0 && "$out" == *"probes held"* ]] || fail "$f: status $rc ($out)"
done
for f in tests/probes/fail/*.gls; do
  err="$("$MPR" gl "$f" --dump "$WORK/dump" 2>&1 >/dev/null)"; rc=$?
  [[ $rc -eq 1 ]] || fail "$f: status $rc, expected 1"
  [[ "$err" == "$(cat "${f%.gls}.expected")" ]] || fail "$f: message differs:"$'\n'"$err"
  [[ ! -e "$WORK/dump" ]] || fail "$f: a failing probe wrote the dump"
done

out="$("$MPR" test tests/probes/pass)"; rc=$?
[[ $rc -eq 0 && "$out" == *$'\n2 passed, 0 failed' ]] || fail "mpr test pass: $rc ($out)"
nfail=$(ls tests/probes/fail/*.gls | wc -l)
out="$("$MPR" test tests/probes --junit "$WORK/junit.xml" --report "$WORK/report")"; rc=$?
[[ $rc -eq 1 && "$out" == *$'\n2 passed, '"$nfail failed" ]] || fail "mpr test all: $rc ($out)"
# The failing probe's output, byte for byte: the probe, expected and found, the pixel's history.
out="$("$MPR" test tests/probes/fail/in_snapshot.gls)"; rc=$?
[[ $rc -eq 1 && "$out" == "$(cat tests/cli/data/probe_test_failure.txt)" ]] || fail "mpr test output: $rc"$'\n'"$out"

# JUnit: valid against the required part of the schema, one testcase per script.
if xmllint --noout --schema tests/cli/data/junit.xsd "$WORK/junit.xml" 2>"$WORK/xmllint.txt"; then :; else
  fail "junit.xml is not valid: $(cat "$WORK/xmllint.txt")"
fi
[[ $(grep -c '<testcase ' "$WORK/junit.xml") -eq $((nfail + 2)) ]] || fail "junit.xml: testcase count"
[[ $(grep -c '<failure type="probe"' "$WORK/junit.xml") -eq $nfail ]] || fail "junit.xml: failure count"
grep -q '<testsuite name="mpr test" tests="'$((nfail + 2))'" failures="'$nfail'" errors="0"' "$WORK/junit.xml" ||
  fail "junit.xml: the suite's counts"
grep -q 'message="tests/probes/fail/stencil_pixel.gls:16: @expect stencil 1 1 2: stencil at (1,1): expected 2, found 1"' \
  "$WORK/junit.xml" || fail "junit.xml: a failure's message"
# One difference image per failing probe, at the window's size.
[[ $(ls "$WORK/report" | wc -l) -eq $nfail && -s "$WORK/report/in_snapshot.line24.png" ]] ||
  fail "report: $(ls "$WORK/report")"

# A script error in any script: status 2, nothing runs, nothing written.
printf '@framebuffer 4 4\n@expect stencil 4 0 0\n' > "$WORK/outside.gls"
out="$("$MPR" test tests/probes/pass "$WORK/outside.gls" --junit "$WORK/j2.xml" 2>&1)"; rc=$?
[[ $rc -eq 2 && "$out" == "$WORK/outside.gls:2:17: pixel (4,0) is outside the 4x4 window (origin bottom-left)" ]] ||
  fail "mpr test script error: $rc ($out)"
[[ ! -e "$WORK/j2.xml" ]] || fail "mpr test wrote JUnit after a script error"
out="$("$MPR" test "$WORK/none" 2>&1)"; rc=$?
[[ $rc -eq 2 ]] || fail "mpr test on a missing file: $rc ($out)"

# Located probe errors.
expect_script_error probe_outside $'@framebuffer 8 8\nglClear GL_STENCIL_BUFFER_BIT\n@expect stencil 3 8 0\n' "3:17: pixel (3,8) is outside the 8x8 window (origin bottom-left)"
expect_script_error probe_outside_late_fb $'@expect depth 300 0 0\n' "1:15: pixel (300,0) is outside the 256x256 window"
expect_script_error rect_outside $'@framebuffer 8 8\n@expect stencil rect 6 0 3 1 0\n' "2:22: the 3x1 region with bottom-left pixel (6,0) reaches outside the 8x8 window"
expect_script_error picture_outside $'@framebuffer 2 2\n@expect-picture stencil 1 0\n. .\n@end\n' "2:25: the 2x1 region with bottom-left pixel (1,0) reaches outside the 2x2 window"
expect_script_error bad_buffer $'@expect stencils 0 0 0\n' "1:9: unknown buffer 'stencils' (known: stencil, depth, color, accum)"
expect_script_error few_values $'@expect color 0 0 1 2 3\n' "1:24: @expect color takes R G B A (bytes) and an optional tolerance, got 3 value(s)"
expect_script_error many_values $'@expect stencil 0 0 1 2\n' "1:23: @expect stencil takes one value, got 2 value(s)"
expect_script_error value_range $'@expect stencil 0 0 256\n' "1:21: stencil value 256 is outside 0..255"
expect_script_error depth_range $'@expect depth all 16777216\n' "1:19: depth value 16777216 is outside 0..16777215"
expect_script_error not_integer $'@expect stencil 0.5 0 1\n' "1:17: X must be an integer, not '0.5'"
expect_script_error in_begin $'glBegin GL_TRIANGLES\n@expect stencil 0 0 0\nglEnd\n' "2:1: @expect between glBegin and glEnd"
expect_script_error no_end $'@expect-picture stencil 0 0\n. .\n' "1:1: @expect-picture without @end"
expect_script_error lone_end $'@end\n' "1:1: @end without @expect-picture"
expect_script_error ragged $'@expect-picture stencil 0 0\n. .\n. . .\n@end\n' "3:1: picture row has 3 cells, the first row has 2"
expect_script_error bad_cell $'@expect-picture stencil 0 0\n. x\n@end\n' "2:3: picture cell 'x' is not a stencil value 0..255, '.' or '*'"
expect_script_error empty_picture $'@expect-picture stencil 0 0\n@end\n' "2:1: @expect-picture has no rows before @end"
finish

# Expectations in scenes (expect:, docs/reference/scene-format.md) under `mpr render`
# and `mpr test`: the scenes of tests/scene_probes/pass hold, every scene of
# tests/scene_probes/fail fails with the exact report in its .expected file
# (standard error less the timing line), the render's files are written all
# the same; located errors for bad entries and for an `after` no pass matched.
source "$(dirname "$0")/lib.bash"
cd "$SRC" || exit 1
for f in tests/scene_probes/pass/*.yaml; do
  err="$("$MPR" render "$f" -o "$WORK/pass.png" 2>&1)"; rc=$?
  [[ $rc -eq 0 && "$err" == *"expectations held" ]] || fail "$f: status $rc ($err)"
done
for f in tests/scene_probes/fail/*.yaml; do
  rm -f "$WORK/fail.png"
  err="$("$MPR" render "$f" -o "$WORK/fail.png" 2>&1 >/dev/null | grep -v '^rendered ')"; rc=${PIPESTATUS[0]}
  [[ $rc -eq 1 ]] || fail "$f: status $rc, expected 1"
  [[ "$err" == "$(cat "${f%.yaml}.expected")" ]] || fail "$f: report differs:"$'\n'"$err"
  [[ -s "$WORK/fail.png" ]] || fail "$f: the image was not written"
done

# mpr test runs scenes beside scripts: one line per scene, the same summary.
nfail=$(ls tests/scene_probes/fail/*.yaml | wc -l)
out="$("$MPR" test tests/scene_probes/pass tests/probes/pass/*.gls)"; rc=$?
[[ $rc -eq 0 && "$out" == "ok   tests/scene_probes/pass/shadow_counts.yaml (14 expectations)"$'\n'*$'\n3 passed, 0 failed' ]] ||
  fail "mpr test pass: $rc ($out)"
out="$("$MPR" test tests/scene_probes --junit "$WORK/junit.xml" --report "$WORK/report")"; rc=$?
[[ $rc -eq 1 && "$out" == *$'\n1 passed, '"$nfail failed" ]] || fail "mpr test all: $rc ($out)"
out="$("$MPR" test tests/scene_probes/fail/render_order.yaml)"; rc=$?
want="FAIL $(sed 's/^  /     /' tests/scene_probes/fail/render_order.expected)"$'\n0 passed, 1 failed'
[[ $rc -eq 1 && "$out" == "$want" ]] || fail "mpr test output: $rc"$'\n'"$out"
xmllint --noout --schema tests/cli/data/junit.xsd "$WORK/junit.xml" 2>/dev/null || fail "junit.xml is not valid"
[[ $(grep -c '<testcase ' "$WORK/junit.xml") -eq $((nfail + 1)) ]] || fail "junit.xml: testcase count"
[[ -s "$WORK/report/render_order.line20.png" ]] || fail "report: $(ls "$WORK/report")"

# expect_scene_error NAME 'expect: entries' 'message after FILE:'
body="$(sed -n '/^camera:/,/^render:/p' tests/scene_probes/pass/shadow_counts.yaml)"
expect_scene_error() {
  local name="$1" text="$2" want="$3" out rc
  printf '%s\n%s' "$body" "$text" > "$WORK/$name.yaml"
  out="$("$MPR" render "$WORK/$name.yaml" -o "$WORK/$name.png" 2>&1 | grep -v '^rendered ')"; rc=${PIPESTATUS[0]}
  [[ $rc -eq 2 ]] || fail "$name: exit status $rc, expected 2 ($out)"
  [[ "$out" == "$WORK/$name.yaml:$want" ]] || fail "$name: message '$out', expected '$WORK/$name.yaml:$want'"
}
# The body is 11 lines; `expect:` is line 12, its first entry line 13.
expect_scene_error misspelled $'expect:\n  - {after: end, stencil: [0, 0], valeu: 0}\n' \
  "13:35: unknown key 'valeu' in an expectation; did you mean 'value'?"
expect_scene_error top_key $'expects:\n  - {after: end, stencil: all, value: 0}\n' \
  "12:1: unknown key 'expects' in the scene; did you mean 'expect'?"
expect_scene_error no_pass $'expect:\n  - {after: end, stencil: all, value: 0}\n  - {after: "draw_all_shadow > shadow volume", stencil: all, value: 0}\n' \
  "14:13: after \"draw_all_shadow > shadow volume\" matched no pass of the render (8 passes; mpr step $WORK/no_pass.yaml lists them)"
expect_scene_error too_few $'expect:\n  - after: "shadow volumes"\n    occurrence: 3\n    stencil: all\n    value: 0\n' \
  "13:12: after \"shadow volumes\" matched 1 pass, not 3 of the render (8 passes; mpr step $WORK/too_few.yaml lists them)"
expect_scene_error no_level_pass $'expect:\n  - {after: "shadow volumes", level: 1, stencil: all, value: 0}\n' \
  "13:13: after \"shadow volumes\" matched no pass of level 1 of the render (8 passes; mpr step $WORK/no_level_pass.yaml lists them)"
expect_scene_error no_light $'expect:\n  - {after: "shadow volumes", light: 1, stencil: all, value: 0}\n' \
  "13:38: expect light must be in [0, 0], not 1"
expect_scene_error bad_level $'expect:\n  - {after: end, stencil: [0, 0], value: SHAD_ZER + 1}\n' \
  "13:42: expect stencil value 'SHAD_ZER + 1' is not an integer or a stencil level; did you mean 'SHAD_ZERO'?"
expect_scene_error level_range $'expect:\n  - {after: end, stencil: [0, 0], value: SHAD_ZERO + 64}\n' \
  "13:42: expect stencil value SHAD_ZERO + 64 = 256 is outside the 8-bit stencil of profile 'indigo' (0 .. 255)"
expect_scene_error outside $'expect:\n  - {after: end, stencil: [16, 0], value: 0}\n' \
  "13:27: pixel (16,0) is outside the 16x16 window (origin bottom-left)"
expect_scene_error rect_outside $'expect:\n  - {after: end, depth: [10, 10, 7, 1], value: 0}\n' \
  "13:25: the 7x1 region with bottom-left pixel (10,10) reaches outside the 16x16 window"
expect_scene_error two_buffers $'expect:\n  - {after: end, stencil: all, depth: all, value: 0}\n' \
  "13:39: an expectation probes one buffer: give stencil or depth, not both"
expect_scene_error end_light $'expect:\n  - {after: end, light: 0, stencil: all, value: 0}\n' \
  "13:25: expect after: end takes no light (the finished render is one point)"
expect_scene_error colour_value $'expect:\n  - {after: end, color: [0, 0], value: 255}\n' \
  "13:40: expect color value must be [r, g, b, a], four bytes 0 .. 255"
expect_scene_error tolerance $'expect:\n  - {after: end, stencil: all, value: 0, tolerance: 1}\n' \
  "13:53: expect tolerance is for color only"
expect_scene_error picture_depth $'expect:\n  - {after: end, depth: [0, 0], picture: "1 2"}\n' \
  "13:42: expect picture takes stencil: [x, y], the picture's bottom-left pixel"
expect_scene_error picture_cell $'expect:\n  - {after: end, stencil: [0, 0], picture: "1 x"}\n' \
  "13:44: expect picture cell 'x' is not a stencil value 0 .. 255, '.' or '*'"
expect_scene_error no_value $'expect:\n  - {after: end, stencil: all}\n' \
  "13:5: an expectation needs a value (or, for stencil [x, y], a picture)"
expect_scene_error not_a_list $'expect: {after: end}\n' \
  "12:9: expect must be a list of expectations, like - {after: end, stencil: [0, 0], value: ZERO}"
# mpr test: a located error is a scene error, status 2.
out="$("$MPR" test "$WORK/no_pass.yaml" 2>&1)"; rc=$?
[[ $rc -eq 2 && "$out" == "FAIL $WORK/no_pass.yaml:14:13: after"*$'\n0 passed, 1 failed' ]] || fail "mpr test no pass: $rc ($out)"
out="$("$MPR" test "$WORK/misspelled.yaml" 2>&1)"; rc=$?
[[ $rc -eq 2 && "$out" == *"unknown key 'valeu'"* ]] || fail "mpr test bad scene: $rc ($out)"
desc="$("$MPR" render --describe-format)"
[[ "$desc" == *'"expect[]"'* && "$desc" == *'"occurrence"'* ]] || fail "--describe-format lacks expect"
finish

# mpr step --html: the page's files, deterministic bytes, the recording's
# contents, and a folder that is never left half-written or clobbered.
source "$(dirname "$0")/lib.bash"
script="$SRC/tests/cli/data/step_history.gls"
page="$WORK/out/page"
out="$("$MPR" step "$script" --html "$page" 2>&1)" || fail "--html failed: $out"
[[ "$out" == *"$page/index.html: 4 passes"* ]] || fail "summary: $out"
for f in index.html stepper.js stepper.css passes.js frames.js history.js; do
  [[ -s "$page/$f" ]] || fail "missing $f"
done
[[ "$(ls -A "$WORK/out")" == "page" ]] || fail "left something beside the page: $(ls -A "$WORK/out")"
grep -q '<meta name="generator" content="mpr step">' "$page/index.html" || fail "index.html lacks its generator"
# The recording: every pass with its --pixel header, the algorithm's stencil
# values, and the history templates worded as --pixel words its lines.
grep -qF '"header": "pass 3 \"test that fails\""' "$page/passes.js" || fail "pass headers: $(head -c 2000 "$page/passes.js")"
grep -qF '"levels": {"zero": 0, "shad_min": 128, "shad_zero": 192, "max": 255}' "$page/passes.js" || fail "stencil levels"
grep -qF '"recorded_passes": 4' "$page/passes.js" || fail "histories of every pass"
grep -qF '"  line {line} glEnd, fragment {k}: stencil GL_ALWAYS (0 & 0xff vs {s0} & 0xff) passed; depth test off; dppass GL_INCR; colour {c1}; stencil {s0} -> {s1}"' "$page/passes.js" || fail "templates"
[[ "$(grep -c '^"' "$page/frames.js")" -eq 5 ]] || fail "frames: the start and one per pass"
# Deterministic: the same bytes again, and an earlier page is replaced whole.
"$MPR" step "$script" --html "$WORK/again" >/dev/null 2>&1 || fail "second run failed"
diff -r "$page" "$WORK/again" >/dev/null || fail "two runs wrote different bytes"
# An earlier page is known by the .mpr-page marker MPR wrote, naming every file.
[[ "$(head -1 "$page/.mpr-page")" == "mpr step" ]] || fail "the marker: $(cat "$page/.mpr-page")"
echo edited > "$page/passes.js"
"$MPR" step "$script" --html "$page" >/dev/null 2>&1 || fail "replacing an earlier page failed"
diff -r "$page" "$WORK/again" >/dev/null || fail "the earlier page was not replaced whole"
[[ "$(ls -A "$WORK/out")" == "page" ]] || fail "left something beside the replaced page: $(ls -A "$WORK/out")"
# A file of someone else's in it: the folder is not only a page, and is refused as it is.
echo keep > "$page/notes.txt"
out="$("$MPR" step "$script" --html "$page" 2>&1)"; [[ $? -eq 2 && "$out" == *"other files"* ]] || fail "a page with another file: $out"
[[ "$(cat "$page/notes.txt")" == keep && -e "$page/index.html" ]] || fail "a page with another file was touched"
rm "$page/notes.txt"
# A lookalike: an index.html with the generator tag but no marker is not a page.
mkdir -p "$WORK/look" && cp "$page/index.html" "$WORK/look/" && echo keep > "$WORK/look/data.csv"
out="$("$MPR" step "$script" --html "$WORK/look" 2>&1)"; [[ $? -eq 2 ]] || fail "a lookalike page was taken: $out"
rm "$WORK/look/data.csv"
out="$("$MPR" step "$script" --html "$WORK/look" 2>&1)"; [[ $? -eq 2 ]] || fail "an index.html alone, without the marker, was taken: $out"
# --history-mb 0: no histories, and the page says up to which pass it has them.
"$MPR" step "$script" --html "$WORK/none" --history-mb 0 >/dev/null 2>&1 || fail "--history-mb 0 failed"
grep -qF '"recorded_passes": 0' "$WORK/none/passes.js" || fail "--history-mb 0 recorded histories"
# Refusals, exit 2, nothing touched.
echo keep > "$WORK/file"
out="$("$MPR" step "$script" --html "$WORK/file" 2>&1)"; [[ $? -eq 2 ]] || fail "--html onto a file should exit 2"
[[ "$out" == *"is not a folder"* && "$(cat "$WORK/file")" == keep ]] || fail "--html onto a file: $out"
out="$("$MPR" step "$script" --html "$WORK/file/sub/page" 2>&1)"; [[ $? -eq 2 && "$out" == *"$WORK/file' is not a folder"* ]] || fail "--html below a file: $out"
mkdir -p "$WORK/mine" && echo keep > "$WORK/mine/notes.txt"
out="$("$MPR" step "$script" --html "$WORK/mine" 2>&1)"; [[ $? -eq 2 ]] || fail "--html onto another folder should exit 2"
[[ "$out" == *"other files"* && "$(ls "$WORK/mine")" == notes.txt ]] || fail "--html onto another folder: $out"
"$MPR" step "$script" --html "$WORK/file/page" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "--html under a file should exit 2"
"$MPR" step "$script" --html "" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "--html '' should exit 2"
"$MPR" step "$script" --html "$WORK/x" --pixel 1,1 >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "--html with --pixel should exit 2"
"$MPR" step "$script" --history-mb 3 >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "--history-mb without --html should exit 2"
printf '@framebuffer 8 8\nglBogus 1\n' > "$WORK/bad.gls"
"$MPR" step "$WORK/bad.gls" --html "$WORK/bad" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "a script error should exit 2"
[[ ! -e "$WORK/bad" ]] || fail "a script error left a folder"
out="$("$MPR" step --help)" || fail "mpr step --help failed"
[[ "$out" == *"--html"*"DIR"* && "$out" == *"--history-mb"* ]] || fail "mpr step --help: $out"
finish

# mpr accuracy: a small sweep writes its whole report; bad input exits 2 and
# writes nothing; an estimate over --budget is refused before anything runs.
source "$(dirname "$0")/lib.bash"
small=(--width 32 --height 24 --spp 1 --repeat 1 -q)
"$MPR" accuracy "${small[@]}" --vary render.recursion_depth=0,1,2 --vary render.shadows=false \
    --report "$WORK/r" || fail "the sweep failed"
for f in results.csv results.json report.html plot.svg plot.png reference.png single-pass.png \
         single-pass-difference.png setting-00.png setting-00-difference.png setting-03.png; do
  [[ -s "$WORK/r/$f" ]] || fail "no $f"
done
# The scene itself, depth 0 and 1 (2 is the scene's own value), shadows off: 4 rows.
[[ $(wc -l < "$WORK/r/results.csv") -eq 5 ]] || fail "results.csv rows: $(cat "$WORK/r/results.csv")"
head -1 "$WORK/r/results.csv" | grep -q '^setting,render.recursion_depth,render.shadows,seconds,' || fail "csv header"
grep -q '^render.recursion_depth=0,0,true,' "$WORK/r/results.csv" || fail "depth 0 row"
grep -q '^render.shadows=false,2,false,' "$WORK/r/results.csv" || fail "shadows row"
# Depth 0 draws one view: the camera's.
awk -F, '$1=="render.recursion_depth=0" && $6!=1 {exit 1}' "$WORK/r/results.csv" || fail "depth 0 views"
# A second run replaces the earlier report.
"$MPR" accuracy "${small[@]}" --vary render.shadows=false --report "$WORK/r" || fail "second run"
[[ $(wc -l < "$WORK/r/results.csv") -eq 3 ]] || fail "the report was not replaced"
[[ ! -e "$WORK/r/setting-03.png" ]] || fail "an earlier report's file is left"
# Comparing with a given reference: the same image the sweep traced.
cp "$WORK/r/reference.png" "$WORK/ref.png"
"$MPR" accuracy "${small[@]}" --vary render.shadows=false --reference "$WORK/ref.png" --report "$WORK/r2" || fail "--reference"
cmp -s <(cut -d, -f1,10-13 "$WORK/r/results.csv") <(cut -d, -f1,10-13 "$WORK/r2/results.csv") || fail "the same reference gives other errors"
# Bad input: status 2, nothing written.
expect2() {
  local what="$1"; shift
  out="$("$MPR" accuracy "$@" 2>&1)"; rc=$?
  [[ $rc -eq 2 ]] || fail "$what: exit $rc ($out)"
  [[ ! -e "$WORK/none" ]] || fail "$what: wrote a report"
  echo "$out"
}
msg="$(expect2 "budget" "${small[@]}" --budget 0.000001 --report "$WORK/none")"
[[ "$msg" == *"over --budget"*"most costly setting is"* ]] || fail "budget message: $msg"
msg="$(expect2 "bad vary" "${small[@]}" --vary render.recursion_depth --report "$WORK/none")"
[[ "$msg" == *"must be KEY=V1,V2"* ]] || fail "vary message: $msg"
msg="$(expect2 "bad value" "${small[@]}" --vary render.recursion_depth=1,x --report "$WORK/none")"
[[ "$msg" == "mpr accuracy: --vary render.recursion_depth=x: render.recursion_depth must be a number, not 'x'" ]] || fail "value message: $msg"
msg="$(expect2 "wrong size" --width 16 --height 12 --spp 1 --repeat 1 --reference "$WORK/ref.png" --report "$WORK/none")"
[[ "$msg" == *"is 32x24, the scene renders 16x12"* ]] || fail "size message: $msg"
expect2 "model" "${small[@]}" --model glossy --report "$WORK/none" >/dev/null
expect2 "repeat" "${small[@]}" --repeat 0 --report "$WORK/none" >/dev/null
mkdir -p "$WORK/other" && echo keep > "$WORK/other/notes.txt"
msg="$("$MPR" accuracy "${small[@]}" --report "$WORK/other" 2>&1)"; [[ $? -eq 2 ]] || fail "a folder of other files was taken"
[[ "$(cat "$WORK/other/notes.txt")" == keep && ! -e "$WORK/other/report.html" ]] || fail "the other folder was touched"
"$MPR" accuracy --help | grep -q -- "--vary" || fail "--help"
finish

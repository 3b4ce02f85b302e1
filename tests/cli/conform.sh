# mpr conform: exit status, report files, bad input.
source "$(dirname "$0")/lib.bash"
out="$("$MPR" conform "$SRC/tests/conformance/stencil_saturate_wrap.gls" --report "$WORK/r")"; rc=$?
[[ $rc -eq 0 ]] || fail "a conforming script exited $rc: $out"
[[ "$out" == *"final           stencil  256/256 (100.000%)"*"conforms"* ]] || fail "report text: $out"
[[ -f "$WORK/r/summary.json" ]] || fail "no summary.json"
grep -q '"conforms": true' "$WORK/r/summary.json" || fail "summary: $(cat "$WORK/r/summary.json")"
printf 'glNope\n' > "$WORK/bad.gls"
"$MPR" conform "$WORK/bad.gls" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "bad script should exit 2"
"$MPR" conform "$SRC/tests/conformance/alpha_test.gls" --driver voodoo >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "bad driver should exit 2"
"$MPR" conform >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "no input should exit 2"
out="$("$MPR" conform -q --random 3 --seed 7)"; rc=$?
[[ $rc -eq 0 && "$out" == *"agreement over 3 scripts on llvmpipe (3 within bounds)"* ]] || fail "random: $rc $out"
finish

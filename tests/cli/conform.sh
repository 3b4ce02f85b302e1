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
# Mesa is opened when a replay needs it, not linked: other commands never load
# libLLVM (the sanitizer build links it: CMakeLists.txt). MPR_OSMESA, when
# set, is the only file tried.
if [[ "${MPR_SANITIZED:-0}" != 1 ]] && command -v readelf >/dev/null; then
  readelf -d "$MPR" | grep -E 'NEEDED.*(OSMesa|LLVM)' && fail "mpr links Mesa"
fi
out="$(MPR_OSMESA=/nonexistent "$MPR" conform "$SRC/tests/conformance/alpha_test.gls" --report "$WORK/nomesa" 2>&1)"; rc=$?
[[ $rc -eq 2 && "$out" == *"cannot open Mesa's OSMesa (tried /nonexistent"*"set MPR_OSMESA"* ]] ||
  fail "without Mesa: $rc $out"
[[ ! -e "$WORK/nomesa" ]] || fail "a report was written without Mesa"
finish

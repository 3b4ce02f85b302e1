# Shared by the CLI tests: $1 is the mpr binary, $2 the source tree.
set -uo pipefail
MPR="$1"
SRC="$2"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
finish() { if ((failures)); then echo "$failures failure(s)" >&2; exit 1; fi; echo "ok"; }
# expect_script_error NAME 'script text' 'expected message fragment'
expect_script_error() {
  local name="$1" text="$2" want="$3"
  printf '%s' "$text" > "$WORK/$name.gls"
  local out rc
  out="$("$MPR" gl "$WORK/$name.gls" --dump "$WORK/dump-$name" 2>&1)"; rc=$?
  [[ $rc -eq 2 ]] || fail "$name: exit status $rc, expected 2 ($out)"
  [[ "$out" == *"$WORK/$name.gls:"*"$want"* ]] || fail "$name: message '$out' lacks '$want'"
  [[ ! -e "$WORK/dump-$name" ]] || fail "$name: the dump folder was created"
}

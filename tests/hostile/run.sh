# The hostile-input corpus (issues 15 and 48): every case of one table
# (cases.tsv, or the table named by $3), run on the real binary. $1 is mpr,
# $2 the source tree. Each case gets a fresh work
# folder; a failing run must leave every file (and link) of it as it was,
# a passing one may only add $W/out/new. The corpus itself is checked too.
set -uo pipefail
MPR="$1"
H="$2/tests/hostile"
TABLE="${3:-cases.tsv}"
ROOT="$(mktemp -d)"
trap 'rm -rf "$ROOT"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
# Every entry under a folder: path, type, link target, and a regular file's hash.
state() {
  (cd "$1" && find . -path ./out/new -prune -o -printf '%p %y %l\n' | LC_ALL=C sort &&
     find . -path ./out/new -prune -o -type f -print0 | LC_ALL=C sort -z | xargs -0r sha256sum)
}
corpus_before="$(state "$H")"
n=0
while IFS=$'\t' read -r name status fragment command; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  if [[ "$name" == nosan_* && -n "${MPR_SANITIZED:-}" ]]; then
    echo "skip $name (sanitizer build)"
    continue
  fi
  n=$((n + 1))
  W="$ROOT/$name"
  mkdir -p "$W/out" "$W/in"
  echo keep > "$W/out/existing.png"
  echo victim > "$W/victim"
  before="$(state "$W")"
  out="$(cd "$W" && MPR="$MPR" H="$H" S="$2/scenes" W="$W" timeout 60 bash -c "$command" 2>&1)"
  rc=$?
  if ((rc == 124)); then fail "$name: ran past 60 s"; continue; fi
  ((rc == status)) || fail "$name: exit status $rc, expected $status: ${out:0:400}"
  [[ "$out" == *"$fragment"* ]] || fail "$name: output lacks '$fragment': ${out:0:400}"
  # Temporary files or folders an mpr run left behind would show here too.
  rm -rf "$W/in" && mkdir "$W/in"
  after="$(state "$W")"
  [[ "$after" == "$before" ]] || fail "$name: files changed: $(diff <(echo "$before") <(echo "$after") | head -8)"
done < "$H/$TABLE"
[[ "$(state "$H")" == "$corpus_before" ]] || fail "the corpus folder itself was changed"
if ((failures)); then echo "$failures failure(s) in $n cases" >&2; exit 1; fi
echo "ok: $n cases"

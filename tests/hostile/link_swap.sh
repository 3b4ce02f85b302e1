# Issue 48: a second process that can write in an output folder swaps a link
# to a victim in under every name the moment it appears (link_swapper, with
# inotify), while each command that writes files writes them. The victim
# file and the victim folder must stay as they were: every output is written
# through the descriptor that created it and renamed from a held folder.
# $1 mpr, $2 the source tree, $3 link_swapper.
source "$(dirname "${BASH_SOURCE[0]}")/../cli/lib.bash"
SWAPPER="$3"
ROOT="$WORK"
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$WORK"' EXIT

# attack NAME EXPECTED_STATUSES COMMAND...: runs the command (with $OUT its
# output folder) under attack; the statuses it may end with ("0 1": written,
# or refused at the write because a name was replaced; mpr test says a
# failed write with 2, its 1 being a failed test).
attack() {
  local name="$1" allowed="$2"
  shift 2
  local W="$ROOT/$name"
  mkdir -p "$W/out" "$W/victim-folder"
  echo victim > "$W/victim"
  echo victim > "$W/victim-folder/index.html"
  local before
  before="$(cd "$W" && sha256sum victim victim-folder/index.html && ls -A victim-folder)"
  "$SWAPPER" "$W/out" "$W/victim" "$W/victim-folder" 120 > "$W/swapper.log" &
  local swapper=$!
  for _ in $(seq 100); do grep -q ready "$W/swapper.log" 2>/dev/null && break; sleep 0.05; done
  local out rc
  out="$(OUT="$W/out" timeout 120 "$@" 2>&1)"
  rc=$?
  sleep 0.3  # the swapper sees the last renames too
  kill "$swapper" 2>/dev/null
  wait "$swapper" 2>/dev/null
  local after
  after="$(cd "$W" && sha256sum victim victim-folder/index.html && ls -A victim-folder)"
  [[ "$after" == "$before" ]] || fail "$name: the victim was written: $(diff <(echo "$before") <(echo "$after") | head -5)"
  [[ " $allowed " == *" $rc "* ]] || fail "$name: exit status $rc, expected one of $allowed: ${out:0:300}"
  # The attack must have found names to swap, or the test proves nothing.
  local events
  events="$(sed -n 's/^swapped //p' "$W/swapper.log")"
  ((${events:-0} > 0)) || fail "$name: the swapper found no name to swap"
  echo "ok $name (status $rc, $events names swapped)"
}

S="$SRC/scenes"
attack render "0 1" bash -c '"$0" render --width 96 --height 72 -o "$OUT/r.png" --trace "$OUT/t.gls" --stats "$OUT/s.json" --dump "$OUT/d"' "$MPR"
attack render_new_folders "0 1" bash -c '"$0" render --width 64 --height 48 -o "$OUT/a/b/r.png"' "$MPR"
attack reference_exr "0 1" bash -c '"$0" reference --width 24 --height 18 --spp 1 -o "$OUT/ref.exr"' "$MPR"
attack reference_tif "0 1" bash -c '"$0" reference --width 24 --height 18 --spp 1 -o "$OUT/ref.tif"' "$MPR"
attack gl "0 1" bash -c '"$0" gl "$1" --dump "$OUT/g"' "$MPR" "$SRC/tests/conformance/alpha_test.gls"
attack test "1 2" bash -c '"$0" test "$1" --junit "$OUT/j.xml" --report "$OUT/rep"' "$MPR" "$SRC/tests/probes/fail/stencil_pixel.gls"
attack step_html "0 1" bash -c '"$0" step "$1" --html "$OUT/page"' "$MPR" "$S/stencil_mirror.gls"
attack accuracy_report "0 1" bash -c '"$0" accuracy --width 16 --height 12 --spp 1 --repeat 1 --vary render.shadows=true,false -q --report "$OUT/acc"' "$MPR"
attack conform_report "0 1" bash -c '"$0" conform "$1" --report "$OUT/c"' "$MPR" "$SRC/tests/conformance/alpha_test.gls"

finish

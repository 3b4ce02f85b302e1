# --threads (issue 14): a draw's triangles have their rows shared out over
# threads, and the bytes do not move: every sample scene rendered at 400x300
# (large enough that its draws are split: a share is at least 16 384 pixels
# of bounding boxes) at 1, 2, 3 and 8 threads gives the same colour, depth,
# stencil and accumulation buffers and the same fragment counts, and so does
# every script of the conformance corpus (and mpr conform's report on it);
# a pixel's history (mpr step --pixel) is the same too.
source "$(dirname "$0")/lib.bash"
counts() { grep -o '"fragments_[a-z]*": *[0-9]*' "$1"; }  # every pass kind's counts
for scene in "" "$SRC"/scenes/*.yaml; do
  name="$(basename "${scene:-default}" .yaml)"
  for t in 1 2 3 8; do
    "$MPR" render $scene --width 400 --height 300 --threads $t -o "$WORK/$name-$t.png" --dump "$WORK/$name-$t" \
        --stats "$WORK/$name-$t.json" 2>/dev/null || fail "$name: render at $t threads failed"
  done
  for t in 2 3 8; do
    for b in color depth stencil accum; do
      cmp -s "$WORK/$name-1/$b.npy" "$WORK/$name-$t/$b.npy" || fail "$name: $b differs at $t threads"
    done
    [[ "$(counts "$WORK/$name-1.json")" == "$(counts "$WORK/$name-$t.json")" ]] || fail "$name: fragment counts differ at $t threads"
  done
done
for s in "$SRC"/tests/conformance/*.gls "$SRC"/tests/conformance/repro/*.gls; do
  name="$(basename "$s" .gls)"
  "$MPR" gl "$s" --threads 1 --dump "$WORK/c1-$name" -q 2>/dev/null || continue  # scripts that are meant to fail
  "$MPR" gl "$s" --threads 3 --dump "$WORK/c3-$name" -q 2>/dev/null || fail "$name: fails at 3 threads only"
  for f in "$WORK/c1-$name"/*.npy; do
    cmp -s "$f" "$WORK/c3-$name/$(basename "$f")" || fail "$name: $(basename "$f") differs at 3 threads"
  done
done
# mpr conform compares MPR's buffers with Mesa's: at 3 threads its report on
# the corpus is the one at 1, word for word.
one="$("$MPR" conform "$SRC"/tests/conformance/*.gls --threads 1 2>&1)"
three="$("$MPR" conform "$SRC"/tests/conformance/*.gls --threads 3 2>&1)"
[[ -n "$one" && "$one" == "$three" ]] || fail "mpr conform reports differently at 1 and 3 threads"
a="$("$MPR" step "$SRC/scenes/stencil_mirror.gls" --pixel 40,30 --threads 1 2>&1)"
b="$("$MPR" step "$SRC/scenes/stencil_mirror.gls" --pixel 40,30 --threads 8 2>&1)"
[[ -n "$a" && "$a" == "$b" ]] || fail "a pixel's history differs between 1 and 8 threads"
finish

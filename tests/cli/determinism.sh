# The same script gives the same bytes on every run.
source "$(dirname "$0")/lib.bash"
for run in 1 2; do
  "$MPR" gl "$SRC/scenes/stencil_mirror.gls" --dump "$WORK/run$run" -q || fail "run $run failed"
done
for f in color.npy depth.npy stencil.npy accum.npy color.png mask-stencil.npy; do
  cmp -s "$WORK/run1/$f" "$WORK/run2/$f" || fail "$f differs between two runs"
done
finish

# mpr render: every sample scene renders, its trace replays to the same bytes
# through mpr gl; bad scenes exit 2 and create or overwrite nothing.
source "$(dirname "$0")/lib.bash"
for scene in "" "$SRC"/scenes/*.yaml; do
  name="$(basename "${scene:-default}" .yaml)"
  "$MPR" render $scene --width 64 --height 48 -o "$WORK/$name.png" --dump "$WORK/$name-render" \
      --trace "$WORK/$name.gls" --stats "$WORK/$name.json" 2>/dev/null || { fail "$name: render failed"; continue; }
  [[ -s "$WORK/$name.png" ]] || fail "$name: no image"
  grep -q '"passes"' "$WORK/$name.json" || fail "$name: no statistics"
  "$MPR" gl "$WORK/$name.gls" --dump "$WORK/$name-replay" -q || fail "$name: trace does not run"
  for b in color depth stencil accum; do
    cmp -s "$WORK/$name-render/$b.npy" "$WORK/$name-replay/$b.npy" || fail "$name: $b differs between render and trace replay"
  done
done
# Output formats by extension.
for ext in tif exr; do
  "$MPR" render --width 16 --height 12 -o "$WORK/x.$ext" 2>/dev/null && [[ -s "$WORK/x.$ext" ]] || fail "no .$ext output"
done
"$MPR" render --width 16 --height 12 -o "$WORK/x.bmp" 2>/dev/null; [[ $? -eq 2 ]] || fail ".bmp should be refused"
# Images other than RGB PNGs go through the image module, opened on first
# use (util/image_io): without it such an image fails with the reason and
# nothing is written; a PNG (util/png_writer, libpng) and a run that writes
# no image do not need it.
out="$(MPR_IMAGE_IO=/nonexistent "$MPR" render --width 16 --height 12 -o "$WORK/nomodule.tif" 2>&1)"; rc=$?
[[ $rc -eq 1 && "$out" == *"cannot load the image module libmpr_image_io.so"*"set MPR_IMAGE_IO"* ]] ||
  fail "without the image module: status $rc, $out"
[[ ! -e "$WORK/nomodule.tif" ]] || fail "without the image module an image was written"
MPR_IMAGE_IO=/nonexistent "$MPR" render --width 16 --height 12 -o "$WORK/nomodule.png" 2>/dev/null &&
  [[ -s "$WORK/nomodule.png" ]] || fail "a PNG render needed the image module"
printf 'glClear GL_COLOR_BUFFER_BIT\n' > "$WORK/clear.gls"
MPR_IMAGE_IO=/nonexistent "$MPR" gl "$WORK/clear.gls" -q || fail "mpr gl without images needed the image module"
# A bad scene: status 2, the message located, the old output untouched, no new output.
echo old > "$WORK/keep.png"
printf 'camera:\n  positon: [0, 1, 2]\n' > "$WORK/bad.yaml"
out="$("$MPR" render "$WORK/bad.yaml" -o "$WORK/keep.png" 2>&1)"; rc=$?
[[ $rc -eq 2 ]] || fail "bad scene exited $rc"
[[ "$out" == "$WORK/bad.yaml:2:3: unknown key 'positon' in camera; did you mean 'position'?" ]] || fail "message: $out"
[[ "$(cat "$WORK/keep.png")" == old ]] || fail "a failed render overwrote its output"
"$MPR" render "$WORK/bad.yaml" -o "$WORK/new.png" >/dev/null 2>&1
[[ ! -e "$WORK/new.png" ]] || fail "a failed render created its output"
"$MPR" render "$WORK/missing.yaml" -o "$WORK/new.png" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "missing scene should exit 2"
"$MPR" render --set render.width=abc -o "$WORK/new.png" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "bad --set should exit 2"
desc="$("$MPR" render --describe-format)"; [[ "$desc" == *"\"recursion_depth\""* ]] || fail "--describe-format"
finish

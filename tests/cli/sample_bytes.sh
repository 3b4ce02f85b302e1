# Every sample render is byte-identical to the hashes in data/sample_bytes.sha256
# (PNG, the four buffers, the trace): a refactoring of the GL seam must not move
# a single byte. A line marked "as before" checks the trace with the directives
# of issue 13 turned back into what the trace held before (no @count_fragments;
# @window_map was a comment), so those traces differ from the old ones in the
# directives only.
source "$(dirname "$0")/lib.bash"
render() {  # NAME [render arguments...]
  local name="$1"; shift
  "$MPR" render "$@" --width 160 --height 120 -o "$WORK/$name.png" --dump "$WORK/$name" \
      --trace "$WORK/$name.gls" 2>/dev/null || fail "$name: render failed"
}
render default
render default_eop --set materials.glass.thickness=0 --set render.refraction_map=end_of_pipeline
for scene in "$SRC"/scenes/*.yaml; do
  name="$(basename "$scene" .yaml)"
  [[ "$name" == default ]] || render "$name" "$scene"
done
as_before() {
  grep -v '^@count_fragments' "$1" | sed 's/^@window_map/# MPR end-of-pipeline map (not a GL call; a replay lacks it):/'
}
while read -r hash file how; do
  [[ -z "$hash" || "$hash" == \#* ]] && continue
  [[ -e "$WORK/$file" ]] || { fail "$file: not rendered"; continue; }
  if [[ "$how" == "as before" ]]; then got="$(as_before "$WORK/$file" | sha256sum | cut -d' ' -f1)"
  else got="$(sha256sum "$WORK/$file" | cut -d' ' -f1)"; fi
  [[ "$got" == "$hash" ]] || fail "$file${how:+ ($how)}: sha256 $got, expected $hash"
done < "$SRC/tests/cli/data/sample_bytes.sha256"
# The end-of-pipeline map is a directive now: its trace replays to the same bytes.
"$MPR" gl "$WORK/default_eop.gls" --dump "$WORK/eop-replay" -q || fail "default_eop: trace does not run"
for b in color depth stencil accum; do
  cmp -s "$WORK/default_eop/$b.npy" "$WORK/eop-replay/$b.npy" || fail "default_eop: $b differs between render and replay"
done
finish

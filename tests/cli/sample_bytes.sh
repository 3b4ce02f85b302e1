# Every sample render is byte-identical to the hashes in data/sample_bytes.sha256
# (PNG, the four buffers, the trace): a refactoring of the GL seam must not move
# a single byte.
source "$(dirname "$0")/lib.bash"
render() {  # NAME [render arguments...]
  local name="$1"; shift
  "$MPR" render "$@" --width 160 --height 120 -o "$WORK/$name.png" --dump "$WORK/$name" \
      --trace "$WORK/$name.gls" 2>/dev/null || fail "$name: render failed"
}
render default
render default_eop --set render.refraction_map=end_of_pipeline
for scene in "$SRC"/scenes/*.yaml; do
  name="$(basename "$scene" .yaml)"
  [[ "$name" == default ]] || render "$name" "$scene"
done
while read -r hash file; do
  [[ -z "$hash" || "$hash" == \#* ]] && continue
  [[ -e "$WORK/$file" ]] || { fail "$file: not rendered"; continue; }
  got="$(sha256sum "$WORK/$file" | cut -d' ' -f1)"
  [[ "$got" == "$hash" ]] || fail "$file: sha256 $got, expected $hash"
done < "$SRC/tests/cli/data/sample_bytes.sha256"
finish

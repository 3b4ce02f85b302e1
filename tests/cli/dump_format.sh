# --dump writes the spec's .npy files (exact headers and bytes), color.png and
# snapshots.
source "$(dirname "$0")/lib.bash"
cat > "$WORK/s.gls" <<'GLS'
@framebuffer 3 2
@profile mesa
glDisable GL_DITHER
glClearStencil 7
glClearDepth 0.5
glClearColor 1 0 0 1
glClearAccum 0.5 0 -1 1
glClear GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT|GL_ACCUM_BUFFER_BIT
@snapshot cleared
glEnable GL_SCISSOR_TEST
glScissor 1 1 1 1
glClearStencil 200
glClear GL_STENCIL_BUFFER_BIT
GLS
"$MPR" gl "$WORK/s.gls" --dump "$WORK/d" >/dev/null || fail "run failed"
for f in color depth stencil accum cleared-color cleared-depth cleared-stencil cleared-accum; do
  [[ -f "$WORK/d/$f.npy" ]] || fail "missing $f.npy"
done
[[ -f "$WORK/d/color.png" ]] || fail "missing color.png"
python3 - "$WORK/d" <<'PY' || fail "npy contents"
import struct, sys
d = sys.argv[1]
def load(name):
    b = open(f"{d}/{name}.npy", "rb").read()
    assert b[:8] == b"\x93NUMPY\x01\x00", b[:8]
    n = struct.unpack("<H", b[8:10])[0]
    assert (10 + n) % 64 == 0 and b[10 + n - 1:10 + n] == b"\n"
    return b[10:10 + n].decode(), b[10 + n:]
h, s = load("stencil")
assert h.startswith("{'descr': '|u1', 'fortran_order': False, 'shape': (2, 3), }"), h
# Rows from window y = 0: the scissored clear hit (1, 1) only.
assert list(s) == [7, 7, 7, 7, 200, 7], list(s)
h, z = load("depth")
assert "'<u4'" in h and "(2, 3)" in h, h
assert struct.unpack("<6I", z) == (8388608,) * 6, struct.unpack("<6I", z)
h, c = load("color")
assert "(2, 3, 4)" in h and list(c[:4]) == [255, 0, 0, 255], list(c[:4])
h, a = load("accum")
assert "'<i2'" in h and "(2, 3, 4)" in h, h
# Mesa's FLOAT_TO_SHORT: ((int)(65535 * v) - 1) / 2 -> 16383, 0, -32768, 32767
assert struct.unpack("<4h", a[:8]) == (16383, 0, -32768, 32767), struct.unpack("<4h", a[:8])
h, s0 = load("cleared-stencil")
assert list(s0) == [7] * 6
PY
finish

# Malformed scripts stop with FILE:LINE:COLUMN, exit status 2, nothing written.
source "$(dirname "$0")/lib.bash"
expect_script_error unknown_call $'@framebuffer 4 4\nglStencilFunk GL_LESS 1 0xFF\n' "2:1: 'glStencilFunk' is not a call of the GL script call set; did you mean 'glStencilFunc'?"
expect_script_error too_few $'glStencilFunc GL_LESS 1\n' "1:24: glStencilFunc takes 3 arguments, got 2"
expect_script_error too_many $'glClear GL_COLOR_BUFFER_BIT 7\n' "1:29: glClear takes 1 argument, got 2"
expect_script_error bad_enum $'glEnable GL_STENCIL_TESTS\n' "1:10: unknown GL enumerant 'GL_STENCIL_TESTS'"
expect_script_error enum_expected $'glDepthFunc 513\n' "1:13: argument 1 of glDepthFunc is an enum"
expect_script_error bad_number $'glClearColor 0 0.5x 0 1\n' "1:16: argument 2 of glClearColor is a number"
expect_script_error bad_int $'glViewport 0 0 1.5 4\n' "1:16: argument 3 of glViewport is an integer"
expect_script_error bad_bool $'glDepthMask 2\n' "1:13: argument 1 of glDepthMask is a boolean"
expect_script_error bad_ubyte $'glColor3ub 0 256 0\n' "1:14: argument 2 of glColor3ub is an unsigned byte"
expect_script_error bad_bitfield $'glClear GL_COLOR_BUFFER_BIT|GL_DEPTH_BIT\n' "1:29: unknown GL enumerant 'GL_DEPTH_BIT' in bitfield"
expect_script_error late_framebuffer $'glClear GL_COLOR_BUFFER_BIT\n@framebuffer 4 4\n' "2:1: @framebuffer must come before the first call"
expect_script_error bad_profile $'@profile onyx\n' "1:10: unknown profile 'onyx'"
expect_script_error bad_directive $'@frame 4 4\n' "1:1: unknown directive '@frame'"
expect_script_error vector_count $'glLightfv GL_LIGHT0 GL_POSITION 0 1 0\n' "1:38: glLightfv GL_POSITION takes 4 values, got 3"
expect_script_error outside_subset $'glEnable GL_TEXTURE_2D\n' "1:10: GL_TEXTURE_2D is valid GL but outside the emulated call set"
expect_script_error lines $'glBegin GL_LINES\n' "1:9: GL_LINES is valid GL but outside the emulated call set"
expect_script_error dup_snapshot $'@snapshot a\n@snapshot a\n' "2:11: snapshot 'a' is taken twice"
expect_script_error zero_size $'@framebuffer 0 4\n' "1:14: framebuffer size 0x4 is not positive"
expect_script_error huge $'@framebuffer 100000 100000\n' "exceeds the largest side of 16384 pixels"
expect_script_error crlf_column $'glClear GL_COLOR_BUFFER_BIT\r\n  glScalef 1 2\r\n' "2:15: glScalef takes 3 arguments, got 2"
# An unreadable script.
out="$("$MPR" gl "$WORK/missing.gls" 2>&1)"; rc=$?
[[ $rc -eq 2 && "$out" == *"missing.gls"*"cannot read the script"* ]] || fail "missing file: $rc $out"
# An existing dump is not touched by a failing run.
mkdir -p "$WORK/keep" && echo old > "$WORK/keep/color.npy"
printf 'glNope\n' > "$WORK/bad.gls"
"$MPR" gl "$WORK/bad.gls" --dump "$WORK/keep" >/dev/null 2>&1
[[ "$(cat "$WORK/keep/color.npy")" == old ]] || fail "a failing run overwrote an existing dump"
finish

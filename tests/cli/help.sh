# --help explains the commands; no subcommand is a usage error.
source "$(dirname "$0")/lib.bash"
out="$("$MPR" --help)" || fail "mpr --help failed"
[[ "$out" == *"gl"*"Run a GL script"* ]] || fail "mpr --help: $out"
out="$("$MPR" gl --help)" || fail "mpr gl --help failed"
[[ "$out" == *"--dump"* && "$out" == *"--profile"* && "$out" == *"FILE:LINE:COLUMN"* ]] || fail "mpr gl --help: $out"
[[ "$out" == *"@expect stencil|depth|color|accum"* && "$out" == *"@expect-picture"* && "$out" == *"status 1"* ]] ||
  fail "mpr gl --help does not explain probes: $out"
"$MPR" >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "no subcommand should exit 2"
"$MPR" gl "$SRC/scenes/stencil_mirror.gls" --profile onyx >/dev/null 2>&1; [[ $? -eq 2 ]] || fail "bad --profile should exit 2"
finish

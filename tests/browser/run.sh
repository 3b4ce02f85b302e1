#!/usr/bin/env bash
# CTest entry of a browser test: skips (exit 77) with a hint when what the
# browser tests need is missing; scripts/setup installs it all.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
missing=()
command -v node >/dev/null || missing+=("node (Debian package nodejs)")
[[ -x /usr/bin/chromium ]] || missing+=("/usr/bin/chromium (Debian package chromium)")
[[ -d "$here/node_modules/playwright-core" ]] || missing+=("playwright-core (npm ci --prefix tests/browser)")
if ((${#missing[@]})); then
  echo "SKIP: missing ${missing[*]}; run scripts/setup" >&2
  exit 77
fi
exec node "$here/stepper_page.js" "$@"

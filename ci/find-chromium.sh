#!/usr/bin/env bash
# Prints the path of a headless Chromium that really runs here, or says why there is none
# (exit 1). Tried in order: $VSGL_CHROMIUM, chromium (Debian), chromium-browser, google-chrome(-stable),
# chrome-headless-shell, headless_shell. Each must render about:blank headless: Ubuntu's
# `chromium` / `chromium-browser` packages are transitional stubs that install a snap, and snaps
# do not run in containers; such a stub is found on PATH but fails this check.
set -uo pipefail
candidates=()
[[ -n "${VSGL_CHROMIUM:-}" ]] && candidates+=("$VSGL_CHROMIUM")
candidates+=(chromium chromium-browser google-chrome-stable google-chrome chrome-headless-shell headless_shell)
tried=()
for c in "${candidates[@]}"; do
  path=$(command -v "$c" 2>/dev/null) || continue
  profile=$(mktemp -d)
  if timeout 120 "$path" --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir="$profile" \
      --dump-dom about:blank 2>/dev/null | grep -q '<html'; then
    rm -rf "$profile"
    echo "$path"
    exit 0
  fi
  rm -rf "$profile"
  tried+=("$path (found, but does not run headless: a snap stub, or broken)")
done
echo "no headless Chromium here. Tried: ${candidates[*]}." >&2
for t in "${tried[@]}"; do echo "  $t" >&2; done
echo "Debian: apt-get install chromium. Ubuntu: its chromium package is a snap (fails in containers);" >&2
echo "install Google Chrome or chrome-headless-shell and point VSGL_CHROMIUM at it." >&2
exit 1

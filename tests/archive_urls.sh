#!/usr/bin/env bash
# No package archive is named in the repository (DESIGN.md §13): every script takes its mirror from
# the machine's apt sources (ci/debian-mirror.sh) or from the environment, so a machine behind its
# own mirror is never sent elsewhere. This greps every tracked file (git ls-files) for what points
# at an archive and fails naming each file and line:
#   - an apt source line (`deb URI ...`, `deb-src URI ...`, deb822 `URIs: URI`) with any URI;
#   - a URL whose path starts at an archive root (/debian, /debian-security, /debian-ports,
#     /ubuntu, /ubuntu-ports);
#   - a URL whose host is a Debian or Ubuntu archive's kind of name (deb., ftp., security.,
#     snapshot., archive., ports., httpredir., mirror(s). under debian or ubuntu), or an apt
#     repository's (apt., ppa., packages.).
# Reserved example names (RFC 2606/6761: *.example, *.invalid, *.test, localhost) are allowed.
# First it checks itself on lines it writes at run time (their URLs are assembled there, so this
# file names none), so a pattern that stopped matching fails.
# Usage: bash tests/archive_urls.sh SOURCE_DIR        (exit 77, skipped: not a git checkout)
set -euo pipefail
src=$1

url='[a-z][a-z0-9+.-]*://[^][:space:]"'\''<>()`]+'
patterns=(
  "(^|[^[:alnum:]_-])deb(-src)?[[:space:]]+(\\[[^]]*\\][[:space:]]+)?$url"
  "URIs:[[:space:]]*$url"
  "[a-z][a-z0-9+.-]*://[^/[:space:]\"']+/(debian|debian-security|debian-ports|ubuntu|ubuntu-ports)(/|[^[:alnum:]_.-]|\$)"
  "[a-z][a-z0-9+.-]*://((deb|ftp[0-9]*|security|snapshot|archive|ports|httpredir|mirrors?)\\.([a-z0-9-]+\\.)*(debian|ubuntu)\\.[a-z]+|(apt|ppa|packages)\\.[a-z0-9.-]+)"
)

# scan FILE...: prints FILE:LINE: TEXT for each hit whose URL is not a reserved example name.
scan() {
  local p
  for p in "${patterns[@]}"; do
    grep -HnoIE -- "$p" "$@" 2>/dev/null || true
  done | awk '{
    line = $0
    u = line; sub(/^[^:]*:[0-9]+:/, "", u)
    if (!match(u, /[a-z][a-z0-9+.-]*:\/\/[^\/[:space:]"\047]+/)) { print line; next }
    host = substr(u, RSTART, RLENGTH); sub(/^[^:]*:\/\//, "", host); sub(/:[0-9]+$/, "", host); sub(/^.*@/, "", host)
    if (host ~ /(^|\.)(example|invalid|test|localhost)$/ || host ~ /^example\.(com|org|net)$/) next
    print line
  }' | sort -u
}

# 1. The checker on lines made here: each must be found, the allowed ones must not.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
s=http t=https d=debian
{
  echo "deb ${s}://mirror.vsgl-selftest.net/repo bookworm main"
  echo "  deb-src [signed-by=/k.gpg] ${s}://mirror.vsgl-selftest.net/repo bookworm main"
  echo "URIs: ${s}://mirror.vsgl-selftest.net/repo"
  echo "see ${s}://files.vsgl-selftest.net/debian/pool/main/"
  echo "see ${s}://files.vsgl-selftest.net/ubuntu"
  echo "curl ${s}://deb.${d}.org/x"
  echo "curl ${t}://apt.vsgl-selftest.net/gpg"
} >"$work/bad.txt"
{
  echo "deb ${s}://mirror.example/debian bookworm main"
  echo "Format: ${t}://www.${d}.org/doc/packaging-manuals/copyright-format/1.0/"
  echo "see ${s}://files.vsgl-selftest.net/debianutils/"
  echo "the deb file, deb822 format"
} >"$work/good.txt"
found=$(scan "$work/bad.txt" | cut -d: -f2 | sort -un | tr '\n' ' ')
expected=$(seq 1 "$(wc -l <"$work/bad.txt")" | tr '\n' ' ')
if [[ $found != "$expected" ]]; then
  echo "tests/archive_urls.sh: the check itself is broken: it found lines [$found] of [$expected]:"
  cat -n "$work/bad.txt"
  exit 1
fi
if [[ -n $(scan "$work/good.txt") ]]; then
  echo "tests/archive_urls.sh: the check itself is broken: it flags allowed lines:"
  scan "$work/good.txt"
  exit 1
fi

# 2. The repository.
if ! git -C "$src" rev-parse --git-dir >/dev/null 2>&1; then
  echo "tests/archive_urls.sh: $src is not a git checkout: skipped"
  exit 77
fi
mapfile -d '' files < <(git -C "$src" ls-files -z)
hits=$(cd "$src" && scan "${files[@]}")
if [[ -n $hits ]]; then
  echo "tests/archive_urls.sh: package archives named in the repository (take the mirror from the machine's"
  echo "  apt sources with ci/debian-mirror.sh, or from an environment variable with no default):"
  echo "$hits" | sed 's/^/  /'
  exit 1
fi
echo "tests/archive_urls.sh: ${#files[@]} tracked files, no package archive named"

#!/usr/bin/env bash
# ci/debian-mirror.sh on apt source files written here (--apt-dir): the one-line and the deb822
# formats, comments, options, disabled stanzas and other suites, and the refusals. Hosts are
# RFC 2606 example names. Usage: bash tests/debian_mirror.sh SOURCE_DIR
set -euo pipefail
script=$1/ci/debian-mirror.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
expect() {  # expect WHAT EXPECTED ACTUAL
  if [[ $2 == "$3" ]]; then echo "ok: $1"; else echo "FAILED: $1: expected '$2', got '$3'"; failures=$((failures + 1)); fi
}
apt() {  # apt NAME: a fresh apt directory
  rm -rf "${work:?}/$1"
  mkdir -p "$work/$1/sources.list.d"
  echo "$work/$1"
}

# One-line format: a comment, another suite, a source without main, then the one to take.
d=$(apt oneline)
cat >"$d/sources.list" <<'L'
# deb http://commented.example/debian bookworm main
deb http://security.example/debian-security bookworm-security main
deb http://contrib-only.example/debian bookworm contrib
deb-src http://sources.example/debian bookworm main
deb [arch=amd64 signed-by=/usr/share/keyrings/example.gpg] http://mirror.example/debian/ bookworm main contrib
L
expect "one-line URI" http://mirror.example/debian "$(bash "$script" --apt-dir "$d" --suite bookworm)"
expect "one-line Signed-By" /usr/share/keyrings/example.gpg "$(bash "$script" --apt-dir "$d" --suite bookworm --signed-by)"
expect "one-line other suite" http://security.example/debian-security "$(bash "$script" --apt-dir "$d" --suite bookworm-security)"

# deb822: a disabled stanza and a deb-src stanza first, several suites and URIs in one stanza.
d=$(apt deb822)
cat >"$d/sources.list.d/debian.sources" <<'S'
# the archive
Types: deb
URIs: http://disabled.example/debian
Suites: bookworm
Components: main
Enabled: no

Types: deb-src
URIs: http://sources.example/debian
Suites: bookworm
Components: main

Types: deb deb-src
URIs: http://mirror822.example/debian http://second.example/debian
Suites: bookworm bookworm-updates
Components: main non-free-firmware
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
S
expect "deb822 URI" http://mirror822.example/debian "$(bash "$script" --apt-dir "$d" --suite bookworm)"
expect "deb822 Signed-By" /usr/share/keyrings/debian-archive-keyring.gpg \
  "$(bash "$script" --apt-dir "$d" --suite bookworm --signed-by)"
expect "deb822 second suite of a stanza" http://mirror822.example/debian \
  "$(bash "$script" --apt-dir "$d" --suite bookworm-updates)"

# Both formats present: sources.list is read first.
cp "$work/oneline/sources.list" "$d/sources.list"
expect "sources.list before sources.list.d" http://mirror.example/debian "$(bash "$script" --apt-dir "$d" --suite bookworm)"

# Nothing matches: exit 1, naming the suite and the files read.
rc=0
out=$(bash "$script" --apt-dir "$d" --suite trixie 2>&1) || rc=$?
expect "no source: exit code" 1 "$rc"
expect "no source: the message names the suite" yes "$([[ $out == *"suite trixie"* && $out == *debian.sources* ]] && echo yes || echo "no: $out")"
rc=0
bash "$script" --bogus >/dev/null 2>&1 || rc=$?
expect "unknown option: exit code" 2 "$rc"

[[ $failures -eq 0 ]] || { echo "tests/debian_mirror.sh: $failures checks failed"; exit 1; }
echo "tests/debian_mirror.sh: all checks passed"

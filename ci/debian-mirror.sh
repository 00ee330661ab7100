#!/usr/bin/env bash
# Prints the URI of the Debian archive this machine's apt already uses, so that what the scripts
# add or fetch (ci/install-deps.sh's deb-src source, ci/package-trial.sh's chroot) comes from the
# same mirror, and no archive host is written into the repository. It reads the apt sources in
# both formats: one-line (/etc/apt/sources.list, sources.list.d/*.list: `deb [options] URI SUITE
# COMPONENT...`) and deb822 (sources.list.d/*.sources: stanzas of `Types:`, `URIs:`, `Suites:`,
# `Components:`, `Enabled:`), and takes the first enabled `deb` source of SUITE whose components
# include main.
# Usage: bash ci/debian-mirror.sh [--suite SUITE] [--signed-by] [--apt-dir DIR]
#   --suite SUITE  the suite to look for (default: VERSION_CODENAME of /etc/os-release)
#   --signed-by    print that source's Signed-By keyring instead of its URI (empty if it has none)
#   --apt-dir DIR  read DIR/sources.list and DIR/sources.list.d/ instead of /etc/apt's
# Exit 0 with the URI (no trailing slash), 1 when no source matches (saying which files were
# read), 2 on a usage error.
set -euo pipefail

suite="" apt_dir=/etc/apt field=uri
while [[ $# -gt 0 ]]; do
  case "$1" in
    --suite) [[ $# -ge 2 ]] || { echo "ci/debian-mirror.sh: --suite needs a suite name" >&2; exit 2; }; suite=$2; shift 2 ;;
    --apt-dir) [[ $# -ge 2 ]] || { echo "ci/debian-mirror.sh: --apt-dir needs a directory" >&2; exit 2; }; apt_dir=$2; shift 2 ;;
    --signed-by) field=signed-by; shift ;;
    *) echo "ci/debian-mirror.sh: unknown option '$1' (--suite SUITE, --signed-by, --apt-dir DIR)" >&2; exit 2 ;;
  esac
done
if [[ -z $suite ]]; then
  [[ -r /etc/os-release ]] && suite=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  [[ -n $suite ]] || { echo "ci/debian-mirror.sh: no VERSION_CODENAME in /etc/os-release: pass --suite SUITE" >&2; exit 2; }
fi

files=()
[[ -f $apt_dir/sources.list ]] && files+=("$apt_dir/sources.list")
shopt -s nullglob
for f in "$apt_dir"/sources.list.d/*.list "$apt_dir"/sources.list.d/*.sources; do files+=("$f"); done

# One awk program for both formats: it prints "URI<TAB>SIGNED-BY" of each matching source, in the
# order the files and their lines come.
matches=$(
  for f in "${files[@]}"; do
    case "$f" in
      *.sources) format=deb822 ;;
      *) format=oneline ;;
    esac
    awk -v suite="$suite" -v format="$format" '
      function has(list, word,   n, i, parts) {
        n = split(list, parts, /[ \t]+/)
        for (i = 1; i <= n; i++) if (parts[i] == word) return 1
        return 0
      }
      function flush(   n, i, uris) {
        if (types != "" && has(types, "deb") && has(suites, suite) && has(components, "main") && enabled != "no") {
          n = split(uri_list, uris, /[ \t]+/)
          for (i = 1; i <= n; i++) if (uris[i] != "") print uris[i] "\t" signed
        }
        types = ""; uri_list = ""; suites = ""; components = ""; enabled = ""; signed = ""
      }
      format == "oneline" {
        sub(/#.*/, "")
        if ($1 != "deb") next
        options = ""
        line = $0
        # [ option=value ... ] after the type
        if (match(line, /\[[^]]*\]/)) { options = substr(line, RSTART + 1, RLENGTH - 2); line = substr(line, 1, RSTART - 1) substr(line, RSTART + RLENGTH) }
        n = split(line, w, /[ \t]+/)
        k = 0
        for (i = 1; i <= n; i++) if (w[i] != "") words[++k] = w[i]
        if (k < 4 || words[3] != suite) next
        main = 0
        for (i = 4; i <= k; i++) if (words[i] == "main") main = 1
        if (!main) next
        signed = ""
        m = split(options, o, /[ \t]+/)
        for (i = 1; i <= m; i++) if (o[i] ~ /^signed-by=/) signed = substr(o[i], 11)
        print words[2] "\t" signed
        next
      }
      format == "deb822" && /^[ \t]*#/ { next }
      format == "deb822" && /^[ \t]*$/ { flush(); next }
      format == "deb822" && /^[^ \t]/ {
        key = tolower($0); sub(/:.*/, "", key)
        value = $0; sub(/^[^:]*:[ \t]*/, "", value)
        if (key == "types") types = value
        else if (key == "uris") uri_list = value
        else if (key == "suites") suites = value
        else if (key == "components") components = value
        else if (key == "enabled") enabled = tolower(value)
        else if (key == "signed-by") signed = value
        next
      }
      END { if (format == "deb822") flush() }
    ' "$f"
  done
)
if [[ -z $matches ]]; then
  echo "ci/debian-mirror.sh: no enabled 'deb' source of suite $suite with component main in: ${files[*]:-no apt source files under $apt_dir}" >&2
  echo "  Set the mirror by hand where the script takes one (e.g. VSGL_TRIAL_MIRROR for ci/package-trial.sh)." >&2
  exit 1
fi
first=$(head -1 <<<"$matches")
if [[ $field == uri ]]; then
  uri=${first%%$'\t'*}
  echo "${uri%/}"
else
  echo "${first#*$'\t'}"
fi

#!/usr/bin/env bash
# Installs the vsgl-bench Debian package on a minimal Debian 12 where none of its dependencies
# are installed, and runs it there (DESIGN.md §13): debootstrap makes a fresh minbase chroot under
# /tmp, `apt install ./vsgl-bench_*.deb` inside it pulls what the package declares from Debian's
# archive (Depends, and the recommended mesa-vulkan-drivers for lavapipe), then the installed
# programs run: `vsgl-bench devices`, `vsgl-bench record --scene tiny`, `vsgl-bench tables --quick`.
# Prints the figures: package size, chroot size before and after, install time, packages pulled in.
#
# Usage (as root, with network access to the Debian mirror; not part of ci/test.sh):
#   cmake --preset ci && cmake --build --preset ci
#   cpack --config build/ci/CPackConfig.cmake -B build/ci/package      # needs dpkg-dev
#   bash ci/package-trial.sh [build/ci/package/vsgl-bench_*.deb]
# Without an argument it takes the one .deb under build/ci/package.
# Environment: VSGL_TRIAL_MIRROR (no default: without it, the mirror this machine's apt uses for
# the suite, found by ci/debian-mirror.sh), VSGL_TRIAL_SUITE (default bookworm), VSGL_TRIAL_KEEP=1
# keeps the chroot (its path is printed) instead of removing it.
# Needs debootstrap (apt-get install debootstrap). Exit 0 only when every step passed.
set -uo pipefail
cd "$(dirname "$0")/.."

suite=${VSGL_TRIAL_SUITE:-bookworm}

die() { echo "ci/package-trial.sh: $*" >&2; exit 2; }
if [[ -n ${VSGL_TRIAL_MIRROR:-} ]]; then
  mirror=$VSGL_TRIAL_MIRROR
else
  mirror=$(bash ci/debian-mirror.sh --suite "$suite") ||
    die "no Debian mirror for $suite in this machine's apt sources: set VSGL_TRIAL_MIRROR=<archive URI>"
fi
[[ $(id -u) -eq 0 ]] || die "needs root (debootstrap, chroot, mount)"
command -v debootstrap >/dev/null || die "needs debootstrap: apt-get install debootstrap"
if [[ $# -ge 1 ]]; then
  deb=$1
else
  shopt -s nullglob
  debs=(build/ci/package/vsgl-bench_*.deb)
  [[ ${#debs[@]} -eq 1 ]] || die "expected one build/ci/package/vsgl-bench_*.deb, found ${#debs[@]}: pass the .deb to try"
  deb=${debs[0]}
fi
[[ -f "$deb" ]] || die "no such package: $deb"
deb=$(realpath "$deb")

root=$(mktemp -d /tmp/vsgl-package-trial.XXXXXX)
cleanup() {
  for m in "$root/dev/pts" "$root/dev" "$root/proc"; do mountpoint -q "$m" && umount "$m"; done
  if [[ "${VSGL_TRIAL_KEEP:-0}" == 1 ]]; then
    echo "ci/package-trial.sh: chroot kept in $root"
  else
    rm -rf --one-file-system "$root"
  fi
}
trap cleanup EXIT

mib() { du -sx --block-size=1M "$1" | cut -f1; }
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  DEBIAN_FRONTEND=noninteractive "$@"; }

failed=()
step() {  # step NAME COMMAND...: runs it, says how long it took and whether it passed
  local name=$1; shift
  local start=$SECONDS
  echo "== $name"
  if "$@"; then
    echo "== $name: ok ($((SECONDS - start)) s)"
  else
    local rc=$?
    echo "== $name: FAILED with exit $rc ($((SECONDS - start)) s)"
    failed+=("$name")
  fi
}

echo "package: $deb ($(stat -c %s "$deb") bytes)"
dpkg-deb -f "$deb" Package Version Architecture Depends Recommends Suggests

start=$SECONDS
debootstrap --variant=minbase "$suite" "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
  { tail -20 "$root.debootstrap.log" >&2; rm -f "$root.debootstrap.log"; die "debootstrap failed"; }
rm -f "$root.debootstrap.log"
debootstrap_s=$((SECONDS - start))
before_mib=$(mib "$root")
mount -t proc proc "$root/proc"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"  # apt's terminal log
cp "$deb" "$root/tmp/"
in_root dpkg-query -W -f='${Package}\n' | sort >"$root/tmp/before.txt"
step "apt-get update" in_root apt-get update -q

start=$SECONDS
step "apt install ./$(basename "$deb")" in_root apt-get install -y -q "/tmp/$(basename "$deb")"
install_s=$((SECONDS - start))
in_root apt-get clean
after_mib=$(mib "$root")
in_root dpkg-query -W -f='${Package}\n' | sort >"$root/tmp/after.txt"
pulled=$(comm -13 "$root/tmp/before.txt" "$root/tmp/after.txt")

# The programs as a user would run them, from a work directory of their own.
in_root mkdir -p /tmp/work
run_in_work() { in_root sh -c "cd /tmp/work && $*"; }
step "vsgl-bench --version" run_in_work vsgl-bench --version
step "vsgl-bench devices" run_in_work vsgl-bench devices
step "vsgl-gbench --help" run_in_work "vsgl-gbench --help >/dev/null"
step "vsgl-bench record --scene tiny" run_in_work vsgl-bench record --scene tiny --out captures/tiny
step "vsgl-bench tables --quick" run_in_work vsgl-bench tables --quick --out results/trial
run_in_work "ls -l results/trial 2>/dev/null"

echo
echo "figures ($suite minbase from $mirror):"
echo "  package:           $(basename "$deb"), $(stat -c %s "$deb") bytes"
echo "  debootstrap:       ${debootstrap_s} s"
echo "  chroot before:     ${before_mib} MiB"
echo "  chroot after:      ${after_mib} MiB (apt cache cleaned)"
echo "  apt install time:  ${install_s} s (download included)"
echo "  packages pulled:   $(echo "$pulled" | grep -c .)"
echo "$pulled" | tr '\n' ' ' | fold -s -w 96 | sed 's/^/    /'
echo
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "ci/package-trial.sh: FAILED: ${failed[*]}"
  exit 1
fi
echo "ci/package-trial.sh: every step passed"

#!/usr/bin/env bash
# Makes every release artefact of the checked-out commit into dist/ (docs/install.md#releases):
#   vsgl-bench_<version>_<arch>.deb          the Debian package, checked with lintian
#   vsgl-bench-<version>-Linux.tar.gz        the same install tree as a tarball
#   vsgl-bench-<version>-windows-x86_64.zip  the Windows programs (mingw-w64 cross build)
#   SHA256SUMS                               of the three (sha256sum -c SHA256SUMS)
#   RELEASE-NOTES.md                         the committed results' headline figures and the
#                                            paper's claims (ci/release_notes.py), sizes, lintian
# It refuses a tree with changes or untracked files (the artefacts must be the commit). The
# version is the latest tag (a leading v dropped) when HEAD is tagged, <tag>+<n>.g<commit> when HEAD
# is n commits past it, and without a tag the CMake project version plus the commit
# (<version>+g<commit>); it names the artefacts and the packages' metadata (VSGL_PACKAGE_VERSION).
# Release builds without tests, in build/release-dist/; manual pages are required (help2man).
# lintian must report no error and no warning (it reported none at the time of writing; a warning
# that has to stay needs a lintian override, with its reason, in the package). The Windows libraries are built once by ci/windows-deps.sh into
# $VSGL_WINDOWS_DEPS (default build/windows-deps), a cache that several checkouts may share.
# Usage: bash ci/release.sh            Exit 0 when every artefact was made and checked.
set -euo pipefail
cd "$(dirname "$0")/.."
src=$PWD
die() {
  echo "ci/release.sh: $*" >&2
  exit 1
}
say() { echo "ci/release.sh: $*"; }

# The tree is the commit.
git rev-parse --git-dir >/dev/null 2>&1 || die "$src is not a git checkout: a release is made from a commit"
dirty=$(git status --porcelain --untracked-files=normal)
if [[ -n $dirty ]]; then
  echo "$dirty" | sed 's/^/  /' >&2
  die "the tree has changes or untracked files (above): commit or remove them, then run it again"
fi
commit=$(git rev-parse HEAD)
short=$(git rev-parse --short=10 HEAD)

# The version.
cmake_version=$(sed -n 's/^project([^)]*VERSION \([0-9][0-9.]*\).*/\1/p' CMakeLists.txt | head -1)
[[ -n $cmake_version ]] || die "no VERSION in CMakeLists.txt's project()"
if tag=$(git describe --tags --abbrev=0 2>/dev/null); then
  past=$(git rev-list --count "$tag..HEAD")
  version=${tag#v}
  [[ $past -eq 0 ]] || version="$version+$past.g$short"
  origin="tag $tag$([[ $past -eq 0 ]] || echo ", $past commits past it")"
else
  version="$cmake_version+g$short"
  origin="no tag: the CMake version $cmake_version and the commit"
fi
[[ $version =~ ^[0-9][A-Za-z0-9.+~]*$ ]] ||
  die "version '$version' (from $origin) is no Debian version: a tag must start with a digit (or v and a digit)"
say "version $version ($origin), commit $commit"

# The tools, all named at once.
missing=()
need() { command -v "$1" >/dev/null 2>&1 || missing+=("$1 ($2)"); }
need cmake cmake
need ninja ninja-build
need help2man help2man
need dpkg-shlibdeps dpkg-dev
need lintian lintian
need sha256sum coreutils
need python3 python3
need x86_64-w64-mingw32-g++-posix g++-mingw-w64-x86-64-posix
[[ ${#missing[@]} -eq 0 ]] || die "missing: ${missing[*]}; run: bash ci/install-deps.sh"

# The commit's time stamps what the tools date (help2man's manual pages), not the hour of the build.
SOURCE_DATE_EPOCH=$(git log -1 --format=%ct)
export SOURCE_DATE_EPOCH

start=$SECONDS
dist=$src/dist
rm -rf "$dist"
mkdir -p "$dist"
work=$src/build/release-dist
mkdir -p "$work"
common=(-G Ninja -DCMAKE_BUILD_TYPE=Release -DVSGL_WERROR=ON -DVSGL_BUILD_TESTS=OFF
        "-DVSGL_PACKAGE_VERSION=$version")

# 1. Linux: the programs and their manual pages, then the .deb and the .tar.gz of one install tree.
t0=$SECONDS
cmake -S "$src" -B "$work/linux" "${common[@]}" -DVSGL_MAN_PAGES=ON >"$work/linux-configure.log" 2>&1 ||
  { cat "$work/linux-configure.log" >&2; die "configuring the Linux build failed"; }
nice -n 10 cmake --build "$work/linux" || die "the Linux build failed"
rm -rf "$work/linux/package"
cpack --config "$work/linux/CPackConfig.cmake" -B "$work/linux/package" -G "DEB;TGZ" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; die "cpack failed"; }
deb=$(find "$work/linux/package" -maxdepth 1 -name "vsgl-bench_${version}_*.deb")
tgz=$(find "$work/linux/package" -maxdepth 1 -name "vsgl-bench-${version}-*.tar.gz")
[[ -f $deb && -f $tgz ]] || die "cpack made no vsgl-bench_${version}_*.deb and vsgl-bench-${version}-*.tar.gz in $work/linux/package"
cp "$deb" "$tgz" "$dist/"
say "Linux build and packages $((SECONDS - t0)) s"

# What the tarball must hold: LICENSE, NOTICE, the README, the programs and their manual pages.
listing=$(tar tzf "$tgz")
for f in share/doc/vsgl-bench/LICENSE share/doc/vsgl-bench/NOTICE share/doc/vsgl-bench/README.md \
  bin/vsgl-bench bin/vsgl-gbench bin/vsgl-mipbench \
  share/man/man1/vsgl-bench.1.gz share/man/man1/vsgl-gbench.1.gz share/man/man1/vsgl-mipbench.1.gz; do
  grep -qE "^[^/]+/$f\$" <<<"$listing" || die "$(basename "$tgz") lacks $f"
done

# 2. lintian: no error and no warning.
lintian_out=$(lintian --fail-on none "$deb" 2>&1) || die "lintian could not check $(basename "$deb"): $lintian_out"
errors=$(grep -c '^E: ' <<<"$lintian_out" || true)
warnings=$(grep -c '^W: ' <<<"$lintian_out" || true)
overridden=$(lintian --fail-on none --show-overrides "$deb" 2>&1 | grep -c '^O: ' || true)
[[ -z $lintian_out ]] || echo "$lintian_out" | sed 's/^/  lintian: /'
lintian_summary="$errors errors, $warnings warnings, $overridden overridden (lintian $(lintian --version | awk '{print $2}'))"
say "lintian: $lintian_summary"
[[ $errors -eq 0 && $warnings -eq 0 ]] ||
  die "lintian reported errors or warnings on $(basename "$deb") (above): fix each, or ship a lintian override with its reason"

# 3. Windows: the libraries (cached), then the three programs and their zip.
t0=$SECONDS
deps=${VSGL_WINDOWS_DEPS:-$src/build/windows-deps}
nice -n 10 bash ci/windows-deps.sh "$deps" || die "ci/windows-deps.sh $deps failed"
cmake -S "$src" -B "$work/windows" "${common[@]}" --toolchain "$src/cmake/toolchains/mingw-w64-x86_64.cmake" \
  "-DVSGL_WINDOWS_DEPS=$deps" >"$work/windows-configure.log" 2>&1 ||
  { cat "$work/windows-configure.log" >&2; die "configuring the Windows build failed"; }
nice -n 10 cmake --build "$work/windows" --target vsgl_windows_zip || die "the Windows build failed"
zip=$work/windows/vsgl-bench-$version-windows-x86_64.zip
[[ -f $zip ]] || die "the Windows build made no $zip"
zlisting=$(python3 -m zipfile -l "$zip" | awk 'NR > 1 {print $1}')
for f in vsgl-bench.exe vsgl-gbench.exe vsgl-mipbench.exe README.md LICENSE NOTICE licences/; do
  grep -qE "^vsgl-bench-[^/]+-windows-x86_64/$f" <<<"$zlisting" || die "$(basename "$zip") lacks $f"
done
cp "$zip" "$dist/"
say "Windows build and zip $((SECONDS - t0)) s"

# 4. Checksums and the notes.
(cd "$dist" && sha256sum -- *.deb *.tar.gz *.zip >SHA256SUMS)
python3 ci/release_notes.py --version "$version" --commit "$commit" >"$dist/RELEASE-NOTES.md" ||
  die "the release notes could not be drawn from the committed results"
{
  echo "## This release's files"
  echo
  echo "| file | bytes | SHA-256 |"
  echo "| --- | ---: | --- |"
  while read -r sum name; do
    echo "| \`$name\` | $(stat -c %s "$dist/$name") | \`$sum\` |"
  done <"$dist/SHA256SUMS"
  echo
  echo "lintian on the .deb: $lintian_summary."
} >>"$dist/RELEASE-NOTES.md"

say "made in $((SECONDS - start)) s:"
(cd "$dist" && ls -l --time-style=+ -- * | awk '{print "  " $5 "  " $NF}')

#!/usr/bin/env bash
# Holds the C++ lines the last commit changed (and any uncommitted changes) to .clang-format; the
# rest of the tree is not reformatted. Exit 0 when they conform or when there is nothing it can
# check, saying why; 1 with the diff that would fix them (apply it with
# `git clang-format HEAD~1`).
# Not checked, each with a message: a checkout without git or git-clang-format, a shallow clone
# without the parent commit, a merge commit (its lines were written, and checked, on the merged
# branch), and a commit whose parent had no .clang-format (its lines predate the style file).
set -euo pipefail
cd "$(dirname "$0")/.."

skip() {
  echo "ci/check-format.sh: not checked: $*"
  exit 0
}
command -v git >/dev/null 2>&1 || skip "git is not installed"
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || skip "not a git checkout"
git clang-format -h >/dev/null 2>&1 || skip "git clang-format is not installed (Debian: clang-format)"
git rev-parse --verify -q HEAD~1 >/dev/null || skip "HEAD has no parent here (a shallow clone or the first commit)"
[[ $(git rev-list --parents -n 1 HEAD | wc -w) -le 2 ]] || skip "HEAD is a merge commit"
git cat-file -e HEAD~1:.clang-format 2>/dev/null || skip "the parent of HEAD has no .clang-format"

extensions=c,h,cc,cpp,hpp
if ! out=$(git clang-format --diff --extensions "$extensions" HEAD~1 -- 2>&1); then
  echo "ci/check-format.sh: git clang-format failed: $out" >&2
  exit 1
fi
case "$out" in
  "" | "no modified files to format" | "clang-format did not modify any files")
    echo "ci/check-format.sh: the changed C++ lines follow .clang-format"
    ;;
  *)
    echo "$out"
    echo "ci/check-format.sh: changed C++ lines above do not follow .clang-format (fix: git clang-format HEAD~1)" >&2
    exit 1
    ;;
esac

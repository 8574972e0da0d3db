#!/bin/sh
# `fsi --version` names the revision the source tree was at when fsi was built (not when the
# build was configured): HEAD's short hash, "-dirty" allowed, or "unknown" outside git.
# Usage: version_revision.sh FSI SOURCE_DIR
fsi=$1
src=$2
got=$("$fsi" --version) || exit 1
if head=$(git -C "$src" rev-parse --short=12 HEAD 2>/dev/null); then
  case "$got" in
  *"($head)" | *"($head-dirty)") exit 0 ;;
  esac
  echo "expected the revision $head (HEAD of $src; rebuild after a commit), got: $got"
  exit 1
fi
case "$got" in
*"(unknown)") exit 0 ;;
esac
echo "expected (unknown) outside git, got: $got"
exit 1

#!/usr/bin/env bash
# Every C++ file of the repository is formatted as .clang-format says.
set -u
cd "$1"
files=$(git ls-files '*.cc' '*.h' 2>/dev/null || find src include controllers tests bench examples -name '*.cc' -o -name '*.h')
if ! out=$(clang-format --dry-run -Werror $files 2>&1); then
  echo "$out" | grep "error:" | head -20
  echo "FAIL: run: clang-format -i \$(git ls-files '*.cc' '*.h')"
  exit 1
fi
echo "ok: $(echo $files | wc -w) files formatted"

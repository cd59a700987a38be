#!/usr/bin/env bash
# Formats the C++ sources with clang-format (.clang-format); --check only reports the files
# that differ and exits non-zero (CI runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' | grep -v '^tests/corpus/')
if [ "${1:-}" = "--check" ]; then
  clang-format-14 --dry-run --Werror "${files[@]}"
  echo "format: ${#files[@]} files as .clang-format says"
else
  clang-format-14 -i "${files[@]}"
fi

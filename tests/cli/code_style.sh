#!/usr/bin/env bash
# The house style that tools can check (STYLE.md, Habits): every .cpp and .hpp as clang-format
# 14 with the root .clang-format leaves it, and no function body over 100 lines
# (tests/tools/function_lengths.py). Skipped (77) without clang-format-14, which
# scripts/install-deps.sh installs.
# Usage: code_style.sh FETICON SOURCE_DIR
set -euo pipefail
cd "$2"
if ! command -v clang-format-14 > /dev/null; then
  echo "skipped: clang-format-14 is missing"
  exit 77
fi
# The tracked sources in a git checkout, else every source under the project's code folders.
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else
  mapfile -t files < <(find src app tests bench examples -name '*.cpp' -o -name '*.hpp')
fi
clang-format-14 --dry-run --Werror "${files[@]}"
/usr/bin/python3 tests/tools/function_lengths.py
echo "code style: ${#files[@]} files formatted, every function under 100 lines"

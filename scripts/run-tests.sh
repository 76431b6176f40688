#!/usr/bin/env bash
# Every test: installs what is missing, builds everything in the tree the main job uses
# (scripts/configure.sh) and runs CTest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/configure.sh"
cmake --build "$root/build" -j "$(nproc)"
cd "$root/build"
ctest --output-on-failure -j "$(nproc)" --timeout 900

#!/usr/bin/env bash
# Every test: installs what is missing, builds (Release with assertions) and runs CTest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
# Release speed, but FETICON_ASSERT stays on: NDEBUG is not defined in this build type.
cmake -S "$root" -B "$root/build-tests" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2" -DFETICON_WERROR=ON >/dev/null
cmake --build "$root/build-tests" -j "$(nproc)"
cd "$root/build-tests"
ctest --output-on-failure -j "$(nproc)" --timeout 900

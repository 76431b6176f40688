#!/usr/bin/env bash
# Configures the one build tree `build/` that both README commands use (scripts/run-main.sh
# builds the executable in it, scripts/run-tests.sh everything), so the second command compiles
# only the tests. Flags (docs/building.md): -O2; FETICON_ASSERT and libstdc++'s assertions on,
# Eigen's per-coefficient checks off (they cost 7 % of a 3D solve); warnings are errors; each
# target compiled in batches (unity build); ccache when installed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2" \
  -DCMAKE_C_FLAGS_RELEASE="-O2" -DFETICON_WERROR=ON "$@" >/dev/null

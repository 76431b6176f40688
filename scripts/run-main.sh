#!/usr/bin/env bash
# The main job: installs what is missing, builds (Release) and runs the seed's Hertz
# benchmark with the default settings. Extra arguments go to `feticon run`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFETICON_BUILD_TESTS=OFF >/dev/null
cmake --build "$root/build" --target feticon -j "$(nproc)"
"$root/build/feticon" run --overwrite --output "$root/results" "$@"

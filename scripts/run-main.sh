#!/usr/bin/env bash
# The main job: installs what is missing, builds the executable and runs the seed's Hertz
# benchmark with the default settings. Extra arguments go to `feticon run`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/configure.sh"
cmake --build "$root/build" --target feticon -j "$(nproc)"
"$root/build/feticon" run --overwrite --output "$root/results" "$@"

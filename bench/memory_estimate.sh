#!/usr/bin/env bash
# The memory guard's estimate (app/memory_guard.cpp) against the measured peak on the
# benchmark cases (issue 21: within 2x). Each case runs once; prints a markdown table.
#
#   bench/memory_estimate.sh                 # the cases below (about 4 minutes)
#   bench/memory_estimate.sh --large         # also hertz3d at 326k DOFs (4.3 GiB, 1-2 minutes more)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=${FETICON:-$root/build/feticon}
large=false
[[ ${1:-} == --large ]] && large=true
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cases=(
  "hertz small 60|--set hertz.refinement=2.2034 --set displacements=small"
  "hertz small 120|--set hertz.refinement=4.4067 --set displacements=small"
  "hertz large 120|--set hertz.refinement=4.4067 --set displacements=large"
  "hertz small 240|--set hertz.refinement=8.8134 --set displacements=small"
  "hertz tensor r1 small|--set hertz.mesh=tensor --set displacements=small"
  "hertz explicit 120 small|--set hertz.refinement=4.4067 --set displacements=small --set dual.operator=explicit"
  "flat punch|$root/examples/flat_punch/problem.yaml"
  "sphere on block|$root/examples/sphere_on_block/problem.yaml"
  "hertz3d r1 small|--set problem=hertz3d --set displacements=small"
  "hertz3d r1.4 small|--set problem=hertz3d --set hertz3d.refinement=1.4 --set displacements=small"
  "hertz3d r1.4 explicit|--set problem=hertz3d --set hertz3d.refinement=1.4 --set displacements=small --set dual.operator=explicit"
)
$large && cases+=("hertz3d r2.15 small|--set problem=hertz3d --set hertz3d.refinement=2.15 --set displacements=small")

echo "| case | DOFs | subdomains | dual operator | estimate (MiB) | measured peak (MiB) | estimate / peak |"
echo "|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  name=${c%%|*}
  read -r -a args <<< "${c#*|}"
  "$feticon" run -q --overwrite --output "$work/run" "${args[@]}" --set output.vtu=false --set output.plots=false \
    > /dev/null
  /usr/bin/python3 - "$name" "$work/run/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[2]))
est, peak = s["memory_estimate_bytes"] / 2**20, s["peak_memory_bytes"] / 2**20
print(f"| {sys.argv[1]} | {s['degrees_of_freedom']} | {s['subdomains']} | {s['dual_operator']['mode']} | "
      f"{est:.0f} | {peak:.0f} | {est / peak:.2f} |")
PY
done

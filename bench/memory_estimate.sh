#!/usr/bin/env bash
# The memory guard's estimate (app/memory_guard.cpp) against the measured peak on the
# benchmark cases (issue 36: every case within 0.8-1.5x), on one rank and on two (mpirun; both
# figures per rank, the peak the larger of the two ranks'). Each case runs once; prints a
# markdown table.
#
#   bench/memory_estimate.sh                 # the cases below (about 10 minutes on 2 cores)
#   bench/memory_estimate.sh --large         # also hertz3d at 326k DOFs (4.3 GiB, 1-2 minutes more)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=${FETICON:-$root/build/feticon}
large=false
[[ ${1:-} == --large ]] && large=true
work=$(mktemp -d)
# Every run meshes (and loads Gmsh where the mesh needs it): a run from the mesh cache holds
# less, and its estimate, made from what the process holds once the mesh is built, with it.
export FETICON_MESH_CACHE=off
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1

# name|ranks|settings
cases=(
  "hertz small 60|1|--set hertz.refinement=2.2034 --set displacements=small"
  "hertz small 120|1|--set hertz.refinement=4.4067 --set displacements=small"
  "hertz large 120|1|--set hertz.refinement=4.4067 --set displacements=large"
  "hertz small 240|1|--set hertz.refinement=8.8134 --set displacements=small"
  "hertz tensor r1 small|1|--set hertz.mesh=tensor --set displacements=small"
  "hertz implicit 240 small|1|--set hertz.refinement=8.8134 --set displacements=small --set dual.operator=implicit"
  "hertz explicit 120 small|1|--set hertz.refinement=4.4067 --set displacements=small --set dual.operator=explicit"
  "hertz large 120, K refreshed per step|1|--set hertz.refinement=4.4067 --set displacements=large --set newton.stiffness=step"
  "hertz primal penalty 120 small|1|--set hertz.refinement=4.4067 --set displacements=small --set method=primal_penalty"
  "flat punch|1|$root/examples/flat_punch/problem.yaml"
  "sphere on block|1|$root/examples/sphere_on_block/problem.yaml"
  "sphere on block implicit|1|$root/examples/sphere_on_block/problem.yaml --set dual.operator=implicit"
  "hertz3d r1 small|1|--set problem=hertz3d --set displacements=small"
  "hertz3d r1 primal penalty|1|--set problem=hertz3d --set displacements=small --set method=primal_penalty"
  "hertz3d r1 large, 2 load steps|1|--set problem=hertz3d --set displacements=large --set load_steps=2"
  "hertz3d r1 large explicit, K refreshed per step|1|--set problem=hertz3d --set displacements=large --set load_steps=2 --set dual.operator=explicit --set newton.stiffness=step"
  "hertz3d r1.4 small|1|--set problem=hertz3d --set hertz3d.refinement=1.4 --set displacements=small"
  "hertz3d r1.4 explicit|1|--set problem=hertz3d --set hertz3d.refinement=1.4 --set displacements=small --set dual.operator=explicit"
  "hertz small 240|2|--set hertz.refinement=8.8134 --set displacements=small"
  "hertz large 120|2|--set hertz.refinement=4.4067 --set displacements=large"
  "sphere on block|2|$root/examples/sphere_on_block/problem.yaml"
  "hertz3d r1 small|2|--set problem=hertz3d --set displacements=small"
  "hertz3d r1.4 small|2|--set problem=hertz3d --set hertz3d.refinement=1.4 --set displacements=small"
  "hertz3d r1.4 explicit|2|--set problem=hertz3d --set hertz3d.refinement=1.4 --set displacements=small --set dual.operator=explicit"
)
$large && cases+=("hertz3d r2.15 small|1|--set problem=hertz3d --set hertz3d.refinement=2.15 --set displacements=small")

echo "| case | ranks | DOFs | subdomains | dual operator | blocks (MiB) | estimate (MiB) | measured peak (MiB) | estimate / peak |"
echo "|---|---|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  IFS='|' read -r name ranks settings <<< "$c"
  read -r -a args <<< "$settings"
  launch=()
  ((ranks == 1)) || launch=(mpirun --oversubscribe -np "$ranks")
  "${launch[@]}" "$feticon" run -q --overwrite --output "$work/run" "${args[@]}" --set output.vtu=false \
    --set output.plots=false > /dev/null
  /usr/bin/python3 - "$name" "$ranks" "$work/run/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[3]))
est, peak = s["memory_estimate_bytes"] / 2**20, s["peak_memory_bytes"] / 2**20
operator = s.get("dual_operator", {})
blocks = f"{operator['bytes'] / 2**20:.0f}" if operator.get("bytes") else "-"
print(f"| {sys.argv[1]} | {sys.argv[2]} | {s['degrees_of_freedom']} | {s['subdomains']} | "
      f"{operator.get('mode') if s['method'] != 'primal_penalty' else '-'} | {blocks} | {est:.0f} | {peak:.0f} | {est / peak:.2f} |")
PY
done

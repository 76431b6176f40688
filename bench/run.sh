#!/usr/bin/env bash
# The benchmark suite of issue 8: Hertz at about 10k, 100k and 1M DOFs with small and large
# displacements (FETI contact solve against the bonded direct solve), numerical scalability
# at fixed H/h, weak scaling on the flat punch (issue 6), and MPRGP alone on a 2D obstacle QP. Each case runs --reps times as its own
# process (`feticon bench`, one JSON line each), niced; bench/summarize.py takes the medians,
# prints the tables and writes bench/results/*.csv and tables.md.
#
#   bench/run.sh                                   # 10k and 100k, 3 repetitions
#   bench/run.sh --sizes 10k,100k,1M --reps 3      # also 1M (minutes per run)
#   bench/run.sh --sizes 1M --kinds large --reps 1 --only contact
#   bench/run.sh --only scalability                # parts: contact, scalability, weak, mprgp
#   bench/run.sh --only weak --weak 1,2,4,8,16     # punch cells x k (k = 16: 1.5M DOFs, 2.8-3.5 GiB)
#   bench/run.sh --only weak --weak-cells 236,15   # cells per subdomain of the weak series
#   bench/run.sh --only weak --weak-problems gluing # the punch (contact) and/or its gluing-only twin
#   bench/run.sh --feticon build-bench/feticon     # another build (default build/feticon)
#   bench/run.sh --obstacle 1000 --obstacle-steps 1000   # MPRGP QP size n^2 and step cap
#   bench/run.sh --preconditioners none,dirichlet  # dual preconditioners of the contact cases
#   bench/run.sh --operators implicit,explicit     # dual.operator of the contact cases (default auto)
#   bench/run.sh --only contact --gamg             # and the bonded system by PETSc GAMG-CG (bench/gamg)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
sizes=10k,100k
kinds=small,large
reps=3
only=contact,scalability,weak,mprgp
weak=1,2,4,8
weak_cells=236,15
weak_problems=punch,gluing
out=$root/bench/results
obstacle=1000
obstacle_steps=1000
preconditioners=dirichlet
operators=auto
gamg=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --sizes) sizes=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --kinds) kinds=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --feticon) feticon=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --obstacle) obstacle=$2; shift 2 ;;
    --obstacle-steps) obstacle_steps=$2; shift 2 ;;
    --preconditioners) preconditioners=$2; shift 2 ;;
    --operators) operators=$2; shift 2 ;;
    --gamg) gamg=1; shift ;;
    --weak) weak=$2; shift 2 ;;
    --weak-cells) weak_cells=$2; shift 2 ;;
    --weak-problems) weak_problems=$2; shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) echo "bench/run.sh: unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done
[[ -x $feticon ]] || { echo "bench/run.sh: no feticon executable at $feticon (build it, or --feticon PATH)" >&2; exit 1; }
mkdir -p "$out/raw"

# The sizes are of the tensor mesh of the earlier tables (hertz.mesh=tensor, growth ratio 1.2;
# the default graded mesh needs 19k DOFs for what the tensor one resolves with 319k, see
# bench/calculix.sh). Hertz refinement and subdomain count per size: DOFs grow about as refinement^2 (one cell
# layer; 9 744 DOFs at refinement 0.75, 93 966 at 2.4). Few, large subdomains are fastest on
# this graded mesh and 2 cores: at 100k, small displacements, 4 / 8 / 16 / 32 subdomains took
# 703 / 867 / 1 604 / 2 328 MPRGP steps and 8.4 / 9.5 / 14.4 / 18.8 s (docs/benchmarks.md).
declare -A refinement=([10k]=0.75 [100k]=2.5 [1M]=7.8)
declare -A subdomains=([10k]=4 [100k]=8 [1M]=16)

# One case: NAME then feticon bench arguments; replaces raw/NAME.rep<i>.json (the other
# cases' files stay, so that a later run of one size adds to the tables).
run_case() {
  local name=$1; shift
  rm -f "$out/raw/$name".rep*.json
  for ((i = 1; i <= reps; i++)); do
    echo "bench: $name ($i/$reps)" >&2
    if ((gamg)) && [[ $name == contact.* ]]; then
      nice -n 10 "$root/bench/gamg/run.sh" --feticon "$feticon" -- "$@" | tail -n 1 > "$out/raw/$name.rep$i.json"
    else
      nice -n 10 "$feticon" bench "$@" | tail -n 1 > "$out/raw/$name.rep$i.json"
    fi
  done
}

if [[ ,$only, == *,contact,* ]]; then
  for size in ${sizes//,/ }; do
    [[ -n ${refinement[$size]:-} ]] || { echo "bench/run.sh: unknown size $size (10k, 100k, 1M)" >&2; exit 1; }
    for kind in ${kinds//,/ }; do
      for preconditioner in ${preconditioners//,/ }; do
        for operator in ${operators//,/ }; do
          # the operator in the name only when chosen, so that earlier raw files keep their names
          name=contact.$size.$kind.$preconditioner
          [[ $operator == auto ]] || name+=.$operator
          run_case "$name" --set hertz.mesh=tensor --set hertz.growth_ratio=1.2 \
            --set hertz.refinement="${refinement[$size]}" \
            --set subdomains="${subdomains[$size]}" --set displacements=$kind \
            --set qp.preconditioner=$preconditioner --set dual.operator=$operator
        done
      done
    done
  done
fi
if [[ ,$only, == *,scalability,* ]]; then
  # H/h fixed: 256 cells (16 x 16 in the one layer) per subdomain, h halved twice.
  for preconditioner in ${preconditioners//,/ }; do
    for r in 1 2 4; do
      run_case "scalability.r$r.$preconditioner" --no-direct --set hertz.mesh=tensor --set hertz.growth_ratio=1.2 \
        --set hertz.refinement=$r \
        --set subdomain_cells=256 --set displacements=small --set qp.preconditioner=$preconditioner
    done
  done
fi
if [[ ,$only, == *,weak,* ]]; then
  # H/h fixed: the flat punch example with its cells multiplied by k in x and y (h / k, a
  # uniform mesh) and a fixed number of cells per subdomain (subdomains x k^2; 236 cells:
  # H/h about 15, 15 cells: about 4), both partitioners.
  punch_dir=$(mktemp -d)
  trap 'rm -rf "$punch_dir"' EXIT
  for k in ${weak//,/ }; do
    sed -e "s/cells: \[40, 20, 1\]/cells: [$((40 * k)), $((20 * k)), 1]/" \
        -e "s/cells: \[12, 12, 1\]/cells: [$((12 * k)), $((12 * k)), 1]/" \
        "$root/examples/flat_punch/problem.yaml" > "$punch_dir/punch$k.yaml"
    # The same meshes without contact: the punch lifted 0.1 m (beyond the search distance, so
    # no contact rows) and held at its top, the traction on the block's top. Its dual has
    # gluing and Dirichlet rows only and MPRGP is plain PCG: the growth of the linear FETI
    # solve with the same operator and preconditioner, the floor under the contact series.
    sed -e "s/origin: \[0, 0, 0\]/origin: [0, 0.1, 0]/" \
        -e "s/{set: punch_ymax, traction/{set: base_ymax, traction/" \
        -e "s/^  - {set: punch_xmin, x: 0}/  - {set: punch_xmin, x: 0}\n  - {set: punch_ymax, y: 0}/" \
        "$punch_dir/punch$k.yaml" > "$punch_dir/gluing$k.yaml"
    for cells in ${weak_cells//,/ }; do
      for partitioner in metis rcb; do
        [[ ,$weak_problems, == *,punch,* ]] || continue
        run_case "weak.punch.c$cells.k$k.$partitioner" --no-direct "$punch_dir/punch$k.yaml" \
          --set subdomain_cells=$cells --set partitioner=$partitioner
      done
      if [[ ,$weak_problems, == *,gluing,* ]]; then
        run_case "weak.gluing.c$cells.k$k.rcb" --no-direct "$punch_dir/gluing$k.yaml" \
          --set subdomain_cells=$cells --set partitioner=rcb
      fi
    done
  done
fi
if [[ ,$only, == *,mprgp,* ]]; then
  # A capped solve: the cost per step is the figure; converging from u = 0 takes tens of
  # thousands of (mostly expansion) steps at n = 1000.
  run_case "mprgp.obstacle$obstacle" --mprgp-obstacle "$obstacle" --max-iterations "$obstacle_steps"
fi
/usr/bin/python3 "$root/bench/summarize.py" "$out"

#!/usr/bin/env bash
# Issue 40: the subdomain count and the dual preconditioner swept on one model, to calibrate
# and check `subdomains = auto` and `qp.preconditioner = auto`. Each point runs --reps times,
# one after the other (not niced, nothing else should run); one TSV line per run with the
# MPRGP steps, the set-up and solve times of summary.json and the peak memory.
#
#   bench/settings_sweep.sh --name hertz3d-r1 --counts 4,8,16,32 -- --set problem=hertz3d
#   bench/settings_sweep.sh --name sphere --counts auto,2,4,8 -- examples/sphere_on_block/problem.yaml
#
# A count of "auto" with a preconditioner of "auto" leaves both choices to feticon (the TSV
# records what it chose); mixed pairs (one auto, one given) are skipped. The points of one
# repetition run one after the other, so auto and the given settings see the same machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
reps=3
counts=auto,4,8,16,32
preconditioners=auto,dirichlet,lumped
name=sweep
out=$root/bench/results/settings_sweep
while [[ $# -gt 0 ]]; do
  case $1 in
    --feticon) feticon=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --counts) counts=$2; shift 2 ;;
    --preconditioners) preconditioners=$2; shift 2 ;;
    --name) name=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    *) echo "bench/settings_sweep.sh: unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done
[[ -x $feticon ]] || { echo "bench/settings_sweep.sh: no feticon executable at $feticon (--feticon PATH)" >&2; exit 1; }
mkdir -p "$out"
tsv=$out/$name.tsv
[[ -f $tsv ]] || printf 'name\tsubdomains_asked\tpreconditioner_asked\trep\tsubdomains\tpreconditioner\tdofs\tsteps\tfactorization_s\tdual_solve_s\ttotal_solve_s\twall_s\tpeak_mib\tpeak_pressure\n' > "$tsv"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One untimed run first: it makes the mesh cache (FETICON_MESH_CACHE), which would otherwise
# charge Gmsh's meshing to the first point.
"$feticon" run "$@" -q --overwrite -o "$work/run" --set output.vtu=false --set output.plots=false > /dev/null 2>&1 || true
IFS=, read -ra count_list <<< "$counts"
IFS=, read -ra preconditioner_list <<< "$preconditioners"
for rep in $(seq 1 "$reps"); do
  for count in "${count_list[@]}"; do
    for preconditioner in "${preconditioner_list[@]}"; do
      [[ $count == auto ]] && count_auto=1 || count_auto=0
      [[ $preconditioner == auto ]] && preconditioner_auto=1 || preconditioner_auto=0
      ((count_auto == preconditioner_auto)) || continue
      start=$(date +%s.%N)
      "$feticon" run "$@" -q --overwrite -o "$work/run" --set output.vtu=false --set output.plots=false \
        --set subdomains="$count" --set qp.preconditioner="$preconditioner" > "$work/log" 2>&1 ||
        { echo "run failed: $count $preconditioner"; tail -3 "$work/log"; continue; }
      end=$(date +%s.%N)
      /usr/bin/python3 - "$work/run/summary.json" "$name" "$count" "$preconditioner" "$rep" "$start" "$end" >> "$tsv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timings_seconds"]
print("\t".join(str(v) for v in [sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5], s["subdomains"],
      s.get("preconditioner", {}).get("choice", sys.argv[4]), s["degrees_of_freedom"], s["qp"]["iterations"],
      round(t.get("factorization", 0), 3), round(t.get("dual solve (MPRGP)", 0), 3), round(t["total solve"], 3),
      round(float(sys.argv[7]) - float(sys.argv[6]), 3), round(s["peak_memory_bytes"] / 2**20),
      s["contact"]["peak_pressure"]]))
PY
      tail -1 "$tsv"
    done
  done
done

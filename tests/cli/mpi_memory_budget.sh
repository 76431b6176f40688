#!/usr/bin/env bash
# dual.operator = auto under a memory_limit on 2 ranks (issue 36): the sphere-on-block example in
# 3 subdomains, whose dense blocks auto forms when memory allows, run on 2 ranks of one node with
# memory_limit = 2 x 135 MiB. That is above the implicit run's peak per rank (about 85 MiB) and
# below the explicit run's (about 155 MiB on the rank with two subdomains): the run must stay
# implicit, say that the blocks did not fit their budget, and stay within 135 MiB on every
# rank. Reference: the same run without memory_limit, which must pick explicit and peak above
# 135 MiB on a rank (so the limit is what kept it implicit). Peaks are VmHWM per rank
# (summary.json peak_memory_bytes_per_rank). (The example's own 4 subdomains stopped testing
# this when METIS began to weigh faces by area: their larger boundaries make auto implicit.)
# Usage: mpi_memory_budget.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
source_dir="$2"
# A sanitizer build's resident memory is the sanitizer's (230 MB of shadow per process).
[[ -z ${FETICON_SANITIZED:-} ]] || { echo "skipped: sanitizer build"; exit 77; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1
export OPENBLAS_NUM_THREADS=1

share=$((135 * 1024 * 1024)) # bytes per rank
run() { # NAME SETTINGS...
  local name=$1
  shift
  timeout 300 mpirun --oversubscribe -np 2 "$feticon" run -q --output "$work/$name" \
    "$source_dir/examples/sphere_on_block/problem.yaml" --set output.vtu=false --set output.plots=false \
    --set qp.preconditioner=dirichlet --set subdomains=3 "$@"
}
run free
run limited --set memory_limit=$((2 * share))

/usr/bin/python3 - "$work" "$share" <<'PY'
import json, sys
work, share = sys.argv[1], int(sys.argv[2])
free = json.load(open(f"{work}/free/summary.json"))
limited = json.load(open(f"{work}/limited/summary.json"))
mib = lambda b: f"{b / 2**20:.0f} MiB"
fail = []
if free["dual_operator"]["mode"] != "explicit":
    fail.append(f"without memory_limit auto picked {free['dual_operator']['mode']}: the case no longer tests the budget")
if max(free["peak_memory_bytes_per_rank"]) <= share:
    fail.append(f"the explicit run peaks at {mib(max(free['peak_memory_bytes_per_rank']))} per rank, "
                f"within {mib(share)}: the limit does not test the budget")
if limited["dual_operator"]["mode"] != "implicit" or "memory budget" not in limited["dual_operator"]["reason"]:
    fail.append(f"with memory_limit: {limited['dual_operator']}")
if max(limited["peak_memory_bytes_per_rank"]) > share:
    fail.append(f"with memory_limit a rank peaked at {mib(max(limited['peak_memory_bytes_per_rank']))} > {mib(share)}")
if limited["memory_estimate_bytes"] > share:
    fail.append(f"the estimate {mib(limited['memory_estimate_bytes'])} exceeds the share it was admitted under")
print("explicit without limit: peaks", [mib(b) for b in free["peak_memory_bytes_per_rank"]],
      "; with limit", mib(share), "per rank:", limited["dual_operator"]["reason"], "; peaks",
      [mib(b) for b in limited["peak_memory_bytes_per_rank"]])
if fail:
    print("\n".join(fail))
    sys.exit(1)
PY
echo "mpi_memory_budget: ok"

#!/usr/bin/env bash
# The iterative floor of issue 40 for one model: `feticon bench` (the FETI contact solve and
# the bonded direct solve by CHOLMOD) writes the bonded system, and PETSc's GAMG-preconditioned
# CG solves it to a relative residual of 1e-8 on --np ranks (gamg_solve.c). Prints one JSON
# line: feticon bench's, with "gamg": {set-up and solve seconds, iterations, residual} and
# "ratio_contact_to_gamg" (the contact solve's "total solve" over GAMG's set-up + solve).
# Installs Debian's petsc-dev if missing (a bench peer, never a dependency of feticon) and
# builds gamg_solve into build-bench/.
#
#   bench/gamg/run.sh -- --set problem=hertz3d --set displacements=small
#   bench/gamg/run.sh --feticon build/feticon --np 2 -- problem.yaml
#   PETSC_OPTIONS="-pc_gamg_agg_nsmooths 0" bench/gamg/run.sh -- ...   # other GAMG settings
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
feticon=$root/build/feticon
np=2
while [[ $# -gt 0 ]]; do
  case $1 in
    --feticon) feticon=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "bench/gamg/run.sh: unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done
[[ -x $feticon ]] || { echo "bench/gamg/run.sh: no feticon executable at $feticon (--feticon PATH)" >&2; exit 1; }
if ! dpkg -s petsc-dev > /dev/null 2>&1; then
  echo "bench/gamg/run.sh: installing Debian's petsc-dev" >&2
  sudo_cmd=(); [[ $(id -u) == 0 ]] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get install -y -qq petsc-dev > /dev/null
fi
solver=$root/build-bench/gamg_solve
if [[ ! -x $solver || $root/bench/gamg/gamg_solve.c -nt $solver ]]; then
  mkdir -p "$root/build-bench"
  petsc_dir=$(ls -d /usr/lib/petscdir/petsc*/*-real 2> /dev/null | head -n 1)
  [[ -n $petsc_dir ]] || { echo "bench/gamg/run.sh: no PETSc under /usr/lib/petscdir" >&2; exit 1; }
  export PKG_CONFIG_PATH=$petsc_dir/lib/pkgconfig
  mpicc -O2 $(pkg-config --cflags PETSc) "$root/bench/gamg/gamg_solve.c" -o "$solver" \
    $(pkg-config --libs PETSc) -Wl,-rpath,"$petsc_dir/lib"
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
system=$(mktemp -d)
trap 'rm -rf "$system"' EXIT
"$feticon" bench "$@" --bonded-system "$system" | tail -n 1 > "$system/bench.json"
kernel=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['bonded_system']['near_kernel_vectors'])" \
  "$system/bench.json")
mpirun --oversubscribe -np "$np" "$solver" -dir "$system" -near_kernel_vectors "$kernel" | tail -n 1 > "$system/gamg.json"
/usr/bin/python3 - "$system/bench.json" "$system/gamg.json" <<'PY'
import json, sys
bench, gamg = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
bench.pop("bonded_system", None)  # a temporary folder
bench["gamg"] = {key[len("gamg_"):]: value for key, value in gamg.items()}
bench["ratio_contact_to_gamg"] = bench["timings_seconds"]["total solve"] / (
    gamg["gamg_setup_seconds"] + gamg["gamg_solve_seconds"])
print(json.dumps(bench))
PY

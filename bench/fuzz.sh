#!/usr/bin/env bash
# The long run of the input fuzzer (tests/tools/fuzz_inputs.py; tests/cli/fuzz_inputs.sh is
# the short one in CTest): mutants of problem files, Gmsh meshes, Matrix Market files and
# CalculiX input decks for a number of minutes; prints the outcome counts per kind and saves
# failing mutants with a command.sh to reproduce them.
#
#   bench/fuzz.sh                          # 10 minutes, seed 1, build/feticon, the run kinds
#   bench/fuzz.sh --minutes 60 --seed 7
#   bench/fuzz.sh --feticon build-asan/feticon --kinds gmsh --keep /tmp/gmsh-failures
#   bench/fuzz.sh --kinds deck --timeout 10  # decks only (each runs in well under 1 s)
#   bench/fuzz.sh --kinds export             # decks and problem files through feticon export
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
minutes=10
seed=1
extra=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --minutes) minutes=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --feticon) feticon=$2; shift 2 ;;
    --kinds | --timeout | --keep) extra+=("$1" "$2"); shift 2 ;;
    *) echo "bench/fuzz.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

# A private copy: a rebuild during the run must not swap the executable between mutants.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$feticon" "$work/feticon"
cp "$(dirname "$feticon")/libfeticon_gmsh.so" "$work/" # its Gmsh module, opened beside it
# Mutated meshes must not fill the user's mesh cache.
export FETICON_MESH_CACHE=off
/usr/bin/python3 "$root/tests/tools/fuzz_inputs.py" "$work/feticon" "$root" \
  --minutes "$minutes" --seed "$seed" "${extra[@]}"

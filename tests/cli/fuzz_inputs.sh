#!/usr/bin/env bash
# Mutation fuzzing of problem files, Gmsh meshes and Matrix Market files (issue 21): 60
# mutants of the seeds in tests/data/fuzz/ with a fixed seed (about 20 s); fails when one
# crashes, hangs, writes a non-finite number, exits with an undocumented status or ends in
# an error of more than one line (tests/tools/fuzz_inputs.py). bench/fuzz.sh is the long run.
# Usage: bash fuzz_inputs.sh FETICON SOURCE_DIR
set -euo pipefail
exec /usr/bin/python3 "$2/tests/tools/fuzz_inputs.py" "$1" "$2" --mutants 60 --seed 1

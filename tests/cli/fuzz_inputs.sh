#!/usr/bin/env bash
# Mutation fuzzing of problem files, Gmsh meshes and Matrix Market files (issue 21): 60
# mutants of the seeds in tests/data/fuzz/ with a fixed seed (about 20 s); then 45 mutated
# CalculiX input decks, seeds tests/data/calculix/{contact1,contactenergy,cubespring}.inp
# (about 5 s); then 30 decks and problem files through feticon export (1 s). Fails when one
# crashes, hangs, writes a non-finite number, exits with an undocumented status or ends in an
# error of more than one line (tests/tools/fuzz_inputs.py).
# bench/fuzz.sh is the long run.
# Usage: bash fuzz_inputs.sh FETICON SOURCE_DIR
set -euo pipefail
driver="$2/tests/tools/fuzz_inputs.py"
/usr/bin/python3 "$driver" "$1" "$2" --kinds problem,gmsh,mm --mutants 60 --seed 1
# A deck mutant runs in well under a second; 10 s is a hang.
/usr/bin/python3 "$driver" "$1" "$2" --kinds deck --mutants 45 --seed 4 --timeout 10
# 30 mutated decks and problem files through feticon export (its deck must hold no non-finite
# number; a refusal is one line).
/usr/bin/python3 "$driver" "$1" "$2" --kinds export --mutants 30 --seed 46 --timeout 10

#!/usr/bin/env bash
# A deck written by other tools than feticon (issue 37): the sphere-on-block mesh exported by
# Gmsh (`-format inp`: C3D8 cells, physical surfaces as CPS4 elements), turned into CalculiX
# surfaces by tests/tools/gmsh_inp_to_calculix.py, with the example's model in CalculiX's
# keywords (tests/data/gmsh_deck: surface-to-surface pair, *DSLOAD pressure). Reference: the
# same model as Gmsh + YAML (examples/sphere_on_block/problem.yaml): pressures to 1e-6 of the
# peak (measured 3.6e-11), the contact force to 1e-9.
# Usage: gmsh_deck.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
command -v gmsh > /dev/null || { echo "gmsh is not installed: test skipped"; exit 77; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
gmsh "$src/examples/sphere_on_block/sphere_on_block.msh" -0 -format inp -o "$work/gmsh.inp" > /dev/null
/usr/bin/python3 "$src/tests/tools/gmsh_inp_to_calculix.py" "$work/gmsh.inp" \
  "$src/tests/data/gmsh_deck/sphere_on_block_tail.inp" "$work/model.inp"
# Double-precision factors: the two paths order the nodes differently, and float factors
# would round the two stiffnesses differently (pressures then agree to 3e-8, not 1e-6 less).
"$feticon" run "$work/model.inp" -o "$work/deck" -q --set output.plots=false --set subdomains=4 \
  --set dual.factor_precision=double
"$feticon" run "$src/examples/sphere_on_block/problem.yaml" -o "$work/yaml" -q --set output.plots=false \
  --set dual.factor_precision=double
/usr/bin/python3 - "$work" <<'PY'
import csv, json, sys
w = sys.argv[1]
p = {d: [float(r["pressure_multipliers_Pa"]) for r in csv.DictReader(open(f"{w}/{d}/contact_pressure.csv"))]
     for d in ("deck", "yaml")}
f = {d: json.load(open(f"{w}/{d}/summary.json"))["contact"]["total_normal_force"] for d in ("deck", "yaml")}
worst = max(abs(a - b) for a, b in zip(p["deck"], p["yaml"])) / max(p["yaml"])
print(f"{len(p['deck'])} samples, pressures differ by {worst:.2g} of the peak; force {f['deck']:.9g} / {f['yaml']:.9g} N")
assert len(p["deck"]) == len(p["yaml"])
assert worst < 1e-6 and abs(f["deck"] / f["yaml"] - 1) < 1e-9
PY

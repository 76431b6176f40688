#!/usr/bin/env bash
# CLI test of `subdomains = auto` and `qp.preconditioner = auto` (app/feti_choice.hpp, issue 40).
# References: the rules of app/feti_choice.hpp (the power of two nearest DOFs / target, at least the
# bodies; Dirichlet in plane strain, in 3D on a one-layer band, lumped with quadratic cells), the memory guard's own estimate written to
# summary.json (it must fit in half of memory_limit when auto raised the count for it), and the
# given values, which must pass through untouched.
# Usage: auto_settings.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
run() { "$feticon" run "$@" -q --overwrite --set output.plots=false --set output.vtu=false; }
field() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1]))
for k in sys.argv[2].split('.'): d=d[k]
print(d)" "$1/summary.json" "$2"; }
fail() { echo "auto_settings: $*"; exit 1; }

# 1. Plane strain (the default Hertz problem, 2D cells): Dirichlet, the power of two nearest
# DOFs / 4000; at 120 elements across 2a (6 306 DOFs) that is 2, where the hex layer's rule
# (3 units a node / 3000) gave 4.
run --output "$work/hertz" --set hertz.refinement=4.4067
dofs=$(field "$work/hertz" degrees_of_freedom)
expected=$(/usr/bin/python3 -c "import math,sys; print(max(2, 2 ** round(math.log2(max(1, int(sys.argv[1]) / 4000)))))" "$dofs") # two bodies at least
[[ $(field "$work/hertz" subdomains) == "$expected" ]] || fail "Hertz: $(field "$work/hertz" subdomains) subdomains, expected $expected for $dofs DOFs"
[[ $(field "$work/hertz" subdomains_reason) == *"DOFs of 2D cells at about 4000 DOFs a subdomain"* ]] || fail "Hertz: reason '$(field "$work/hertz" subdomains_reason)'"
[[ $(field "$work/hertz" preconditioner.choice) == dirichlet ]] || fail "Hertz: preconditioner $(field "$work/hertz" preconditioner.choice)"
# problem.yaml keeps the choices, so that a restart decomposes the same way on any machine.
grep -qx "subdomains: $expected" "$work/hertz/problem.yaml" || fail "problem.yaml: $(grep '^subdomains' "$work/hertz/problem.yaml")"
grep -qx "qp.preconditioner: dirichlet" "$work/hertz/problem.yaml" || fail "problem.yaml lacks the preconditioner"
[[ $(field "$work/hertz" factor_precision.choice) == double ]] || fail "Hertz: $(field "$work/hertz" factor_precision.choice) factors"
grep -qx "dual.factor_precision: double" "$work/hertz/problem.yaml" || fail "problem.yaml lacks the factor precision"

# 2. 3D (hertz3d): the Dirichlet preconditioner on a band of one cell layer.
run --output "$work/h3" --set problem=hertz3d --set hertz3d.refinement=0.8 --set displacements=small
[[ $(field "$work/h3" preconditioner.choice) == dirichlet ]] || fail "hertz3d: preconditioner $(field "$work/h3" preconditioner.choice)"
[[ $(field "$work/h3" preconditioner.dirichlet_layers) == 1 ]] || fail "hertz3d: $(field "$work/h3" preconditioner.dirichlet_layers) layers"
[[ $(field "$work/h3" dual_operator.mode) == implicit ]] || fail "hertz3d: the band's S_s must be applied implicitly"
grep -qx "qp.dirichlet_layers: 1" "$work/h3/problem.yaml" || fail "problem.yaml lacks the band"
[[ $(field "$work/h3" converged) == True ]] || fail "hertz3d did not converge"
# ... with single-precision factors, whose round-off the primal recovery's refinement step
# takes below newton.residual_tolerance (1e-6) in a linear run.
[[ $(field "$work/h3" factor_precision.choice) == single ]] || fail "hertz3d: $(field "$work/h3" factor_precision.choice) factors"
/usr/bin/python3 -c "import json,sys; r=json.load(open(sys.argv[1]))['steps'][0]['residual_norm']; sys.exit(0 if r <= 1e-6 else 1)" \
  "$work/h3/summary.json" || fail "hertz3d: residual above 1e-6 with single-precision factors"
[[ $(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['steps'][0]['outer_iterations'])" \
  "$work/h3/summary.json") == 1 ]] || fail "hertz3d: a second QP for the float factors' round-off"
run --output "$work/h3double" --set problem=hertz3d --set hertz3d.refinement=0.8 --set displacements=small \
  --set dual.factor_precision=double
[[ $(field "$work/h3double" factor_precision.reason) == given ]] || fail "given dual.factor_precision not kept"
# Quadratic cells keep the lumped preconditioner (a cell layer is two node layers there).
run --output "$work/h3q" --set problem=hertz3d --set hertz3d.cell=hex20 --set hertz3d.refinement=0.5 \
  --set displacements=small
[[ $(field "$work/h3q" preconditioner.choice) == lumped ]] || fail "hex20: preconditioner $(field "$work/h3q" preconditioner.choice)"
[[ $(field "$work/h3q" preconditioner.reason) == *"quadratic cells"* ]] || fail "hex20: '$(field "$work/h3q" preconditioner.reason)'"
# The reason names the model's DOFs, and the larger count hex20's factors are sized by.
h3q_reason=$(field "$work/h3q" subdomains_reason)
[[ $h3q_reason == "$(field "$work/h3q" degrees_of_freedom) DOFs, counted as "* ]] || fail "hex20: count reason '$h3q_reason'"
# The band is the user's to set, and a banded S_s cannot be explicit.
run --output "$work/h3whole" --set problem=hertz3d --set hertz3d.refinement=0.8 --set displacements=small \
  --set qp.dirichlet_layers=0
[[ $(field "$work/h3whole" preconditioner.dirichlet_layers) == 0 ]] || fail "given qp.dirichlet_layers=0 not kept"
if run --output "$work/bad" --set problem=hertz3d --set qp.dirichlet_layers=2 --set dual.operator=explicit 2> "$work/err"; then
  fail "a band with dual.operator=explicit accepted"
fi
grep -q "qp.dirichlet_layers = 2 bands the implicit Schur complements" "$work/err" || fail "message: $(cat "$work/err")"

# 2b. 3D in small subdomains (the sphere example's 4 given subdomains of 4 200 DOFs): the band
# too, with single-precision factors (the whole interior's second factors cost more than they
# save there: docs/benchmarks.md, "The whole interior in small 3D subdomains").
run "$2/examples/sphere_on_block/problem.yaml" --output "$work/sphere"
[[ $(field "$work/sphere" preconditioner.choice) == dirichlet && $(field "$work/sphere" preconditioner.dirichlet_layers) == 1 ]] \
  || fail "sphere: preconditioner $(field "$work/sphere" preconditioner.choice), layers $(field "$work/sphere" preconditioner.dirichlet_layers)"
[[ $(field "$work/sphere" factor_precision.choice) == single ]] || fail "sphere: $(field "$work/sphere" factor_precision.choice) factors"

# 3. Given values win, and say so.
run --output "$work/given" --set hertz.refinement=0.5 --set subdomains=3 --set qp.preconditioner=lumped
[[ $(field "$work/given" subdomains) == 3 && $(field "$work/given" subdomains_reason) == given ]] || fail "given count not kept"
[[ $(field "$work/given" preconditioner.choice) == lumped && $(field "$work/given" preconditioner.reason) == given ]] \
  || fail "given preconditioner not kept"

# 4. A tight budget raises the count until the guard's estimate fits in half of it.
limit=2.4e8
run --output "$work/tight" --set problem=hertz3d --set hertz3d.refinement=0.8 --set displacements=small \
  --set memory_limit=$limit
[[ $(field "$work/tight" subdomains_reason) == *"raised from"* ]] || fail "tight budget: '$(field "$work/tight" subdomains_reason)'"
/usr/bin/python3 -c "import sys; e, l = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if e <= 0.5 * l else 1)" \
  "$(field "$work/tight" memory_estimate_bytes)" "$limit" || fail "estimate $(field "$work/tight" memory_estimate_bytes) over half of $limit"
(( $(field "$work/tight" subdomains) > $(field "$work/h3" subdomains) )) || fail "tight budget did not raise the count"

# 4b. Tighter: even subdomains of 1000 DOFs leave the estimate over half the budget; the run
# takes them (the guard checks the whole budget) and says so.
run --output "$work/tighter" --set problem=hertz3d --set hertz3d.refinement=0.8 --set displacements=small \
  --set memory_limit=1.3e8
[[ $(field "$work/tighter" subdomains_reason) == *"the smallest auto takes"* ]] \
  || fail "tighter budget: '$(field "$work/tighter" subdomains_reason)'"

# 5. "auto" is no number elsewhere; a bad count names the key.
if "$feticon" run -q --output "$work/bad" --set subdomains=many 2> "$work/err"; then fail "subdomains=many accepted"; fi
grep -q "subdomains = 'many' is not a finite number or auto" "$work/err" || fail "message: $(cat "$work/err")"
# 5. Slender bodies: eight stacked leaves 0.5 x 0.04 x 0.008 m (bench/leaf_spring.py, 1 120 cells,
# 7 272 DOFs): one subdomain per leaf would be auto's rule (8), which took 16 773 MPRGP steps; the
# slender rule cuts each leaf into pieces of about 4 thicknesses (16 a leaf, 128), at most one
# per 16 cells (70: 64), and the QP takes 1 903 steps.
src="$2"
/usr/bin/python3 "$src/bench/leaf_spring.py" 0.5 > "$work/leaves.yaml"
run "$work/leaves.yaml" --output "$work/leaves"
[[ $(field "$work/leaves" subdomains) == 64 ]] || fail "leaves: $(field "$work/leaves" subdomains) subdomains, expected 64"
[[ $(field "$work/leaves" subdomains_reason) == *"slender bodies"* ]] || fail "leaves: reason '$(field "$work/leaves" subdomains_reason)'"
[[ $(field "$work/leaves" converged) == True ]] || fail "leaves did not converge"
(( $(field "$work/leaves" qp.iterations) < 4000 )) || fail "leaves: $(field "$work/leaves" qp.iterations) MPRGP steps"
echo "auto_settings: ok"

#!/usr/bin/env bash
# Runs every example of examples/ at a small size (issue 7: examples run in CI) and checks
# that each converges with the contact force equal to the applied load.
# Usage: examples.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
check_force() { # folder expected_force [relative tolerance, default 1e-6]
  /usr/bin/python3 - "$1/summary.json" "$2" "${3:-1e-6}" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["converged"] is True, "not converged"
force, expected = s["contact"]["total_normal_force"], float(sys.argv[2])
assert abs(force / expected - 1) < float(sys.argv[3]), (force, expected)
PY
}
"$feticon" run -q "$src/examples/hertz/problem.yaml" --output "$work/hertz" --set hertz.refinement=0.5 --set subdomains=4
/usr/bin/python3 -c "import json; s=json.load(open('$work/hertz/summary.json')); assert s['converged'] and len(s['steps']) == 2"
# Flat punch: 500 MPa on 0.2 m x 0.01 m = 1e6 N (large displacements: the normal force in
# the deformed configuration differs from the load by O(strain), so small displacements).
"$feticon" run -q "$src/examples/flat_punch/problem.yaml" --output "$work/punch"
check_force "$work/punch" 1e6
if [[ -f "$src/examples/sphere_on_block/problem.yaml" ]]; then
  "$feticon" run -q "$src/examples/sphere_on_block/problem.yaml" --output "$work/sphere"
  /usr/bin/python3 -c "import json; s=json.load(open('$work/sphere/summary.json')); assert s['converged']"
fi
# The tet10 sphere on block from OpenCASCADE solids: 50 MPa on the 10 mm x 10 mm quarter
# punch = 5 kN, carried by contact alone.
"$feticon" run -q "$src/examples/sphere_on_block_tet10/problem.yaml" --output "$work/sphere_tet10"
check_force "$work/sphere_tet10" 5000
# The rubber seal (Neo-Hooke, 30 % compression): the plate's force as CalculiX 2.20 gives it on
# the exported deck, 4.705276 N (bench/rubber_seal.sh: within 6.4e-7 over the curve), to 1e-5.
"$feticon" run -q "$src/examples/rubber_seal/problem.yaml" --output "$work/seal"
check_force "$work/seal" 4.705276 1e-5
# Nearly incompressible (K_0 / mu_0 = 500) on coarse quad8: K_M turns indefinite (the law is not
# convex in E), which CHOLMOD's simplicial LDL' used to accept and MPRGP then failed on; now the
# subdomain is factored from each point's positive definite tangent and summary.json says so.
gmsh -2 -format msh41 -clscale 2 -order 2 -string "Mesh.SecondOrderIncomplete=1;" \
  "$src/examples/rubber_seal/rubber_seal.geo" -o "$work/seal_quad8.msh" > /dev/null
sed -e "s|rubber_seal.msh|$work/seal_quad8.msh|" "$src/examples/rubber_seal/problem.yaml" > "$work/seal_quad8.yaml"
"$feticon" run -q "$work/seal_quad8.yaml" --output "$work/seal_quad8" --set bodies.seal.hyperelastic.d1=4e-9 \
  --set load_steps=5 2> /dev/null
/usr/bin/python3 - "$work/seal_quad8/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["converged"] is True, "not converged"
assert any("K_M was indefinite" in w for w in s["warnings"]), s["warnings"]
PY
echo "examples: all ran"

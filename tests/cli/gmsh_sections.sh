#!/usr/bin/env bash
# Materials per section in a problem file (issue 66, item 1): one connected Gmsh mesh of two
# materials (tests/data/gmsh_sections: the halves of a bar fragmented together, so they share
# the nodes of x = 1) given as one body of two sections, with named materials.
# References:
#   - nu = 0: uniaxial stress in both halves, the tip's u_x = p (L_steel / E_steel + L_alu /
#     E_alu) = 7.7142857e-4 m (closed form; linear cells reproduce it) to 1e-9 relative, in 3D
#     (hex8) and in plane stress (quad4), and on 2 MPI ranks the 1-rank run to 1e-10;
#   - nu = 0.3 (the halves' lateral contractions differ, so the interface is not uniaxial):
#     the run of the CalculiX deck `feticon export` writes of the same model (its bodies from
#     *SOLID SECTIONs, io/deck_model.cpp) node by node to 1e-8 of max |u|, and CalculiX's own
#     answer on that deck to its 6 printed digits (5e-6 of max |u|) where ccx is installed (ccx 2.20: 6.6e-7 of max
#     |u|, 2026-12-04);
#   - the same mesh with the halves as two plain bodies is refused in one line: a node two
#     bodies share glues them, which is a meshing mistake unless they are sections of one body.
# Usage: gmsh_sections.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
quiet=(-q --set output.plots=false --set qp.rtol=1e-12 --set qp.force_rtol=0)
data="$src/tests/data/gmsh_sections"
cp "$data/bar.yaml" "$work/"
gmsh -3 "$data/bar.geo" -format msh41 -o "$work/bar.msh" > /dev/null
gmsh -2 "$data/strip.geo" -format msh41 -o "$work/strip.msh" > /dev/null

# tip RESULTS_DIR: the end face's u_x against the closed form, 1e-9 relative.
tip() {
  /usr/bin/python3 - "$1/step_001.vtu" "$src/tests/tools" <<'PY'
import sys
import numpy
sys.path.insert(0, sys.argv[2])
import read_vtu
arrays = read_vtu.point_data(sys.argv[1])
u, end = arrays["displacement"], arrays["set_end"] > 0
exact = 4e7 * (1 / 2e11 + 1 / 7e10)
error = numpy.abs(u[end, 0] / exact - 1).max()
print(f"{sys.argv[1].split('/')[-2]}: tip u_x vs the closed form {exact:.8e} m: {error:.2e} ({end.sum()} nodes)")
sys.exit(0 if error <= 1e-9 and end.sum() > 0 else 1)
PY
}

"$feticon" run "$work/bar.yaml" -o "$work/bar" "${quiet[@]}" --set subdomains=2
tip "$work/bar"
if command -v mpirun > /dev/null; then
  timeout 300 mpirun --oversubscribe -np 2 "$feticon" run "$work/bar.yaml" -o "$work/bar_np2" "${quiet[@]}" \
    --set subdomains=2
  /usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-10 "$work/bar" "$work/bar_np2"
fi

# Plane stress: the strip's sections, thickness 0.5 (the same cross-section area).
sed -e 's|file: bar.msh}|file: strip.msh, formulation: plane_stress, thickness: 0.5}|' -e '/set: zmin/d' \
  "$work/bar.yaml" > "$work/strip.yaml"
"$feticon" run "$work/strip.yaml" -o "$work/strip" "${quiet[@]}"
tip "$work/strip"

# nu = 0.3: the problem file against the exported deck's run (and CalculiX's, where installed).
sed -e 's/poisson: 0}/poisson: 0.3}/' "$work/bar.yaml" > "$work/bar03.yaml"
"$feticon" run "$work/bar03.yaml" -o "$work/bar03" "${quiet[@]}"
"$feticon" export "$work/bar03.yaml" --format calculix -o "$work/deck" > /dev/null
"$feticon" run "$work/deck/feticon.inp" -o "$work/deck_run" "${quiet[@]}" 2> /dev/null
/usr/bin/python3 - "$work" "$src/tests/tools" <<'PY'
import sys
import numpy
sys.path.insert(0, sys.argv[2])
import frd_vs_vtu
work = sys.argv[1]
a = numpy.array(frd_vs_vtu.vtu_displacements(work + "/bar03/step_001.vtu"))
b = numpy.array(frd_vs_vtu.vtu_displacements(work + "/deck_run/step_001.vtu"))
difference = numpy.abs(a - b).max() / numpy.abs(a).max()
print(f"nu = 0.3: sections against the exported deck's bodies: {difference:.2e} of max |u| {numpy.abs(a).max():.6e} m")
sys.exit(0 if a.shape == b.shape and difference <= 1e-8 else 1)
PY
if command -v ccx > /dev/null; then
  (cd "$work/deck" && ccx -i feticon > ccx.log 2>&1)
  /usr/bin/python3 - "$work" "$src/tests/tools" <<'PY'
import sys
import numpy
sys.path.insert(0, sys.argv[2])
import frd_vs_vtu
work = sys.argv[1]
a = numpy.array(frd_vs_vtu.vtu_displacements(work + "/bar03/step_001.vtu"))
printed = numpy.array([d for label, *d in frd_vs_vtu.frd_displacements(work + "/deck/feticon.frd")])
difference = numpy.abs(a - printed).max() / numpy.abs(a).max()
print(f"nu = 0.3: sections against CalculiX on the exported deck: {difference:.2e} of max |u|")
sys.exit(0 if a.shape == printed.shape and difference <= 5e-6 else 1)  # %12.5E: 6 digits
PY
fi

# The halves as two plain bodies: refused, naming both and the shared node.
sed -e '/^materials:/,/^supports:/c\bodies:\n  steel_half: {young: 2e11, poisson: 0}\n  aluminium_half: {young: 7e10, poisson: 0}\nsupports:' \
  "$work/bar.yaml" > "$work/plain.yaml"
if "$feticon" run "$work/plain.yaml" -o "$work/plain" -q 2> "$work/plain.err"; then
  echo "FAIL: two plain bodies sharing nodes ran"
  exit 1
fi
[[ $(wc -l < "$work/plain.err") -eq 1 ]] && grep -q "bodies 'steel_half' and 'aluminium_half' share the node at (1, " \
  "$work/plain.err" || { echo "FAIL: not the one-line refusal:"; cat "$work/plain.err"; exit 1; }
echo "plain bodies sharing nodes: $(cat "$work/plain.err")"
echo "gmsh_sections: ok"

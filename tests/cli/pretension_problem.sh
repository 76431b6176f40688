#!/usr/bin/env bash
# Pretension sections in problem files (fem/coupling.hpp, io/problem_couplings.hpp): a bolt
# modelled as two parts that meet at the section with matching meshes, joined by the section's
# rows. References:
#  - a 1 x 1 x 10 m bar of two boxes (E = 1e9 Pa, nu = 0), both ends held, the section at
#    mid-length: a tension F = 1e6 N opens the gap q = F L / (E A) = 0.01 m (1e-6; the reference
#    node's force is F), and a held gap of 0.01 m needs E A q / L = 1e6 N (1e-6); the same on 2
#    MPI ranks (difference below 1e-10, the same iterations); with large displacements the gap is
#    CalculiX 2.20's on the equivalent deck bar (tests/cli/pretension.sh), 9.985040e-3 m (6e-7);
#  - feticon export of it (the upper part's nodes at the section written as the lower part's, the
#    section as *PRE-TENSION SECTION, which doubles them again) run again: the problem file's
#    answer (1e-8, the QPs' tolerance; measured 1.2e-9);
#  - bad input, one line each: partner and surface of different node counts, a partner node with no
#    surface node at its position, a surface paired with itself, a gap on a kinematic coupling, a
#    force on a pretension section, a coupling that is not a map.
# Usage: pretension_problem.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
quiet=(-q --set output.plots=false)
bar() { # the bar with the given section load and extra lines
  cat <<YAML
problem: custom
mesh:
  boxes:
    - {name: lower, origin: [0, 0, 0], lengths: [1, 1, 5], cells: [2, 2, 5]}
    - {name: upper, origin: [0, 0, 5], lengths: [1, 1, 5], cells: [2, 2, 5]}
bodies:
  lower: {young: 1e9, poisson: 0}
  upper: {young: 1e9, poisson: 0}
couplings:
  - {name: preload, kind: pretension, surface: lower_zmax, partner: upper_zmin}
supports:
  - {set: lower_zmin, x: 0, y: 0, z: 0}
  - {set: upper_zmax, x: 0, y: 0, z: 0}
$1
displacements: small
subdomains: 4
qp.rtol: 1e-12
YAML
}
bar "loads: [{coupling: preload, tension: 1e6}]" > "$work/force.yaml"
bar "  - {coupling: preload, gap: 0.01}" > "$work/gap.yaml"
sed 's/displacements: small/displacements: large/' "$work/force.yaml" > "$work/large.yaml"
for kind in force gap large; do
  "$feticon" run "$work/$kind.yaml" -o "$work/$kind" "${quiet[@]}"
done
mpirun --oversubscribe -np 2 "$feticon" run "$work/force.yaml" -o "$work/np2" "${quiet[@]}"
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-10 "$work/force" "$work/np2"
"$feticon" export "$work/force.yaml" --format calculix -o "$work/deck" > /dev/null
grep -q '^\*PRE-TENSION SECTION, SURFACE=PRETENSION_1, NODE=' "$work/deck/feticon.inp"
"$feticon" run "$work/deck/feticon.inp" -o "$work/from-deck" "${quiet[@]}" --set qp.rtol=1e-12 --set subdomains=4 2> /dev/null
/usr/bin/python3 - "$work" "$src/tests/tools" <<'PY'
import json
import sys

import numpy

work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
import read_vtu

# The deck's node order differs (CalculiX appends the doubled nodes): compared by position.
def by_position(folder):
    d = read_vtu.point_data(f"{folder}/step_001.vtu")
    points = read_vtu.points(f"{folder}/step_001.vtu")
    order = numpy.lexsort((d["displacement"][:, 2], points[:, 2], points[:, 1], points[:, 0]))
    return d["displacement"][order]
a, b = by_position(f"{work}/force"), by_position(f"{work}/from-deck")
difference = numpy.abs(a - b).max() / numpy.abs(a).max()
print(f"exported and run again: {difference:.2g} of max |u| from the problem file's run")
assert a.shape == b.shape and difference <= 1e-8
# Large displacements: CalculiX 2.20's gap on the deck bar of tests/cli/pretension.sh (the same
# homogeneous stretch; its printed digits).
for kind, dof, expected, bound in (("force", "displacement", 0.01, 1e-6), ("gap", "force", 1e6, 1e-6),
                                   ("large", "displacement", 9.985040e-3, 6e-7)):
    s = json.load(open(f"{work}/{kind}/summary.json"))
    value = s["couplings"][0][dof][0]
    print(f"{kind}: section {dof} {value:.10g} against {expected:g}")
    assert s["converged"] and abs(value / expected - 1) <= bound, (kind, value)
PY

bad() { # name, pattern, sed expressions on force.yaml
  local name=$1 pattern=$2
  shift 2
  sed "$@" "$work/force.yaml" > "$work/$name.yaml"
  if "$feticon" run "$work/$name.yaml" -o "$work/$name" "${quiet[@]}" 2> "$work/$name.err"; then
    echo "$name: accepted"; exit 1
  fi
  [ "$(wc -l < "$work/$name.err")" -eq 1 ] || { cat "$work/$name.err"; exit 1; }
  grep -q "$pattern" "$work/$name.err" || { cat "$work/$name.err"; exit 1; }
  echo "$name: $(cat "$work/$name.err")"
}
bad counts "surface lower_zmax has 9 nodes, partner upper_zmin 12" \
  -e 's/origin: \[0, 0, 5\], lengths: \[1, 1, 5\], cells: \[2, 2, 5\]/origin: [0, 0, 5], lengths: [1, 1, 5], cells: [3, 2, 5]/'
bad unmatched "has no node of surface lower_zmax there" -e 's/origin: \[0, 0, 5\]/origin: [0.1, 0, 5]/'
bad itself "lies on both surface lower_zmax and partner lower_zmax" -e 's/partner: upper_zmin/partner: lower_zmax/'
bad gap_on_kinematic "gap belongs to a pretension coupling" \
  -e 's/^  - {name: preload, kind: pretension.*$/&\n  - {name: tip, kind: kinematic, surface: upper_xmax, reference: [1, 0.5, 7]}/' \
  -e 's/^  - {set: upper_zmax, x: 0, y: 0, z: 0}$/&\n  - {coupling: tip, gap: 0.1}/'
bad force_on_section "holds a pretension section's tension alone" -e 's/tension: 1e6/force: [1e6, 0, 0]/'
# A coupling that is not a map (the fuzz driver's mutant 9885, seed 4802: yaml-cpp's own error
# and exit 2 before).
bad scalar_coupling "couplings.1 must be a map of keys" -e 's/^supports:$/  - s\nsupports:/'

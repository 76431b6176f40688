#!/usr/bin/env bash
# Friction on the 2D Hertz cylinder (issue 39, docs/friction.md): Cattaneo-Mindlin's figures at
# Q/(mu P) = 0.3, 0.6, 0.9 with Coulomb mu = 0.3, and the cost of Coulomb and Tresca against the
# frictionless half model, medians of --reps runs one after the other. Prints markdown tables.
#
#   bench/friction.sh                        # 120 elements across 2a (refinement 4.4), 3 reps
#   bench/friction.sh --refinement 2 --reps 1
#   FETICON=build-tests/feticon bench/friction.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=${FETICON:-$root/build/feticon}
refinement=4.4
reps=3
while [[ $# -gt 0 ]]; do
  case $1 in
    --refinement) refinement=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    *) echo "bench/friction.sh: unknown argument $1" >&2; exit 1 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set displacements=small --set "hertz.refinement=$refinement")
coulomb=(--set contact.friction.model=coulomb --set contact.friction.coefficient=0.3)

echo "| Q/(mu P) | c computed / analytic (mm) | shear RMS / mu p0 | symmetric part | antisymmetric part | |F_T - Q| / Q | sliding / sticking |"
echo "|---|---|---|---|---|---|---|"
for ratio in 0.3 0.6 0.9; do
  q=$(/usr/bin/python3 -c "print($ratio * 0.3 * 4e8)")
  "$feticon" run --output "$work/cm" --overwrite "${common[@]}" "${coulomb[@]}" --set "hertz.tangential_load=$q" \
    > /dev/null 2>&1
  /usr/bin/python3 - "$work/cm/summary.json" "$ratio" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))["hertz"]["friction"]
c, ca = f["stick_half_width_computed"], f["stick_half_width_analytic"]
print("| %s | %.2f / %.2f (%+.2f %%) | %.2f %% | %.2f %% | %.2f %% | %.0e | %d / %d |" % (
    sys.argv[2], 1e3 * c, 1e3 * ca, 100 * (c / ca - 1), 100 * f["shear_rms_error_over_mu_p0"],
    100 * f["shear_symmetric_rms_error_over_mu_p0"], 100 * f["shear_antisymmetric_rms_over_mu_p0"],
    f["tangential_force_error"], f["slipping_nodes"], f["sticking_nodes"]))
PY
done

echo
echo "| run | DOFs | QPs | MPRGP steps | products | dual solve (s) | total solve (s), median of $reps |"
echo "|---|---|---|---|---|---|---|"
runs=(
  "frictionless, half model|"
  "Tresca g = 1.1 GPa, full model|--set contact.friction.model=tresca --set contact.friction.slip_bound=1.1e9 --set hertz.tangential_load=7.2e7"
  "Coulomb mu = 0.3, full model|--set contact.friction.model=coulomb --set contact.friction.coefficient=0.3 --set hertz.tangential_load=7.2e7"
)
for run in "${runs[@]}"; do
  name=${run%%|*}
  read -r -a settings <<< "${run#*|}"
  for ((k = 1; k <= reps; ++k)); do
    "$feticon" run --output "$work/run$k" --overwrite "${common[@]}" "${settings[@]}" > /dev/null 2>&1
  done
  /usr/bin/python3 - "$name" "$work" "$reps" <<'PY'
import json, statistics, sys
name, work, reps = sys.argv[1], sys.argv[2], int(sys.argv[3])
runs = [json.load(open("%s/run%d/summary.json" % (work, k))) for k in range(1, reps + 1)]
s, t = runs[0], [r["timings_seconds"] for r in runs]
print("| %s | %d | %d | %d | %d | %.3f | %.2f |" % (
    name, s["degrees_of_freedom"], sum(st["outer_iterations"] for st in s["steps"]), s["qp"]["iterations"],
    s["qp"]["hessian_multiplications"], statistics.median(x["dual solve (MPRGP)"] for x in t),
    statistics.median(x["total solve"] for x in t)))
PY
done

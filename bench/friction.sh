#!/usr/bin/env bash
# Friction on the 2D Hertz cylinder (issue 39, docs/friction.md): Cattaneo-Mindlin's figures at
# Q/(mu P) = 0.3, 0.6, 0.9 with Coulomb mu = 0.3, and the cost of Coulomb and Tresca against the
# frictionless half model and, on the same full mesh, Coulomb against frictionless contact under
# displacement control, medians of --reps runs one after the other. Prints markdown tables.
#
#   bench/friction.sh                        # 120 elements across 2a (refinement 4.4), 3 reps
#   bench/friction.sh --refinement 2 --reps 1
#   FETICON=build/feticon bench/friction.sh
#   bench/friction.sh --large --line-load 1e8   # large displacements under displacement control
#
# --large: the first table with large displacements (deformed frame), the load face moved by
# what the force-controlled small-displacement run gives it (summary.json hertz.load_face_shift)
# with the couple of Q (hertz.tangential_couple); Cattaneo-Mindlin at the force the face carries.
# --line-load P (N/m, default 4e8) keeps 120 elements across 2a: refinement 4.4 sqrt(4e8 / P).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=${FETICON:-$root/build/feticon}
refinement=
reps=3
large=0
line_load=4e8
while [[ $# -gt 0 ]]; do
  case $1 in
    --refinement) refinement=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --large) large=1; shift ;;
    --line-load) line_load=$2; shift 2 ;;
    *) echo "bench/friction.sh: unknown argument $1" >&2; exit 1 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
refinement=${refinement:-$(/usr/bin/python3 -c "print(round(4.4 * ($line_load / 4e8) ** -0.5, 3))")}
common=(--set displacements=small --set "hertz.refinement=$refinement" --set "hertz.line_load=$line_load")
coulomb=(--set contact.friction.model=coulomb --set contact.friction.coefficient=0.3)

# summary.json's value at the dotted path $2.
json_value() {
  /usr/bin/python3 -c "import json, sys; v = json.load(open(sys.argv[1]))
for k in sys.argv[2].split('.'): v = v[k]
print(repr(v))" "$1" "$2"
}

# A row of the Cattaneo-Mindlin table from the summary $1 at Q/(mu P) = $2; $3: the face's shift.
cm_row() {
  /usr/bin/python3 - "$1" "$2" "$3" <<'PY'
import json, sys
h = json.load(open(sys.argv[1]))["hertz"]
f = h["friction"]
c, ca = f["stick_half_width_computed"], f["stick_half_width_analytic"]
shift = "%.5g mm | %+.1e | " % (1e3 * float(sys.argv[3]),
                                 -f["tangential_reaction"] / f["applied_tangential_force"] - 1) if sys.argv[3] else ""
print("| %s | %s%.3f / %.3f (%+.2f %%) | %.2f %% | %.2f %% | %.2f %% | %.0e | %d / %d |" % (
    sys.argv[2], shift, 1e3 * c, 1e3 * ca, 100 * (c / ca - 1), 100 * f["shear_rms_error_over_mu_p0"],
    100 * f["shear_symmetric_rms_error_over_mu_p0"], 100 * f["shear_antisymmetric_rms_over_mu_p0"],
    f["tangential_force_error"], f["slipping_nodes"], f["sticking_nodes"]))
PY
}

if [[ $large == 1 ]]; then
  echo "| Q/(mu P) | face moved | face's force / Q - 1 | c computed / analytic (mm) | shear RMS / mu p0 | symmetric part | antisymmetric part | |F_T - Q| / Q | sliding / sticking |"
  echo "|---|---|---|---|---|---|---|---|---|"
else
  echo "| Q/(mu P) | c computed / analytic (mm) | shear RMS / mu p0 | symmetric part | antisymmetric part | |F_T - Q| / Q | sliding / sticking |"
  echo "|---|---|---|---|---|---|---|"
fi
for ratio in 0.3 0.6 0.9; do
  q=$(/usr/bin/python3 -c "print($ratio * 0.3 * $line_load)")
  "$feticon" run --output "$work/cm" --overwrite "${common[@]}" "${coulomb[@]}" --set "hertz.tangential_load=$q" \
    > /dev/null 2>&1
  d=$(json_value "$work/cm/summary.json" hertz.load_face_shift)
  [[ $ratio == 0.6 ]] && shift_06=$d
  if [[ $large == 1 ]]; then
    "$feticon" run --output "$work/large" --overwrite "${common[@]}" "${coulomb[@]}" --set displacements=large \
      --set "hertz.tangential_displacement=$d" --set "hertz.tangential_couple=$q" > /dev/null 2>&1
    cm_row "$work/large/summary.json" "$ratio" "$d"
  else
    cm_row "$work/cm/summary.json" "$ratio" ""
  fi
done
[[ $large == 1 ]] && exit 0

# One line of a cost table: the runs $work/run1..run$reps, their medians.
cost_row() {
  /usr/bin/python3 - "$1" "$work" "$reps" <<'PY'
import json, statistics, sys
name, work, reps = sys.argv[1], sys.argv[2], int(sys.argv[3])
runs = [json.load(open("%s/run%d/summary.json" % (work, k))) for k in range(1, reps + 1)]
s, t = runs[0], [r["timings_seconds"] for r in runs]
print("| %s | %d | %d | %d | %d | %.3f | %.2f |" % (
    name, s["degrees_of_freedom"], sum(st["outer_iterations"] for st in s["steps"]), s["qp"]["iterations"],
    s["qp"]["hessian_multiplications"], statistics.median(x["dual solve (MPRGP)"] for x in t),
    statistics.median(x["total solve"] for x in t)))
PY
}

# Q = 0.6 mu P, and Tresca's bound mu p0 (1.1 GPa at the benchmark's 4e8 N/m; p0 ~ sqrt(P)).
q06=$(/usr/bin/python3 -c "print(0.18 * $line_load)")
g_tresca=$(/usr/bin/python3 -c "print(1.1e9 * ($line_load / 4e8) ** 0.5)")
echo
echo "| run | DOFs | QPs | MPRGP steps | products | dual solve (s) | total solve (s), median of $reps |"
echo "|---|---|---|---|---|---|---|"
runs=(
  "frictionless, half model|"
  "Tresca g = mu p0, full model|--set contact.friction.model=tresca --set contact.friction.slip_bound=$g_tresca --set hertz.tangential_load=$q06"
  "Coulomb mu = 0.3, full model|--set contact.friction.model=coulomb --set contact.friction.coefficient=0.3 --set hertz.tangential_load=$q06"
)
for run in "${runs[@]}"; do
  name=${run%%|*}
  read -r -a settings <<< "${run#*|}"
  for ((k = 1; k <= reps; ++k)); do
    "$feticon" run --output "$work/run$k" --overwrite "${common[@]}" "${settings[@]}" > /dev/null 2>&1
  done
  cost_row "$name"
done

# The same mesh with and without friction. The full model's cylinder is held along x only by
# friction under a tangential load, so the frictionless run of the same mesh moves the load face
# instead: the deck of the Coulomb run under displacement control (the face moved by what the
# force-controlled small-displacement run at Q = 0.6 mu P gives it, with the couple of Q), and
# the same deck without *FRICTION and without the couple, which frictionless contact cannot
# carry (the second step's loads are the first's).
d=$shift_06
"$feticon" export --format calculix --output "$work/deck" "${common[@]}" "${coulomb[@]}" \
  --set "hertz.tangential_displacement=$d" --set "hertz.tangential_couple=$q06" > /dev/null
/usr/bin/python3 - "$work/deck/feticon.inp" "$work/deck/frictionless.inp" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
out, skip = [], 0
for line in lines:  # without *FRICTION and its data line
    if line.startswith("*FRICTION"):
        skip = 2
    if skip:
        skip -= 1
        continue
    out.append(line)
def block(at):  # the data lines of the keyword at line `at`, and the next keyword's line
    end = at + 1
    while not out[end].startswith("*"):
        end += 1
    return out[at + 1:end], end
cloads = [i for i, line in enumerate(out) if line.startswith("*CLOAD")]
first, _ = block(cloads[0])
_, end = block(cloads[1])
out = out[:cloads[1] + 1] + first + out[end:]
open(sys.argv[2], "w").write("\n".join(out))
PY
echo
echo "| run (same mesh, load face moved by $(/usr/bin/python3 -c "print('%.5g' % (1e3 * $d))") mm) | DOFs | QPs | MPRGP steps | products | dual solve (s) | total solve (s), median of $reps |"
echo "|---|---|---|---|---|---|---|"
for deck in frictionless feticon; do
  for ((k = 1; k <= reps; ++k)); do
    "$feticon" run "$work/deck/$deck.inp" --output "$work/run$k" --overwrite > /dev/null 2>&1
  done
  name=$([[ $deck == feticon ]] && echo "Coulomb mu = 0.3, Q = 0.6 mu P by displacement" || echo "frictionless")
  cost_row "$name"
done

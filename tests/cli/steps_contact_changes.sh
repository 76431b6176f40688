#!/usr/bin/env bash
# A problem file's step may change a contact pair (issue 65, item 6): `contact: [{pair, friction,
# in_force}]` in a step entry, as a deck's *CHANGE FRICTION and *MODEL CHANGE. A block pressed by
# a traction of 100 (N on 1 mm^2) onto a base, its top pushed along x (Coulomb mu = 0.3), then
# further with mu changed to 0.1. Reference: sliding, the friction force is mu N: 30 at the end
# of step 2 (a copy without step 3), 10 at the end of step 3 (asserted 1e-6 relative, the QP's
# order; measured below 2e-8), on 1 and 2 MPI ranks. A third copy takes the pair out in step 3 with
# the top held at z = 0: no contact force. Bad input: a pair index out of range, one line.
# Usage: steps_contact_changes.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
head=$(cat <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: base,  origin: [0, 0, 0],     lengths: [2, 2, 0.5], cells: [4, 4, 1]}
    - {name: block, origin: [0.5, 0.5, 0.5], lengths: [1, 1, 1], cells: [2, 2, 2]}
bodies:
  base:  {young: 2e5, poisson: 0.3}
  block: {young: 2e5, poisson: 0.3}
supports:
  - {set: base_zmin, x: 0, y: 0, z: 0}
  - {set: block_zmax, x: 0, y: 0}
loads: [{set: block_zmax, traction: [0, 0, -100]}]
contact:
  - {slave: block_zmin, master: base_zmax, friction: {model: coulomb, coefficient: 0.3}}
subdomains: 4
displacements: small
steps:
  - increments: 1
  - supports:
      - {set: base_zmin, x: 0, y: 0, z: 0}
      - {set: block_zmax, x: 0.01, y: 0}
    increments: 2
YAML
)
printf '%s\n' "$head" >"$work/pushed.yaml"
printf '%s\n' "$head" "  - supports:" "      - {set: base_zmin, x: 0, y: 0, z: 0}" \
  "      - {set: block_zmax, x: 0.02, y: 0}" \
  "    contact: [{pair: 0, friction: {model: coulomb, coefficient: 0.1}}]" "    increments: 2" >"$work/changed.yaml"
printf '%s\n' "$head" "  - supports:" "      - {set: base_zmin, x: 0, y: 0, z: 0}" \
  "      - {set: block_zmax, x: 0.01, y: 0, z: 0}" "    contact: [{pair: 0, in_force: false}]" >"$work/removed.yaml"
settings=(--set output.plots=false --set output.vtu=false)
for run in pushed changed removed; do
  "$feticon" run -q "$work/$run.yaml" --output "$work/$run" "${settings[@]}"
done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
mpirun --oversubscribe -np 2 "$feticon" run -q "$work/changed.yaml" --output "$work/ranks" "${settings[@]}"
/usr/bin/python3 - "$work" <<'PY'
import json
import sys

work = sys.argv[1]
pair = {run: json.load(open(f"{work}/{run}/summary.json"))["contact"]["pairs"][0] for run in ("pushed", "changed", "ranks")}
for run, mu in (("pushed", 0.3), ("changed", 0.1), ("ranks", 0.1)):
    force, normal = pair[run]["friction_force_magnitudes"], pair[run]["total_normal_force"]
    assert abs(normal / 100 - 1) <= 1e-6 and abs(force / (mu * normal) - 1) <= 1e-6, (run, force, normal)
    print(f"{run}: friction force {force:.12g} (mu {mu} of N = {normal:.12g})")
removed = json.load(open(f"{work}/removed/summary.json"))
assert removed["converged"] and removed["contact"]["total_normal_force"] == 0, removed["contact"]
print("removed: no contact force")
PY
# Both exported (*CHANGE FRICTION with its *FRICTION, *MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE;
# refused before 2026-12-04) and run again: the problem file's answer (1e-8; measured 4.9e-14 and 1.7e-14).
for run in changed removed; do
  "$feticon" export "$work/$run.yaml" --format calculix --overclosure 0 -o "$work/$run-deck" >/dev/null
  "$feticon" run -q "$work/$run-deck/feticon.inp" --output "$work/$run-from-deck" "${settings[@]}" --set subdomains=4 2>/dev/null
  /usr/bin/python3 "$(dirname "$0")/../tools/compare_runs.py" 1e-8 "$work/$run" "$work/$run-from-deck" --answer
done
grep -q '^\*CHANGE FRICTION, INTERACTION=SI_1$' "$work/changed-deck/feticon.inp"
grep -q '^\*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE$' "$work/removed-deck/feticon.inp"
# What a deck cannot say, one line each: friction that starts after the first step (the pair
# frictionless, step 3 gives mu = 0.1) and friction taken away (step 3 model none).
sed 's/friction: {model: coulomb, coefficient: 0.3}}$/friction: {model: none}}/' "$work/changed.yaml" >"$work/late.yaml"
sed 's/contact: \[{pair: 0, friction: {model: coulomb, coefficient: 0.1}}\]/contact: [{pair: 0, friction: {model: none}}]/' \
  "$work/changed.yaml" >"$work/taken.yaml"
source "$src/tests/tools/expect_deck_error.sh"
for case in "late:has friction in a later step but none in the first" "taken:takes the friction of contact pair"; do
  name=${case%%:*}
  ! cmp -s "$work/$name.yaml" "$work/changed.yaml"
  expect_export_error "$work/$name.yaml" "$name" "calculix export: .*${case#*:}"
done
sed 's/contact: \[{pair: 0,/contact: [{pair: 3,/' "$work/changed.yaml" >"$work/bad.yaml"
if "$feticon" run -q "$work/bad.yaml" --output "$work/bad" >"$work/bad.log" 2>&1; then echo "pair 3 accepted"; exit 1; fi
grep -q "steps.2.contact.0.pair = 3 is not an index into the contact list (1 pairs)" "$work/bad.log" || { cat "$work/bad.log"; exit 1; }
[ "$(grep -c . "$work/bad.log")" -le 2 ]
echo "steps_contact_changes: ok"

#!/usr/bin/env bash
# CalculiX's own contact test decks (tests/data/calculix: calculix-ccx-test 2.11, the five that
# use only what feticon implements) run through `feticon run DECK.inp` (issue 37).
# References (tests/tools/check_calculix_example.py): with small displacements, an
# independent exact-contact solve of the deck (numpy, tests/data/calculix/exact_contact_
# estimate.py) to 1e-6 of max |u| and of the contact force; as the deck asks (NLGEOM), CalculiX's
# reference output to within 3 times the penetration its penalty law allows, the contact
# force to 1e-4 of the linear solve's, and the reactions balancing the load where RF is printed.
# Also: each run writes DECK.frd and DECK.dat, the .frd's displacements equal to the VTU's to
# its printed digits (tests/tools/frd_vs_vtu.py).
# Usage: calculix_examples.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for deck in contact1 contact3 contact6 contactenergy cubespring; do
  for kind in small deck; do
    out="$work/$deck-$kind"
    extra=()
    checks=(--exact-rtol 1e-6 --force-rtol 1e-6)
    if [[ $kind == small ]]; then
      extra=(--set displacements=small)
    else
      checks=(--exact-rtol 1 --force-rtol 1e-4)
    fi
    if ! "$feticon" run "$src/tests/data/calculix/$deck.inp" -o "$out" -q --set output.plots=false "${extra[@]}" \
      2> "$work/stderr"; then
      echo "$deck ($kind): feticon failed"; cat "$work/stderr"; status=1; continue
    fi
    [[ -s "$out/$deck.frd" && -s "$out/$deck.dat" ]] || { echo "$deck ($kind): no .frd or .dat"; status=1; }
    last_vtu="$(ls "$out"/step_*.vtu | tail -n 1)"
    /usr/bin/python3 "$src/tests/tools/frd_vs_vtu.py" "$out/$deck.frd" "$last_vtu" || status=1
    /usr/bin/python3 "$src/tests/tools/check_calculix_example.py" "$deck" "$out" --json "${checks[@]}" || status=1
  done
done
exit $status

#!/usr/bin/env bash
# Materials per section (issue 66, item 1): tests/data/calculix/two_materials.inp, one connected
# bar whose two halves are steel and aluminium, pulled by F = 1e7 N. Its two materials make two
# bodies that share the interface nodes (deck_model.cpp). Reference: uniaxial stress, the tip's
# u_x = F / A (L_steel / E_steel + L_alu / E_alu) = 7.7142857e-4 m, to the .dat's 7 digits (half a
# unit of the last, 5e-11 m; CalculiX 2.20 prints the same 7.714286E-04), on 1 rank with 2
# subdomains and 2 ranks with 4. Before, the deck was refused: one material per connected body.
# Usage: deck_two_materials.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1
export OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
deck="$src/tests/data/calculix/two_materials.inp"
options=(--set output.plots=false --set output.vtu=false)
"$feticon" run "$deck" -o "$work/one" "${options[@]}" --set subdomains=2 > "$work/one.log" 2>&1 \
  || { cat "$work/one.log"; exit 1; }
runs=(one)
if command -v mpirun > /dev/null; then
  timeout 300 mpirun --oversubscribe -np 2 "$feticon" run "$deck" -o "$work/two" "${options[@]}" \
    --set subdomains=4 > "$work/two.log" 2>&1 || { cat "$work/two.log"; exit 1; }
  runs+=(two)
fi
/usr/bin/python3 - "$work" "${runs[@]}" <<'PY'
import json, sys
work, *runs = sys.argv[1:]
exact = 1e7 / 0.25 * (1 / 2e11 + 1 / 7e10)
for run in runs:
    s = json.load(open(f"{work}/{run}/summary.json"))
    assert s["converged"], f"{run}: not converged"
    ux = []
    for line in open(f"{work}/{run}/two_materials.dat"):
        f = line.split()
        if len(f) == 4 and f[0] in ("5", "10", "15", "20"):
            ux.append(float(f[1]))
    assert len(ux) == 4, ux
    print(f"{run} rank(s): tip u_x {min(ux):.7e} to {max(ux):.7e} m, closed form {exact:.7e} m")
    assert all(abs(u - exact) <= 5e-11 for u in ux), "the tip is not the closed form's"
PY
echo "deck_two_materials: ok"

#!/usr/bin/env bash
# Assemblies through the files (issue 63): three stacked blocks with non-matching meshes held
# by two contact pairs (the middle block master of one, slave of the other), as a problem
# file, as the CalculiX deck `feticon export` writes of it (two *CONTACT PAIRs), on 1 and 2 MPI
# ranks; and a model with no contact pair. References: the exact uniaxial state (each pair
# carries the load p A = 2e8 N, p = 1e8 Pa on A = 2 m^2), to 1e-6; the 1-rank run for the
# 2-rank one (tests/tools/compare_runs.py, 1e-10). The settlement and stresses of the same
# state are checked in tests/verification/test_assemblies.cpp.
# Usage: assembly.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
quiet=(-q --set output.plots=false --set qp.rtol=1e-10 --set qp.force_rtol=0)

cp "$src/tests/data/stack_three_blocks.yaml" "$work/stack.yaml"

# check RESULTS_DIR PAIRS: converged, PAIRS pairs each carrying 2e8 N, a pair column in the CSV.
check() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import json, sys
folder, n = sys.argv[1], int(sys.argv[2])
s = json.load(open(folder + "/summary.json"))
assert s["converged"], folder + ": not converged"
pairs = s["contact"]["pairs"]
assert len(pairs) == n, f"{folder}: {len(pairs)} pairs in summary.json, expected {n}"
for k, p in enumerate(pairs):
    assert abs(p["total_normal_force"] - 2e8) <= 2e8 * 1e-6, f"pair {k}: force {p['total_normal_force']}"
rows = open(folder + "/contact_pressure.csv").read().splitlines()
assert rows[0].startswith("pair,"), rows[0]
assert {r.split(",")[0] for r in rows[1:]} == {str(k) for k in range(n)}, "pair column"
print(f"{folder.split('/')[-1]}: {n} pairs, forces " + ", ".join(f"{p['total_normal_force']:.9g}" for p in pairs))
PY
}
"$feticon" run "$work/stack.yaml" -o "$work/yaml" "${quiet[@]}"
check "$work/yaml" 2
grep -q 'Name="contact_pair"' "$work/yaml/step_001.vtu" || { echo "FAIL: no contact_pair field in the VTU"; exit 1; }

# The exported deck has two *CONTACT PAIRs and runs (its pairs as the deck's TYPEs say).
"$feticon" export "$work/stack.yaml" --format calculix --overclosure 0 -o "$work/deck" > /dev/null
[[ $(grep -c '^\*CONTACT PAIR' "$work/deck/feticon.inp") -eq 2 ]] || { echo "FAIL: the deck has not two pairs"; exit 1; }
"$feticon" run "$work/deck/feticon.inp" -o "$work/deck1" "${quiet[@]}" --set subdomains=6 2> /dev/null
check "$work/deck1" 2
# The node-to-segment pair comes back as one (TYPE=NODE TO SURFACE, its law's sigma_inf 0).
/usr/bin/python3 - "$work/yaml/summary.json" "$work/deck1/summary.json" <<'PY'
import json, sys
a, b = ([p["formulation"] for p in json.load(open(f))["contact"]["pairs"]] for f in sys.argv[1:3])
print(f"formulations: problem file {a}, exported deck {b}")
assert a == b == ["mortar", "node_to_segment"], "the export changed a pair's formulation"
PY

# Two ranks: the same iterations and answer as one.
mpirun --oversubscribe -np 2 "$feticon" run "$work/stack.yaml" -o "$work/np2" "${quiet[@]}"
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-10 "$work/yaml" "$work/np2"

# No contact pair: the lower block alone on its supports.
sed -e '/^contact:/,$d' -e 's/c_zmax/a_zmax/' -e '/- {name: [bc],/d' -e '/^  [bc]:/d' -e '/set: [bc]_/d' \
  "$work/stack.yaml" > "$work/alone.yaml"
echo "displacements: small" >> "$work/alone.yaml"
"$feticon" run "$work/alone.yaml" -o "$work/alone" "${quiet[@]}"
/usr/bin/python3 - "$work/alone" <<'PY'
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
assert s["converged"] and "contact" not in s, "a model without contact: converged, no contact figures"
PY
echo "assembly: all checks passed"

# Sourced by tests/cli scripts (not run by itself; needs $src, the source folder).
# agreement DECK REFERENCE FOLDER BOUND [within|beyond] [NODES]: feticon's run of DECK in FOLDER
# within BOUND of max |u| of CalculiX's REFERENCE (.dat.ref or .frd.ref, compared by
# tests/tools/calculix_reference_agreement.py), or beyond it (so that a test shows the bound can
# fail); NODES: the count of nodes compared, if given. Prints the figure; exits the script on
# failure.
agreement() {
  local deck=$1 reference=$2 folder=$3 bound=$4 kind=${5:-within} nodes=${6:-}
  local figures
  figures=$(/usr/bin/python3 "$src/tests/tools/calculix_reference_agreement.py" "$deck" "$reference" "$folder") || true
  /usr/bin/python3 - "$figures" "$bound" "$kind" "$nodes" "$(basename "$reference")" <<'PY' || exit 1
import json, sys
f, bound, kind, nodes, reference = json.loads(sys.argv[1]), float(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
if f.get("nodes", 0) == 0 or (nodes and f["nodes"] != int(nodes)):
    sys.exit(f"{f['deck']}: {f.get('nodes', 0)} nodes compared with {reference}" + (f", expected {nodes}" if nodes else ""))
ok = f["relative"] <= bound if kind == "within" else f["relative"] > bound
print(f"{f['deck']}: {f['relative']:.3g} of max |u| from {reference} ({kind} {bound:g}, {f['nodes']} nodes)")
sys.exit(0 if ok else 1)
PY
}

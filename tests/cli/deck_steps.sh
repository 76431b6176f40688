#!/usr/bin/env bash
# Several *STEPs (issue 37): CalculiX's cubespring deck with a second step that doubles the
# pressure (*DLOAD, OP=MOD) ends where a one-step deck with the doubled pressure ends.
# Reference: that one-step run; frictionless elastic contact is path independent, so the two
# agree to the solver tolerances, below the .frd's six printed digits (asserted: 2e-5 of max
# |u|; measured 6.5e-7, small displacements and NLGEOM). The .frd holds both steps' results.
# Usage: deck_steps.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
deck="$src/tests/data/calculix/cubespring.inp"
# Step 2: the same step again with the pressure doubled on every face.
/usr/bin/python3 - "$deck" "$work" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
step = text[text.upper().index("*STEP"):]
doubled = re.sub(r"(P5,\s*)([0-9.Ee+-]+)", lambda m: m.group(1) + repr(2 * float(m.group(2))), step)
open(f"{sys.argv[2]}/two_steps.inp", "w").write(text + "\n" + doubled.replace("*STEP,NLGEOM", "*STEP"))
open(f"{sys.argv[2]}/doubled.inp", "w").write(text[:text.upper().index("*STEP")] + doubled)
PY
for kind in small large; do
  for model in two_steps doubled; do
    "$feticon" run "$work/$model.inp" -o "$work/$model-$kind" -q --set output.plots=false \
      --set displacements=$kind 2> /dev/null
  done
  /usr/bin/python3 - "$work" "$kind" <<'PY'
import sys
sys.path.insert(0, sys.argv[0].rsplit("/", 1)[0])
w, kind = sys.argv[1:]
def disp(path):
    blocks, rows = [], None
    for line in open(path):
        if line.startswith(" -4  DISP"):
            rows = []; blocks.append(rows)
        elif rows is not None and line.startswith(" -1"):
            rows.append([float(line[13 + 12 * k:25 + 12 * k]) for k in range(3)])
        elif line.startswith(" -3"):
            rows = None
    return blocks
a, b = disp(f"{w}/two_steps-{kind}/two_steps.frd"), disp(f"{w}/doubled-{kind}/doubled.frd")
scale = max(abs(v) for r in b[-1] for v in r)
worst = max(abs(x - y) for ra, rb in zip(a[-1], b[-1]) for x, y in zip(ra, rb)) / scale
print(f"{kind}: {len(a)} output times against {len(b)}; end of step 2 against the doubled load: {worst:.2g} of max |u|")
assert len(a) > len(b), "the two-step run wrote no more output times"
assert worst < 2e-5, "the steps do not end where the doubled load does"  # the .frd prints 6 digits
PY
done

#!/usr/bin/env bash
# The Python module (issue 67, item 4) from the build tree: examples/python/hertz_sweep.py runs
# and draws its figure; feticon.run's summary is the command line's to round-off (the same
# library call, so the reference is the executable's summary.json of the same problem); a dict
# problem and settings act as a problem file and --set do; a bad deck raises feticon.Error with
# the executable's one-line message.
# Usage: python_module.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$(realpath "$1")"
src="$(realpath "$2")"
build="$(dirname "$feticon")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
if [[ ! -f "$build/python/feticon/__init__.py" ]]; then
  echo "no Python module in $build (FETICON_PYTHON=OFF)"
  exit 77
fi
export PYTHONPATH="$build/python"
cd "$work"
/usr/bin/python3 "$src/examples/python/hertz_sweep.py" --loads 3 --out "$work" >sweep.log
test -s "$work/hertz_sweep.png"
grep -q "^Hertz benchmark: p_peak" sweep.log

"$feticon" run -q --output "$work/cli" --set load_steps=2 --set hertz.refinement=0.7
printf 'not a deck\n*NODE\n1, x\n' >"$work/bad.inp"
cli_error="$("$feticon" run -q --output "$work/bad" "$work/bad.inp" 2>&1 >/dev/null || true)"
/usr/bin/python3 - "$work/cli/summary.json" "$cli_error" <<'PY'
import json
import sys

import numpy as np

import feticon

cli = json.load(open(sys.argv[1]))
r = feticon.run(settings={"load_steps": 2, "hertz.refinement": 0.7})
# The same library call in another process: equal to round-off, not to the last digit (the heap
# addresses of the two processes differ, and with them where Eigen's vectorized sums start their
# packets; measured 8.4e-14 on one machine, 0 on another).
for key in ("p_peak_computed", "a_computed", "rms_error_over_p0"):
    a, b = r.summary["hertz"][key], cli["hertz"][key]
    assert abs(a - b) <= 1e-12 * abs(b), (key, a, b)
assert r.summary["qp"]["iterations"] == cli["qp"]["iterations"]
n = cli["nodes"]
assert r.coordinates.shape == (n, 3) and r.displacements.shape == (n, 3)
assert r.cell_stress.shape == (cli["elements"], 6) and r.von_mises.shape == (cli["elements"],)
# Conservation: the nodal contact forces of the pressure columns sum to the summary's force.
force = r.contact["normal_force"].sum()
assert abs(force / cli["contact"]["total_normal_force"] - 1) < 1e-9, force

# A dict is a problem file: the same problem as the settings above.
d = feticon.run({"problem": "hertz", "load_steps": 2, "hertz": {"refinement": 0.7}})
assert d.summary["hertz"]["p_peak_computed"] == r.summary["hertz"]["p_peak_computed"]
assert np.array_equal(d.displacements, r.displacements)

try:
    feticon.run(sys.argv[0] if False else "bad.inp")
    raise SystemExit("a bad deck did not raise")
except feticon.Error as e:
    expected = sys.argv[2].removeprefix("feticon: error: ").strip()
    assert str(e) == expected, (str(e), expected)
try:
    feticon.run(settings={"no_such_key": 1})
    raise SystemExit("an unknown setting did not raise")
except feticon.Error as e:
    assert "no_such_key" in str(e), str(e)
print("python module: results as on the command line")
PY

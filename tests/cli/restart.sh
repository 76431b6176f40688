#!/usr/bin/env bash
# Restart (issue 7): a large-displacement run is killed (SIGKILL) once load step 2 is on
# disk; `feticon run --restart DIR` continues it. Reference: the same run uninterrupted;
# the result must be the same (checkpoint holds u, the multipliers and the records, so the
# continuation repeats the uninterrupted arithmetic: compared to 1e-12 relative).
# Usage: restart.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'pkill -9 -f "$work/killed" 2> /dev/null || true; rm -rf "$work"' EXIT
args=(--set displacements=large --set load_steps=6 --set hertz.refinement=0.7 --set subdomains=4)
"$feticon" run -q --output "$work/full" "${args[@]}"

"$feticon" run -q --output "$work/killed" "${args[@]}" &
pid=$!
for _ in $(seq 1 3000); do
  [[ -f "$work/killed/step_002.vtu" ]] && break
  sleep 0.01
done
kill -9 "$pid" 2> /dev/null || true
wait "$pid" 2> /dev/null || true
[[ -f "$work/killed/checkpoint.bin" ]] || { echo "no checkpoint after step 2"; exit 1; }
if [[ -f "$work/killed/summary.json" ]]; then echo "the run finished before it was killed; test inconclusive"; exit 1; fi

"$feticon" run -q --restart "$work/killed"
/usr/bin/python3 - "$work/full/summary.json" "$work/killed/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
assert b["converged"] is True
assert [s["outer_iterations"] for s in a["steps"]] == [s["outer_iterations"] for s in b["steps"]]
for key in ["p_peak_computed", "axis_approach", "a_computed"]:
    x, y = a["hertz"][key], b["hertz"][key]
    assert abs(x - y) <= 1e-12 * abs(x), (key, x, y)
# The records of the steps before the kill come from the checkpoint, the spectrum estimate
# of their CG runs included.
assert a["qp"]["face_spectrum"] == b["qp"]["face_spectrum"], (a["qp"]["face_spectrum"], b["qp"]["face_spectrum"])
# and every counter (the times differ from run to run).
for key, x in a["qp"].items():
    if not key.endswith("seconds"):
        assert b["qp"][key] == x, (key, x, b["qp"][key])
PY
[[ $(grep -c "<DataSet" "$work/killed/solution.pvd") -eq 6 ]]

# Restarting a finished run, or one without a checkpoint, is a clear error.
if "$feticon" run -q --restart "$work/killed" 2> "$work/err"; then echo "restart of a finished run succeeded"; exit 1; fi
grep -q "already done" "$work/err"
mkdir -p "$work/empty"
if "$feticon" run -q --restart "$work/empty" 2> "$work/err"; then echo "restart without files succeeded"; exit 1; fi
[[ $(wc -l < "$work/err") -eq 1 ]]
# Killed before its first checkpoint: the folder has problem.yaml only.
mkdir -p "$work/early" && cp "$work/killed/problem.yaml" "$work/early/"
if "$feticon" run -q --restart "$work/early" 2> "$work/err"; then echo "restart without a checkpoint succeeded"; exit 1; fi
[[ $(wc -l < "$work/err") -eq 1 ]] && grep -q "before its first load step converged" "$work/err" || { cat "$work/err"; exit 1; }
# Without VTU output a run still keeps its checkpoint (a restart needs nothing else).
"$feticon" run -q --output "$work/novtu" --set displacements=large --set load_steps=2 --set hertz.refinement=0.5 \
  --set output.vtu=false --set output.plots=false
[[ -f "$work/novtu/checkpoint.bin" ]] || { echo "no checkpoint with output.vtu=false"; exit 1; }
echo "restart: all checks passed"

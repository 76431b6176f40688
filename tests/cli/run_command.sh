#!/usr/bin/env bash
# CLI tests of `feticon run` (issues 2, 4, 5): results folder, summary.json fields, one-line
# errors with non-zero exit, and a non-converged run that keeps its converged steps.
# Usage: run_command.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3

# 1. The built-in Hertz problem (coarse, for time) writes a complete results folder.
"$feticon" run -q --output "$work/hertz" --set hertz.refinement=0.5 --set subdomains=4 --set displacements=small
for f in summary.json problem.yaml contact_pressure.csv history.csv solution.pvd step_001.vtu; do
  [[ -s "$work/hertz/$f" ]] || { echo "missing $f"; exit 1; }
done
$py - "$work/hertz/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
for key in ["degrees_of_freedom", "elements", "subdomains", "timings_seconds", "contact", "qp", "hertz", "steps"]:
    assert key in s, key
for key in ["total_normal_force", "applied_load", "active_constraints", "feasibility_error"]:
    assert key in s["contact"], key
for key in ["a_analytic", "p0_analytic", "a_computed", "p_peak_computed", "rms_error_over_p0"]:
    assert key in s["hertz"], key
assert s["converged"] is True
# Force balance with SMALBE-M (reference: the applied load Q/2 * thickness).
assert abs(s["contact"]["total_normal_force"] / s["contact"]["applied_load"] - 1) < 1e-6
assert abs(s["hertz"]["p0_analytic"] / 3.7405e9 - 1) < 1e-3   # ALGORITHMS.md section 9
PY
/usr/bin/python3 "$2/tests/tools/read_vtu.py" "$work/hertz/step_001.vtu" > /dev/null

# 2. Bad input: one line on stderr naming the key, non-zero exit, no crash.
check_error() {
  local expect="$1"; shift
  set +e
  "$feticon" run -q --output "$work/bad" "$@" 2> "$work/err" > /dev/null
  local rc=$?
  set -e
  [[ $rc -ne 0 ]] || { echo "expected failure for: $*"; exit 1; }
  [[ $(wc -l < "$work/err") -eq 1 ]] || { echo "expected one error line for: $*"; cat "$work/err"; exit 1; }
  grep -q -- "$expect" "$work/err" || { echo "error for '$*' does not name '$expect':"; cat "$work/err"; exit 1; }
}
check_error "material.young" --set material.young=-1
check_error "material.poisson" --set material.poisson=0.5
check_error "contact.linear_band" --set contact.linear_band=0
check_error "contact.first_rows" --set contact.first_rows=wide
check_error "no_such_key" --set no_such_key=3
check_error "method" --set method=magic
check_error "KEY=VALUE" --set rho
printf 'rho: [1, 2\n' > "$work/broken.yaml"
check_error "broken.yaml" "$work/broken.yaml"

# The default is Vondrák et al.'s benchmark: large displacements, in one load increment
# (load_steps = 1, which converges without a cutback; the paper took two).
"$feticon" run -q --output "$work/default" --set hertz.refinement=0.5 --set subdomains=4
$py -c "import json; s=json.load(open('$work/default/summary.json')); assert s['displacements'] == 'large' and len(s['steps']) == 1 and s['converged'] and s['warnings'] == []"

# The plots run without a shell: quotes and a command in the folder name stay a name.
odd="$work/x'; touch $work/PWNED; echo '"
"$feticon" run -q --output "$odd" --set hertz.refinement=0.5 --set subdomains=4 --set displacements=small
[[ ! -e "$work/PWNED" ]] || { echo "the output folder name ran a command"; exit 1; }
[[ -s "$odd/contact_pressure.png" ]] || { echo "no plot in the oddly named folder"; exit 1; }
"$feticon" run -q --output "$work/noplots" --set hertz.refinement=0.5 --set subdomains=4 \
  --set displacements=small --set output.plots=false
[[ ! -e "$work/noplots/contact_pressure.png" ]] || { echo "output.plots=false drew plots"; exit 1; }

# Settings named under a custom problem's section (contact.formulation) apply to the built-in
# problem too: node-to-segment rows give another peak pressure than the default mortar rows.
for f in node_to_segment mortar; do
  "$feticon" run -q --output "$work/$f" --set hertz.refinement=0.5 --set subdomains=4 \
    --set displacements=small --set output.plots=false --set output.vtu=false --set contact.formulation=$f
done
$py -c "import json; p = [json.load(open('$work/%s/summary.json' % f))['contact']['peak_pressure'] for f in ('node_to_segment', 'mortar')]; assert abs(p[0] / p[1] - 1) > 1e-3, p"

# The dual penalty at rho = 1 leaves the contact forces out of balance with the load: two
# warnings (feasibility, contact force against Hertz's load) in summary.json and on stderr,
# exit 0 (a result, flagged); SMALBE-M gives none.
"$feticon" run -q --output "$work/dp" --set hertz.refinement=0.5 --set subdomains=4 \
  --set displacements=small --set method=dual_penalty --set rho=1 --set output.plots=false 2> "$work/dp.err"
grep -q "warning: the dual penalty with rho = 1" "$work/dp.err" || { echo "no dual penalty warning on stderr"; cat "$work/dp.err"; exit 1; }
$py -c "import json; s=json.load(open('$work/dp/summary.json')); w = s['warnings']; assert len(w) == 2 and 'method=smalbe' in w[0] and 'do not carry the load' in w[1], w"
$py -c "import json; s=json.load(open('$work/hertz/summary.json')); assert s['warnings'] == [], s['warnings']"

# The dual penalty's MPRGP stops at the outer loop's force tolerance too (qp.force_rtol), as
# SMALBE-M does: fewer steps on Hertz small (12 against 14), and the answer within a decade
# above that tolerance of the solve to qp.rtol alone (reference: qp.force_rtol=0).
for fr in 1e-7 0; do
  "$feticon" run -q --output "$work/dpf$fr" --set displacements=small --set method=dual_penalty \
    --set qp.force_rtol=$fr --set output.plots=false --set output.vtu=false 2> /dev/null
done
$py -c "
import json
a, b = (json.load(open('$work/dpf' + f + '/summary.json')) for f in ('1e-7', '0'))
sa, sb = a['qp']['iterations'], b['qp']['iterations']
pa, pb = a['contact']['peak_pressure'], b['contact']['peak_pressure']
assert sa < sb, (sa, sb)
assert abs(pa - pb) <= 1e-6 * pb, (pa, pb)"

# An output folder holding another run's results is refused; --overwrite removes feticon's
# files first (a stale step of the earlier run does not survive), and only those.
if "$feticon" run -q --output "$work/hertz" --set hertz.refinement=0.5 2> "$work/err"; then
  echo "a folder with another run's results was written over"; exit 1; fi
[[ $(wc -l < "$work/err") -eq 1 ]] && grep -q "holds another run's results (.*); give --overwrite" "$work/err" ||
  { cat "$work/err"; exit 1; }
: > "$work/noplots/step_009.vtu"; echo keep > "$work/noplots/notes.txt"
"$feticon" run -q --overwrite --output "$work/noplots" --set hertz.refinement=0.5 --set subdomains=4 \
  --set displacements=small --set output.plots=false
[[ ! -e "$work/noplots/step_009.vtu" && -s "$work/noplots/step_001.vtu" ]] || { echo "--overwrite left a stale step"; exit 1; }
[[ -s "$work/noplots/notes.txt" ]] || { echo "--overwrite removed a file that is not feticon's"; exit 1; }

# 3. Non-convergence: large displacements with too few outer iterations for load step 2.
#    The run fails with a message, but step 1 (converged) stays on disk with its PVD entry.
#    Exact QPs (newton.forcing=0): 5 and 6 outer iterations on the tensor mesh (step 2's
#    fifth has |du|/|u| = 1.05e-6, just above the tolerance).
set +e
"$feticon" run -q --output "$work/nc" --set displacements=large --set newton.max_iterations=5 \
  --set newton.forcing=0 --set hertz.refinement=0.5 --set subdomains=4 --set hertz.mesh=tensor \
  --set load_steps=2 --set newton.cutbacks=0 \
  --set hertz.growth_ratio=1.2 2> "$work/err"
rc=$?
set -e
[[ $rc -ne 0 ]] || { echo "non-converged run exited 0"; exit 1; }
grep -q "did not converge" "$work/err" || { cat "$work/err"; exit 1; }
[[ -s "$work/nc/step_001.vtu" ]] || { echo "converged step 1 lost"; exit 1; }
grep -q "step_001.vtu" "$work/nc/solution.pvd"
$py -c "import json,sys; s=json.load(open('$work/nc/summary.json')); assert s['converged'] is False and s['steps'][0]['converged'] is True"
echo "run_command: all checks passed"

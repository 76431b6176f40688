#!/usr/bin/env bash
# CLI test of `feticon qp` (app/qp_command.cpp).
# Usage: bash qp_command.sh <path-to-feticon> <source-dir>
#
# Problem: the 1D obstacle problem -u'' = -15 on (0,1), u(0) = u(1) = 0,
# u >= sin(4 pi x - pi/6)/2 - 2 at n = 20 interior points, A = tridiag(-1,2,-1)/h^2
# (stored as a symmetric lower triangle), b = -15. Checks: exit status 0, one JSON line with
# the nine report keys and converged = true, x written and x >= l exactly; an unconstrained
# run (l = -inf) converges; an iteration limit gives exit status 3 with the JSON still
# printed; malformed input gives a non-zero status and exactly one line on stderr; with
# --upper the box l <= x <= u is solved and an empty box is one line; with --discs MPGP
# solves the QP with discs (KKT checked here) and an empty disc file reproduces MPRGP's
# standard run.
set -euo pipefail

feticon=$1
python=/usr/bin/python3 # Debian's python3 (the first one on PATH may be a different build)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

n=20
awk -v n="$n" 'BEGIN {
  h = 1.0 / (n + 1)
  print "%%MatrixMarket matrix coordinate real symmetric"
  print n, n, 2 * n - 1
  for (i = 1; i <= n; ++i) {
    printf "%d %d %.17g\n", i, i, 2.0 / (h * h)
    if (i < n) printf "%d %d %.17g\n", i + 1, i, -1.0 / (h * h)
  }
}' >A.mtx
awk -v n="$n" 'BEGIN {
  print "%%MatrixMarket matrix array real general"
  print n, 1
  for (i = 1; i <= n; ++i) print -15
}' >b.mtx
awk -v n="$n" 'BEGIN {
  pi = atan2(0, -1)
  h = 1.0 / (n + 1)
  print "%%MatrixMarket matrix array real general"
  print n, 1
  for (i = 1; i <= n; ++i) printf "%.17g\n", 0.5 * sin(4 * pi * i * h - pi / 6) - 2
}' >l.mtx

# Checks that $1 holds one JSON object with the nine keys and converged == $2.
check_json() {
  "$python" - "$1" "$2" <<'PY'
import json, sys
lines = open(sys.argv[1]).read().splitlines()
assert len(lines) == 1, f"expected one line on stdout, got {len(lines)}: {lines}"
report = json.loads(lines[0])
assert isinstance(report, dict), "stdout is not a JSON object"
keys = ["converged", "iterations", "cg_steps", "expansion_steps", "proportioning_steps",
        "hessian_multiplications", "projected_gradient_norm", "cost", "seconds"]
missing = [k for k in keys if k not in report]
assert not missing, f"missing keys {missing}"
assert report["converged"] is (sys.argv[2] == "true"), f"converged = {report['converged']}"
steps = report["cg_steps"] + report["expansion_steps"] + report["proportioning_steps"]
assert steps == report["iterations"], "step counts do not add up to iterations"
assert report["hessian_multiplications"] > report["iterations"], "too few products"
PY
}

# 1. The obstacle problem converges; x is written and feasible.
status=0
"$feticon" qp --A A.mtx --b b.mtx --lower l.mtx --rtol 1e-8 --out x.mtx >out.json 2>err.txt ||
  status=$?
[ "$status" -eq 0 ] || fail "obstacle run: exit status $status: $(cat err.txt)"
check_json out.json true || fail "obstacle run: bad JSON: $(cat out.json)"
[ -s x.mtx ] || fail "x.mtx not written"
"$python" - <<'PY' || fail "x violates x >= l or has the wrong size"
def read(path):
    lines = [s for s in open(path).read().splitlines() if s.strip() and not s.startswith("%")]
    rows, cols = map(int, lines[0].split())
    assert cols == 1 and len(lines) == rows + 1
    return [float(s) for s in lines[1:]]
x, lower = read("x.mtx"), read("l.mtx")
assert len(x) == len(lower) == 20
assert all(xi >= li for xi, li in zip(x, lower)), "x < l somewhere"
assert any(xi == li for xi, li in zip(x, lower)), "no contact, but the obstacle is active"
PY

# 2. Without finite bounds (l = -inf parsed from the file) MPRGP is plain CG.
awk -v n="$n" 'BEGIN {
  print "%%MatrixMarket matrix array real general"
  print n, 1
  for (i = 1; i <= n; ++i) print "-inf"
}' >free.mtx
status=0
"$feticon" qp --A A.mtx --b b.mtx --lower free.mtx >free.json 2>err.txt || status=$?
[ "$status" -eq 0 ] || fail "unbounded run: exit status $status: $(cat err.txt)"
check_json free.json true || fail "unbounded run: bad JSON: $(cat free.json)"

# 3. An iteration limit is a result: exit status 3, JSON still printed, x still written.
status=0
"$feticon" qp --A A.mtx --b b.mtx --lower l.mtx --rtol 1e-12 --max-iterations 2 \
  --out x2.mtx >limit.json 2>err.txt || status=$?
[ "$status" -eq 3 ] || fail "iteration limit: expected exit status 3, got $status"
check_json limit.json false || fail "iteration limit: bad JSON: $(cat limit.json)"
[ -s x2.mtx ] || fail "iteration limit: x2.mtx not written"

# 4. Malformed input: non-zero status, exactly one line on stderr naming the file and line.
printf '%%%%MatrixMarket matrix coordinate real general\n2 2 1\n1 3 1.0\n' >bad.mtx
status=0
"$feticon" qp --A bad.mtx --b b.mtx >bad.out 2>bad.err || status=$?
[ "$status" -ne 0 ] || fail "malformed A accepted"
[ "$(wc -l <bad.err)" -eq 1 ] || fail "expected one line on stderr, got: $(cat bad.err)"
grep -q 'bad.mtx:3:' bad.err || fail "stderr does not name bad.mtx line 3: $(cat bad.err)"

# 5. A nonsymmetric A is rejected the same way.
printf '%%%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 2\n2 2 2\n1 2 1\n' >asym.mtx
printf '%%%%MatrixMarket matrix array real general\n2 1\n1\n1\n' >b2.mtx
status=0
"$feticon" qp --A asym.mtx --b b2.mtx >asym.out 2>asym.err || status=$?
[ "$status" -ne 0 ] || fail "nonsymmetric A accepted"
[ "$(wc -l <asym.err)" -eq 1 ] || fail "expected one line on stderr, got: $(cat asym.err)"
grep -q 'not symmetric' asym.err || fail "stderr does not say 'not symmetric': $(cat asym.err)"

# 6. NaN in A is an input error (inf keeps its meaning of an absent bound in l).
printf '%%%%MatrixMarket matrix coordinate real general\n2 2 2\n1 1 nan\n2 2 2\n' >nan.mtx
status=0
"$feticon" qp --A nan.mtx --b b2.mtx >nan.out 2>nan.err || status=$?
[ "$status" -eq 1 ] || fail "NaN in A: expected exit status 1, got $status"
[ "$(wc -l <nan.err)" -eq 1 ] || fail "expected one line on stderr, got: $(cat nan.err)"
grep -q 'nan.mtx:3:.*NaN' nan.err || fail "stderr does not name the NaN of nan.mtx line 3: $(cat nan.err)"

# 7. Bounds whose cost overflows: a one-line error and exit status 1, not a null cost.
printf '%%%%MatrixMarket matrix coordinate real general\n2 2 2\n1 1 2\n2 2 2\n' >spd.mtx
printf '%%%%MatrixMarket matrix array real general\n2 1\n1e300\n1e300\n' >huge.mtx
status=0
"$feticon" qp --A spd.mtx --b b2.mtx --lower huge.mtx >huge.out 2>huge.err || status=$?
[ "$status" -eq 1 ] || fail "bounds of 1e300: expected exit status 1, got $status ($(cat huge.out))"
[ "$(wc -l <huge.err)" -eq 1 ] || fail "expected one line on stderr, got: $(cat huge.err)"
grep -q 'non-finite' huge.err || fail "stderr does not say non-finite: $(cat huge.err)"

# 8. Memory guard (issue 21): a 2e9 x 2e9 header is refused from its size line, before
# anything is allocated (it ended in std::bad_alloc), within 5 s and 200 MB; a vector file
# declaring more values than it could hold and a device as a matrix are input errors too.
printf '%%%%MatrixMarket matrix coordinate real symmetric\n2000000000 2000000000 2\n1 1 2\n2 2 2\n' >giant.mtx
printf '%%%%MatrixMarket matrix array real general\n2000000000 1\n1\n1\n' >giant_b.mtx
one_line_error() { # NAME PATTERN ARGS...
  local name=$1 pattern=$2 status=0
  shift 2
  /usr/bin/time -f "%e %M" -o time.txt timeout 5 "$feticon" qp "$@" >guard.out 2>guard.err || status=$?
  [ "$status" -eq 1 ] || fail "$name: expected exit status 1, got $status"
  [ "$(wc -l <guard.err)" -eq 1 ] || fail "$name: expected one line on stderr, got: $(cat guard.err)"
  grep -q -- "$pattern" guard.err || fail "$name: stderr does not say '$pattern': $(cat guard.err)"
  read -r seconds kilobytes < <(tail -1 time.txt)
  # A sanitizer build's process alone takes 230 MB (shadow memory): there only the status counts.
  [ -n "${FETICON_SANITIZED:-}" ] || [ "$kilobytes" -lt 204800 ] || fail "$name: peak memory $kilobytes KB"
}
one_line_error "2e9 x 2e9 matrix" "needs about .* GiB, more than the" --A giant.mtx --b b2.mtx
one_line_error "2e9 values declared" "giant_b.mtx:2: the size line declares 2000000000 values" --A spd.mtx --b giant_b.mtx
one_line_error "a device as matrix" "/dev/zero: is not a regular file" --A /dev/zero --b b2.mtx

# 9. Box constraints (--upper): u = l + 0.3 leaves the ends of the string, far above the
# obstacle, on the upper bound; x is inside the box with both bounds active somewhere. With
# u = +inf the report equals the run without --upper (same steps, cost and norm: the box
# solve reproduces the lower-bound one bitwise, qp/mprgp.hpp), and an empty box (l_i > u_i)
# is one line naming the component.
awk 'NR <= 2 { print; next } { printf "%.17g\n", $1 + 0.3 }' l.mtx >u.mtx
status=0
"$feticon" qp --A A.mtx --b b.mtx --lower l.mtx --upper u.mtx --rtol 1e-8 --out xb.mtx >box.json 2>err.txt ||
  status=$?
[ "$status" -eq 0 ] || fail "box run: exit status $status: $(cat err.txt)"
check_json box.json true || fail "box run: bad JSON: $(cat box.json)"
"$python" - <<'PY' || fail "x violates l <= x <= u, or a bound is never active"
def read(path):
    lines = [s for s in open(path).read().splitlines() if s.strip() and not s.startswith("%")]
    return [float(s) for s in lines[1:]]
x, lower, upper = read("xb.mtx"), read("l.mtx"), read("u.mtx")
assert all(l <= xi <= u for xi, l, u in zip(x, lower, upper)), "x outside the box"
assert any(xi == l for xi, l in zip(x, lower)), "no component at its lower bound"
assert any(xi == u for xi, u in zip(x, upper)), "no component at its upper bound"
PY
sed 's/^-*[0-9].*$/inf/' l.mtx | awk 'NR == 2 { print "20 1"; next } { print }' >inf.mtx
"$feticon" qp --A A.mtx --b b.mtx --lower l.mtx --upper inf.mtx --rtol 1e-8 >inf.json 2>err.txt ||
  fail "u = +inf run failed: $(cat err.txt)"
"$python" - <<'PY' || fail "u = +inf differs from the run without --upper"
import json
a, b = json.load(open("out.json")), json.load(open("inf.json"))
for key in ["iterations", "cg_steps", "expansion_steps", "proportioning_steps",
            "hessian_multiplications", "projected_gradient_norm", "cost"]:
    assert a[key] == b[key], f"{key}: {a[key]} != {b[key]}"
PY
awk 'NR <= 2 { print; next } { printf "%.17g\n", $1 - (NR == 5 ? 1 : -1) }' l.mtx >empty.mtx
status=0
"$feticon" qp --A A.mtx --b b.mtx --lower l.mtx --upper empty.mtx >empty.out 2>empty.err || status=$?
[ "$status" -eq 1 ] || fail "empty box: expected exit status 1, got $status"
[ "$(wc -l <empty.err)" -eq 1 ] || fail "expected one line on stderr, got: $(cat empty.err)"
grep -q 'component 2' empty.err || fail "stderr does not name component 2: $(cat empty.err)"

# 10. Discs (--discs, MPGP): ||(x_1, x_2)|| <= 1e-3 (active), ||(x_5, x_6)|| <= 1e6 (inactive),
# (x_9, x_10) = 0 (radius 0), x_i >= -1 on components 13..20, the rest free. KKT checked from
# the written x with A and b: on the active disc g = -nu x/|x| with nu >= 0, elsewhere the
# sign conditions, to 1e-6 (rtol 1e-10 times |b| = 3e3, and the Matrix Market round trip).
awk -v n="$n" 'BEGIN {
  print "%%MatrixMarket matrix array real general"
  print n, 1
  for (i = 1; i <= n; ++i) printf "%.17g\n", 1000 * sin(i)
}' >bd.mtx
awk -v n="$n" 'BEGIN {
  print "%%MatrixMarket matrix array real general"
  print n, 1
  for (i = 1; i <= n; ++i) print (i >= 13 ? -1 : "-inf")
}' >ld.mtx
printf '%% i j radius (1-based)\n1 2 1e-3\n\n5 6 1e6\n# a fixed pair\n9 10 0\n' >discs.txt
status=0
"$feticon" qp --A A.mtx --b bd.mtx --lower ld.mtx --discs discs.txt --rtol 1e-10 --out xd.mtx >discs.json \
  2>err.txt || status=$?
[ "$status" -eq 0 ] || fail "disc run: exit status $status: $(cat err.txt)"
check_json discs.json true || fail "disc run: bad JSON: $(cat discs.json)"
"$python" - <<'PY' || fail "disc run: x is not the KKT point"
import math
def vector(path):
    lines = [s for s in open(path).read().splitlines() if s.strip() and not s.startswith("%")]
    return [float(s) for s in lines[1:]]
x, b, lower = vector("xd.mtx"), vector("bd.mtx"), vector("ld.mtx")
n, h = len(x), 1.0 / (len(x) + 1)
g = [(2 * x[i] - (x[i - 1] if i > 0 else 0) - (x[i + 1] if i + 1 < n else 0)) / h**2 - b[i] for i in range(n)]
tol = 1e-6
r = math.hypot(x[0], x[1])
assert abs(r - 1e-3) <= 1e-15, f"disc (1, 2) not active: |x| = {r}"
nu = -(x[0] * g[0] + x[1] * g[1]) / r
assert nu > 0, f"disc (1, 2): nu = {nu}"
assert math.hypot(g[0] + nu * x[0] / r, g[1] + nu * x[1] / r) <= tol, "disc (1, 2): tangential gradient"
assert math.hypot(x[4], x[5]) < 1e6 and math.hypot(g[4], g[5]) <= tol, "disc (5, 6) inactive but g != 0"
assert x[8] == 0 and x[9] == 0, "disc (9, 10) of radius 0 not at 0"
for i in [2, 3, 6, 7, 10, 11]:
    assert abs(g[i]) <= tol, f"free component {i + 1}: g = {g[i]}"
for i in range(12, n):
    assert x[i] >= -1, f"x_{i + 1} < -1"
    assert (g[i] >= -tol) if x[i] == -1 else (abs(g[i]) <= tol), f"component {i + 1}: g = {g[i]}"
PY
printf '%% no discs\n' >no_discs.txt
"$feticon" qp --A A.mtx --b b.mtx --lower l.mtx --discs no_discs.txt --rtol 1e-8 >nodisc.json 2>err.txt ||
  fail "run with an empty disc file failed: $(cat err.txt)"
"$feticon" qp --A A.mtx --b b.mtx --lower l.mtx --expansion std --rtol 1e-8 >std.json 2>err.txt ||
  fail "MPRGP std run failed: $(cat err.txt)"
"$python" - <<'PY' || fail "MPGP without discs differs from MPRGP's standard run"
import json
a, b = json.load(open("std.json")), json.load(open("nodisc.json"))
for key in ["iterations", "cg_steps", "expansion_steps", "proportioning_steps",
            "hessian_multiplications", "projected_gradient_norm", "cost"]:
    assert a[key] == b[key], f"{key}: {a[key]} != {b[key]}"
PY

echo "qp_command: all checks passed"

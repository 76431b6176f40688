#!/usr/bin/env bash
# A tie of about 1e5 rows (issue 63, item 3: "a tie of 10^5 rows: set-up under 2 s"): two
# 1 x 1 x 0.05 m plates of 150^2 and 183^2 hex8 cells (one layer each, 340k DOFs), the finer
# one's bottom tied to the coarser one's top (33 856 slave nodes, 101 200 rows), pulled by
# 1e8 Pa; beside it the same plates pressed together through a mortar contact pair instead, as
# the reference of the same mesh measured in the same run. Each case --reps times (default 3):
# the log's "rows made in" (contact/tie_rows: closest points, ADJUST, mortar integration), the
# run's MPRGP steps, dual solve and total solve time, and the peak memory; medians printed.
# With --calculix, the deck `feticon export` writes of the tie model is also run by CalculiX
# (ccx, 2 threads) and by feticon, one after the other, --reps times each: wall time, peak
# memory and the error against the exact uniaxial tension of both.
#
#   bench/tie_setup.sh [--reps N] [--feticon build/feticon] [--calculix]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
reps=3
calculix=false
while [[ $# -gt 0 ]]; do
  case $1 in
    --reps) reps=$2; shift 2 ;;
    --feticon) feticon=$2; shift 2 ;;
    --calculix) calculix=true; shift ;;
    *) echo "usage: $0 [--reps N] [--feticon PATH] [--calculix]" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/tie.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: a, origin: [0, 0, 0], lengths: [1, 1, 0.05], cells: [150, 150, 1]}
    - {name: b, origin: [0, 0, 0.05], lengths: [1, 1, 0.05], cells: [183, 183, 1]}
bodies:
  a: {young: 2e11, poisson: 0.3}
  b: {young: 2e11, poisson: 0.3}
supports:
  - {set: a_zmin, z: 0}
  - {set: a_xmin, x: 0}
  - {set: b_xmin, x: 0}
  - {set: a_ymin, y: 0}
  - {set: b_ymin, y: 0}
loads:
  - {set: b_zmax, traction: [0, 0, 1e8]}
ties:
  - {name: glue, slave: b_zmin, master: a_zmax}
displacements: small
YAML
sed -e 's/^ties:/contact:/' -e 's/  - {name: glue, slave: b_zmin, master: a_zmax}/  - {slave: b_zmin, master: a_zmax}/' \
  -e 's/traction: \[0, 0, 1e8\]/traction: [0, 0, -1e8]/' "$work/tie.yaml" > "$work/contact.yaml"
for case in tie contact; do
  for ((r = 1; r <= reps; ++r)); do
    /usr/bin/time -f "%M" -o "$work/$case.$r.mem" "$feticon" run "$work/$case.yaml" -o "$work/$case.$r" \
      --set output.plots=false --set output.vtu=false > "$work/$case.$r.log" 2>&1
  done
done
/usr/bin/python3 - "$work" "$reps" <<'PY'
import json, re, statistics, sys
work, reps = sys.argv[1], int(sys.argv[2])
for case in ("tie", "contact"):
    made, steps, dual, total, memory = [], [], [], [], []
    for r in range(1, reps + 1):
        log = open(f"{work}/{case}.{r}.log").read()
        if m := re.search(r"ties: (\d+) rows made in ([0-9.]+) s", log):
            made.append(float(m.group(2)))
            rows = int(m.group(1))
        s = json.load(open(f"{work}/{case}.{r}/summary.json"))
        assert s["converged"], f"{case} run {r} did not converge"
        steps.append(s["qp"]["iterations"])
        dual.append(s["timings_seconds"]["dual solve (MPRGP)"])
        total.append(s["timings_seconds"]["total solve"])
        memory.append(int(open(f"{work}/{case}.{r}.mem").read().split()[-1]) / 2**20)
    line = f"{case:8s} DOFs {s['degrees_of_freedom']}, MPRGP steps {statistics.median(steps)}, " \
           f"dual solve {statistics.median(dual):.2f} s, total solve {statistics.median(total):.2f} s, " \
           f"peak memory {statistics.median(memory):.2f} GiB"
    if made:
        line += f", {rows} tie rows made in {statistics.median(made):.2f} s"
    print(line + f" (medians of {reps})")
PY
$calculix || exit 0
"$feticon" export "$work/tie.yaml" --format calculix -o "$work/deck" > /dev/null
for ((r = 1; r <= reps; ++r)); do
  (cd "$work/deck" && OMP_NUM_THREADS=2 /usr/bin/time -f "%e %M" -o "ccx.$r.time" ccx -i feticon > ccx.log 2>&1)
  cp "$work/deck/feticon.frd" "$work/ccx.frd"
  /usr/bin/time -f "%e %M" -o "$work/deck/feticon.$r.time" "$feticon" run "$work/deck/feticon.inp" -o "$work/deckrun" \
    --overwrite --set output.plots=false --set output.vtu=false > /dev/null 2>&1
done
/usr/bin/python3 - "$work" "$reps" "$root" <<'PY'
import statistics, sys
work, reps, root = sys.argv[1], int(sys.argv[2]), sys.argv[3]
sys.path.insert(0, root + "/tests/tools")
from frd_vs_vtu import frd_displacements
coords, reading = {}, False
for line in open(work + "/deck/feticon.inp"):
    if line.startswith("*"):
        reading = line.upper().startswith("*NODE,")
        continue
    if reading:
        f = line.split(",")
        coords[int(f[0])] = [float(v) for v in f[1:4]]
E, nu, s = 2e11, 0.3, 1e8
def error(frd):
    u = {r[0]: r[1:] for r in frd_displacements(frd)}
    worst = scale = 0.0
    for n, (x, y, z) in coords.items():
        exact = (-nu * s * x / E, -nu * s * y / E, s * z / E)
        worst = max(worst, max(abs(a - b) for a, b in zip(u[n], exact)))
        scale = max(scale, max(abs(v) for v in exact))
    return worst / scale
for code, frd in (("ccx", work + "/ccx.frd"), ("feticon", work + "/deckrun/feticon.frd")):
    times = [open(f"{work}/deck/{code}.{r}.time").read().split() for r in range(1, reps + 1)]
    wall = statistics.median(float(t[0]) for t in times)
    memory = statistics.median(int(t[1]) for t in times) / 2**20
    print(f"deck, {code:8s} wall {wall:.2f} s, peak memory {memory:.2f} GiB, max |u - u_exact| / max |u_exact| "
          f"{error(frd):.2e} (medians of {reps})")
PY

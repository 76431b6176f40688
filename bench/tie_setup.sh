#!/usr/bin/env bash
# A tie of about 1e5 rows (issue 63, item 3: "a tie of 10^5 rows: set-up under 2 s"): two
# 1 x 1 x 0.05 m plates of 150^2 and 183^2 hex8 cells (one layer each, 340k DOFs), the finer
# one's bottom tied to the coarser one's top (33 856 slave nodes, 101 200 rows), pulled by
# 1e8 Pa; beside it the same plates pressed together through a mortar contact pair instead, as
# the reference of the same mesh measured in the same run. Each case --reps times (default 3):
# the log's "rows made in" (contact/tie_rows: closest points, ADJUST, mortar integration), the
# run's MPRGP steps, dual solve and total solve time, and the peak memory; medians printed.
#
#   bench/tie_setup.sh [--reps N] [--feticon build/feticon]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
reps=3
while [[ $# -gt 0 ]]; do
  case $1 in
    --reps) reps=$2; shift 2 ;;
    --feticon) feticon=$2; shift 2 ;;
    *) echo "usage: $0 [--reps N] [--feticon PATH]" >&2; exit 2 ;;
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
